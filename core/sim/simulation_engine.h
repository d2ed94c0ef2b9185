#pragma once
// SimulationEngine::step() advances truth, sensors and the DRKF by one output cycle and returns a value
// snapshot (SimFrame). Plain C++: the GUI's worker thread and the headless runs drive it the same way.
#include <array>
#include <deque>
#include <memory>
#include <optional>
#include <vector>

#include "navigation/dead_reckoning_monitor.h"
#include "navigation/dr_horizon.h"
#include "navigation/drkf.h"
#include "radar/coastline.h"
#include "radar/radar_image.h"
#include "sensors/own_ship_simulators.h"
#include "sensors/radar.h"
#include "sim/ais_traffic.h"
#include "sim/scenario.h"
#include "sim/vessel_motion.h"
#include "sim/voyage_watch.h"
#include "tracking/track_manager.h"

namespace reckoner::sim {

/// A track as the ARPA shows it at a time.
struct TrackSnapshot {
  int trackId = 0;
  int targetId = -1;  ///< the true target whose plots it mostly used (-1: clutter or none)
  track::TrackStatus status = track::TrackStatus::Tentative;
  bool dangerous = false;
  bool manual = false;
  bool manoeuvring = false;                           ///< the manoeuvre flag (ekf-ie and imm tracks)
  track::TrackerKind kind = track::TrackerKind::Ekf;  ///< the track's filter
  TimeUs initiatedUs = 0;
  est::ttkf::Belief estimate;  ///< predicted to the snapshot time (lost: at its last plot)
  track::TrackKinematics kinematics;
  int radarUpdates = 0;
  double lastNis = 0.0;       ///< NIS of its last radar update attempt
  std::uint32_t aisMmsi = 0;  ///< the AIS station associated with it (0: none)
};

/// The picture at the end of a radar sweep: every track and the truth at that instant.
struct SweepSnapshot {
  TimeUs timeUs = 0;
  VesselTruth ownTruth;
  std::vector<VesselTruth> targets;  ///< in scenario order
  std::vector<TrackSnapshot> tracks;
};

/// A radar picture matched to the chart and applied to the DRKF (seed 004).
struct RadarFixReport {
  TimeUs timeUs = 0;
  int echoes = 0, used = 0;
  bool valid = false;                            ///< the matching gave a correction
  bool informative = false;                      ///< good enough to apply (RadarMatchingSpec limits)
  est::Vec<3> correction = est::Vec<3>::Zero();  ///< to the estimated position (grid m) and heading (rad)
  est::Mat<3> covariance = est::Mat<3>::Zero();
  est::Vec<2> fixPosition = est::Vec<2>::Zero();  ///< the fix given to the DRKF: position (grid m) ...
  double fixHeadingRad = 0.0;                     ///< ... and heading (grid)
  /// The velocity over ground and turn rate the picture was placed with, and how the fix moves with
  /// an error in them (radar::MatchResult::motionSensitivity): fix = truth + S (true - assumed) + noise.
  est::Vec<3> assumedMotion = est::Vec<3>::Zero();
  est::Mat<3> motionSensitivity = est::Mat<3>::Zero();
  est::UpdateReport<3> update;  ///< the DRKF's update with it
  /// Scoring only (the simulator's record of what lit each echo point's bins, not given to the
  /// matching): echo points from vessels and from clutter and noise, and how many of those it used.
  int vesselEchoes = 0, clutterEchoes = 0, spuriousUsed = 0;
  std::vector<est::Vec<2>> echoPoints, chartPoints;  ///< matched echoes (corrected) and their chart points
  std::vector<est::Vec<2>>
      rawEchoPoints;                   ///< the matched echoes as placed from the estimate (before the fix)
  double rmsNormalizedResidual = 0.0;  ///< of the matched echoes off their contours, in their sd (about 1)
};

/// One sweep's simulated radar picture (seed 004) and the estimated pose the radar draws it from.
struct RadarPicture {
  TimeUs timeUs = 0;  ///< the sweep's end
  std::shared_ptr<const radar::PolarImage> image;
  radar::SweepPose estimatedPose;  ///< own ship through the sweep as the DRKF has it
  double maxRangeM = 0.0;
};

struct SimFrame {
  TimeUs timeUs = 0;
  /// A simulation's frame carries the truth; a live run's (sim/live_session.h) does not: its truth
  /// and trueState then hold the estimate, only so that geometry (the grid convergence at own ship)
  /// has a place; nothing may score or draw them as truth.
  bool hasTruth = true;
  VesselTruth truth;
  est::drkf::State trueState;  ///< truth in the DRKF's coordinates (incl. sensor error states)
  bool shipMotion = false;     ///< trueState's x4, x8 are the ship model's (along-track, turn rate)
  /// Per nav::DrkfBlock: its last window of 60 updates had NIS above the 99% band (est::NisWindow): the
  /// sensor's noise, or the ship's motion, is larger than configured.
  std::array<bool, nav::kDrkfBlockCount> noisierThanConfigured{};
  est::drkf::Belief estimate;
  std::vector<sensors::OwnShipSample> measurements;  ///< taken during this cycle
  std::vector<nav::DrkfUpdateReport> updates;        ///< one per measurement epoch of this cycle
  SensorStates sensors;
  std::optional<HelmOrder> order;            ///< own ship's helm order in force, if any
  std::vector<VesselTruth> targets;          ///< in scenario order
  std::vector<std::uint8_t> targetPresent;   ///< per target: 1 from appear_s until leave_s
  std::vector<sensors::RadarPlot> plots;     ///< radar plots of this cycle
  std::vector<int> plotSources;              ///< target id of each plot (-1: clutter); not given to trackers
  std::vector<TrackSnapshot> tracks;         ///< at timeUs
  std::vector<RadarFixReport> radarFixes;    ///< radar pictures matched to the chart this cycle
  std::optional<RadarPicture> radarPicture;  ///< the latest simulated picture of this cycle, if any
  std::vector<SweepSnapshot> sweeps;         ///< sweeps that ended during this cycle
  std::vector<track::TrackEvent> trackEvents;
  bool capacityWarning = false;
  /// The acquisition (guard) zones in force at timeUs (true bearings from own ship).
  std::vector<track::AcquisitionZone> zones;
  /// Dead reckoning at timeUs: no recent position fix (nav::DeadReckoningMonitor's rule).
  nav::DeadReckoningStatus deadReckoning;
  /// AIS (sim/ais_traffic.h): messages heard this cycle, the target table at timeUs (null: no
  /// transponder in the scenario), the stations associated with tracks and the changes this cycle.
  std::vector<sensors::AisReception> aisReceived;
  std::shared_ptr<const std::vector<track::AisTarget>> aisTargets;
  std::vector<track::AisAssociation> aisAssociations;
  std::vector<track::AisAssociationEvent> aisEvents;
  /// The voyage (sim/voyage_watch.h): own ship against the active route (none: no route), the
  /// anti-grounding look-ahead when one was made this cycle (charts present), the grounding of this
  /// cycle, and whether own ship is aground.
  std::optional<nav::RouteStatus> route;
  std::optional<GroundingOutlook> lookAhead;
  std::optional<Grounding> grounded;
  bool aground = false;
};

/// A track of `bank` as the ARPA shows it at `time` (its belief predicted there; lost: at its last
/// plot), with course and speed true through the grid convergence at own ship.
TrackSnapshot trackSnapshotOf(const track::TrackManager& bank, const track::Track& t, TimeUs time,
                              double convergenceRad);

/// Truth of own ship and a target in the TTKF's coordinates (own acceleration: through the water,
/// exact when there is no current).
est::ttkf::State trueTrackState(const VesselTruth& own, const VesselTruth& target);

class SimulationEngine {
 public:
  /// Throws std::invalid_argument when checkScenario() finds a problem.
  SimulationEngine(const Scenario& scenario, std::uint64_t seed);

