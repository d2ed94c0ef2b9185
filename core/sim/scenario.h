#pragma once
// A complete simulation description (resources/scenarios/*.json, format in docs/scenarios.md).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/step_schedule.h"
#include "common/time.h"
#include "estimation/gauss_markov.h"
#include "estimation/models/drkf_process.h"
#include "geo/local_frame.h"
#include "sensors/ais_transmitter.h"
#include "sensors/own_ship_sensor_specs.h"
#include "sensors/radar.h"
#include "sim/voyage_spec.h"
#include "tracking/ais_fusion.h"
#include "tracking/track_manager.h"

namespace reckoner::sim {

/// A helm order: the ship turns towards the heading at no more than the vessel's turn-rate limit and
/// changes speed at no more than its acceleration limit (what a watch officer orders from the bridge).
struct HelmOrder {
  double headingRad = 0.0;        ///< grid heading through the water, [0, 2 pi)
  double speedMps = 0.0;          ///< speed through the water, >= 0
  double turnRateRadPerS = 0.0;   ///< > 0: turn at this rate instead of the vessel's limit
  double accelerationMps2 = 0.0;  ///< > 0: change speed at this rate instead of the vessel's limit
  friend bool operator==(const HelmOrder&, const HelmOrder&) = default;
};

/// A change of the own-ship kinematics at a time (seed 000 Table II), or a helm order.
struct KinematicEvent {
  TimeUs timeUs = 0;
  std::optional<std::array<double, 2>> setVelocityMps;  ///< commanded velocity through water, grid (vx, vy)
  std::optional<double> turnRateRadPerS;                ///< rotation of the velocity, clockwise positive
  std::optional<HelmOrder> order;  ///< exclusive with the two above; ends at the next event
};

struct VesselMotionSpec {
  geo::GridPoint initialPosition;              ///< grid metres
  std::array<double, 2> initialVelocityMps{};  ///< through water, grid (vx, vy)
  std::optional<double> initialHeadingRad;     ///< grid; default: bearing of the first non-zero velocity
  std::vector<KinematicEvent> schedule;        ///< increasing time
  /// > 0: a commanded velocity is reached at this acceleration; 0: instantly (as Table II prints it).
  double maxAccelerationMps2 = 0.0;
  /// > 0: helm orders turn the ship at no more than this rate; 0: helm orders turn instantly.
  double maxTurnRateRadPerS = 0.0;
  /// Optional Gauss-Markov acceleration added to the scheduled motion (truth drawn from the filter's
  /// own model for consistency tests).
  std::optional<est::GaussMarkov> randomAcceleration;
  /// Optional random motion of a ship's kind (drkf_process.h's ship motion model: an along-track
  /// acceleration and a turn rate, Gauss-Markov, and a white acceleration) added to the scheduled motion;
  /// a matched-model test of a filter with that model. Not together with randomAcceleration.
  std::optional<est::drkf::ShipMotionParams> randomShipMotion;
};

/// A radar target: its motion is over ground (no current).
struct TargetSpec {
  int id = 0;  ///< unique, >= 0
  std::string name;
  /// The target exists (moves, echoes) from this time on; its motion starts here from the initial
  /// position (targets added during a run).
  TimeUs appearUs = 0;
  /// The target leaves the scene at this time (no more echoes or AIS messages; its tracks and AIS
  /// target are then lost as with a vessel gone out of range); none: it stays to the end.
  std::optional<TimeUs> leaveUs;
  VesselMotionSpec motion;

