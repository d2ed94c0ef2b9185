#include "studies/manoeuvre_trial.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/angles.h"
#include "common/rng.h"
#include "estimation/pcrb.h"
#include "sim/vessel_motion.h"

// The studies drive the engine and score its runs: the engine's names unqualified here.
using namespace reckoner::sim;

namespace reckoner::studies {
namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}

double ManoeuvreTrial::manoeuvreEndS() const {
  double d = 0.0;
  if (turnRad != 0.0) d = std::max(d, std::abs(turnRad) / turnRateRadPerS);
  if (speedChangeMps != 0.0) d = std::max(d, std::abs(speedChangeMps) / accelerationMps2);
  return manoeuvreStartS + d;
}

const char* trackerName(TrackerKind k) {
  switch (k) {
    case kEkf:
      return "EKF";
    case kEkfIe:
      return "EKF + input estimation";
    case kAbg:
      return "alpha-beta-gamma";
    case kImm:
      return "IMM (CV + CT)";
    default:
      return "?";
  }
}

TrackerConfigs radarRateTrackers(const ManoeuvreTrial& trial) {
  TrackerConfigs c;
  c.ie.bearingSdRad = trial.bearingSdRad;
  c.ie.rangeSdM = trial.rangeSdM;
  c.ie.window = 15;                   // 30 s at 2 s sweeps (seed 001's s = 2 spans 160 s at its 80 s pings)
  c.ie.processNoiseQ = 1e-4;          // m^2/s^3
  c.ie.falseAlarmProbability = 1e-4;  // tested every sweep: 1800 overlapping windows an hour
  c.imm.bearingSdRad = trial.bearingSdRad;
  c.imm.rangeSdM = trial.rangeSdM;
  c.abg.alpha = 0.1;
  return c;
}

namespace {
/// The posterior Cramer-Rao bound of the target's position along its true trajectory, for range and
/// bearing measurements from a known observer and a constant-velocity model with white acceleration q.
class PositionBound {
 public:
  PositionBound(double q, double initialSpeedSdMps, double bearingSdRad, double rangeSdM)
      : q_(q),
        speedSd_(initialSpeedSdMps),
        R_(est::Vec<2>(bearingSdRad * bearingSdRad, rangeSdM * rangeSdM).asDiagonal()) {}

  /// A measurement at t of the target at (tx, ty) from (ox, oy); returns sqrt(trace) of the position
  /// bound.
  double measure(double tS, double tx, double ty, double ox, double oy) {
    const double dx = tx - ox, dy = ty - oy, r2 = dx * dx + dy * dy, rr = std::sqrt(r2);
    est::MatRC<2, 4> H = est::MatRC<2, 4>::Zero();
    H(0, 0) = dy / r2;
    H(0, 1) = -dx / r2;
    H(1, 0) = dx / rr;
    H(1, 1) = dy / rr;
    if (!pcrb_) {
      est::Mat<4> P0 = est::Mat<4>::Zero();
      P0.topLeftCorner<2, 2>() = est::Mat<2>::Identity() * 1e8;  // position from the first plot only
      P0(2, 2) = P0(3, 3) = speedSd_ * speedSd_;
      pcrb_.emplace(P0);
      pcrb_->measure(H, R_);
    } else {
      const double dt = tS - lastS_;
      est::Mat<4> F = est::Mat<4>::Identity();
      F(0, 2) = F(1, 3) = dt;
      est::Mat<4> Q = est::Mat<4>::Zero();
      for (int a = 0; a < 2; ++a) {
        Q(a, a) = q_ * dt * dt * dt / 3.0;
        Q(a, a + 2) = Q(a + 2, a) = q_ * dt * dt / 2.0;
        Q(a + 2, a + 2) = q_ * dt;
      }
      pcrb_->step(F, Q, H, R_);
    }
    lastS_ = tS;
    const est::Mat<4> bound = pcrb_->bound();
    return std::sqrt(bound(0, 0) + bound(1, 1));
  }

 private:
  double q_, speedSd_;
  est::Mat<2> R_;
  std::optional<metrics::Pcrb<4, 2>> pcrb_;
  double lastS_ = 0.0;
};

/// The four trackers on the same measurements.
class TrackerBank {
 public:
  explicit TrackerBank(const TrackerConfigs& configs)
      : ekf_(neverDeclaring(configs.ie)), ie_(configs.ie), imm_(configs.imm), abg_(configs.abg) {}