  /// Advances one output cycle (scenario.stepUs, the last one shortened to end at the duration).
  SimFrame step();
  [[nodiscard]] bool finished() const { return timeUs_ >= scenario_.durationUs; }
  [[nodiscard]] TimeUs timeUs() const { return timeUs_; }
  [[nodiscard]] const Scenario& scenario() const { return scenario_; }
  [[nodiscard]] const geo::LocalFrame& frame() const { return frame_; }
  [[nodiscard]] const nav::Drkf& drkf() const { return *drkf_; }
  [[nodiscard]] const track::TrackManager& trackers() const { return *manager_; }
  /// Test hooks: the filters themselves, for tests that break a covariance on purpose (the divergence
  /// guards'). Nothing else changes the engine's filters from outside.
  nav::Drkf& drkfForTest() { return *drkf_; }
  track::TrackManager& trackersForTest() { return *manager_; }
  /// The AIS transponders, table and fusion (idle when no target carries a transponder).
  [[nodiscard]] const AisTraffic& ais() const { return *ais_; }
  /// The voyage: route monitoring, the autopilot, the look-ahead and grounding (sim/voyage_watch.h).
  [[nodiscard]] const VoyageWatch& voyage() const { return *voyage_; }
  /// The charts' answers (charts/route/chart_safety.h); null: no look-ahead and no grounding.
  void setChartGuard(std::shared_ptr<const ChartGuard> guard) { voyage_->setChartGuard(std::move(guard)); }
  /// The active route from now on (none: no monitoring), followed by the autopilot when `follow`;
  /// recorded into scenario().voyage. Throws std::invalid_argument for a route with problems.
  void setRoute(const std::optional<geo::Route>& route, bool follow);
  /// When own ship has been dead reckoning so far (evaluated at the end of every step).
  [[nodiscard]] const nav::DeadReckoningMonitor& deadReckoning() const { return deadReckoning_; }

