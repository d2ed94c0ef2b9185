#include "tracking/ais_fusion.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/angles.h"
#include "common/units.h"
#include "estimation/chi_square.h"
#include "estimation/ekf.h"
#include "tracking/assignment.h"

namespace reckoner::track {
namespace tk = est::ttkf;

namespace {
bool positiveFinite(double v) {
  return std::isfinite(v) && v > 0.0;
}

/// (1 + rho) / (1 - rho) for errors correlated with time constant tau over dt: the long-run variance of
/// their mean over the variance of one (1 when there is no previous report).
double inflation(double dtS, double tauS) {
  if (!(dtS > 0.0)) return 1.0;
  const double rho = std::exp(-dtS / tauS);
  return std::min(1e4, (1.0 + rho) / (1.0 - rho));
}

bool isPositionReport(int type) {
  return (type >= 1 && type <= 3) || type == 18 || type == 19 || type == 27;
}
}  // namespace

std::string AisAssociationConfig::check() const {
  if (!positiveFinite(positionLimitM)) return "position_limit_m: must be positive";
  if (!positiveFinite(courseLimitDeg) || courseLimitDeg > 180.0)
    return "course_limit_deg: must lie in (0, 180]";
  if (!positiveFinite(speedLimitKn)) return "speed_limit_kn: must be positive";
  if (!(courseMinSpeedKn >= 0.0) || !std::isfinite(courseMinSpeedKn))
    return "course_min_speed_kn: must be >= 0";
  if (associateAfter < 1 || associateAfter > 100) return "associate_after: must lie in [1, 100]";
  if (dissociateAfter < 1 || dissociateAfter > 100) return "dissociate_after: must lie in [1, 100]";
  if (rejectAfter < 1 || rejectAfter > 100) return "reject_after: must lie in [1, 100]";
  if (!(releaseFactor >= 1.0) || !std::isfinite(releaseFactor)) return "release_factor: must be >= 1";
  if (!(gateProbability >= 0.0 && gateProbability < 1.0)) return "gate_probability: must lie in [0, 1)";
  if (!(manoeuvreNisProbability > 0.5 && manoeuvreNisProbability < 1.0))
    return "manoeuvre_nis_probability: must lie in (0.5, 1)";
  const AisErrorModel& e = errors;
  for (double v : {e.positionSdAccurateM, e.positionSdM, e.positionCorrelationS, e.velocitySdClassAMps,
                   e.velocitySdClassBMps, e.velocityCorrelationS, e.headingSdDeg, e.cogOffsetSdDeg,
                   e.unknownOffsetSdM, e.unknownLatencySdS, e.accelerationSdMps2})
    if (!positiveFinite(v)) return "errors: every sd and correlation time must be positive";
  if (!(e.unknownLatencyS >= 0.0) || !std::isfinite(e.unknownLatencyS))
    return "errors: unknown latency must be >= 0";
  return {};
}

est::Gaussian<4> AisObservation::at(TimeUs t, bool inflate, double accelerationSd) const {
  const double dt = toSeconds(t - fixUs);
  est::Mat<4> A = est::Mat<4>::Identity();
  A(0, 2) = A(1, 3) = dt;
  est::Mat<4> Rw = R;
  if (inflate) {
    Rw.topLeftCorner<2, 2>() *= inflationPosition;
    Rw.bottomRightCorner<2, 2>() *= inflationVelocity;
    Rw.topRightCorner<2, 2>() *= std::sqrt(inflationPosition * inflationVelocity);
    Rw.bottomLeftCorner<2, 2>() *= std::sqrt(inflationPosition * inflationVelocity);
  }
  est::Gaussian<4> g;
  g.x = A * z;
  g.P = A * Rw * A.transpose();
  // Unknown acceleration over |dt| (white, per axis): position dt^2/2, velocity dt.
  const double sa = accelerationSd >= 0.0 ? accelerationSd : accelerationSdMps2;
  const double a2 = sa * sa;
  const double adt = std::abs(dt);
  for (int i = 0; i < 2; ++i) {
    g.P(i, i) += a2 * adt * adt * adt * adt / 4.0;
    g.P(i + 2, i + 2) += a2 * adt * adt;
    g.P(i, i + 2) += a2 * adt * adt * adt / 2.0;
    g.P(i + 2, i) += a2 * adt * adt * adt / 2.0;
  }
  est::symmetrise(g.P);
  return g;
}

std::optional<TimeUs> aisFixTime(TimeUs rxUs, std::optional<int> second, TimeUs utcOffsetUs) {
  if (!second || *second < 0 || *second > 59) return std::nullopt;
  const TimeUs utc = rxUs + utcOffsetUs;
  const TimeUs whole = utc - (((utc % kMicrosPerSecond) + kMicrosPerSecond) % kMicrosPerSecond);
  const TimeUs rxSecond = ((whole / kMicrosPerSecond) % 60 + 60) % 60;
  const TimeUs back = ((rxSecond - *second) % 60 + 60) % 60;
  return whole - back * kMicrosPerSecond - utcOffsetUs;
}

std::optional<AisObservation> aisObservation(const io::AisMessage& m, TimeUs rxUs, const AisStatic& info,
                                             const geo::LocalFrame& frame, const AisErrorModel& e,
                                             TimeUs previousFixUs, TimeUs utcOffsetUs) {
  if (!isPositionReport(m.type) || !m.latDeg || !m.lonDeg || !m.sogKn || !m.cogDeg) return std::nullopt;
  // A position entered by hand, dead reckoned or from an inoperative positioning system (time stamp 61-63)
  // is no fix: it is shown, never fused into a radar track as a measurement.
  if (m.positionNotFix) return std::nullopt;
  const geo::GridPoint antenna = frame.toLocal({*m.latDeg, *m.lonDeg});
  if (!std::isfinite(antenna.xM) || !std::isfinite(antenna.yM)) return std::nullopt;
  const double convergence = frame.gridInfo(antenna).convergenceRad;
  const double speed = knotsToMps(*m.sogKn);
  const double cog = degToRad(*m.cogDeg) - convergence;  // grid
  AisObservation o;
  o.mmsi = m.mmsi;
  o.rxUs = rxUs;
  o.accelerationSdMps2 = e.accelerationSdMps2;
  o.z << antenna.xM, antenna.yM, speed * std::sin(cog), speed * std::cos(cog);
  o.R.setZero();

  const std::optional<TimeUs> fix = aisFixTime(rxUs, m.second, utcOffsetUs);
  o.fixUs = fix ? *fix : rxUs - fromSeconds(e.unknownLatencyS);
  const double sdFix = m.accuracy.value_or(false) ? e.positionSdAccurateM : e.positionSdM;
  const bool classB = m.type == 18 || m.type == 19;
  const double sdVel = classB ? e.velocitySdClassBMps : e.velocitySdClassAMps;
  // Quantisation (uniform over a step: step^2 / 12). Types 1-3, 18, 19: SOG 0.1 kn (positions to 1/10000
  // minute and COG to 0.1 degree are negligible). Type 27: 1/10 minute (185 m), SOG 1 kn, COG 1 degree.
  const bool longRange = m.type == 27;
  const double posStepM = longRange ? 1852.0 / 10.0 : 0.0;
  const double sogStep = knotsToMps(longRange ? 1.0 : 0.1);
  const double cogStep = longRange ? degToRad(1.0) * speed : 0.0;
  o.R(0, 0) = o.R(1, 1) = sdFix * sdFix + posStepM * posStepM / 12.0;
  o.R(2, 2) = o.R(3, 3) = sdVel * sdVel + (sogStep * sogStep + cogStep * cogStep) / 12.0;
  if (!fix) {  // the latency's uncertainty moves the position along the velocity
    const est::Vec<2> v = o.z.tail<2>();
    o.R.topLeftCorner<2, 2>() += e.unknownLatencySdS * e.unknownLatencySdS * v * v.transpose();
  }

  // The antenna's place on the hull: the centre is the antenna minus the rotated offset.
  const double toBow = info.toBowM.value_or(0), toStern = info.toSternM.value_or(0);
  const double toPort = info.toPortM.value_or(0), toStbd = info.toStarboardM.value_or(0);
  const bool known = toBow + toStern > 0 && toPort + toStbd > 0;
  std::optional<double> headingGrid;
  double headingSd = degToRad(e.headingSdDeg);
  if (m.headingDeg) {
    headingGrid = degToRad(*m.headingDeg) - convergence;
  } else if (*m.sogKn >= 1.0) {
    headingGrid = cog;
    headingSd = degToRad(e.cogOffsetSdDeg) + sdVel / std::max(speed, 0.1);
  }
  if (known && headingGrid) {
    // The antenna's place ahead of and to starboard of the centre (sensors/ais_transmitter.h).
    const double fwd = 0.5 * (toStern - toBow), stbd = 0.5 * (toPort - toStbd);
    const double s = std::sin(*headingGrid), c = std::cos(*headingGrid);
    const est::Vec<2> offset(fwd * s + stbd * c, fwd * c - stbd * s);
    o.z.head<2>() -= offset;
    // d(offset)/d(heading) is the offset turned by 90 degrees: (offset.y, -offset.x).
    const est::Vec<2> dOffset(offset.y(), -offset.x());
    o.R.topLeftCorner<2, 2>() += headingSd * headingSd * dOffset * dOffset.transpose();
    o.offsetCorrected = true;
  } else {
    const double off = known ? 0.5 * std::hypot(toBow + toStern, toPort + toStbd) : e.unknownOffsetSdM;
    o.R(0, 0) += off * off;
    o.R(1, 1) += off * off;
  }
  if (previousFixUs >= 0 && o.fixUs > previousFixUs) {
    const double dt = toSeconds(o.fixUs - previousFixUs);
    o.inflationPosition = inflation(dt, e.positionCorrelationS);
    o.inflationVelocity = inflation(dt, e.velocityCorrelationS);
  }
  if (!o.z.allFinite() || !o.R.allFinite()) return std::nullopt;
  return o;
}

AisRadarFusion::AisRadarFusion(const AisAssociationConfig& config) : config_(config), gate_(0.0) {
  if (const std::string e = config.check(); !e.empty()) throw std::invalid_argument("AIS association: " + e);
  gate_ = config.gateProbability > 0.0 ? est::chiSquareQuantile(config.gateProbability, 4.0) : 0.0;
  velocityGate_ = est::chiSquareQuantile(0.999, 2.0);
  manoeuvreNis_ = est::chiSquareQuantile(config.manoeuvreNisProbability, 4.0);
}

void AisRadarFusion::addReport(const io::AisMessage& m, TimeUs rxUs, const AisStatic& info,
                               const geo::LocalFrame& frame, TimeUs utcOffsetUs) {
  if (!config_.enabled || m.mmsi == 0) return;
  Station& s = stations_[m.mmsi];
  const TimeUs previous = s.latest ? s.latest->fixUs : -1;
  auto o = aisObservation(m, rxUs, info, frame, config_.errors, previous, utcOffsetUs);
  if (!o) return;
  ++counters_.reports;
  s.latest = *o;
  s.fresh.push_back(*o);
  if (s.fresh.size() > 8) s.fresh.erase(s.fresh.begin());  // bounded between two updates
}

AisRadarFusion::Difference AisRadarFusion::differenceAt(const AisObservation& o, const tk::Belief& b,
                                                        TimeUs now) const {
  const est::Gaussian<4> a = o.at(now, false);
  Difference d{};
  d.positionM = std::hypot(a.x[0] - b.x[tk::kTgtX], a.x[1] - b.x[tk::kTgtY]);
  const double sa = std::hypot(a.x[2], a.x[3]), st = std::hypot(b.x[tk::kTgtVx], b.x[tk::kTgtVy]);
  d.speedKn = std::abs(mpsToKnots(sa - st));
  const double minSpeed = knotsToMps(config_.courseMinSpeedKn);
  d.courseCompared = sa > minSpeed && st > minSpeed;
  d.courseDeg = d.courseCompared ? std::abs(radToDeg(angleDiff(bearingOf(a.x[2], a.x[3]),
                                                               bearingOf(b.x[tk::kTgtVx], b.x[tk::kTgtVy]))))
                                 : 0.0;
  const est::Vec<4> diff = a.x - b.x.segment<4>(tk::kTgtX);
  const est::Mat<4> S = a.P + b.P.block<4, 4>(tk::kTgtX, tk::kTgtX);
  d.mahalanobis2 = est::nees<4>(diff, S);
  d.velocityMahalanobis2 = est::nees<2>(diff.tail<2>(), S.bottomRightCorner<2, 2>());
  if (!std::isfinite(d.mahalanobis2)) d.mahalanobis2 = 1e6;
  if (!std::isfinite(d.velocityMahalanobis2)) d.velocityMahalanobis2 = 1e6;
  return d;
}

void AisRadarFusion::dissociate(Station& s, TrackManager& bank, TimeUs now, std::uint32_t mmsi,
                                std::string reason) {
  if (!s.pair) return;
  bank.setFused(s.pair->trackId, false);
  events_.push_back({AisAssociationEvent::Kind::Dissociated, now, mmsi, s.pair->trackId, std::move(reason)});
  byTrack_.erase(s.pair->trackId);
  s.pair.reset();
  s.outside = s.rejectedInRow = 0;
  s.pendingTrack = -1;
  s.pendingCount = 0;
  ++counters_.dissociated;
}

void AisRadarFusion::dropBroken(TimeUs now, TrackManager& bank, const AisTargetTable& table) {
  for (auto it = stations_.begin(); it != stations_.end();) {
    Station& s = it->second;
    const AisTarget* t = table.find(it->first);
    if (s.pair) {
      const Track* tr = bank.find(s.pair->trackId);
      if (!tr || !tr->active())
        dissociate(s, bank, now, it->first, "radar track lost");
      else if (!t || t->lost)
        dissociate(s, bank, now, it->first, "AIS target lost");
    }
    if (!t) {  // removed from the table: forget the station
      it = stations_.erase(it);
      continue;
    }
    ++it;
  }
}

void AisRadarFusion::check(TimeUs now, TrackManager& bank, const std::vector<std::uint32_t>& fresh) {
  // Columns: confirmed tracks not held by a station outside this round.
  std::vector<const Track*> cols;
  std::vector<tk::Belief> beliefs;
  for (const Track& t : bank.tracks()) {
    if (t.status != TrackStatus::Confirmed) continue;
    const auto held = byTrack_.find(t.id);
    if (held != byTrack_.end() && std::find(fresh.begin(), fresh.end(), held->second) == fresh.end())
      continue;
    cols.push_back(&t);
    beliefs.push_back(bank.beliefAt(t, now));
  }
  const double kMiss = 1e6;
  GnnProblem problem(fresh.size(), cols.size(), std::vector<double>(fresh.size(), kMiss));
  for (std::size_t i = 0; i < fresh.size(); ++i) {
    const Station& s = stations_.at(fresh[i]);
    for (std::size_t j = 0; j < cols.size(); ++j) {
      const double f = s.pair && s.pair->trackId == cols[j]->id ? config_.releaseFactor : 1.0;
      const Difference d = differenceAt(*s.latest, beliefs[j], now);
      if (d.positionM > f * config_.positionLimitM) continue;
      const bool withinLimits =
          d.speedKn <= f * config_.speedLimitKn && d.courseDeg <= f * config_.courseLimitDeg;
      if (!withinLimits && d.velocityMahalanobis2 > f * f * velocityGate_) continue;
      problem.addPair(i, j, std::min(d.mahalanobis2, 1e5));
    }
  }
  const std::vector<int> chosen = problem.solve();
  for (std::size_t i = 0; i < fresh.size(); ++i) {
    ++counters_.checks;
    Station& s = stations_.at(fresh[i]);
    const int trackId = chosen[i] >= 0 ? cols[static_cast<std::size_t>(chosen[i])]->id : -1;
    if (s.pair) {
      s.outside = trackId == s.pair->trackId ? 0 : s.outside + 1;
      if (s.outside >= config_.dissociateAfter)
        dissociate(s, bank, now, fresh[i], "outside the association limits");
      continue;
    }
    if (trackId < 0) {
      s.pendingTrack = -1;
      s.pendingCount = 0;
      continue;
    }
    s.pendingCount = trackId == s.pendingTrack ? s.pendingCount + 1 : 1;
    s.pendingTrack = trackId;
    if (s.pendingCount < config_.associateAfter || byTrack_.contains(trackId)) continue;
    s.pair = AisAssociation{fresh[i], trackId, now, 0, 0, 0.0};
    byTrack_[trackId] = fresh[i];
    if (config_.fuse) bank.setFused(trackId, true);
    events_.push_back({AisAssociationEvent::Kind::Associated, now, fresh[i], trackId, {}});
    ++counters_.associated;
  }
}

void AisRadarFusion::fuse(Station& s, TrackManager& bank, TimeUs now) {
  for (const AisObservation& o : s.fresh) {
    if (!s.pair) return;
    const Track* tr = bank.find(s.pair->trackId);
    if (!tr) return;
    const TimeUs t = std::max(tr->filter.timeUs(), o.fixUs);
    const est::Gaussian<4> g = o.at(t, true, bank.config().fusedTargetAcceleration.sigma);
    const est::UpdateReport<4> rep = bank.fuseTargetState(s.pair->trackId, t, g.x, g.P, gate_, manoeuvreNis_);
    if (rep.status == est::UpdateStatus::Accepted) {
      ++s.pair->fused;
      ++counters_.fused;
      s.pair->lastNis = rep.nis;
      s.rejectedInRow = 0;
    } else if (rep.status == est::UpdateStatus::RejectedGate) {
      ++s.pair->rejected;
      ++counters_.rejected;
      if (++s.rejectedInRow >= config_.rejectAfter)
        dissociate(s, bank, now, o.mmsi, "AIS inconsistent with the radar track");
    } else {
      ++counters_.notFusable;
    }
  }
}

void AisRadarFusion::update(TimeUs now, TrackManager& bank, const AisTargetTable& table) {
  if (!config_.enabled) return;
  dropBroken(now, bank, table);
  std::vector<std::uint32_t> fresh;
  for (const auto& [mmsi, s] : stations_)
    if (!s.fresh.empty()) fresh.push_back(mmsi);
  std::sort(fresh.begin(), fresh.end());  // deterministic order (the map's is not)
  if (!fresh.empty()) check(now, bank, fresh);
  for (std::uint32_t mmsi : fresh) {
    Station& s = stations_.at(mmsi);
    if (config_.fuse && s.pair) fuse(s, bank, now);
    s.fresh.clear();
  }
}

std::vector<AisAssociation> AisRadarFusion::associations() const {
  std::vector<AisAssociation> out;
  for (const auto& [mmsi, s] : stations_)
    if (s.pair) out.push_back(*s.pair);
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.mmsi < b.mmsi; });
  return out;
}

std::uint32_t AisRadarFusion::mmsiOfTrack(int trackId) const {
  const auto it = byTrack_.find(trackId);
  return it == byTrack_.end() ? 0 : it->second;
}

const AisObservation* AisRadarFusion::latest(std::uint32_t mmsi) const {
  const auto it = stations_.find(mmsi);
  return it == stations_.end() || !it->second.latest ? nullptr : &*it->second.latest;
}

std::vector<AisAssociationEvent> AisRadarFusion::takeEvents() {
  std::vector<AisAssociationEvent> out;
  out.swap(events_);
  return out;
}

}  // namespace reckoner::track
