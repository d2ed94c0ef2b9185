#include "sim/run_rows.h"

#include <cmath>
#include <limits>

#include "common/angles.h"
#include "common/units.h"
#include "estimation/ekf.h"
#include "estimation/models/drkf_radar_fix.h"
#include "navigation/dr_horizon.h"

namespace reckoner::sim {

namespace {
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
}  // namespace

double OwnShipRow::positionErrorM() const {
  return std::hypot(estXM - trueXM, estYM - trueYM);
}
double OwnShipRow::velocityErrorMps() const {
  return std::hypot(estVxMps - trueVxMps, estVyMps - trueVyMps);
}
double OwnShipRow::sdPositionM() const {
  return std::hypot(sdXM, sdYM);
}
bool OwnShipRow::positionWithin(double k) const {
  return std::abs(estXM - trueXM) <= k * sdXM && std::abs(estYM - trueYM) <= k * sdYM;
}

GroundEstimate groundEstimateOf(const est::drkf::Belief& b, const geo::LocalFrame& geo) {
  const est::Vec<4> g = nav::groundStateOf(b);
  const est::Mat<4> C = nav::groundCovarianceOf(b);
  const geo::GeoPoint ll = geo.toGeodetic({g[0], g[1]});
  GroundEstimate e;
  e.xM = g[0];
  e.yM = g[1];
  e.vxMps = g[2];
  e.vyMps = g[3];
  e.sdXM = std::sqrt(C(0, 0));
  e.sdYM = std::sqrt(C(1, 1));
  e.sdVxMps = std::sqrt(C(2, 2));
  e.sdVyMps = std::sqrt(C(3, 3));
  e.latDeg = ll.latDeg;
  e.lonDeg = ll.lonDeg;
  e.covXYM2 = C(0, 1);
  e.headingRad = headingOf(b);
  return e;
}

double headingOf(const est::drkf::Belief& b) {
  using namespace est::drkf;
  const double vx = b.x[kVelX], vy = b.x[kVelY];
  if (!(std::hypot(vx, vy) >= kMinHeadingSpeedMps)) return kNan;
  return wrapTwoPi(bearingOf(vx, vy));
}

OwnShipRow groundRow(const SimFrame& f, const est::Gaussian<4>& g, const geo::LocalFrame& geo) {
  OwnShipRow r;
  r.timeUs = f.timeUs;
  r.trueXM = f.truth.position.xM;
  r.trueYM = f.truth.position.yM;
  r.trueVxMps = f.truth.groundVxMps();
  r.trueVyMps = f.truth.groundVyMps();
  r.estXM = g.x[0];
  r.estYM = g.x[1];
  r.estVxMps = g.x[2];
  r.estVyMps = g.x[3];
  r.sdXM = std::sqrt(g.P(0, 0));
  r.sdYM = std::sqrt(g.P(1, 1));
  r.sdVxMps = std::sqrt(g.P(2, 2));
  r.sdVyMps = std::sqrt(g.P(3, 3));
  const geo::GeoPoint ll = geo.toGeodetic({g.x[0], g.x[1]});
  r.estLatDeg = ll.latDeg;
  r.estLonDeg = ll.lonDeg;
  r.nees = est::nees<4>(est::Vec<4>(r.trueXM, r.trueYM, r.trueVxMps, r.trueVyMps) - g.x, g.P);
  r.sensors = f.sensors;
  r.covXYM2 = g.P(0, 1);
  r.deadReckoning = f.deadReckoning.active;
  return r;
}

OwnShipRow makeRow(const SimFrame& f, const geo::LocalFrame& geo, const est::drkf::ProcessParams& process) {
  OwnShipRow r = groundRow(f, {nav::groundStateOf(f.estimate), nav::groundCovarianceOf(f.estimate)}, geo);
  r.nees = nav::drkfNees(f.trueState - f.estimate.x, f.estimate.P, process);
  r.estHeadingRad = headingOf(f.estimate);
  r.estCurrentXMps = f.estimate.x[est::drkf::kCurX];
  r.estCurrentYMps = f.estimate.x[est::drkf::kCurY];
  for (const auto& u : f.updates) r.rowsApplied += u.dim;
  return r;
}

OwnShipDetailRow ownShipDetailRow(const SimFrame& f) {
  using namespace est::drkf;
  const State& x = f.estimate.x;
  const Covariance& P = f.estimate.P;
  const State& t = f.trueState;
  const auto sd = [&P](int i) { return std::sqrt(P(i, i)); };
  OwnShipDetailRow r;
  r.trueCurrentXMps = t[kCurX];
  r.trueCurrentYMps = t[kCurY];
  r.estCurrentXMps = x[kCurX];
  r.estCurrentYMps = x[kCurY];
  r.sdCurrentXMps = sd(kCurX);
  r.sdCurrentYMps = sd(kCurY);
  r.trueLoranXM = t[kLoranX];
  r.trueLoranYM = t[kLoranY];
  r.estLoranXM = x[kLoranX];
  r.estLoranYM = x[kLoranY];
  r.sdLoranXM = sd(kLoranX);
  r.sdLoranYM = sd(kLoranY);
  r.trueLogBiasMps = t[kLogBias];
  r.estLogBiasMps = x[kLogBias];
  r.sdLogBiasMps = sd(kLogBias);
  r.error95M = nav::positionError95M(f.estimate);
  return r;
}

double TrackRow::positionErrorM() const {
  return std::hypot(estXM - trueXM, estYM - trueYM);
}
double TrackRow::velocityErrorMps() const {
  return std::hypot(estVxMps - trueVxMps, estVyMps - trueVyMps);
}

TrackRow trackEstimateRow(TimeUs t, int trackId, int targetId, track::TrackStatus status, bool dangerous,
                          const est::ttkf::Belief& b, const track::TrackKinematics& k, double nis,
                          const geo::LocalFrame& geo) {
  namespace tk = est::ttkf;
  TrackRow r;
  r.timeUs = t;
  r.trackId = trackId;
  r.targetId = targetId;
  r.status = status;
  r.dangerous = dangerous;
  r.estXM = b.x[tk::kTgtX];
  r.estYM = b.x[tk::kTgtY];
  r.estVxMps = b.x[tk::kTgtVx];
  r.estVyMps = b.x[tk::kTgtVy];
  r.sdXM = std::sqrt(b.P(tk::kTgtX, tk::kTgtX));
  r.sdYM = std::sqrt(b.P(tk::kTgtY, tk::kTgtY));
  r.sdVxMps = std::sqrt(b.P(tk::kTgtVx, tk::kTgtVx));
  r.sdVyMps = std::sqrt(b.P(tk::kTgtVy, tk::kTgtVy));
  const geo::GeoPoint ll = geo.toGeodetic({r.estXM, r.estYM});
  r.estLatDeg = ll.latDeg;
  r.estLonDeg = ll.lonDeg;
  r.rangeNm = metresToNm(k.rangeM);
  r.bearingDeg = radToDeg(wrapTwoPi(k.trueBearingRad));
  r.courseDeg = radToDeg(k.trueCourseRad);
  r.speedKn = mpsToKnots(k.speedMps);
  r.cpaNm = k.cpa.defined ? metresToNm(k.cpa.cpaM) : kNan;
  r.tcpaMin = k.cpa.defined ? k.cpa.tcpaS / 60.0 : kNan;
  r.nis = nis;
  r.nees = kNan;
  r.positionVelocityNees4 = kNan;
  return r;
}

double positionVelocityNees4(const est::ttkf::Belief& b, const VesselTruth& truth) {
  namespace tk = est::ttkf;
  constexpr std::array<int, 4> kIdx{tk::kTgtX, tk::kTgtY, tk::kTgtVx, tk::kTgtVy};
  const est::Vec<4> trueState(truth.position.xM, truth.position.yM, truth.groundVxMps(), truth.groundVyMps());
  est::Vec<4> e;
  est::Mat<4> P;
  for (std::size_t r = 0; r < kIdx.size(); ++r) {
    e[static_cast<int>(r)] = b.x[kIdx[r]] - trueState[static_cast<int>(r)];
    for (std::size_t c = 0; c < kIdx.size(); ++c)
      P(static_cast<int>(r), static_cast<int>(c)) = b.P(kIdx[r], kIdx[c]);
  }
  return est::nees<4>(e, P);
}

TrackRow trackRow(const SweepSnapshot& sw, const TrackSnapshot& t, const std::vector<TargetSpec>& targets,
                  const geo::LocalFrame& geo) {
  namespace tk = est::ttkf;
  TrackRow r = trackEstimateRow(sw.timeUs, t.trackId, t.targetId, t.status, t.dangerous, t.estimate,
                                t.kinematics, t.lastNis, geo);
  r.manoeuvring = t.manoeuvring;
  r.manual = t.manual;
  r.aisMmsi = t.aisMmsi;
  std::size_t i = 0;
  while (i < targets.size() && targets[i].id != t.targetId) ++i;
  if (t.targetId < 0 || i >= targets.size() || i >= sw.targets.size()) return r;
  const VesselTruth& truth = sw.targets[i];
  r.hasTruth = true;
  r.trueXM = truth.position.xM;
  r.trueYM = truth.position.yM;
  r.trueVxMps = truth.groundVxMps();
  r.trueVyMps = truth.groundVyMps();
  r.nees = est::nees<tk::kStateDim>(trueTrackState(sw.ownTruth, truth) - t.estimate.x, t.estimate.P);
  r.positionVelocityNees4 = positionVelocityNees4(t.estimate, truth);
  return r;
}

void appendSweepRows(const SimFrame& f, const Scenario& scenario, const geo::LocalFrame& geo,
                     std::vector<TrackRow>& tracks, std::vector<TargetSweepRow>& targets) {
  for (const SweepSnapshot& sw : f.sweeps) {
    for (std::size_t i = 0; i < scenario.targets.size(); ++i) {
      const auto& p = sw.targets[i].position;
      const double range = std::hypot(p.xM - sw.ownTruth.position.xM, p.yM - sw.ownTruth.position.yM);
      targets.push_back({sw.timeUs, scenario.targets[i].id,
                         range <= scenario.radar.maxRangeM && range >= scenario.radar.minRangeM, p.xM, p.yM});
    }
    for (const TrackSnapshot& t : sw.tracks) tracks.push_back(trackRow(sw, t, scenario.targets, geo));
  }
}

est::Vec<3> radarFixError(const RadarFixReport& r, const SimFrame& f) {
  const est::Vec<3> err(r.fixPosition[0] - f.truth.position.xM, r.fixPosition[1] - f.truth.position.yM,
                        angleDiff(r.fixHeadingRad, f.truth.headingRad));
  return err - r.motionSensitivity * (est::drkf::sweepMotionOf(f.trueState, f.shipMotion) - r.assumedMotion);
}

RadarFixRow radarFixRow(const RadarFixReport& r, const SimFrame& f) {
  RadarFixRow s;
  s.timeUs = r.timeUs;
  s.informative = r.informative;
  s.applied = r.update.applied();
  s.echoes = r.echoes;
  s.used = r.used;
  s.xM = r.fixPosition[0];
  s.yM = r.fixPosition[1];
  s.headingRad = r.fixHeadingRad;
  s.sdXM = std::sqrt(r.covariance(0, 0));
  s.sdYM = std::sqrt(r.covariance(1, 1));
  s.sdHeadingRad = std::sqrt(r.covariance(2, 2));
  s.trueXM = f.truth.position.xM;
  s.trueYM = f.truth.position.yM;
  s.trueHeadingRad = r.fixHeadingRad - angleDiff(r.fixHeadingRad, f.truth.headingRad);
  s.nees = est::nees<3>(radarFixError(r, f), r.covariance);
  s.rmsResidual = r.rmsNormalizedResidual;
  s.nis = r.update.nis;
  s.dim = r.update.dim;
  return s;
}

std::vector<geo::GridPoint> plotPositionsFromEstimate(const SimFrame& f, const geo::LocalFrame& geo) {
  const double cx = f.estimate.x[est::drkf::kPosX], cy = f.estimate.x[est::drkf::kPosY];
  const double gamma = geo.gridInfo({cx, cy}).convergenceRad;
  std::vector<geo::GridPoint> out;
  out.reserve(f.plots.size());
  for (const auto& p : f.plots) {
    const double gridBearing = p.bearingRad - gamma;
    out.push_back({cx + p.rangeM * std::sin(gridBearing), cy + p.rangeM * std::cos(gridBearing)});
  }
  return out;
}

}  // namespace reckoner::sim