  /// Operator commands, applied between steps. Manual acquisition of the plot nearest to a point.
  std::optional<int> acquireAt(const geo::GridPoint& p) { return manager_->acquire(p.xM, p.yM); }
  bool cancelTrack(int id) { return manager_->cancel(id); }
  void cancelAllTracks() { manager_->cancelAll(); }
  /// Automatic acquisition on or off from now (not recorded into the scenario, like manual acquisition).
  void setAutoAcquire(bool on) { manager_->setAutoAcquire(on); }
  /// The dangerous-target limits from now on (the operator's; not recorded into the scenario).
  void setDangerLimits(double cpaM, double tcpaS) { manager_->setDangerLimits(cpaM, tcpaS); }

  // Operator changes to the scenario itself, effective one microsecond after the current time (the
  // epoch at the current time has been processed). Each is written into scenario() (replacing what
  // the script had planned from then on), so the edited scenario, saved and run again with the same
  // seed, reproduces this run.
  /// A helm order for own ship (grid heading through the water, speed through the water >= 0).
  void orderOwnShip(const HelmOrder& order);
  /// A helm order for a target (its id); false if there is no such target (present now).
  bool orderTarget(int targetId, const HelmOrder& order);
  /// Powers an own-ship sensor on or off (ignored for a sensor that is not fitted).
  void setSensorPower(sensors::SensorId id, bool on);
  void setSpeedlogMode(sensors::SpeedlogMode mode);
  void setRadarPower(bool on);
  /// The filter of tracks started from now on (tracks keep theirs).
  void setTrackerKind(track::TrackerKind kind);
  /// The acquisition (guard) zones from now on (empty: the whole picture); false, changing nothing,
  /// when one is not a ring sector (track::validZone).
  bool setAcquisitionZones(const std::vector<track::AcquisitionZone>& zones);
  /// The chart contours for radar matching (scenario.radarMatching); null: none.
  void setCoastline(std::shared_ptr<const radar::Coastline> coast) { coast_ = std::move(coast); }
  /// Radar matching on or off from now (an operator change, recorded in radarMatching.active).
  void setRadarMatching(bool on);
  /// Simulate a radar picture at every sweep for display (SimFrame::radarPicture), besides those
  /// matched. Display pictures draw their noise from their own stream: the run does not change.
  void setRadarPicturesWanted(bool on) { picturesWanted_ = on; }
  /// Charted land for chart-aided acquisition (TrackManager::setLandMask); null: none.
  void setLandMask(std::shared_ptr<const radar::LandMask> land) { manager_->setLandMask(std::move(land)); }
  /// Adds a target that appears now at its spec's initial position; its id is replaced by a free one
  /// when negative or taken. Returns the id, or nullopt if the spec is invalid.
  std::optional<int> addTarget(TargetSpec target);
  /// Makes the run last at least until t (> now; never shortens it); returns false otherwise.
  bool extendTo(TimeUs t);
  /// The time from which operator changes take effect.
  [[nodiscard]] TimeUs commandTimeUs() const { return timeUs_ + 1; }