  void measure(TimeUs t, double bearingRad, double rangeM, double ox, double oy) {
    ekf_.measure(t, bearingRad, rangeM, ox, oy);
    ieManoeuvring_ = ie_.measure(t, bearingRad, rangeM, ox, oy).manoeuvring;
    imm_.update(t, bearingRad, rangeM, ox, oy);
    abg_.update(t, ox + rangeM * std::sin(bearingRad), oy + rangeM * std::cos(bearingRad));
    ox_ = ox;
    oy_ = oy;
  }
  /// Target position and velocity over ground by each tracker (none before it has an estimate).
  [[nodiscard]] std::array<std::optional<std::array<double, 4>>, kTrackerKinds> estimates() const {
    std::array<std::optional<std::array<double, 4>>, kTrackerKinds> e;
    namespace rp = reckoner::est::relpolar;
    const auto fromRelative =
        [this](const track::InputEstimationEkf& f) -> std::optional<std::array<double, 4>> {
      if (!f.initialised()) return std::nullopt;
      const auto& x = f.belief().x;
      return std::array<double, 4>{x[rp::kRx] + ox_, x[rp::kRy] + oy_, x[rp::kVx], x[rp::kVy]};
    };
    e[kEkf] = fromRelative(ekf_);
    e[kEkfIe] = fromRelative(ie_);
    if (abg_.plots() >= 2) {
      const auto& a = abg_.estimate();
      e[kAbg] = std::array<double, 4>{a.smoothedPos[0], a.smoothedPos[1], a.smoothedVel[0], a.smoothedVel[1]};
    }
    if (imm_.initialised()) {
      const auto g = imm_.combined();
      e[kImm] = std::array<double, 4>{g.x[0], g.x[1], g.x[2], g.x[3]};
    }
    return e;
  }
  [[nodiscard]] std::array<bool, kTrackerKinds> flags() const {
    return {false, ieManoeuvring_, false, imm_.initialised() && imm_.manoeuvring()};
  }

 private:
  static track::InputEstimationConfig neverDeclaring(track::InputEstimationConfig c) {
    c.correction = track::InputEstimationConfig::Correction::None;  // the EKF alone
    return c;
  }
  track::InputEstimationEkf ekf_, ie_;
  track::ImmTracker imm_;
  track::AlphaBetaGammaFilter abg_;
  bool ieManoeuvring_ = false;
  double ox_ = 0.0, oy_ = 0.0;
};
}  // namespace

