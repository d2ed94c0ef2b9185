#pragma once
// Closest point of approach from a relative-motion estimate, with first-order standard deviations,
// and the course and speed figures a radar observer reads (docs/ttkf.md, "CPA and TCPA").
//   r: target minus own position, v: target minus own velocity (grid frame, SI).
//   TCPA = -(r . v) / |v|^2,  CPA = |r + v TCPA|.
// The standard deviations propagate the covariance of (r, v) through the analytic gradients; near a
// collision course (CPA within 3 sd of 0) the CPA's sd is the RMS spread of the CPA point instead.
#include "estimation/gaussian.h"
#include "estimation/models/ttkf_state.h"

namespace reckoner::track {

/// Below this relative speed the geometry has no defined closest approach.
inline constexpr double kMinRelativeSpeedMps = 0.01;

struct Cpa {
  bool defined = false;  ///< false: no relative motion; cpa is the present range and tcpa 0
  double cpaM = 0.0;
  double tcpaS = 0.0;  ///< negative: the closest approach is past
  double sdCpaM = 0.0;
  double sdTcpaS = 0.0;
};

/// The danger rule of a confirmed track: the closest approach within cpaLimitM, ahead (TCPA >= 0) and
/// within tcpaLimitS.
[[nodiscard]] inline bool withinDangerLimits(const Cpa& c, double cpaLimitM, double tcpaLimitS) {
  return c.cpaM <= cpaLimitM && c.tcpaS >= 0.0 && c.tcpaS <= tcpaLimitS;
}

/// A with A x = [target minus own position; target minus own velocity] for a TTKF state x.
Eigen::Matrix<double, 4, est::ttkf::kStateDim> relativeSelector();

/// CPA and TCPA of relative state [rx, ry, vx, vy] with covariance P.
Cpa cpaOf(const est::Vec<4>& rel, const est::Mat<4>& P);
/// d(cpa, tcpa) / d(rx, ry, vx, vy), analytic (tested against the numeric Jacobian).
est::MatRC<2, 4> cpaJacobian(const est::Vec<4>& rel);

/// What an ARPA shows for a track: relative and true motion and the CPA.
struct TrackKinematics {
  double rangeM = 0.0;
  double trueBearingRad = 0.0;
  double trueCourseRad = 0.0;  ///< course over ground, true, [0, 2 pi)
  double speedMps = 0.0;       ///< speed over ground
  double sdCourseRad = 0.0;
  double sdSpeedMps = 0.0;
  double relativeCourseRad = 0.0;
  double relativeSpeedMps = 0.0;
  Cpa cpa;
};

/// From a TTKF belief (grid frame) and the grid convergence at own ship (true = grid + convergence).
TrackKinematics kinematicsOf(const est::ttkf::Belief& b, double convergenceRad);

}  // namespace reckoner::track
