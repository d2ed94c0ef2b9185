#include "ui/bridge/simulation_worker.h"

#include <algorithm>
#include <cmath>
#include <exception>

#include "charts/radar/radar_contours.h"
#include "common/angles.h"
#include "sim/run_rows.h"
#include "ui/bridge/frame_samples.h"

namespace reckoner::ui {
namespace {
constexpr qint64 kTickMs = 10;
constexpr qint64 kStepBudgetNs = 8'000'000;        // per tick: the worker stays responsive to commands
constexpr qint64 kMinEmitIntervalNs = 33'000'000;  // <= 30 frames per second
constexpr double kMaxBacklogS = 2.0;               // wall seconds of simulated time the clock may run ahead
constexpr qint64 kRasterIntervalNs = 100'000'000;  // radar pictures rasterised at most 10 times a second
constexpr double kChartRadiusM = 100000.0;         // contours and land taken within this of the origin

// Rows (sim/run_rows.h) as the window's samples: conversions only, every figure is the row's.
RadarFixSample radarFixSampleOf(const sim::RadarFixRow& r) {
  RadarFixSample s;
  s.tS = toSeconds(r.timeUs);
  s.informative = r.informative;
  s.applied = r.applied;
  s.echoes = r.echoes;
  s.used = r.used;
  s.x = r.xM;
  s.y = r.yM;
  s.headingDeg = radToDeg(r.headingRad);
  s.sdX = r.sdXM;
  s.sdY = r.sdYM;
  s.sdHeadingDeg = radToDeg(r.sdHeadingRad);
  s.trueX = r.trueXM;
  s.trueY = r.trueYM;
  s.trueHeadingDeg = radToDeg(r.trueHeadingRad);
  s.nees = r.nees;
  s.rmsResidual = r.rmsResidual;
  s.nis = r.nis;
  s.dim = r.dim;
  return s;
}

}  // namespace

SimulationWorker::SimulationWorker(QObject* parent) : QObject(parent), timer_(new QTimer(this)) {
  timer_->setTimerType(Qt::PreciseTimer);
  timer_->setInterval(static_cast<int>(kTickMs));
  connect(timer_, &QTimer::timeout, this, &SimulationWorker::tick);
  wall_.start();
}

SimulationWorker::~SimulationWorker() = default;

void SimulationWorker::load(const sim::Scenario& scenario, quint64 generation) {
  generation_ = generation;
  stopAtS_.reset();
  try {
    engine_ = std::make_unique<sim::SimulationEngine>(scenario, scenario.seed);
    seed002_ = std::make_unique<studies::Seed002Filters>(engine_->scenario(), engine_->drkf().belief(),
                                                         engine_->frame());
  } catch (const std::exception& e) {
    emit failed(QString::fromStdString(std::string("cannot start the scenario: ") + e.what()));
    return;
  }
  picture_.reset();
  match_.reset();
  lookAhead_.reset();
  pending_ = LiveFrame{};
  applyCharts();
  applyRoute();
  engine_->setRadarPicturesWanted(picturesWanted_);
  rate_ = 0.0;
  timer_->stop();
  targetS_ = 0.0;
  inFlight_ = false;
  folder_.clear();
  rateWindow_.clear();
  drHorizon_ = nav::DeadReckoningHorizon{};
  alerts_ = alerts::AlertManager{};
  sim::AlertFeedSettings feedSettings = sim::alertFeedSettingsFor(engine_->scenario());
  feedSettings.drLimitM = drLimitM_;
  feedSettings.positionDiscrepancyM = discrepancyLimitM_;
  alertFeed_.emplace(feedSettings);
  emit loaded(engine_->scenario());
  // The first frame shows the state at t = 0 + one step, so the picture is never empty.
  stepEngine();
  maybeEmit(true);
}

void SimulationWorker::setRate(double rate) {
  if (!engine_) return;
  if (rate == 0.0 && rate_ == 0.0 && !timer_->isActive()) {
    dirty_ = true;  // already paused: still answer with a frame, so the GUI sees "paused"
    maybeEmit(true);
    return;
  }
  if (rate != 0.0 && engine_->finished()) engine_->extendTo(engine_->timeUs() + 1800 * kMicrosPerSecond);
  rate_ = std::isfinite(rate) ? rate : -1.0;
  targetS_ = toSeconds(engine_->timeUs());
  lastTickNs_ = wall_.nsecsElapsed();
  rateWindow_.clear();
  if (rate_ != 0.0)
    timer_->start();
  else
    timer_->stop();
  dirty_ = true;
  maybeEmit(true);
}

void SimulationWorker::runTo(double tS, double rate) {
  if (!engine_ || !std::isfinite(tS)) return;
  if (tS <= toSeconds(engine_->timeUs())) {
    setRate(0.0);
    return;
  }
  if (fromSeconds(tS) > engine_->scenario().durationUs) engine_->extendTo(fromSeconds(tS));
  stopAtS_ = tS;
  setRate(rate);
}

void SimulationWorker::stepOnce() {
  if (!engine_) return;
  setRate(0.0);
  if (engine_->finished()) engine_->extendTo(engine_->timeUs() + 1800 * kMicrosPerSecond);
  stepEngine();
  maybeEmit(true);
}

void SimulationWorker::frameConsumed() {
  inFlight_ = false;
  if (dirty_ && rate_ == 0.0) maybeEmit(true);
}

void SimulationWorker::tick() {
  if (!engine_) return;
  const qint64 now = wall_.nsecsElapsed();
  const double wallDt = static_cast<double>(now - lastTickNs_) * 1e-9;
  lastTickNs_ = now;
  const double simNow = toSeconds(engine_->timeUs());
  if (rate_ > 0.0) targetS_ = std::min(targetS_ + rate_ * wallDt, simNow + rate_ * kMaxBacklogS);
  while (!engine_->finished() && wall_.nsecsElapsed() - now < kStepBudgetNs &&
         (rate_ < 0.0 || toSeconds(engine_->timeUs()) < targetS_) &&
         !(stopAtS_ && toSeconds(engine_->timeUs()) >= *stopAtS_))
    stepEngine();
  if (stopAtS_ && toSeconds(engine_->timeUs()) >= *stopAtS_) {
    stopAtS_.reset();
    setRate(0.0);
    return;
  }
  rateWindow_.emplace_back(now, toSeconds(engine_->timeUs()));
  while (rateWindow_.size() > 2 && now - rateWindow_.front().first > 1'000'000'000) rateWindow_.pop_front();
  if (engine_->finished()) {
    rate_ = 0.0;
    timer_->stop();
    maybeEmit(true);
    return;
  }
  maybeEmit(false);
}

void SimulationWorker::setTrial(bool on, double trueHeadingRad, double speedMps, double delayS) {
  if (on)
    trial_ = sim::TrialOrder{wrapTwoPi(trueHeadingRad), std::max(0.0, speedMps), std::max(0.0, delayS)};
  else
    trial_.reset();
  dirty_ = true;
  maybeEmit(true);
}

void SimulationWorker::updateTrial() {
  if (!trial_ || !engine_) {
    pending_.trial.reset();
    return;
  }
  const sim::SimFrame& f = pending_.frame;
  const auto& scenario = engine_->scenario();
  sim::TrialSettings settings;
  settings.cpaLimitM = engine_->trackers().config().dangerCpaM;
  settings.tcpaLimitS = engine_->trackers().config().dangerTcpaS;
  pending_.trial = std::make_shared<const sim::TrialResult>(sim::trialManoeuvre(
      f.timeUs, sim::trialOwnShipOf(f, scenario.ownShip, engine_->frame()),
      sim::trialTargetsOf(f, scenario.tracker.aisAssociation.errors, engine_->frame()), *trial_, settings));
}

void SimulationWorker::stepEngine() {
  absorb(engine_->step());
  dirty_ = true;
}

void SimulationWorker::absorb(sim::SimFrame&& f) {
  const auto& scenario = engine_->scenario();
  const geo::LocalFrame& geo = engine_->frame();
  folder_.fold(f, geo, engine_->drkf().config().process, scenario.targets, pending_);
  if (seed002_) {
    seed002_->feed(f);
    pending_.seed002 = std::array<est::Gaussian<4>, 2>{seed002_->ground(studies::OwnShipFilter::Geodetic),
                                                       seed002_->ground(studies::OwnShipFilter::Lsq)};
  }
  if (alertFeed_) {
    alertFeed_->feed(f, alerts_);
    const auto log = alerts_.takeLog();
    pending_.alertLog.insert(pending_.alertLog.end(), log.begin(), log.end());
  }
  // Radar fixes are taken at sweep ends, inside the cycle; the truth they are scored against is the
  // cycle's end, which is the fix's time when the sweep ends on a step (the usual 1 s step and 2 s
  // sweep). Fixes in between are scored against it too: the plot shows them; their NEES is only
  // indicative.
  for (const auto& r : f.radarFixes) {
    if (!r.valid) continue;
    pending_.radarFixes.push_back(radarFixSampleOf(sim::radarFixRow(r, f)));
    pending_.lastRadarFix = pending_.radarFixes.back();
    if (r.echoPoints.empty()) continue;
    auto shown = std::make_shared<RadarMatchShown>();
    shown->tS = toSeconds(r.timeUs);
    shown->raw = r.rawEchoPoints;
    shown->corrected = r.echoPoints;
    shown->chart = r.chartPoints;
    match_ = std::move(shown);
  }
  if (f.radarPicture) picture_ = std::move(f.radarPicture);
  if (f.lookAhead) lookAhead_ = std::make_shared<const sim::GroundingOutlook>(std::move(*f.lookAhead));
  f.lookAhead.reset();
  if (f.grounded) pending_.aground = f.grounded;
  if (!f.aground) pending_.aground.reset();
  if (f.aisTargets) {  // simulated transponders: the same AIS picture as Live mode's
    pending_.aisTargets = f.aisTargets;
    pending_.aisCounts = engine_->ais().table().counts();
    pending_.aisUtc = f.timeUs;
  }
  f.radarFixes.clear();
  f.sweeps.clear();
  pending_.frame = std::move(f);
}

void SimulationWorker::updateDeadReckoning() {
  const sim::SimFrame& f = pending_.frame;
  pending_.positionFixUsed = !f.deadReckoning.active;
  pending_.drLimitM = drLimitM_;
  pending_.drHorizonS =
      drHorizon_.update(f.deadReckoning.active, f.timeUs, engine_->drkf(),
                        sim::deadReckoningAidsFor(engine_->scenario(), f.sensors), drLimitM_);
}

void SimulationWorker::maybeEmit(bool force) {
  if (!engine_ || inFlight_ || !dirty_) return;
  const qint64 now = wall_.nsecsElapsed();
  if (!force && now - lastEmitNs_ < kMinEmitIntervalNs) return;
  updateDeadReckoning();
  updateTrial();
  pending_.sequence = ++sequence_;
  pending_.loadGeneration = generation_;
  pending_.recentPlots.assign(folder_.plots().begin(), folder_.plots().end());
  pending_.rate = rate_;
  pending_.radarOn =
      engine_->scenario().radar.fitted && engine_->scenario().radar.power.at(engine_->timeUs());
  pending_.trackerKind = sim::trackerKindAt(engine_->scenario().tracker, engine_->commandTimeUs());
  pending_.radarMatching = engine_->scenario().radarMatching.active.at(engine_->commandTimeUs());
  pending_.chartContourSegments = coast_ ? static_cast<int>(coast_->segments().size()) : 0;
  pending_.land = landMask_;
  pending_.radarMatch = match_;
  if (!picturesWanted_) {
    pending_.radarRaster.reset();
  } else if (picture_ && (force || now - rasterisedNs_ >= kRasterIntervalNs)) {
    pending_.radarRaster = std::make_shared<const RadarRaster>(
        rasteriseRadarPicture(*picture_->image, picture_->estimatedPose, toSeconds(picture_->timeUs)));
    picture_.reset();
    rasterisedNs_ = now;
  }
  pending_.route = shownRoute_;
  pending_.followingRoute = engine_->scenario().voyage.followRoute;
  pending_.lookAhead = lookAhead_;
  pending_.alerts = alerts_.alerts();
  pending_.alertAudible = alerts_.audible();
  pending_.autoAcquire = engine_->trackers().config().autoAcquire;
  pending_.running = rate_ != 0.0;
  pending_.finished = engine_->finished();
  pending_.durationS = toSeconds(engine_->scenario().durationUs);
  if (rateWindow_.size() >= 2 && rate_ != 0.0) {
    const auto& [n0, s0] = rateWindow_.front();
    const auto& [n1, s1] = rateWindow_.back();
    pending_.achievedRate = n1 > n0 ? (s1 - s0) / (static_cast<double>(n1 - n0) * 1e-9) : 0.0;
  } else {
    pending_.achievedRate = 0.0;
  }
  inFlight_ = true;
  dirty_ = false;
  lastEmitNs_ = now;
  emit frameReady(pending_);
  pending_.clearBatches();
}

void SimulationWorker::orderOwnShip(double trueHeadingRad, double speedMps) {
  if (!engine_) return;
  const auto& p = pending_.frame.truth.position;
  const double gamma = engine_->frame().gridInfo(p).convergenceRad;
  // A helm order takes the ship off track control (as taking the wheel does): the route stays monitored.
  if (engine_->scenario().voyage.followRoute) {
    follow_ = false;
    engine_->setRoute(engine_->scenario().voyage.route, false);
  }
  engine_->orderOwnShip(sim::HelmOrder{wrapTwoPi(trueHeadingRad - gamma), std::max(0.0, speedMps)});
  dirty_ = true;
}

void SimulationWorker::orderTarget(int targetId, double trueHeadingRad, double speedMps,
                                   double turnRateRadPerS, double accelerationMps2) {
  if (!engine_) return;
  const double gamma = engine_->frame().gridInfo(pending_.frame.truth.position).convergenceRad;
  const sim::HelmOrder order{wrapTwoPi(trueHeadingRad - gamma), std::max(0.0, speedMps), turnRateRadPerS,
                             accelerationMps2};
  if (!engine_->orderTarget(targetId, order))
    emit failed(QStringLiteral("target %1 cannot be steered (not in the simulation now)").arg(targetId));
}

void SimulationWorker::setSensorPower(sensors::SensorId id, bool on) {
  if (!engine_) return;
  engine_->setSensorPower(id, on);
  pending_.frame.sensors = sim::sensorStatesAt(engine_->scenario(), engine_->commandTimeUs());
  dirty_ = true;
  maybeEmit(true);
}

void SimulationWorker::setSpeedlogMode(sensors::SpeedlogMode mode) {
  if (!engine_) return;
  engine_->setSpeedlogMode(mode);
  pending_.frame.sensors = sim::sensorStatesAt(engine_->scenario(), engine_->commandTimeUs());
  dirty_ = true;
  maybeEmit(true);
}

void SimulationWorker::setCharts(std::vector<charts::CellPtr> cells) {
  cells_ = std::move(cells);
  guard_.setCells(cells_);
  chartsOrigin_.reset();
  applyCharts();
  dirty_ = true;
  maybeEmit(true);
}

void SimulationWorker::applyCharts() {
  if (!engine_) return;
  const sim::Scenario& s = engine_->scenario();
  if (!chartsOrigin_ || chartsOrigin_->latDeg != s.origin.latDeg ||
      chartsOrigin_->lonDeg != s.origin.lonDeg) {
    coast_.reset();
    landMask_.reset();
    if (!cells_.empty()) {
      try {
        coast_ = std::make_shared<const radar::Coastline>(
            charts::radarContours(cells_, engine_->frame(), {0.0, 0.0}, kChartRadiusM));
        landMask_ = std::make_shared<const radar::LandMask>(
            charts::landMask(cells_, engine_->frame(), {0.0, 0.0}, kChartRadiusM));
      } catch (const std::exception& e) {
        emit failed(QString::fromStdString(std::string("radar contours of the charts: ") + e.what()));
      }
    }
    chartsOrigin_ = s.origin;
  }
  engine_->setCoastline(coast_);
  engine_->setLandMask(landMask_);
  applyGuard();
}

void SimulationWorker::applyGuard() {
  if (!engine_) return;
  try {
    engine_->setChartGuard(guard_.guardFor(engine_->scenario().voyage));
  } catch (const std::exception& e) {
    engine_->setChartGuard(nullptr);
    emit failed(QString::fromStdString(std::string("anti-grounding on the charts: ") + e.what()));
  }
}

void SimulationWorker::applyRoute() {
  if (!engine_) return;
  if (routeSet_) {
    try {
      engine_->setRoute(route_, follow_);
    } catch (const std::exception& e) {
      emit failed(QString::fromStdString(std::string("route: ") + e.what()));
    }
  }
  const auto& r = engine_->scenario().voyage.route;
  shownRoute_ = r ? std::make_shared<const geo::Route>(*r) : nullptr;
}

void SimulationWorker::setVoyageRoute(const std::optional<geo::Route>& route, bool follow) {
  route_ = route;
  follow_ = follow && route.has_value();
  routeSet_ = route.has_value();
  if (!engine_) return;
  if (!route) engine_->setRoute(std::nullopt, false);
  applyRoute();
  dirty_ = true;
  maybeEmit(true);
}

void SimulationWorker::setSafety(const charts::SafetySettings& safety) {
  guard_.setSafety(safety);
  applyGuard();
  dirty_ = true;
  maybeEmit(true);
}

void SimulationWorker::setRadarMatching(bool on) {
  if (!engine_) return;
  engine_->setRadarMatching(on);
  dirty_ = true;
  maybeEmit(true);
}

void SimulationWorker::setRadarPicturesWanted(bool on) {
  picturesWanted_ = on;
  if (engine_) engine_->setRadarPicturesWanted(on);
  if (!on) picture_.reset();
  dirty_ = true;
  maybeEmit(true);
}

void SimulationWorker::setRadarPower(bool on) {
  if (engine_) engine_->setRadarPower(on);
}

void SimulationWorker::setTrackerKind(track::TrackerKind kind) {
  if (!engine_) return;
  engine_->setTrackerKind(kind);
  dirty_ = true;
  maybeEmit(true);
}

void SimulationWorker::addTarget(double xM, double yM, double vxMps, double vyMps) {
  if (!engine_) return;
  sim::TargetSpec t;
  t.id = -1;
  t.motion.initialPosition = {xM, yM};
  t.motion.initialVelocityMps = {vxMps, vyMps};
  if (!engine_->addTarget(t))
    emit failed(QStringLiteral("the target could not be added (position or velocity not finite)"));
}

void SimulationWorker::acquireAt(double xM, double yM) {
  if (engine_ && !engine_->acquireAt({xM, yM}))
    emit failed(QStringLiteral("no radar plot near that point to acquire"));
}

void SimulationWorker::cancelTrack(int trackId) {
  if (engine_) engine_->cancelTrack(trackId);
}

void SimulationWorker::setAutoAcquire(bool on) {
  if (!engine_) return;
  engine_->setAutoAcquire(on);
  dirty_ = true;
  maybeEmit(true);
}

void SimulationWorker::setDrLimit(double metres) {
  if (!(metres > 0.0) || !std::isfinite(metres)) return;
  drLimitM_ = metres;
  if (alertFeed_) {
    sim::AlertFeedSettings s = alertFeed_->settings();
    s.drLimitM = metres;
    alertFeed_->setSettings(s);
  }
  dirty_ = true;
  maybeEmit(true);
}

void SimulationWorker::setAcquisitionZones(const std::vector<track::AcquisitionZone>& zones) {
  if (!engine_ || !engine_->setAcquisitionZones(zones)) return;
  // Shown at once, as the sensor switches are, though the tracker applies them from the next event.
  pending_.frame.zones = *sim::zonesAt(engine_->scenario().tracker, engine_->commandTimeUs()).first;
  dirty_ = true;
  maybeEmit(true);
}

void SimulationWorker::setDiscrepancyLimit(double metres) {
  if (!(metres >= 0.0) || !std::isfinite(metres)) return;
  discrepancyLimitM_ = metres;
  if (alertFeed_) {
    sim::AlertFeedSettings s = alertFeed_->settings();
    s.positionDiscrepancyM = metres;
    alertFeed_->setSettings(s);
  }
  dirty_ = true;
  maybeEmit(true);
}

void SimulationWorker::setCpaLimits(double cpaM, double tcpaS) {
  if (!alertFeed_ || !engine_) return;
  engine_->setDangerLimits(cpaM, tcpaS);  // the tracker's flag and the alert keep one rule
  sim::AlertFeedSettings s = alertFeed_->settings();
  s.cpa.cpaM = cpaM;
  s.cpa.tcpaS = tcpaS;
  try {
    alertFeed_->setSettings(s);
  } catch (const std::exception& e) {
    emit failed(QString::fromStdString(e.what()));
  }
}

void SimulationWorker::acknowledgeAlert(alerts::AlertId id) {
  if (engine_ && alerts_.acknowledge(engine_->timeUs(), id)) alertsChanged();
}

void SimulationWorker::silenceAlerts() {
  if (engine_ && alerts_.silenceAll(engine_->timeUs()) > 0) alertsChanged();
}

void SimulationWorker::alertsChanged() {
  const auto log = alerts_.takeLog();
  pending_.alertLog.insert(pending_.alertLog.end(), log.begin(), log.end());
  dirty_ = true;
  maybeEmit(true);
}

void SimulationWorker::requestScenario() {
  if (engine_) emit scenarioSnapshot(engine_->scenario());
}

}  // namespace reckoner::ui
