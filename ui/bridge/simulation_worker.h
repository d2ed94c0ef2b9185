#pragma once
// The simulation in its own thread: a QObject living in a QThread that owns the SimulationEngine (plain
// C++), steps it against the wall clock at the requested rate and sends LiveFrame values to the GUI
// through a queued signal, at most one in flight (the GUI acknowledges each with frameConsumed()) and
// at most ~30 per second; at high rates the steps in between are folded into the frame's history
// batch. Commands arrive as queued calls (SimulationController) and are applied between steps.
#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <deque>
#include <memory>
#include <optional>

#include "alerts/alert_manager.h"
#include "charts/model/chart_model.h"
#include "navigation/dead_reckoning_monitor.h"
#include "radar/land_mask.h"
#include "sim/alert_feed.h"
#include "ui/bridge/frame_samples.h"
#include "ui/bridge/live_frame.h"
#include "ui/bridge/voyage_guard.h"

namespace reckoner::ui {

class SimulationWorker : public QObject {
  Q_OBJECT
 public:
  explicit SimulationWorker(QObject* parent = nullptr);
  ~SimulationWorker() override;

  // Called in the worker's thread (queued from the controller).
  /// Replaces the simulation (paused at t = 0); emits loaded() or failed().
  void load(const sim::Scenario& scenario, quint64 generation);
  /// Simulated seconds per wall second: 0 pauses, a negative value runs as fast as possible.
  void setRate(double rate);
  /// One output step, then paused.
  void stepOnce();
  /// Runs at `rate` until the simulated time reaches tS, then pauses there exactly.
  void runTo(double tS, double rate);
  void frameConsumed();
  /// Helm order: true heading (radians) and speed through the water (m/s).
  void orderOwnShip(double trueHeadingRad, double speedMps);
  /// The trial manoeuvre (docs/trial.md) computed on every frame from now: a true heading and speed
  /// through the water ordered after delayS; off: none. The run itself is untouched.
  void setTrial(bool on, double trueHeadingRad, double speedMps, double delayS);
  /// Helm order for a simulated target: true course, speed, turn rate and acceleration limits.
  void orderTarget(int targetId, double trueHeadingRad, double speedMps, double turnRateRadPerS,
                   double accelerationMps2);
  void setSensorPower(sensors::SensorId id, bool on);
  void setSpeedlogMode(sensors::SpeedlogMode mode);
  void setRadarPower(bool on);
  /// The filter of ARPA tracks started from now on.
  void setTrackerKind(track::TrackerKind kind);
  /// A target appearing now at a grid position with a velocity over ground (grid m/s).
  void addTarget(double xM, double yM, double vxMps, double vyMps);
  void acquireAt(double xM, double yM);
  void cancelTrack(int trackId);
  void setAutoAcquire(bool on);
  /// The 95% position error limit of the dead-reckoning indication and alert, metres.
  void setDrLimit(double metres);
  /// The GPS to Loran-C distance above which POSITION DISCREPANCY holds, metres (0: off).
  void setDiscrepancyLimit(double metres);
  void setAcquisitionZones(const std::vector<track::AcquisitionZone>& zones);
  /// The CPA (m) and TCPA (s) limits of the CPA/TCPA alert from now on.
  void setCpaLimits(double cpaM, double tcpaS);
  /// Operator actions on one alert (docs/alerts.md); applied at the current simulated time.
  void acknowledgeAlert(reckoner::alerts::AlertId id);
  void silenceAlerts();
  /// Emits scenarioSnapshot() with the scenario as edited so far (for saving).
  void requestScenario();
  /// The charts the window shows: their radar contours and land areas (around the scenario's origin)
  /// go to the engine for radar matching and chart-aided acquisition, now and at every load.
  void setCharts(std::vector<charts::CellPtr> cells);
  /// The window's active route for own ship, now and at every load, followed by the autopilot when
  /// `follow` (none: the route ends now, and a loaded scenario's own voyage route stands). A route
  /// with problems is refused (failed()).
  void setVoyageRoute(const std::optional<geo::Route>& route, bool follow);
  /// The safety contour and depth of the anti-grounding look-ahead (the mariner's settings); the
  /// draught, clearance and half-beam are the scenario's voyage's.
  void setSafety(const charts::SafetySettings& safety);
  /// Radar matching on or off from now (an operator change recorded in the scenario).
  void setRadarMatching(bool on);
  /// A radar picture at every sweep for the overlay (rasterised at most every 100 ms of wall time).
  void setRadarPicturesWanted(bool on);

 signals:
  void frameReady(const reckoner::ui::LiveFrame& frame);
  void loaded(const reckoner::sim::Scenario& scenario);
  void scenarioSnapshot(const reckoner::sim::Scenario& scenario);
  void failed(const QString& message);

 private:
  void updateTrial();
  void tick();
  void stepEngine();
  void absorb(sim::SimFrame&& f);
  void maybeEmit(bool force);
  void updateDeadReckoning();
  void applyCharts();
  /// The charts' answers to the voyage (charts::ChartSafety) on the cells and settings now, made
  /// again only when they changed.
  void applyGuard();
  void applyRoute();

  std::unique_ptr<sim::SimulationEngine> engine_;
  std::unique_ptr<studies::Seed002Filters> seed002_;  ///< beside the DRKF, on the same samples (display)
  QTimer* timer_ = nullptr;
  QElapsedTimer wall_;
  qint64 lastTickNs_ = 0;
  qint64 lastEmitNs_ = 0;
  double rate_ = 0.0;
  double targetS_ = 0.0;  // simulated time the clock asks for
  bool inFlight_ = false;
  bool dirty_ = false;
  quint64 sequence_ = 0;
  quint64 generation_ = 0;
  std::optional<double> stopAtS_;
  LiveFrame pending_;
  std::deque<std::pair<qint64, double>> rateWindow_;  // (wall ns, sim s) for the achieved rate
  FrameFolder folder_;
  std::vector<charts::CellPtr> cells_;
  std::shared_ptr<const radar::Coastline> coast_;
  std::shared_ptr<const radar::LandMask> landMask_;
  std::optional<geo::GeoPoint> chartsOrigin_;  // the origin coast_ and land_ were made for
  bool picturesWanted_ = false;
  std::optional<sim::TrialOrder> trial_;
  std::optional<sim::RadarPicture> picture_;  // latest, not yet rasterised
  qint64 rasterisedNs_ = 0;
  std::shared_ptr<const RadarMatchShown> match_;
  double drLimitM_ = 185.2;  // 0.1 NM
  double discrepancyLimitM_ = sim::AlertFeedSettings::kDefaultPositionDiscrepancyM;
  alerts::AlertManager alerts_;
  std::optional<sim::AlertFeed> alertFeed_;
  void alertsChanged();
  nav::DeadReckoningHorizon drHorizon_;
  // The voyage: the window's route (routeSet_: one was given since the last "none"), the charts'
  // answers, and the latest look-ahead (kept between the cycles that
  // compute one).
  bool routeSet_ = false;
  std::optional<geo::Route> route_;
  bool follow_ = false;
  VoyageGuard guard_;
  std::shared_ptr<const geo::Route> shownRoute_;
  std::shared_ptr<const sim::GroundingOutlook> lookAhead_;
};

}  // namespace reckoner::ui
