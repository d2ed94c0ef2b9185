#pragma once
// Seed 002 section 4: the integrating Kalman filter in geodetic coordinates (docs/seed002.md).
// State (eq. 17): latitude, longitude (rad), the speed over ground projected on the parallel and the
// meridian (true east and north, m/s), course and speed over ground (rad, m/s). The transition (eqs.
// 18-20) moves the position by the velocity converted to angles with the WGS-84 meridian radius M and
// prime-vertical radius N at the current latitude (GeographicLib's ellipsoid):
//   lat' = lat + T vN / M(lat),   lon' = lon + T vE / (N(lat) cos lat),   v' = v + w,
//   COG' = atan2(vE', vN'),   SOG' = |v'| (+ their own small disturbances, eq. 24).
// The velocity is a random walk driven by white acceleration ("yawing", eqs. 21-23). Measurements
// (eq. 25): GPS latitude and longitude; the velocity projections from dead reckoning (gyro heading
// and log speed, their covariance through the Jacobian of (speed, heading) -> (vE, vN)); and COG and
// SOG from the GPS velocity. The measurement covariance is block diagonal (eq. 27). It is an EKF:
// the transition is linearised (its Jacobian is tested against a numeric one).
#include <span>
#include <string>

#include "common/time.h"
#include "estimation/gaussian.h"
#include "estimation/update_report.h"
#include "geo/local_frame.h"
#include "sensors/own_ship_samples.h"

namespace reckoner::nav {

namespace geod {
enum Index : int { kLat = 0, kLon, kVe, kVn, kCog, kSog, kStateDim };
using State = est::Vec<kStateDim>;
using Covariance = est::Mat<kStateDim>;
using Belief = est::Gaussian<kStateDim>;

/// WGS-84 radii of curvature at a latitude (rad): meridian M and prime vertical N, metres.
double meridianRadius(double latRad);
double primeVerticalRadius(double latRad);

/// The transition over T seconds and its Jacobian (minSpeedMps: below it COG is held, not recomputed).
State transition(const State& x, double T, double minSpeedMps);
Covariance transitionJacobian(const State& x, double T, double minSpeedMps);
}  // namespace geod

struct GeodeticKfConfig {
  double accelerationQ = 0.02;      ///< white acceleration per axis driving the velocity, m^2/s^3
  double cogQ = 1e-6;               ///< extra COG disturbance (eq. 24), rad^2/s
  double sogQ = 1e-4;               ///< extra SOG disturbance (eq. 24), m^2/s^3
  double minSpeedMps = 0.5;         ///< below: COG and the heading-based velocity are not used
  double gateProbability = 0.9999;  ///< per-block chi-square gate; 0 disables
  double gateReopenS = 10.0;  ///< a GPS position rejected this long is applied ungated once (as the DRKF)
  [[nodiscard]] std::string check() const;  ///< empty when valid
};

/// What one epoch applied.
struct GeodeticUpdate {
  est::UpdateReport<2> position, deadReckoning, courseSpeed;
  [[nodiscard]] int rowsApplied() const;
};

class GeodeticKf {
 public:
  /// Throws std::invalid_argument for an invalid configuration or initial belief.
  GeodeticKf(const GeodeticKfConfig& config, const geod::Belief& initial, TimeUs t0);
  /// A start at a grid position (sd in metres) and velocity over ground (true east, north; sd m/s).
  static geod::Belief initialBelief(const geo::LocalFrame& frame, const geo::GridPoint& p, double sdPosM,
                                    double vEast, double vNorth, double sdVelMps);

  /// Predicts to t; false (unchanged) when t is earlier or the result is not finite.
  bool predictTo(TimeUs t);
  /// Predicts to t and applies one epoch of samples (GPS position and velocity, gyro and speedlog
  /// paired into the dead-reckoning velocity). Loran-C is not part of seed 002's model and is ignored.
  GeodeticUpdate update(TimeUs t, std::span<const sensors::OwnShipSample> samples,
                        const geo::LocalFrame& frame);

  [[nodiscard]] const geod::Belief& belief() const { return belief_; }
  [[nodiscard]] TimeUs timeUs() const { return timeUs_; }
  /// Position and velocity over ground in the grid frame [x, y, vx, vy] with their covariance (the
  /// position through the projection's Jacobian), for comparison with the DRKF.
  [[nodiscard]] est::Gaussian<4> groundInGrid(const geo::LocalFrame& frame) const;

 private:
  GeodeticKfConfig config_;
  double gate_;
  TimeUs positionRejectedSinceUs_ = -1;
  geod::Belief belief_;
  TimeUs timeUs_;
};

}  // namespace reckoner::nav
