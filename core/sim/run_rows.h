#pragma once
// The rows of a run: what one SimFrame says about own ship, each track, each target and each radar fix,
// as plain values against the truth. The one row builder: the headless runs write these rows into
// ownship.csv and targets.csv (runScenario, io/), and the window's worker turns the same rows into
// what it draws and plots (ui/bridge/simulation_worker.cpp), computing nothing itself.
#include <limits>
#include <vector>

#include "estimation/gaussian.h"
#include "geo/local_frame.h"
#include "navigation/drkf.h"
#include "sim/scenario.h"
#include "sim/simulation_engine.h"

namespace reckoner::sim {

/// One output cycle of a run: truth, estimate, standard deviations and NEES (ownship.csv's columns).
/// Velocities are over ground in the grid frame.
struct OwnShipRow {
  TimeUs timeUs = 0;
  double trueXM = 0, trueYM = 0, trueVxMps = 0, trueVyMps = 0;
  double estXM = 0, estYM = 0, estVxMps = 0, estVyMps = 0;
  double sdXM = 0, sdYM = 0, sdVxMps = 0, sdVyMps = 0;
  double estLatDeg = 0, estLonDeg = 0;
  double nees = 0;  ///< the DRKF's NEES over nav::neesStates (11 states with every sensor error modelled)
  SensorStates sensors;
  int rowsApplied = 0;  ///< measurement rows applied during the cycle
  /// For the NMEA output (sim/nmea_output.h): the position covariance's off-diagonal (grid, m^2); the
  /// heading (grid, rad: the direction of the velocity through the water; NaN below kMinHeadingSpeedMps
  /// or for a filter without it); the estimated current (grid, m/s; NaN without one); dead reckoning at
  /// the row's time (the engine's nav::DeadReckoningMonitor).
  double covXYM2 = 0;
  double estHeadingRad = std::numeric_limits<double>::quiet_NaN();
  double estCurrentXMps = std::numeric_limits<double>::quiet_NaN();
  double estCurrentYMps = std::numeric_limits<double>::quiet_NaN();
  bool deadReckoning = false;

  [[nodiscard]] double positionErrorM() const;
  [[nodiscard]] double velocityErrorMps() const;
  [[nodiscard]] double sdPositionM() const;  ///< sqrt(sd_x^2 + sd_y^2)
  /// Both position errors within k standard deviations of their axis.
  [[nodiscard]] bool positionWithin(double k) const;
};

/// The DRKF's row of a frame.
OwnShipRow makeRow(const SimFrame& frame, const geo::LocalFrame& geo,
                   const est::drkf::ProcessParams& process);
/// The row of any estimate of position and velocity over ground [x, y, vx, vy] (grid) with covariance;
/// nees is that of those 4 states, rowsApplied 0.
OwnShipRow groundRow(const SimFrame& frame, const est::Gaussian<4>& estimate, const geo::LocalFrame& geo);

/// The rest of the DRKF's picture of a frame, which the window plots beside the OwnShipRow (not in
/// ownship.csv): the sensor error states against their truth, and the 95% position radius.
struct OwnShipDetailRow {
  double trueCurrentXMps = 0, trueCurrentYMps = 0, estCurrentXMps = 0, estCurrentYMps = 0;
  double sdCurrentXMps = 0, sdCurrentYMps = 0;
  double trueLoranXM = 0, trueLoranYM = 0, estLoranXM = 0, estLoranYM = 0;  ///< Loran-C error, m
  double sdLoranXM = 0, sdLoranYM = 0;
  double trueLogBiasMps = 0, estLogBiasMps = 0, sdLogBiasMps = 0;  ///< speedlog error
  double error95M = 0;  ///< semi-major axis of the 95% position ellipse (nav::positionError95M)
};
OwnShipDetailRow ownShipDetailRow(const SimFrame& frame);

/// A DRKF estimate as output columns: position and velocity over ground, their sds, latitude/longitude.
struct GroundEstimate {
  double xM = 0, yM = 0, vxMps = 0, vyMps = 0;
  double sdXM = 0, sdYM = 0, sdVxMps = 0, sdVyMps = 0;
  double latDeg = 0, lonDeg = 0;
  double covXYM2 = 0;  ///< the position covariance's off-diagonal, grid m^2
  /// Grid heading, rad: the direction of the velocity through the water; NaN below kMinHeadingSpeedMps.
  double headingRad = std::numeric_limits<double>::quiet_NaN();
};
/// Below this speed through the water the direction of the DRKF's water velocity is no heading (the
/// DRKF's own linearisation limit, nav::DrkfConfig::minSpeedMps).
inline constexpr double kMinHeadingSpeedMps = 0.5;
/// The DRKF's heading (grid, rad), NaN below kMinHeadingSpeedMps.
double headingOf(const est::drkf::Belief& b);
GroundEstimate groundEstimateOf(const est::drkf::Belief& b, const geo::LocalFrame& geo);

/// One track at the end of one radar sweep (targets.csv's columns). Truth columns are filled when the
/// track's plots came mostly from a real target (hasTruth). Two NEES, named by what they measure:
/// `nees` over all 12 TTKF states (targets.csv's `nees`), positionVelocityNees4 over the target's
/// position and velocity only (the window's target plot); docs/outputs.md, "Two track NEES".
struct TrackRow {
  TimeUs timeUs = 0;
  int trackId = 0;
  int targetId = -1;
  track::TrackStatus status = track::TrackStatus::Tentative;
  bool dangerous = false;
  bool hasTruth = false;
  double trueXM = 0, trueYM = 0, trueVxMps = 0, trueVyMps = 0;
  double estXM = 0, estYM = 0, estVxMps = 0, estVyMps = 0;
  double sdXM = 0, sdYM = 0, sdVxMps = 0, sdVyMps = 0;
  double estLatDeg = 0, estLonDeg = 0;
  double courseDeg = 0, speedKn = 0;
  double cpaNm = 0, tcpaMin = 0;       ///< NaN when there is no relative motion
  double nees = 0;                     ///< all 12 TTKF states (own ship and target); NaN without truth
  double positionVelocityNees4 = 0;    ///< target x, y, vx, vy (4 dof); NaN without truth
  double nis = 0;                      ///< of the last radar update
  bool manoeuvring = false;            ///< the track's manoeuvre flag (ekf-ie, imm)
  bool manual = false;                 ///< acquired by the operator
  double rangeNm = 0, bearingDeg = 0;  ///< from own ship's estimate, true (track::TrackKinematics)
  std::uint32_t aisMmsi = 0;           ///< the AIS station associated with (and fused into) the track

