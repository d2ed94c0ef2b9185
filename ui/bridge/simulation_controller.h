#pragma once
// The GUI side of the simulation: owns the worker's thread (WorkerThread<SimulationWorker>), forwards
// commands as queued calls (the GUI never waits on the worker), keeps the latest LiveFrame and
// acknowledges each one so that at most one is in flight. Latest load wins: frames of a scenario
// replaced since (LatestRequest) are acknowledged and dropped.
#include <QObject>
#include <memory>

#include "ui/bridge/latest_request.h"
#include "ui/bridge/live_worker.h"
#include "ui/bridge/simulation_worker.h"
#include "ui/bridge/worker_thread.h"

namespace reckoner::ui {

class SimulationController : public QObject {
  Q_OBJECT
 public:
  explicit SimulationController(QObject* parent = nullptr);
  ~SimulationController() override;

  void load(const sim::Scenario& scenario);
  void setRate(double rate);  ///< 0 pauses; < 0 as fast as possible
  void stepOnce();
  /// Runs at `rate` (< 0: as fast as possible) until the simulated time tS, then pauses there.
  void runTo(double tS, double rate);
  void orderOwnShip(double trueHeadingRad, double speedMps);
  /// The trial manoeuvre on (true heading, speed through the water, delay) or off (SimulationWorker).
  void setTrial(bool on, double trueHeadingRad, double speedMps, double delayS);
  void orderTarget(int targetId, double trueHeadingRad, double speedMps, double turnRateRadPerS,
                   double accelerationMps2);
  void setSensorPower(sensors::SensorId id, bool on);
  void setSpeedlogMode(sensors::SpeedlogMode mode);
  void setRadarPower(bool on);
  void setTrackerKind(track::TrackerKind kind);
  /// The charts the window shows, for radar matching and chart-aided acquisition (SimulationWorker).
  void setCharts(const std::vector<charts::CellPtr>& cells);
  /// The window's active route (none: no route of the window's), followed by the autopilot when
  /// `follow` (SimulationWorker::setVoyageRoute); in Live mode, monitored on the live estimate.
  void setVoyageRoute(const std::optional<geo::Route>& route, bool follow);
  /// The mariner's safety contour and depth for the anti-grounding look-ahead.
  void setSafety(const charts::SafetySettings& safety);
  void setRadarMatching(bool on);
  void setRadarPicturesWanted(bool on);
  void addTarget(double xM, double yM, double vxMps, double vyMps);
  void acquireAt(double xM, double yM);
  void cancelTrack(int trackId);
  void setAutoAcquire(bool on);
  void setDrLimit(double metres);
  void setDiscrepancyLimit(double metres);
  /// The guard (acquisition) zones from now on, recorded in the scenario (an operator change).
  void setAcquisitionZones(const std::vector<track::AcquisitionZone>& zones);
  void setCpaLimits(double cpaM, double tcpaS);
  /// One alert acknowledged; every audible alert silenced for 30 s (docs/alerts.md).
  void acknowledgeAlert(alerts::AlertId id);
  void silenceAlerts();
  /// Asks for the edited scenario; scenarioReady() answers.
  void requestScenario();

  /// Live mode (docs/gui.md, "Live"): the hub's lines through the live session and watch (LiveWorker,
  /// its own thread, started at the first call) instead of the simulation, which waits paused. The hub
  /// must outlive the run (stopLive() first). Simulation commands are ignored meanwhile; alerts, CPA
  /// and DR limits go to the live run.
  void startLive(conn::ConnectionHub* hub, const sim::LiveOptions& options,
                 const sim::LiveWatchSettings& watch);
  /// Ends Live mode (or a playback); the window loads a scenario again to go back to the simulation.
  void stopLive();
  [[nodiscard]] bool isLive() const { return live_; }
  /// Playback of a voyage record in the live worker (LiveWorker::startPlayback), paused at its start;
  /// commands go to it as in Live mode. stopLive() ends it.
  void startPlayback(const QString& path);
  [[nodiscard]] bool isPlayback() const { return live_ && playback_; }
  void setPlaybackRate(double rate);
  void seekPlayback(UtcUs utc);
  /// Operator activation and selection of an AIS target (Live mode).
  void activateAis(quint32 mmsi, bool on);
  void selectAis(quint32 mmsi);
  /// The voyage record of the live runs started from now on (LiveWorker::setRecordPath); empty: none.
  void setLiveRecordPath(const QString& path);
  /// The live run's NMEA 0183 output (LiveWorker::setNmeaOut); empty: none.
  void setLiveNmeaOut(const QString& spec);

  [[nodiscard]] const LiveFrame& latest() const { return latest_; }
  [[nodiscard]] bool hasFrame() const { return latest_.sequence > 0; }
  /// The scenario as loaded (the worker's copy is edited by commands; requestScenario() gets it).
  [[nodiscard]] const sim::Scenario& scenario() const { return scenario_; }

 signals:
  /// A new frame is stored in latest(); `frame` also carries the history batch of the steps since.
  void frameArrived(const reckoner::ui::LiveFrame& frame);
  void loaded(const reckoner::sim::Scenario& scenario);
  void scenarioReady(const reckoner::sim::Scenario& scenario);
  void failed(const QString& message);
  /// An operator change that the scenario records (helm orders, sensors, targets added, tracker
  /// kind, radar matching): what a save would keep.
  void scenarioEdited();

 private:
  void onFrame(const LiveFrame& frame);
  void onLiveFrame(const LiveFrame& frame);
  WorkerThread<LiveWorker>& live();

  WorkerThread<SimulationWorker> sim_{QStringLiteral("simulation")};
  std::unique_ptr<WorkerThread<LiveWorker>> liveThread_;
  bool live_ = false;
  bool playback_ = false;
  LiveFrame latest_;
  sim::Scenario scenario_;
  LatestRequest loads_;
  // The window's charts, active route and safety settings, for a live worker started later.
  std::vector<charts::CellPtr> cells_;
  std::optional<geo::Route> route_;
  bool follow_ = false;
  std::optional<charts::SafetySettings> safety_;
};

}  // namespace reckoner::ui
