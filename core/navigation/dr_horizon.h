#pragma once
// How long dead reckoning stays within a position-error limit: the DRKF's covariance is propagated
// forward with the aids still working (speedlog, gyro) applied at their rates as measurements of their
// predicted values, and no position fix. Only the covariance matters; the mean is carried along so that
// the speedlog and gyro are linearised where the ship is heading.
#include <optional>

#include "navigation/drkf.h"
#include "sensors/own_ship_samples.h"

namespace reckoner::nav {

struct DeadReckoningAids {
  bool speedlog = false;
  sensors::SpeedlogMode speedlogMode = sensors::SpeedlogMode::GroundLock;
  double speedlogVarM2PerS2 = 0.01;  ///< white-noise variance of the log, (m/s)^2
  bool gyro = false;
  double gyroVarRad2 = 3e-4;  ///< white-noise variance of the gyro, rad^2
  double periodS = 1.0;       ///< interval of the aids' updates, s (> 0)

  friend bool operator==(const DeadReckoningAids&, const DeadReckoningAids&) = default;
};

/// The semi-major axis of the 95% position error ellipse of a belief, metres (chi-square 2 dof).
double positionError95M(const drkf::Belief& b);

/// Seconds from the filter's time until positionError95M first exceeds limitM with only the aids
/// (0 if it already does); nullopt if it stays within the limit for maxS. Resolution: one step of 5 s
/// (or the aids' period if longer). Applying the aids once a step instead of at their own rate uses
/// less information than the filter will, so the growth is faster and the answer errs on the short
/// (safe) side.
std::optional<double> timeToPositionLimitS(const Drkf& filter, const DeadReckoningAids& aids, double limitM,
                                           double maxS);

}  // namespace reckoner::nav
