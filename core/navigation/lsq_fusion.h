#pragma once
// Seed 002 section 2: position fusion by weighted least squares (docs/seed002.md).
//   x = (H' R^-1 H)^-1 H' R^-1 z,   P = (H' R^-1 H)^-1                      (eqs. 1, 2)
// With a GPS fix and a dead-reckoning position, H = [I; I] and R = diag(R_GPS, R_DR) (eqs. 3, 4); the
// block-diagonal inverse (eq. 5) gives P = (R_GPS^-1 + R_DR^-1)^-1 and x = P (R_GPS^-1 z_GPS +
// R_DR^-1 z_DR) (eqs. 6, 7). LsqNavigator runs it recursively: between fixes it dead-reckons from
// the gyro heading and the log speed (its covariance grows by the velocity's, through the Jacobian of
// (speed, heading) -> velocity, times the interval squared, plus an optional random walk for what
// the log and gyro do not see, such as current), and at every GPS fix it fuses the two positions.
#include <optional>
#include <span>
#include <string>

#include "common/time.h"
#include "estimation/gaussian.h"
#include "geo/local_frame.h"
#include "sensors/own_ship_samples.h"

namespace reckoner::nav {

struct PositionFix {
  est::Vec<2> z;  ///< grid metres
  est::Mat<2> R;
};

/// Weighted least squares of several fixes of the same position (H = [I; I; ...], block-diagonal R);
/// nullopt when the normal matrix is not positive definite or a fix is not finite.
std::optional<est::Gaussian<2>> leastSquares(std::span<const PositionFix> fixes);

struct LsqNavigatorConfig {
  double driftM2PerS = 0.0;         ///< dead-reckoning position random walk beyond the sensors' noise
  double minSpeedMps = 0.0;         ///< below: the heading does not matter (speed only)
  double maxDeadReckoningS = 10.0;  ///< a velocity older than this is not used (the position holds)
  [[nodiscard]] std::string check() const;
};

class LsqNavigator {
 public:
  /// Throws std::invalid_argument for an invalid configuration or a non-finite start.
  LsqNavigator(const LsqNavigatorConfig& config, const est::Gaussian<2>& position, TimeUs t0);

  /// Dead-reckons to t, takes the epoch's gyro and log for the velocity from now on, and fuses a GPS
  /// fix if there is one. Returns true when a fix was fused.
  bool update(TimeUs t, std::span<const sensors::OwnShipSample> samples, const geo::LocalFrame& frame);

  /// [x, y, vx, vy] in the grid frame, velocity from dead reckoning (zero with a large variance before
  /// the first heading and log pair).
  [[nodiscard]] est::Gaussian<4> ground() const;
  [[nodiscard]] TimeUs timeUs() const { return timeUs_; }

 private:
  void deadReckonTo(TimeUs t);
  LsqNavigatorConfig config_;
  est::Gaussian<2> position_;
  est::Gaussian<2> velocity_;  ///< grid, from the last heading and log pair
  bool hasVelocity_ = false;
  TimeUs velocityUs_ = 0;
  TimeUs timeUs_;
};

}  // namespace reckoner::nav