  /// Moving and seen (echoes, transmissions) at time t: from appearUs until leaveUs.
  [[nodiscard]] bool presentAt(TimeUs t) const { return appearUs <= t && (!leaveUs || t < *leaveUs); }
  /// An AIS transponder on board (sensors/ais_transmitter.h); none: a target the radar alone sees.
  std::optional<sensors::AisTransmitterSpec> ais;
};

/// The target trackers (TTKFs), their bank and its track management (docs/ttkf.md).
struct TrackerSpec {
  est::GaussMarkov ownAcceleration{0.5, 1.0};     ///< Table III "Ves" sigma (m/s^2), beta
  est::GaussMarkov targetAcceleration{0.5, 1.0};  ///< Table III "Tgt" sigma (m/s^2), beta
  track::OwnShipFeed feed = track::OwnShipFeed::Marginal;
  double gateProbability = 0.9999;
  double initialSpeedSdMps = 10.0;
  std::size_t capacity = 1000;
  track::Association association = track::Association::Nearest;
  int confirmHits = 3, confirmSweeps = 5;
  int keepHits = 5, keepSweeps = 10;
  double lostHoldS = 60.0;
  bool autoAcquire = true;
  std::vector<track::AcquisitionZone> zones;  ///< empty: the whole picture
  /// Later changes of the zones (the operator's, drawn on the chart), in increasing time: from each
  /// change's time on, its zones replace the previous ones.
  std::vector<std::pair<TimeUs, std::vector<track::AcquisitionZone>>> zoneChanges;
  double dangerCpaM = 1852.0;
  double dangerTcpaS = 720.0;
  /// The filter of every track (track_filter.h) and the parameters of each kind.
  track::TrackerKind kind = track::TrackerKind::Ekf;
  /// Later changes of the filter for new tracks (the operator's), in increasing time.
  std::vector<std::pair<TimeUs, track::TrackerKind>> kindChanges;
  int inputEstimationWindow = 15;  ///< ekf-ie: radar updates per input-estimation window
  double inputEstimationPfa = 1e-4;
  track::AbgConfig abg{0.1, true};
  track::ImmConfig imm;
  /// AIS stations associated with radar tracks and fused into them (tracking/ais_fusion.h).
  track::AisAssociationConfig aisAssociation;
};

/// The filter for tracks started at t.
track::TrackerKind trackerKindAt(const TrackerSpec& t, TimeUs time);
/// The acquisition zones in force at t, and the index of the change that set them (-1: the initial).
std::pair<const std::vector<track::AcquisitionZone>*, int> zonesAt(const TrackerSpec& t, TimeUs time);

/// The track manager configuration a scenario implies (sweep period from the radar).
track::TrackManagerConfig trackManagerConfigFor(const TrackerSpec& t, double sweepPeriodS);

struct FilterSpec {
  est::GaussMarkov acceleration{0.5, 1.0};  ///< Table I footnote: sigma_a = 0.5 m/s^2, beta_a = 1 /s
  std::optional<est::GaussMarkov> current;  ///< default: the scenario's current model
  double initialPositionSdM = 30.0;
  double initialVelocitySdMps = 0.5;
  double gateProbability = 0.9999;  ///< per-sensor chi-square gate; 0 disables gating
  double gateReopenS = 10.0;        ///< a sensor rejected this long is applied ungated once
  double minSpeedMps = 0.5;         ///< below: gyro and speedlog are not linearisable
  /// A ship's motion model in place of the Cartesian acceleration (drkf_process.h); off in the paper.
  est::drkf::ShipMotionParams shipMotion{};
  /// nav::DrkfConfig::adaptiveGnssNoise: the GNSS position noise scaled by a variational-Bayes estimate.
  bool adaptiveGnssNoise = false;
};

/// Seed 004: a radar picture matched to the chart's contours every few sweeps, fed to the DRKF as a
/// position and heading fix (docs/radar_matching.md). The contours come from the charts loaded by
/// the program (SimulationEngine::setCoastline); without them nothing is matched.
struct RadarMatchingSpec {
  /// Matching on or off over the run: the block's "enabled" (true when the block is there) and its
  /// "schedule" of {t_s, on} changes; the window's operator switch adds changes.
  StepSchedule<bool> active{false};
  int azimuths = 1024;
  int rangeBins = 512;
  double maxRangeM = 6000.0;
  int everySweeps = 1;            ///< match every n-th sweep
  double rejectDistanceM = 60.0;  ///< echoes farther than this from every contour are not the chart's
  double beamWidthDeg = 1.0;
  /// A fix is applied only when the picture pins the ship down: its position sd (along the worst
  /// direction) and heading sd under these. A coast seen end-on leaves a direction unobservable; such a
  /// fix carries little and its linearisation (errors of several degrees) is not to be trusted.
  double maxFixSdM = 30.0;
  double maxFixHeadingSdDeg = 0.5;
  /// Correlation rho of consecutive fixes' errors (the same shore seen sweep after sweep pulls them the
  /// same way). The DRKF takes each fix with its covariance times (1 + rho) / (1 - rho), the long-run
  /// variance of such errors over the short-term one, so frequent fixes do not make it overconfident.
  double errorCorrelation = 0.0;
};

struct Scenario {
  std::string name;
  std::string description;
  geo::GeoPoint origin{49.29, -123.11};
  TimeUs durationUs = 0;
  TimeUs stepUs = kMicrosPerSecond;  ///< filter output cycle
  std::uint64_t seed = 1;
  VesselMotionSpec ownShip;
  est::GaussMarkov current{0.0, 1.0};  ///< ocean current, sigma m/s, beta 1/s
  sensors::GpsSpec gps;
  sensors::LoranSpec loran;
  sensors::SpeedlogSpec speedlog;
  sensors::GyroSpec gyro;
  sensors::RadarSpec radar;
  RadarMatchingSpec radarMatching;
  std::vector<TargetSpec> targets;
  FilterSpec filter;
  TrackerSpec tracker;
  VoyageSpec voyage;  ///< the route, draught and look-ahead (sim/voyage_spec.h)
};

/// Which own-ship sensors are fitted and powered, and the speedlog mode.
struct SensorStates {
  std::array<bool, sensors::kOwnShipSensorCount> on{};  ///< indexed by SensorId
  sensors::SpeedlogMode speedlogMode = sensors::SpeedlogMode::GroundLock;

  [[nodiscard]] bool isOn(sensors::SensorId id) const { return on[static_cast<std::size_t>(id)]; }
  friend bool operator==(const SensorStates&, const SensorStates&) = default;
};

/// The sensor states the scenario's schedules give at time t.
SensorStates sensorStatesAt(const Scenario& s, TimeUs t);

/// Compact label of a sensor set, e.g. "gps+loran_c+speedlog_gl+gyro", or "none".
std::string sensorLabel(const SensorStates& s);

/// Checks the invariants the engine relies on; returns an empty string when valid, else the first
/// problem (field names as in the JSON format).
std::string checkScenario(const Scenario& s);
/// checkScenario, and the run's rows within the output budget (docs/scenarios.md "Limits": a row per
/// step, a row per present target and clutter track per sweep): what a run that keeps or writes every
/// row (the scenario files' reader, runScenario, reckoner-cli) needs. The engine alone streams its
/// frames and does not need it (the soak of docs/robustness.md runs a day of 240 vessels).
std::string checkScenarioForRows(const Scenario& s);

}  // namespace reckoner::sim