 private:
  void applyZonesAt(TimeUs t);
  struct Clock {
    bool fitted = false;
    TimeUs periodUs = 0;
    TimeUs nextUs = 0;
  };
  struct PendingPlot {
    TimeUs timeUs;
    std::size_t target;                      ///< index, or kClutter
    std::optional<sensors::RadarPlot> plot;  ///< clutter: drawn at the sweep start
  };
  static constexpr std::size_t kClutter = static_cast<std::size_t>(-1);
  [[nodiscard]] est::drkf::State trueState() const;
  const geo::GridInfo& truthGrid();
  void ownShipEpoch(TimeUs t, SimFrame& frame);
  void startSweep(TimeUs t, SimFrame& frame);
  void radarPlot(const PendingPlot& p, SimFrame& frame);
  void advanceTargetsTo(TimeUs t);
  void matchRadar(TimeUs t, SimFrame& frame);
  RadarPicture sweepPicture(TimeUs t, std::optional<double> lastHeadingRad, bool matchNow);
  [[nodiscard]] track::OwnShipInput ownShipInput() const;

  Scenario scenario_;
  std::uint64_t seed_;
  geo::LocalFrame frame_;
  VesselMotionModel truth_;
  sensors::GpsSimulator gps_;
  sensors::LoranSimulator loran_;
  sensors::SpeedlogSimulator speedlog_;
  sensors::GyroSimulator gyro_;
  std::array<Clock, sensors::kOwnShipSensorCount> clocks_{};
  std::optional<nav::Drkf> drkf_;
  nav::DrkfNisWindows nis_{};  ///< 60 updates, 99% band
  std::vector<VesselMotionModel> targets_;
  sensors::RadarSimulator radar_;
  std::optional<track::TrackManager> manager_;
  TimeUs nextSweepUs_ = 0;
  int zonesApplied_ = -1;  ///< the zone change in force in the tracker (zonesAt; -1 the initial zones)
  std::deque<PendingPlot> pending_;
  TimeUs timeUs_ = 0;
  TimeUs gridTimeUs_ = -1;
  geo::GridInfo grid_;
  std::shared_ptr<const radar::Coastline> coast_;
  Rng radarImageRng_, radarDisplayRng_;
  bool picturesWanted_ = false;
  long sweepIndex_ = 0;
  std::optional<double> lastSweepHeadingRad_;
  nav::DeadReckoningMonitor deadReckoning_;
  std::optional<AisTraffic> ais_;
  std::unique_ptr<VoyageWatch> voyage_;
};

/// The DRKF configuration a scenario implies (the filter is tuned with the sensors' specifications).
nav::DrkfConfig drkfConfigFor(const Scenario& s);

/// The aids dead reckoning goes on with under the given sensor states (for nav::timeToPositionLimitS):
/// the speedlog and gyro when on, with the scenario's noise, at the slower of their rates.
nav::DeadReckoningAids deadReckoningAidsFor(const Scenario& s, const SensorStates& on);

}  // namespace reckoner::sim
