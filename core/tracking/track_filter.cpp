#include "tracking/track_filter.h"

#include <Eigen/Cholesky>
#include <cmath>
#include <stdexcept>

#include "common/angles.h"
#include "estimation/ekf.h"

namespace reckoner::track {
namespace {

/// The plot as an absolute grid position with own ship at `ownPos` (covariance ownPosP).
struct AbsolutePlot {
  est::Vec<2> z;
  est::Mat<2> R;
};
AbsolutePlot absolute(const GridPlot& p, const est::Vec<2>& ownPos, const est::Mat<2>& ownPosP) {
  const double s = std::sin(p.bearingRad), c = std::cos(p.bearingRad), r = p.rangeM;
  est::Mat<2> J;  // d(dx, dy) / d(range, bearing)
  J << s, r * c, c, -r * s;
  AbsolutePlot a;
  a.z = ownPos + est::Vec<2>(r * s, r * c);
  a.R = J * est::Vec<2>(p.rangeVarM2, p.bearingVarRad2).asDiagonal() * J.transpose() + ownPosP;
  est::symmetrise(a.R);
  return a;
}

bool finitePlot(const GridPlot& p) {
  return std::isfinite(p.rangeM) && std::isfinite(p.bearingRad) && std::isfinite(p.rangeVarM2) &&
         std::isfinite(p.bearingVarRad2) && p.rangeVarM2 > 0.0 && p.bearingVarRad2 > 0.0;
}

tk::Belief compose(const est::Gaussian<6>& own, const est::Gaussian<6>& target) {
  tk::Belief b;
  b.x.head<6>() = own.x;
  b.x.tail<6>() = target.x;
  b.P.setZero();
  b.P.topLeftCorner<6, 6>() = own.P;
  b.P.bottomRightCorner<6, 6>() = target.P;
  return b;
}

/// Range and bearing of a composed belief against a plot, gated: the report of a radar update that has
/// not been applied yet (status Accepted when it passes).
est::UpdateReport<2> radarInnovation(const TtkfContext& ctx, const tk::Belief& b, const GridPlot& plot) {
  est::UpdateReport<2> rep;
  rep.dim = 2;
  rep.gate = ctx.radarGate;
  const tk::RadarModel model(ctx.config.minRangeM);
  if (model.degenerate(b.x)) {
    rep.status = est::UpdateStatus::RejectedDegenerate;
    return rep;
  }
  const auto H = model.jacobian(b.x);
  rep.innovation = model.residual(est::Vec<2>(plot.rangeM, plot.bearingRad), model.h(b.x));
  rep.S = H * b.P * H.transpose();
  rep.S += est::Vec<2>(plot.rangeVarM2, plot.bearingVarRad2).asDiagonal();
  const Eigen::LDLT<est::Mat<2>> ldlt(rep.S);
  if (!est::ldltPositiveDefinite(ldlt)) {
    rep.status = est::UpdateStatus::RejectedNumerical;
    return rep;
  }
  rep.nis = rep.innovation.dot(ldlt.solve(rep.innovation));
  rep.status = ctx.radarGate > 0.0 && rep.nis > ctx.radarGate ? est::UpdateStatus::RejectedGate
                                                              : est::UpdateStatus::Accepted;
  return rep;
}
}  // namespace

const char* trackerKindName(TrackerKind k) {
  switch (k) {
    case TrackerKind::Ekf:
      return "ekf";
    case TrackerKind::EkfInputEstimation:
      return "ekf-ie";
    case TrackerKind::AlphaBetaGamma:
      return "abg";
    case TrackerKind::Imm:
      return "imm";
  }
  return "?";
}

const char* trackerKindLabel(TrackerKind k) {
  switch (k) {
    case TrackerKind::Ekf:
      return "EKF";
    case TrackerKind::EkfInputEstimation:
      return "EKF + input estimation";
    case TrackerKind::AlphaBetaGamma:
      return "alpha-beta-gamma";
    case TrackerKind::Imm:
      return "IMM (CV/CT)";
  }
  return "?";
}

std::optional<TrackerKind> trackerKindFromName(std::string_view name) {
  for (int k = 0; k < kTrackerKindCount; ++k)
    if (name == trackerKindName(static_cast<TrackerKind>(k))) return static_cast<TrackerKind>(k);
  return std::nullopt;
}

est::Gaussian<6> ownShipAt(const TtkfContext& ctx, const OwnShipInput& own, TimeUs t) {
  est::Gaussian<6> g;
  g.x << own.x, 0.0, 0.0;
  g.P.setZero();
  g.P.topLeftCorner<4, 4>() = own.P;
  const double sa = ctx.config.process.ownAcceleration.sigma;
  g.P(tk::kOwnAx, tk::kOwnAx) = g.P(tk::kOwnAy, tk::kOwnAy) = std::max(sa * sa, 1e-12);
  if (t > own.timeUs) {
    const auto& d = ctx.discrete(t - own.timeUs);
    const est::Mat<6> Phi = d.Phi.dense().topLeftCorner<6, 6>();
    g.x = Phi * g.x;
    g.P = Phi * g.P * Phi.transpose() + d.Q.topLeftCorner<6, 6>();
    est::symmetrise(g.P);
  }
  return g;
}

// ---------------------------------------------------------------------------------------------------
AbgTrackFilter::AbgTrackFilter(std::shared_ptr<const TtkfContext> ctx, const AbgConfig& config,
                               const OwnShipInput& own, const GridPlot& plot)
    : ctx_(std::move(ctx)), abg_(config), own_(own), targetUs_(plot.timeUs) {
  if (!finitePlot(plot) || !(plot.rangeM >= ctx_->config.minRangeM))
    throw std::invalid_argument("alpha-beta-gamma track: degenerate plot");
  const auto o = ownShipAt(*ctx_, own, plot.timeUs);
  const AbsolutePlot a = absolute(plot, o.x.head<2>(), o.P.topLeftCorner<2, 2>());
  abg_.update(plot.timeUs, a.z[0], a.z[1]);
  P_.setZero();
  P_.topLeftCorner<2, 2>() = a.R;
  const double v2 = ctx_->config.initialSpeedSdMps * ctx_->config.initialSpeedSdMps;
  P_(2, 2) = P_(3, 3) = v2;
  const double sa = ctx_->config.process.targetAcceleration.sigma;
  P_(4, 4) = P_(5, 5) = std::max(sa * sa, 1e-12);
}

void AbgTrackFilter::feedOwnShip(const OwnShipInput& own) {
  if (own.timeUs >= own_.timeUs && own.x.allFinite() && own.P.allFinite()) own_ = own;
}

est::Gaussian<6> AbgTrackFilter::targetAt(TimeUs t) const {
  const double dt = toSeconds(std::max<TimeUs>(0, t - targetUs_));
  const auto& e = abg_.estimate();
  est::Gaussian<6> g;
  g.x << e.smoothedPos[0], e.smoothedPos[1], e.smoothedVel[0], e.smoothedVel[1], e.smoothedAcc[0],
      e.smoothedAcc[1];
  if (dt == 0.0) {
    g.P = P_;
    return g;
  }
  est::Mat<6> F = est::Mat<6>::Identity();
  for (int a = 0; a < 2; ++a) {
    F(a, 2 + a) = dt;
    F(a, 4 + a) = 0.5 * dt * dt;
    F(2 + a, 4 + a) = dt;
  }
  // The target moves as the tracker's target model says (its Gauss-Markov acceleration noise); the
  // filter predicts with constant acceleration.
  const est::Mat<6> Q = ctx_->discrete(t - targetUs_).Q.bottomRightCorner<6, 6>();
  g.x = F * g.x;
  g.P = F * P_ * F.transpose() + Q;
  est::symmetrise(g.P);
  return g;
}

est::UpdateReport<2> AbgTrackFilter::updateRadar(const GridPlot& plot) {
  est::UpdateReport<2> rep;
  if (!finitePlot(plot)) {
    rep.status = est::UpdateStatus::RejectedNonFinite;
    return rep;
  }
  if (plot.timeUs <= targetUs_) {
    rep.status = est::UpdateStatus::RejectedStale;
    return rep;
  }
  const auto o = ownShipAt(*ctx_, own_, plot.timeUs);
  const auto prior = targetAt(plot.timeUs);
  rep = radarInnovation(*ctx_, compose(o, prior), plot);
  if (!rep.applied()) return rep;
  const AbsolutePlot a = absolute(plot, o.x.head<2>(), o.P.topLeftCorner<2, 2>());
  if (!abg_.update(plot.timeUs, a.z[0], a.z[1])) {
    rep.status = est::UpdateStatus::RejectedNumerical;
    return rep;
  }
  // The covariance that the gains just used give (Joseph form holds for any gain).
  const auto& e = abg_.estimate();
  const double dt = toSeconds(plot.timeUs - targetUs_);
  Eigen::Matrix<double, 6, 2> K = Eigen::Matrix<double, 6, 2>::Zero();
  for (int ax = 0; ax < 2; ++ax) {
    K(ax, ax) = e.alpha;
    K(2 + ax, ax) = e.beta / dt;
    K(4 + ax, ax) = 2.0 * e.gamma / (dt * dt);
  }
  Eigen::Matrix<double, 2, 6> H = Eigen::Matrix<double, 2, 6>::Zero();
  H(0, 0) = H(1, 1) = 1.0;
  const est::Mat<6> IKH = est::Mat<6>::Identity() - K * H;
  est::Mat<6> P = IKH * prior.P * IKH.transpose() + K * a.R * K.transpose();
  est::symmetrise(P);
  if (!P.allFinite()) {
    rep.status = est::UpdateStatus::RejectedNumerical;
    return rep;
  }
  P_ = P;
  targetUs_ = plot.timeUs;
  return rep;
}

tk::Belief AbgTrackFilter::predicted(TimeUs t) const {
  const TimeUs at = std::max(t, timeUs());
  return compose(ownShipAt(*ctx_, own_, at), targetAt(at));
}

// ---------------------------------------------------------------------------------------------------
ImmTrackFilter::ImmTrackFilter(std::shared_ptr<const TtkfContext> ctx, const ImmConfig& config,
                               const OwnShipInput& own, const GridPlot& plot)
    : ctx_(std::move(ctx)), imm_(config), own_(own) {
  if (!finitePlot(plot) || !(plot.rangeM >= ctx_->config.minRangeM))
    throw std::invalid_argument("IMM track: degenerate plot");
  const auto o = ownShipAt(*ctx_, own, plot.timeUs);
  const AbsolutePlot a = absolute(plot, o.x.head<2>(), o.P.topLeftCorner<2, 2>());
  imm_.initialise(plot.timeUs, a.z, a.R);
}

void ImmTrackFilter::feedOwnShip(const OwnShipInput& own) {
  if (own.timeUs >= own_.timeUs && own.x.allFinite() && own.P.allFinite()) own_ = own;
}

est::UpdateReport<2> ImmTrackFilter::updateRadar(const GridPlot& plot) {
  est::UpdateReport<2> rep;
  if (!finitePlot(plot)) {
    rep.status = est::UpdateStatus::RejectedNonFinite;
    return rep;
  }
  if (plot.timeUs <= imm_.timeUs()) {
    rep.status = est::UpdateStatus::RejectedStale;
    return rep;
  }
  const auto o = ownShipAt(*ctx_, own_, plot.timeUs);
  const auto tgt = imm_.predicted(plot.timeUs);
  const double dx = tgt.x[est::ct::kX] - o.x[0], dy = tgt.x[est::ct::kY] - o.x[1];
  const double r2 = dx * dx + dy * dy, r = std::sqrt(r2);
  if (!(r >= std::max(ctx_->config.minRangeM, 1e-3))) {
    rep.status = est::UpdateStatus::RejectedDegenerate;
    return rep;
  }
  // Own ship's position uncertainty enters as measurement noise (bearing, range order of the IMM).
  est::Mat<2> Ho;
  Ho << -dy / r2, dx / r2, -dx / r, -dy / r;
  est::Mat<2> R = est::Vec<2>(plot.bearingVarRad2, plot.rangeVarM2).asDiagonal();
  R += Ho * o.P.topLeftCorner<2, 2>() * Ho.transpose();
  const auto br =
      imm_.updatePlot(plot.timeUs, plot.bearingRad, plot.rangeM, o.x[0], o.x[1], R, ctx_->radarGate);
  // Report in the TTKF's order (range, bearing).
  rep = br;
  rep.innovation = est::Vec<2>(br.innovation[1], br.innovation[0]);
  rep.S << br.S(1, 1), br.S(1, 0), br.S(0, 1), br.S(0, 0);
  return rep;
}

tk::Belief ImmTrackFilter::predicted(TimeUs t) const {
  using namespace est::ct;
  const TimeUs at = std::max(t, timeUs());
  const auto g = imm_.predicted(at);
  // Acceleration of the turn: the velocity rotates clockwise at w, a = w (vy, -vx).
  const double w = g.x[kW], vx = g.x[kVx], vy = g.x[kVy];
  est::Gaussian<6> tgt;
  tgt.x << g.x[kX], g.x[kY], vx, vy, w * vy, -w * vx;
  Eigen::Matrix<double, 6, kStateDim> J = Eigen::Matrix<double, 6, kStateDim>::Zero();
  J(0, kX) = J(1, kY) = J(2, kVx) = J(3, kVy) = 1.0;
  J(4, kVy) = w;
  J(4, kW) = vy;
  J(5, kVx) = -w;
  J(5, kW) = -vx;
  tgt.P = J * g.P * J.transpose();
  est::symmetrise(tgt.P);
  return compose(ownShipAt(*ctx_, own_, at), tgt);
}

// ---------------------------------------------------------------------------------------------------
void TrackFilter::feedOwnShip(const OwnShipInput& own) {
  std::visit([&own](auto& f) { f.feedOwnShip(own); }, f_);
}

est::UpdateReport<2> TrackFilter::updateRadar(const GridPlot& plot, Ttkf::RadarDetail* detail) {
  if (Ttkf* t = ttkf()) return t->updateRadar(plot, detail);
  return std::visit([&plot](auto& f) { return f.updateRadar(plot); }, f_);
}

est::UpdateReport<4> TrackFilter::updateTargetState(TimeUs t, const est::Vec<4>& z, const est::Mat<4>& R,
                                                    double gate, double adaptNis) {
  if (Ttkf* f = ttkf()) return f->updateTargetState(t, z, R, gate, adaptNis);
  return {};
}

tk::Belief TrackFilter::belief() const {
  if (const Ttkf* t = ttkf()) return t->belief();
  return predicted(timeUs());
}

tk::Belief TrackFilter::predicted(TimeUs t) const {
  if (const Ttkf* f = ttkf()) {
    Ttkf copy = *f;
    copy.predictTo(t);
    return copy.belief();
  }
  if (const auto* a = abg()) return a->predicted(t);
  return std::get<ImmTrackFilter>(f_).predicted(t);
}

TimeUs TrackFilter::timeUs() const {
  return std::visit([](const auto& f) { return f.timeUs(); }, f_);
}

bool TrackFilter::modelManoeuvring() const {
  const auto* i = imm();
  return i && i->filter().initialised() && i->filter().manoeuvring();
}

}  // namespace reckoner::track
