#include "ui/bridge/simulation_controller.h"

namespace reckoner::ui {

SimulationController::SimulationController(QObject* parent) : QObject(parent) {
  qRegisterMetaType<reckoner::ui::LiveFrame>();
  qRegisterMetaType<reckoner::sim::Scenario>();
  SimulationWorker* w = sim_.worker();
  connect(w, &SimulationWorker::frameReady, this, &SimulationController::onFrame, Qt::QueuedConnection);
  connect(
      w, &SimulationWorker::loaded, this,
      [this](const sim::Scenario& s) {
        scenario_ = s;
        emit loaded(s);
      },
      Qt::QueuedConnection);
  connect(w, &SimulationWorker::scenarioSnapshot, this, &SimulationController::scenarioReady,
          Qt::QueuedConnection);
  connect(w, &SimulationWorker::failed, this, &SimulationController::failed, Qt::QueuedConnection);
}

SimulationController::~SimulationController() = default;

void SimulationController::onFrame(const LiveFrame& frame) {
  if (loads_.isCurrent(frame.loadGeneration)) {  // else from the scenario before the last load()
    latest_ = frame;
    emit frameArrived(frame);
  }
  sim_.post(&SimulationWorker::frameConsumed);
}

void SimulationController::load(const sim::Scenario& scenario) {
  latest_ = LiveFrame{};
  sim_.post(&SimulationWorker::load, scenario, loads_.issue());
}
void SimulationController::setRate(double rate) {
  if (live_) return;  // the simulation is not running in Live mode
  sim_.post(&SimulationWorker::setRate, rate);
}
void SimulationController::stepOnce() {
  if (live_) return;  // the simulation is not running in Live mode
  sim_.post(&SimulationWorker::stepOnce);
}
void SimulationController::runTo(double tS, double rate) {
  if (live_) return;  // the simulation is not running in Live mode
  sim_.post(&SimulationWorker::runTo, tS, rate);
}
void SimulationController::orderOwnShip(double trueHeadingRad, double speedMps) {
  if (live_) return;  // the simulation is not running in Live mode
  sim_.post(&SimulationWorker::orderOwnShip, trueHeadingRad, speedMps);
  emit scenarioEdited();
}
void SimulationController::setTrial(bool on, double trueHeadingRad, double speedMps, double delayS) {
  if (live_) return;  // the trial runs on the simulation's frames
  sim_.post(&SimulationWorker::setTrial, on, trueHeadingRad, speedMps, delayS);
}
void SimulationController::orderTarget(int targetId, double trueHeadingRad, double speedMps,
                                       double turnRateRadPerS, double accelerationMps2) {
  if (live_) return;  // the simulation is not running in Live mode
  sim_.post(&SimulationWorker::orderTarget, targetId, trueHeadingRad, speedMps, turnRateRadPerS,
            accelerationMps2);
  emit scenarioEdited();
}
void SimulationController::setSensorPower(sensors::SensorId id, bool on) {
  if (live_) return;  // the simulation is not running in Live mode
  sim_.post(&SimulationWorker::setSensorPower, id, on);
  emit scenarioEdited();
}
void SimulationController::setSpeedlogMode(sensors::SpeedlogMode mode) {
  if (live_) return;  // the simulation is not running in Live mode
  sim_.post(&SimulationWorker::setSpeedlogMode, mode);
  emit scenarioEdited();
}
void SimulationController::setRadarPower(bool on) {
  if (live_) return;  // the simulation is not running in Live mode
  sim_.post(&SimulationWorker::setRadarPower, on);
  emit scenarioEdited();
}
void SimulationController::setCharts(const std::vector<charts::CellPtr>& cells) {
  cells_ = cells;
  sim_.post(&SimulationWorker::setCharts, cells);
  if (liveThread_) live().post(&LiveWorker::setCharts, cells);
}
void SimulationController::setVoyageRoute(const std::optional<geo::Route>& route, bool follow) {
  const bool changed = route != route_ || follow != follow_;
  route_ = route;
  follow_ = follow;
  sim_.post(&SimulationWorker::setVoyageRoute, route, follow);
  if (liveThread_) live().post(&LiveWorker::setRoute, route);
  if (changed) emit scenarioEdited();  // the scenario records its route (a save keeps it)
}
void SimulationController::setSafety(const charts::SafetySettings& safety) {
  safety_ = safety;
  sim_.post(&SimulationWorker::setSafety, safety);
  if (liveThread_) live().post(&LiveWorker::setSafety, safety);
}
void SimulationController::setRadarMatching(bool on) {
  if (live_) return;  // the simulation is not running in Live mode
  sim_.post(&SimulationWorker::setRadarMatching, on);
  emit scenarioEdited();
}
void SimulationController::setRadarPicturesWanted(bool on) {
  sim_.post(&SimulationWorker::setRadarPicturesWanted, on);
}
void SimulationController::setTrackerKind(track::TrackerKind kind) {
  if (live_) return;  // the simulation is not running in Live mode
  sim_.post(&SimulationWorker::setTrackerKind, kind);
  emit scenarioEdited();
}
void SimulationController::addTarget(double xM, double yM, double vxMps, double vyMps) {
  if (live_) return;  // the simulation is not running in Live mode
  sim_.post(&SimulationWorker::addTarget, xM, yM, vxMps, vyMps);
  emit scenarioEdited();
}
void SimulationController::acquireAt(double xM, double yM) {
  if (live_) return;  // the simulation is not running in Live mode
  sim_.post(&SimulationWorker::acquireAt, xM, yM);
}
void SimulationController::cancelTrack(int trackId) {
  if (live_) return;  // the simulation is not running in Live mode
  sim_.post(&SimulationWorker::cancelTrack, trackId);
}
void SimulationController::setAutoAcquire(bool on) {
  if (live_) return;  // the simulation is not running in Live mode
  sim_.post(&SimulationWorker::setAutoAcquire, on);
}
void SimulationController::setDrLimit(double metres) {
  live_ ? live().post(&LiveWorker::setDrLimit, metres) : sim_.post(&SimulationWorker::setDrLimit, metres);
}
void SimulationController::setAcquisitionZones(const std::vector<track::AcquisitionZone>& zones) {
  if (live_) return;  // the simulation is not running in Live mode
  sim_.post(&SimulationWorker::setAcquisitionZones, zones);
  emit scenarioEdited();
}
void SimulationController::setDiscrepancyLimit(double metres) {
  if (live_) return;  // the simulation is not running in Live mode
  sim_.post(&SimulationWorker::setDiscrepancyLimit, metres);
}
void SimulationController::setCpaLimits(double cpaM, double tcpaS) {
  sim_.post(&SimulationWorker::setCpaLimits, cpaM, tcpaS);  // kept for the simulation after Live mode
  if (live_) live().post(&LiveWorker::setCpaLimits, cpaM, tcpaS);
}
void SimulationController::acknowledgeAlert(alerts::AlertId id) {
  live_ ? live().post(&LiveWorker::acknowledgeAlert, id) : sim_.post(&SimulationWorker::acknowledgeAlert, id);
}
void SimulationController::silenceAlerts() {
  live_ ? live().post(&LiveWorker::silenceAlerts) : sim_.post(&SimulationWorker::silenceAlerts);
}

WorkerThread<LiveWorker>& SimulationController::live() {
  if (!liveThread_) {
    liveThread_ = std::make_unique<WorkerThread<LiveWorker>>(QStringLiteral("live"));
    LiveWorker* w = liveThread_->worker();
    connect(w, &LiveWorker::frameReady, this, &SimulationController::onLiveFrame, Qt::QueuedConnection);
    connect(w, &LiveWorker::failed, this, &SimulationController::failed, Qt::QueuedConnection);
    // What the window gave before the live worker existed: its charts, route and safety settings.
    liveThread_->post(&LiveWorker::setCharts, cells_);
    liveThread_->post(&LiveWorker::setRoute, route_);
    if (safety_) liveThread_->post(&LiveWorker::setSafety, *safety_);
  }
  return *liveThread_;
}

void SimulationController::startLive(conn::ConnectionHub* hub, const sim::LiveOptions& options,
                                     const sim::LiveWatchSettings& watch) {
  sim_.post(&SimulationWorker::setRate, 0.0);  // the simulation waits, paused, behind the live run
  live_ = true;
  playback_ = false;
  latest_ = LiveFrame{};
  live().post(&LiveWorker::start, hub, options, watch, loads_.issue());
}

void SimulationController::setLiveRecordPath(const QString& path) {
  live().post(&LiveWorker::setRecordPath, path);
}

void SimulationController::startPlayback(const QString& path) {
  sim_.post(&SimulationWorker::setRate, 0.0);  // the simulation waits, paused, behind the playback
  live_ = true;
  playback_ = true;
  latest_ = LiveFrame{};
  live().post(&LiveWorker::startPlayback, path, loads_.issue());
}

void SimulationController::setPlaybackRate(double rate) {
  if (isPlayback()) live().post(&LiveWorker::setPlaybackRate, rate);
}

void SimulationController::seekPlayback(UtcUs utc) {
  if (isPlayback()) live().post(&LiveWorker::seekPlayback, static_cast<qint64>(utc));
}

void SimulationController::stopLive() {
  if (!live_) return;
  live_ = false;
  playback_ = false;
  live().post(&LiveWorker::stop);
  loads_.issue();  // the live run's frames still queued are dropped
}

void SimulationController::activateAis(quint32 mmsi, bool on) {
  if (live_) live().post(&LiveWorker::activateAis, mmsi, on);
}
void SimulationController::setLiveNmeaOut(const QString& spec) {
  live().post(&LiveWorker::setNmeaOut, spec);
}
void SimulationController::selectAis(quint32 mmsi) {
  if (live_) live().post(&LiveWorker::selectAis, mmsi);
}

void SimulationController::onLiveFrame(const LiveFrame& frame) {
  if (live_ && loads_.isCurrent(frame.loadGeneration)) {
    latest_ = frame;
    emit frameArrived(frame);
  }
  live().post(&LiveWorker::frameConsumed);
}
void SimulationController::requestScenario() {
  sim_.post(&SimulationWorker::requestScenario);
}

}  // namespace reckoner::ui
