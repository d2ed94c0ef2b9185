#include "sim/manoeuvre_trial.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/angles.h"
#include "common/rng.h"
#include "metrics/pcrb.h"
#include "sim/vessel_motion.h"

namespace reckoner::sim {
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
  c.abg.alpha = 0.4;
  return c;
}

ManoeuvreRun runManoeuvreTrial(const ManoeuvreTrial& m, const TrackerConfigs& configs, std::uint64_t seed) {
  track::InputEstimationConfig plain = configs.ie;
  plain.falseAlarmProbability = 1e-15;  // never declares: the EKF alone
  track::InputEstimationEkf ekf(plain), ie(configs.ie);
  track::ImmTracker imm(configs.imm);
  track::AlphaBetaGammaFilter abg(configs.abg);
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
  double lastPlot = 0.0;
  std::array<bool, kTrackerKinds> flag{};
  std::optional<metrics::Pcrb<4, 2>> pcrb;
  const est::Mat<2> R = est::Vec<2>(m.bearingSdRad * m.bearingSdRad, m.rangeSdM * m.rangeSdM).asDiagonal();
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
    ekf.measure(tu, b, r, ox, oy);
    const auto ieStep = ie.measure(tu, b, r, ox, oy);
    imm.update(tu, b, r, ox, oy);
    abg.update(tu, ox + r * std::sin(b), oy + r * std::cos(b));

    // The bound along the truth: CV with the EKF's white acceleration, the plot's information.
    const double dx = tx - ox, dy = ty - oy, r2 = dx * dx + dy * dy, rr = std::sqrt(r2);
    est::MatRC<2, 4> H = est::MatRC<2, 4>::Zero();
    H(0, 0) = dy / r2;
    H(0, 1) = -dx / r2;
    H(1, 0) = dx / rr;
    H(1, 1) = dy / rr;
    if (!pcrb) {
      est::Mat<4> P0 = est::Mat<4>::Zero();
      P0.topLeftCorner<2, 2>() = est::Mat<2>::Identity() * 1e8;  // position from the first plot only
      P0(2, 2) = P0(3, 3) = configs.imm.initialSpeedSdMps * configs.imm.initialSpeedSdMps;
      pcrb.emplace(P0);
      pcrb->measure(H, R);
    } else {
      const double dt = tPlot - lastPlot;
      est::Mat<4> F = est::Mat<4>::Identity();
      F(0, 2) = F(1, 3) = dt;
      est::Mat<4> Q = est::Mat<4>::Zero();
      const double q = m.boundProcessNoiseQ;
      for (int a = 0; a < 2; ++a) {
        Q(a, a) = q * dt * dt * dt / 3.0;
        Q(a, a + 2) = Q(a + 2, a) = q * dt * dt / 2.0;
        Q(a + 2, a + 2) = q * dt;
      }
      pcrb->step(F, Q, H, R);
    }
    lastPlot = tPlot;
    const est::Mat<4> bound = pcrb->bound();
    out.tS.push_back(tPlot);
    out.pcrbPosM.push_back(std::sqrt(bound(0, 0) + bound(1, 1)));

    // Estimates of target position and velocity over ground by each tracker.
    std::array<std::optional<std::array<double, 4>>, kTrackerKinds> estimates;
    namespace rp = reckoner::est::relpolar;
    const auto fromRelative =
        [&](const track::InputEstimationEkf& f) -> std::optional<std::array<double, 4>> {
      if (!f.initialised()) return std::nullopt;
      const auto& x = f.belief().x;
      return std::array<double, 4>{x[rp::kRx] + ox, x[rp::kRy] + oy, x[rp::kVx], x[rp::kVy]};
    };
    estimates[kEkf] = fromRelative(ekf);
    estimates[kEkfIe] = fromRelative(ie);
    if (abg.plots() >= 2) {
      const auto& e = abg.estimate();
      estimates[kAbg] =
          std::array<double, 4>{e.smoothedPos[0], e.smoothedPos[1], e.smoothedVel[0], e.smoothedVel[1]};
    }
    if (imm.initialised()) {
      const auto g = imm.combined();
      estimates[kImm] = std::array<double, 4>{g.x[0], g.x[1], g.x[2], g.x[3]};
    }
    const std::array<bool, kTrackerKinds> now{false, ieStep.manoeuvring, false,
                                              imm.initialised() && imm.manoeuvring()};
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

}  // namespace reckoner::sim
