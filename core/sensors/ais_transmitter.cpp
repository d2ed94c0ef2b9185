#include "sensors/ais_transmitter.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/angles.h"
#include "common/units.h"

namespace reckoner::sensors {
namespace {
constexpr double kTurningRadPerS = 5.0 / 30.0 * std::numbers::pi / 180.0;  // 5 degrees in 30 s

/// One step of a first-order Gauss-Markov error with stationary sd over dt (exact discretisation).
double gaussMarkovStep(double e, double sd, double tauS, double dtS, Rng& rng) {
  if (sd <= 0.0) return 0.0;
  const double rho = std::exp(-dtS / tauS);
  return rho * e + sd * std::sqrt(1.0 - rho * rho) * rng.normal();
}

double roundTo(double v, double step) {
  return std::round(v / step) * step;
}
}  // namespace

AisTransmitterSpec AisTransmitterSpec::defaults(AisStationClass cls) {
  AisTransmitterSpec s;
  s.cls = cls;
  if (cls == AisStationClass::B) {
    s.positionSdM = 6.0;
    s.velocitySdMps = 0.1;
    s.headingSdDeg = 0.0;
    s.latencyMaxS = 3.0;
    s.shipType = 37;  // pleasure craft
  } else if (cls == AisStationClass::Sart) {
    s.positionSdM = 5.0;  // a GNSS receiver of its own, at the waterline
    s.velocitySdMps = 0.1;
    s.headingSdDeg = 0.0;
    s.staticIntervalS = 240.0;  // the type 14 text
  }
  return s;
}

std::string AisTransmitterSpec::check() const {
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  auto nonNegative = [](double v) { return std::isfinite(v) && v >= 0.0; };
  if (mmsi < 1 || mmsi > 999'999'999) return "mmsi: must lie in [1, 999999999]";
  if (shipType < 1 || shipType > 99) return "ship_type: must lie in [1, 99]";
  if (cls == AisStationClass::Sart && mmsi / 1000000 != 970 && mmsi / 1000000 != 972 && mmsi / 1000000 != 974)
    return "mmsi: a search and rescue device's must be 970xxyyyy (AIS-SART), 972xxyyyy (MOB) or 974xxyyyy "
           "(EPIRB-AIS)";
  if (test && cls != AisStationClass::Sart)
    return "test: only a search and rescue device (class SART) has it";
  for (int d : {toBowM, toSternM})
    if (d < 0 || d > 511) return "to_bow_m/to_stern_m: must lie in [0, 511]";
  for (int d : {toPortM, toStarboardM})
    if (d < 0 || d > 63) return "to_port_m/to_starboard_m: must lie in [0, 63]";
  if (!nonNegative(positionSdM) || !positive(positionCorrelationS))
    return "position_sd_m / position_correlation_s: sd must be >= 0 and the time > 0";
  if (!nonNegative(velocitySdMps) || !positive(velocityCorrelationS))
    return "velocity_sd_mps / velocity_correlation_s: sd must be >= 0 and the time > 0";
  if (!nonNegative(headingSdDeg)) return "heading_sd_deg: must be >= 0";
  if (!nonNegative(latencyMinS) || !(latencyMaxS >= latencyMinS) || latencyMaxS > 30.0)
    return "latency_s: must be [min, max] with 0 <= min <= max <= 30";
  if (!(lossProbability >= 0.0 && lossProbability < 1.0)) return "loss_probability: must lie in [0, 1)";
  if (!(staticIntervalS >= 10.0) || !std::isfinite(staticIntervalS))
    return "static_interval_s: must be >= 10";
  return {};
}

AntennaOffset antennaOffset(int toBowM, int toSternM, int toPortM, int toStarboardM) {
  AntennaOffset o;
  o.known = toBowM + toSternM > 0 && toPortM + toStarboardM > 0;
  if (!o.known) return o;
  // The bow is half the length ahead of the centre and the antenna toBow aft of the bow, so the
  // antenna is (toBow + toStern) / 2 - toBow ahead of the centre. Likewise across.
  o.forwardM = 0.5 * (toSternM - toBowM);
  o.starboardM = 0.5 * (toPortM - toStarboardM);
  return o;
}

AisTransmitter::AisTransmitter(const AisTransmitterSpec& spec, int targetId, Rng rng, TimeUs startUs)
    : spec_(spec), targetId_(targetId), rng_(rng) {
  if (const std::string e = spec.check(); !e.empty()) throw std::invalid_argument("AIS transmitter: " + e);
  const double first = spec.cls == AisStationClass::B ? 30.0 : spec.cls == AisStationClass::A ? 10.0 : 60.0;
  nextReportUs_ = startUs + fromSeconds(rng_.uniform() * first);
  nextStaticUs_ = startUs + fromSeconds(1.0 + rng_.uniform() * 5.0);
}

double AisTransmitter::intervalS(const AisHullState& h) const {
  const double kn = mpsToKnots(std::hypot(h.vxMps, h.vyMps));
  const bool turning = std::abs(h.turnRateRadPerS) > kTurningRadPerS;
  if (spec_.cls == AisStationClass::B) return kn > 2.0 ? 30.0 : 180.0;
  if (spec_.cls == AisStationClass::Sart) return 60.0;
  // Under way (the simulated ships never anchor): 10 s even below 3 kn.
  if (kn <= 14.0) return turning ? 10.0 / 3.0 : 10.0;
  if (kn <= 23.0) return turning ? 2.0 : 6.0;
  return 2.0;
}

const AisHullState& AisTransmitter::fixAt(TimeUs t) const {
  for (auto it = history_.rbegin(); it != history_.rend(); ++it)
    if (it->timeUs <= t) return *it;
  return history_.front();
}

void AisTransmitter::advanceErrors(TimeUs t) {
  if (errorUs_ < 0) {
    errX_ = spec_.positionSdM * rng_.normal();
    errY_ = spec_.positionSdM * rng_.normal();
    errVx_ = spec_.velocitySdMps * rng_.normal();
    errVy_ = spec_.velocitySdMps * rng_.normal();
  } else if (t > errorUs_) {
    const double dt = toSeconds(t - errorUs_);
    errX_ = gaussMarkovStep(errX_, spec_.positionSdM, spec_.positionCorrelationS, dt, rng_);
    errY_ = gaussMarkovStep(errY_, spec_.positionSdM, spec_.positionCorrelationS, dt, rng_);
    errVx_ = gaussMarkovStep(errVx_, spec_.velocitySdMps, spec_.velocityCorrelationS, dt, rng_);
    errVy_ = gaussMarkovStep(errVy_, spec_.velocitySdMps, spec_.velocityCorrelationS, dt, rng_);
  }
  errorUs_ = std::max(errorUs_, t);
}

void AisTransmitter::positionReport(TimeUs txUs, const geo::LocalFrame& frame,
                                    std::vector<AisReception>& out) {
  const double latency = spec_.latencyMinS + rng_.uniform() * (spec_.latencyMaxS - spec_.latencyMinS);
  // GNSS fixes at whole seconds: the last one at or before tx - latency.
  TimeUs fixUs = txUs - fromSeconds(latency);
  fixUs -= ((fixUs % kMicrosPerSecond) + kMicrosPerSecond) % kMicrosPerSecond;
  const AisHullState& h = fixAt(fixUs);
  advanceErrors(fixUs);
  const bool lost = rng_.uniform() < spec_.lossProbability;
  if (lost) return;
  const AntennaOffset off = antennaOffset(spec_.toBowM, spec_.toSternM, spec_.toPortM, spec_.toStarboardM);
  const double s = std::sin(h.headingRad), c = std::cos(h.headingRad);
  // Forward is (sin, cos) of the grid heading, starboard (cos, -sin).
  const geo::GridPoint antenna{h.position.xM + off.forwardM * s + off.starboardM * c + errX_,
                               h.position.yM + off.forwardM * c - off.starboardM * s + errY_};
  const geo::GeoPoint g = frame.toGeodetic(antenna);
  const double convergence = frame.gridInfo(antenna).convergenceRad;
  const double vx = h.vxMps + errVx_, vy = h.vyMps + errVy_;

  AisReception r;
  r.rxUs = txUs;
  r.fixUs = fixUs;
  r.sourceTarget = targetId_;
  io::AisMessage& m = r.message;
  m.type = spec_.cls == AisStationClass::B ? 18 : 1;
  m.mmsi = spec_.mmsi;
  m.latDeg = roundTo(g.latDeg, 1.0 / 600000.0);  // 1/10000 minute
  m.lonDeg = roundTo(g.lonDeg, 1.0 / 600000.0);
  m.sogKn = std::min(102.2, roundTo(mpsToKnots(std::hypot(vx, vy)), 0.1));
  m.cogDeg = std::fmod(roundTo(radToDeg(wrapTwoPi(bearingOf(vx, vy) + convergence)), 0.1), 360.0);
  if (spec_.cls == AisStationClass::A) {
    const double hdg = radToDeg(h.headingRad + convergence) + spec_.headingSdDeg * rng_.normal();
    m.headingDeg = static_cast<int>(std::lround(radToDeg(wrapTwoPi(degToRad(hdg))))) % 360;
    m.navStatus = 0;  // under way using engine
    m.rotDegMin = radToDeg(h.turnRateRadPerS) * 60.0;
  } else if (spec_.cls == AisStationClass::Sart) {
    m.navStatus = spec_.test ? 15 : 14;
  }
  m.accuracy = spec_.positionSdM * 2.45 < 10.0;  // 95% radius under 10 m
  m.second = static_cast<int>((fixUs / kMicrosPerSecond) % 60);
  out.push_back(std::move(r));
}

void AisTransmitter::staticReports(TimeUs txUs, std::vector<AisReception>& out) {
  auto base = [&](int type) {
    AisReception r;
    r.rxUs = txUs;
    r.sourceTarget = targetId_;
    r.message.type = type;
    r.message.mmsi = spec_.mmsi;
    r.message.shipType = spec_.shipType;
    r.message.name = spec_.shipName;
    if (spec_.toBowM + spec_.toSternM > 0) {
      r.message.toBowM = spec_.toBowM;
      r.message.toSternM = spec_.toSternM;
      r.message.toPortM = spec_.toPortM;
      r.message.toStarboardM = spec_.toStarboardM;
    }
    return r;
  };
  if (spec_.cls == AisStationClass::A) {
    if (rng_.uniform() >= spec_.lossProbability) out.push_back(base(5));
    return;
  }
  if (spec_.cls == AisStationClass::Sart) {
    AisReception r;
    r.rxUs = txUs;
    r.sourceTarget = targetId_;
    r.message.type = 14;
    r.message.mmsi = spec_.mmsi;
    const std::uint32_t prefix = spec_.mmsi / 1000000;
    r.message.text = std::string(prefix == 972   ? "MOB"
                                 : prefix == 974 ? "EPIRB"
                                                 : "SART") +
                     (spec_.test ? " TEST" : " ACTIVE");
    if (rng_.uniform() >= spec_.lossProbability) out.push_back(std::move(r));
    return;
  }
  AisReception a = base(24), b = base(24);
  a.message.part = 'A';
  a.message.shipType.reset();
  a.message.toBowM = a.message.toSternM = a.message.toPortM = a.message.toStarboardM = std::nullopt;
  b.message.part = 'B';
  b.message.name.clear();
  if (rng_.uniform() >= spec_.lossProbability) out.push_back(std::move(a));
  if (rng_.uniform() >= spec_.lossProbability) out.push_back(std::move(b));
}

void AisTransmitter::advance(const AisHullState& hull, const geo::LocalFrame& frame,
                             std::vector<AisReception>& out) {
  if (!history_.empty() && hull.timeUs <= history_.back().timeUs) return;
  history_.push_back(hull);
  const TimeUs keep = fromSeconds(spec_.latencyMaxS + 3.0);
  while (history_.size() > 2 && history_[1].timeUs < hull.timeUs - keep) history_.pop_front();
  while (nextStaticUs_ <= hull.timeUs) {
    staticReports(nextStaticUs_, out);
    nextStaticUs_ += fromSeconds(spec_.staticIntervalS);
  }
  while (nextReportUs_ <= hull.timeUs) {
    positionReport(nextReportUs_, frame, out);
    if (spec_.cls == AisStationClass::Sart && ++burstSent_ < 8) {  // the burst's next report
      nextReportUs_ += kMicrosPerSecond;
      continue;
    }
    const double interval =
        intervalS(fixAt(nextReportUs_)) - (spec_.cls == AisStationClass::Sart ? 7.0 : 0.0);
    burstSent_ = 0;
    nextReportUs_ += fromSeconds(interval);
  }
}

}  // namespace reckoner::sensors