ManoeuvreRun runManoeuvreTrial(const ManoeuvreTrial& m, const TrackerConfigs& configs, std::uint64_t seed) {
  TrackerBank bank(configs);
  Rng rng(seed, 6);
  ManoeuvreRun out;
  const bool manoeuvres = m.manoeuvres();
  out.straightS = manoeuvres ? m.manoeuvreStartS : m.durationS;
  // Target truth: the simulator's vessel model with one helm order at the manoeuvre's start.
  VesselMotionSpec spec;
  spec.initialPosition = {m.targetRangeM * std::sin(m.targetBearingRad),
                          m.targetRangeM * std::cos(m.targetBearingRad)};
  spec.initialVelocityMps = {m.targetSpeedMps * std::sin(m.targetCourseRad),
                             m.targetSpeedMps * std::cos(m.targetCourseRad)};
  if (manoeuvres) {
    KinematicEvent e;
    e.timeUs = fromSeconds(m.manoeuvreStartS);
    e.order = HelmOrder{wrapTwoPi(m.targetCourseRad + m.turnRad), m.targetSpeedMps + m.speedChangeMps,
                        m.turnRateRadPerS, m.accelerationMps2};
    spec.schedule.push_back(e);
  }
  VesselMotionModel target(spec, est::GaussMarkov{0.0, 1.0}, Rng(seed, kStreamTargetBase));
  std::array<bool, kTrackerKinds> flag{};
  PositionBound pcrb(m.boundProcessNoiseQ, configs.imm.initialSpeedSdMps, m.bearingSdRad, m.rangeSdM);
  for (int k = 0; k * m.sweepS <= m.durationS + 1e-9; ++k) {
    const double tPlot = k * m.sweepS;
    target.advanceTo(fromSeconds(tPlot));
    const VesselTruth& truth = target.state();
    const double tx = truth.position.xM, ty = truth.position.yM;
    const double tvx = truth.groundVxMps(), tvy = truth.groundVyMps();
    const double course = bearingOf(tvx, tvy);
    const double ox = m.ownSpeedMps * tPlot * std::sin(m.ownCourseRad);
    const double oy = m.ownSpeedMps * tPlot * std::cos(m.ownCourseRad);
    const double b = wrapTwoPi(bearingOf(tx - ox, ty - oy) + rng.normal(0.0, m.bearingSdRad));
    const double r = std::hypot(tx - ox, ty - oy) + rng.normal(0.0, m.rangeSdM);
    const TimeUs tu = fromSeconds(tPlot);
    bank.measure(tu, b, r, ox, oy);

    // The bound along the truth: CV with the EKF's white acceleration, the plot's information.
    const double bound = pcrb.measure(tPlot, tx, ty, ox, oy);
    out.tS.push_back(tPlot);
    out.pcrbPosM.push_back(bound);

    const auto estimates = bank.estimates();
    const auto now = bank.flags();
    const bool before = !manoeuvres || tPlot < m.manoeuvreStartS;
    for (int i = 0; i < kTrackerKinds; ++i) {
      TrackerSeries& s = out.trackers[static_cast<std::size_t>(i)];
      if (before) {
        s.falseAlarms += now[i] && !flag[i] ? 1 : 0;
      } else if (now[i] && !s.delayS) {
        s.delayS = tPlot - m.manoeuvreStartS;
      }
      flag[i] = now[i];
      const auto& e = estimates[static_cast<std::size_t>(i)];
      s.posErrM.push_back(e ? std::hypot((*e)[0] - tx, (*e)[1] - ty) : kNaN);
      s.courseErrRad.push_back(e ? std::abs(angleDiff(bearingOf((*e)[2], (*e)[3]), course)) : kNaN);
      s.speedErrMps.push_back(e ? std::abs(std::hypot((*e)[2], (*e)[3]) - std::hypot(tvx, tvy)) : kNaN);
    }
  }
  return out;
}

TrackerConfigs sonarTrackers() {
  TrackerConfigs c;  // seed 001's filter as printed: s = 2, Pfa 0.01, q 1e-6, 1 deg and 20 m
  c.imm.bearingSdRad = c.ie.bearingSdRad;
  c.imm.rangeSdM = c.ie.rangeSdM;
  c.abg.alpha = 0.6;  // few pings, far apart: the paper's upper bound
  return c;
}

Seed001TrackerRun runSeed001Trackers(const Seed001Scenario& s, const TrackerConfigs& configs,
                                     std::uint64_t seed) {
  TrackerBank bank(configs);
  PositionBound pcrb(configs.ie.processNoiseQ, configs.imm.initialSpeedSdMps, configs.ie.bearingSdRad,
                     configs.ie.rangeSdM);
  Seed001TrackerRun out;
  for (const Seed001Ping& p : seed001Pings(s, configs.ie.bearingSdRad, configs.ie.rangeSdM, seed)) {
    bank.measure(fromSeconds(p.stampS), p.bearingRad, p.rangeM, p.observerXM, p.observerYM);
    const double bound = pcrb.measure(p.stampS, p.trueXM, p.trueYM, p.observerXM, p.observerYM);
    const auto estimates = bank.estimates();
    const auto flags = bank.flags();
    for (int k = 0; k < kTrackerKinds; ++k) {
      const auto& e = estimates[static_cast<std::size_t>(k)];
      if (!e || p.index < 2) continue;
      Seed001TrackerSample r;
      r.index = p.index;
      r.tS = p.tS;
      const double range = std::hypot((*e)[0] - p.observerXM, (*e)[1] - p.observerYM);
      r.rangeErrorPct = 100.0 * std::abs(range - p.trueRangeM) / p.trueRangeM;
      r.courseErrorDeg = std::abs(radToDeg(angleDiff(bearingOf((*e)[2], (*e)[3]), p.trueCourseRad)));
      r.speedErrorMps = std::abs(std::hypot((*e)[2], (*e)[3]) - p.trueSpeedMps);
      r.manoeuvring = flags[static_cast<std::size_t>(k)];
      r.positionErrorM = std::hypot((*e)[0] - p.trueXM, (*e)[1] - p.trueYM);
      r.pcrbPositionM = bound;
      out.trackers[static_cast<std::size_t>(k)].push_back(r);
    }
  }
  return out;
}

}  // namespace reckoner::studies
