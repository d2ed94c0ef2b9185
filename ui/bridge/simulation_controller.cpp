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
  sim_.post(&SimulationWorker::setRate, rate);
}
void SimulationController::stepOnce() {
  sim_.post(&SimulationWorker::stepOnce);
}
void SimulationController::runTo(double tS, double rate) {
  sim_.post(&SimulationWorker::runTo, tS, rate);
}
void SimulationController::orderOwnShip(double trueHeadingRad, double speedMps) {
  sim_.post(&SimulationWorker::orderOwnShip, trueHeadingRad, speedMps);
  emit scenarioEdited();
}
void SimulationController::orderTarget(int targetId, double trueHeadingRad, double speedMps,
                                       double turnRateRadPerS, double accelerationMps2) {
  sim_.post(&SimulationWorker::orderTarget, targetId, trueHeadingRad, speedMps, turnRateRadPerS,
            accelerationMps2);
  emit scenarioEdited();
}
void SimulationController::setSensorPower(sensors::SensorId id, bool on) {
  sim_.post(&SimulationWorker::setSensorPower, id, on);
  emit scenarioEdited();
}
void SimulationController::setSpeedlogMode(sensors::SpeedlogMode mode) {
  sim_.post(&SimulationWorker::setSpeedlogMode, mode);
  emit scenarioEdited();
}
void SimulationController::setRadarPower(bool on) {
  sim_.post(&SimulationWorker::setRadarPower, on);
  emit scenarioEdited();
}
void SimulationController::setCharts(const std::vector<charts::CellPtr>& cells) {
  sim_.post(&SimulationWorker::setCharts, cells);
}
void SimulationController::setRadarMatching(bool on) {
  sim_.post(&SimulationWorker::setRadarMatching, on);
  emit scenarioEdited();
}
void SimulationController::setRadarPicturesWanted(bool on) {
  sim_.post(&SimulationWorker::setRadarPicturesWanted, on);
}
void SimulationController::setTrackerKind(track::TrackerKind kind) {
  sim_.post(&SimulationWorker::setTrackerKind, kind);
  emit scenarioEdited();
}
void SimulationController::addTarget(double xM, double yM, double vxMps, double vyMps) {
  sim_.post(&SimulationWorker::addTarget, xM, yM, vxMps, vyMps);
  emit scenarioEdited();
}
void SimulationController::acquireAt(double xM, double yM) {
  sim_.post(&SimulationWorker::acquireAt, xM, yM);
}
void SimulationController::cancelTrack(int trackId) {
  sim_.post(&SimulationWorker::cancelTrack, trackId);
}
void SimulationController::setAutoAcquire(bool on) {
  sim_.post(&SimulationWorker::setAutoAcquire, on);
}
void SimulationController::setDrLimit(double metres) {
  sim_.post(&SimulationWorker::setDrLimit, metres);
}
void SimulationController::setAcquisitionZones(const std::vector<track::AcquisitionZone>& zones) {
  sim_.post(&SimulationWorker::setAcquisitionZones, zones);
  emit scenarioEdited();
}
void SimulationController::setDiscrepancyLimit(double metres) {
  sim_.post(&SimulationWorker::setDiscrepancyLimit, metres);
}
void SimulationController::setCpaLimits(double cpaM, double tcpaS) {
  sim_.post(&SimulationWorker::setCpaLimits, cpaM, tcpaS);
}
void SimulationController::acknowledgeAlert(alerts::AlertId id) {
  sim_.post(&SimulationWorker::acknowledgeAlert, id);
}
void SimulationController::silenceAlerts() {
  sim_.post(&SimulationWorker::silenceAlerts);
}
void SimulationController::requestScenario() {
  sim_.post(&SimulationWorker::requestScenario);
}

}  // namespace reckoner::ui