  [[nodiscard]] double positionErrorM() const;
  [[nodiscard]] double velocityErrorMps() const;
};

/// NEES of a track's target position and velocity alone (the 4 x 4 block of its covariance) against
/// the target's truth.
double positionVelocityNees4(const est::ttkf::Belief& b, const VesselTruth& truth);

/// A TrackRow's estimate columns from a track's belief and kinematics (no truth; both NEES NaN).
TrackRow trackEstimateRow(TimeUs t, int trackId, int targetId, track::TrackStatus status, bool dangerous,
                          const est::ttkf::Belief& b, const track::TrackKinematics& k, double nis,
                          const geo::LocalFrame& geo);

/// The row of one track of a sweep, with the truth of the scenario target it follows (if any).
TrackRow trackRow(const SweepSnapshot& sweep, const TrackSnapshot& track,
                  const std::vector<TargetSpec>& targets, const geo::LocalFrame& geo);

/// One target at the end of one radar sweep: where it truly is and whether the radar can see it.
struct TargetSweepRow {
  TimeUs timeUs = 0;
  int targetId = 0;
  bool inRange = false;
  double xM = 0, yM = 0;
};

/// Rows of every track and every target of each sweep that ended in the frame.
void appendSweepRows(const SimFrame& frame, const Scenario& scenario, const geo::LocalFrame& geo,
                     std::vector<TrackRow>& tracks, std::vector<TargetSweepRow>& targets);

/// A radar fix's error against the frame's truth (position grid m, heading rad), less what the error of
/// the motion it was placed with explains (S times the true minus the assumed velocity and turn rate):
/// the part its covariance claims. For fixes taken at the frame's time.
est::Vec<3> radarFixError(const RadarFixReport& fix, const SimFrame& frame);

/// A valid radar fix (seed 004) against the truth at the end of its frame (grid m, grid radians).
struct RadarFixRow {
  TimeUs timeUs = 0;
  bool informative = false, applied = false;
  int echoes = 0, used = 0;
  double xM = 0, yM = 0, headingRad = 0;
  double sdXM = 0, sdYM = 0, sdHeadingRad = 0;
  double trueXM = 0, trueYM = 0;
  double trueHeadingRad = 0;  ///< within pi of headingRad (not wrapped to [0, 2 pi))
  double nees = 0;            ///< 3 dof, of radarFixError (NaN when the covariance is not positive definite)
  double rmsResidual = 0;     ///< matched echoes off their contours, in their sd
  double nis = 0;             ///< of the DRKF's update with it
  int dim = 0;                ///< rows of that update
};
RadarFixRow radarFixRow(const RadarFixReport& fix, const SimFrame& frame);

/// The frame's radar plots where a radar draws them: range and bearing from the estimated own-ship
/// position (grid), so a wrong estimate shows as plots off their targets.
std::vector<geo::GridPoint> plotPositionsFromEstimate(const SimFrame& frame, const geo::LocalFrame& geo);

}  // namespace reckoner::sim
