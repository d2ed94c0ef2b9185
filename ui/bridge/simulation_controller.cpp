#include "ui/bridge/simulation_controller.h"

#include <QMetaObject>

namespace reckoner::ui {

SimulationController::SimulationController(QObject* parent) : QObject(parent) {
  qRegisterMetaType<reckoner::ui::LiveFrame>();
  qRegisterMetaType<reckoner::sim::Scenario>();
  worker_ = new SimulationWorker;
  worker_->moveToThread(&thread_);
  connect(&thread_, &QThread::finished, worker_, &QObject::deleteLater);
  connect(worker_, &SimulationWorker::frameReady, this, &SimulationController::onFrame, Qt::QueuedConnection);
  connect(
      worker_, &SimulationWorker::loaded, this,
      [this](const sim::Scenario& s) {
        scenario_ = s;
        emit loaded(s);
      },
      Qt::QueuedConnection);
  connect(worker_, &SimulationWorker::scenarioSnapshot, this, &SimulationController::scenarioReady,
          Qt::QueuedConnection);
  connect(worker_, &SimulationWorker::failed, this, &SimulationController::failed, Qt::QueuedConnection);
  thread_.setObjectName(QStringLiteral("simulation"));
  thread_.start();
}

SimulationController::~SimulationController() {
  thread_.quit();
  thread_.wait();
}

template <class F>
void SimulationController::post(F&& f) {
  QMetaObject::invokeMethod(worker_, std::forward<F>(f), Qt::QueuedConnection);
}

void SimulationController::onFrame(const LiveFrame& frame) {
  if (frame.loadGeneration != generation_) {  // from the scenario before the last load()
    post([w = worker_] { w->frameConsumed(); });
    return;
  }
  latest_ = frame;
  emit frameArrived(frame);
  post([w = worker_] { w->frameConsumed(); });
}

void SimulationController::load(const sim::Scenario& scenario) {
  latest_ = LiveFrame{};
  post([w = worker_, scenario, g = ++generation_] { w->load(scenario, g); });
}
void SimulationController::setRate(double rate) {
  post([w = worker_, rate] { w->setRate(rate); });
}
void SimulationController::stepOnce() {
  post([w = worker_] { w->stepOnce(); });
}
void SimulationController::runTo(double tS, double rate) {
  post([w = worker_, tS, rate] { w->runTo(tS, rate); });
}
void SimulationController::orderOwnShip(double trueHeadingRad, double speedMps) {
  post([w = worker_, trueHeadingRad, speedMps] { w->orderOwnShip(trueHeadingRad, speedMps); });
}
void SimulationController::orderTarget(int targetId, double trueHeadingRad, double speedMps,
                                       double turnRateRadPerS, double accelerationMps2) {
  post([w = worker_, targetId, trueHeadingRad, speedMps, turnRateRadPerS, accelerationMps2] {
    w->orderTarget(targetId, trueHeadingRad, speedMps, turnRateRadPerS, accelerationMps2);
  });
}
void SimulationController::setSensorPower(sensors::SensorId id, bool on) {
  post([w = worker_, id, on] { w->setSensorPower(id, on); });
}
void SimulationController::setSpeedlogMode(sensors::SpeedlogMode mode) {
  post([w = worker_, mode] { w->setSpeedlogMode(mode); });
}
void SimulationController::setRadarPower(bool on) {
  post([w = worker_, on] { w->setRadarPower(on); });
}
void SimulationController::setCharts(const std::vector<charts::CellPtr>& cells) {
  post([w = worker_, cells] { w->setCharts(cells); });
}
void SimulationController::setRadarMatching(bool on) {
  post([w = worker_, on] { w->setRadarMatching(on); });
}
void SimulationController::setRadarPicturesWanted(bool on) {
  post([w = worker_, on] { w->setRadarPicturesWanted(on); });
}
void SimulationController::setTrackerKind(track::TrackerKind kind) {
  post([w = worker_, kind] { w->setTrackerKind(kind); });
}
void SimulationController::addTarget(double xM, double yM, double vxMps, double vyMps) {
  post([w = worker_, xM, yM, vxMps, vyMps] { w->addTarget(xM, yM, vxMps, vyMps); });
}
void SimulationController::acquireAt(double xM, double yM) {
  post([w = worker_, xM, yM] { w->acquireAt(xM, yM); });
}
void SimulationController::cancelTrack(int trackId) {
  post([w = worker_, trackId] { w->cancelTrack(trackId); });
}
void SimulationController::setDrLimit(double metres) {
  post([w = worker_, metres] { w->setDrLimit(metres); });
}
void SimulationController::requestScenario() {
  post([w = worker_] { w->requestScenario(); });
}

}  // namespace reckoner::ui
