#include "sim/simulation_engine.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "common/angles.h"
#include "estimation/models/drkf_radar_fix.h"
#include "io/error_line.h"
#include "radar/chart_matching.h"
#include "sim/scenario_limits.h"

namespace reckoner::sim {
namespace {
using namespace est::drkf;
using sensors::SensorId;
constexpr TimeUs kNever = std::numeric_limits<TimeUs>::max();

radar::RadarImageParams imageParamsOf(const RadarMatchingSpec& m) {
  radar::RadarImageParams ip;
  ip.azimuths = m.azimuths;
  ip.rangeBins = m.rangeBins;
  ip.maxRangeM = m.maxRangeM;
  ip.beamWidthRad = degToRad(m.beamWidthDeg);
  return ip;
}

TimeUs periodOf(double rateHz) {
  return std::max<TimeUs>(1, fromSeconds(1.0 / rateHz));
}

const Scenario& checked(const Scenario& s) {
  if (const std::string problem = checkScenario(s); !problem.empty())
    throw std::invalid_argument("scenario " + io::quoted(s.name) + ": " + problem);
  return s;
}

}  // namespace

nav::DrkfConfig drkfConfigFor(const Scenario& s) {
  nav::DrkfConfig c;
  c.process.current = s.filter.current.value_or(s.current);
  c.process.acceleration = s.filter.acceleration;
  c.process.loranError = s.loran.error;
  c.process.speedlogError = s.speedlog.error;
  c.process.headingBias = s.gyro.bias;
  c.process.logScale = s.speedlog.scaleError;
  c.process.ship = s.filter.shipMotion;
  c.adaptiveGnssNoise = s.filter.adaptiveGnssNoise;
  c.gateProbability = s.filter.gateProbability;
  c.gateReopenS = s.filter.gateReopenS;
  c.minSpeedMps = s.filter.minSpeedMps;
  return c;
}

nav::DeadReckoningAids deadReckoningAidsFor(const Scenario& s, const SensorStates& on) {
  nav::DeadReckoningAids aids;
  aids.speedlog = on.isOn(SensorId::Speedlog);
  aids.speedlogMode = on.speedlogMode;
  aids.speedlogVarM2PerS2 = s.speedlog.whiteVarM2PerS2;
  aids.gyro = on.isOn(SensorId::Gyro);
  aids.gyroVarRad2 = s.gyro.sdRad * s.gyro.sdRad;
  aids.periodS = 1.0 / std::max(1e-3, std::min(s.speedlog.rateHz, s.gyro.rateHz));
  return aids;
}

est::ttkf::State trueTrackState(const VesselTruth& own, const VesselTruth& target) {
  namespace tk = est::ttkf;
  tk::State x;
  x[tk::kOwnX] = own.position.xM;
  x[tk::kOwnY] = own.position.yM;
  x[tk::kOwnVx] = own.groundVxMps();
  x[tk::kOwnVy] = own.groundVyMps();
  x[tk::kOwnAx] = own.accelXMps2;
  x[tk::kOwnAy] = own.accelYMps2;
  x[tk::kTgtX] = target.position.xM;
  x[tk::kTgtY] = target.position.yM;
  x[tk::kTgtVx] = target.groundVxMps();
  x[tk::kTgtVy] = target.groundVyMps();
  x[tk::kTgtAx] = target.accelXMps2;
  x[tk::kTgtAy] = target.accelYMps2;
  return x;
}

SimulationEngine::SimulationEngine(const Scenario& scenario, std::uint64_t seed)
    : scenario_(checked(scenario)),
      seed_(seed),
      frame_(scenario.origin.latDeg, scenario.origin.lonDeg),
      truth_(scenario.ownShip, scenario.current, Rng(seed, kStreamTruth)),
      gps_(scenario.gps, Rng(seed, kStreamGps)),
      loran_(scenario.loran, Rng(seed, kStreamLoran), 0),
      speedlog_(scenario.speedlog, Rng(seed, kStreamSpeedlog), 0, Rng(seed, kStreamLogScale)),
      gyro_(scenario.gyro, Rng(seed, kStreamGyro), 0, Rng(seed, kStreamGyroBias)),
      radar_(scenario.radar, Rng(seed, kStreamRadar), Rng(seed, kStreamClutter)),
      radarImageRng_(seed, kStreamRadarImage),
      radarDisplayRng_(seed, kStreamRadarDisplay),
      deadReckoning_(
          nav::deadReckoningRule(scenario.radar.sweepPeriodS, scenario.radarMatching.everySweeps)) {
  const std::array<std::pair<bool, double>, sensors::kOwnShipSensorCount> rates{
      {{scenario.gps.fitted, scenario.gps.rateHz},
       {scenario.loran.fitted, scenario.loran.rateHz},
       {scenario.speedlog.fitted, scenario.speedlog.rateHz},
       {scenario.gyro.fitted, scenario.gyro.rateHz}}};
  for (std::size_t i = 0; i < clocks_.size(); ++i) {
    if (!rates[i].first) continue;
    clocks_[i] = {true, periodOf(rates[i].second), periodOf(rates[i].second)};
  }
  // The filter starts from the truth perturbed by a draw from its own initial covariance.
  const nav::DrkfConfig config = drkfConfigFor(scenario);
  Belief initial;
  initial.P = nav::initialCovariance(config.process, scenario.filter.initialPositionSdM,
                                     scenario.filter.initialVelocitySdMps);
  Rng initRng(seed, kStreamFilterInit);
  initial.x = trueState();
  // The calibration states are drawn only when modelled (the paper's draws stay as they were).
  const auto modelled = nav::neesStates(config.process);
  for (int i = 0; i < kStateDim; ++i)
    if (i < kPaperStateDim || modelled[static_cast<std::size_t>(i)])
      initial.x[i] += initRng.normal(0.0, std::sqrt(initial.P(i, i)));
  drkf_.emplace(config, frame_, initial, 0);

  const est::GaussMarkov noCurrent{0.0, 1.0};
  targets_.reserve(scenario.targets.size());
  for (std::size_t i = 0; i < scenario.targets.size(); ++i)
    targets_.emplace_back(scenario.targets[i].motion, noCurrent, Rng(seed, kStreamTargetBase + i),
                          scenario.targets[i].appearUs);
  manager_.emplace(trackManagerConfigFor(scenario.tracker, scenario.radar.sweepPeriodS));
  ais_.emplace(scenario, seed);
  voyage_ = std::make_unique<VoyageWatch>(scenario.voyage);
  nextSweepUs_ = scenario.radar.fitted ? 0 : kNever;
}

void SimulationEngine::setRoute(const std::optional<geo::Route>& route, bool follow) {
  voyage_->setRoute(route, follow);
  scenario_.voyage.route = route;
  scenario_.voyage.followRoute = follow && route.has_value();
}

const geo::GridInfo& SimulationEngine::truthGrid() {
  if (gridTimeUs_ != truth_.state().timeUs) {
    grid_ = frame_.gridInfo(truth_.state().position);
    gridTimeUs_ = truth_.state().timeUs;
  }
  return grid_;
}

State SimulationEngine::trueState() const {
  const VesselTruth& t = truth_.state();
  State x;
  x[kPosX] = t.position.xM;
  x[kCurX] = t.currentXMps;
  x[kVelX] = t.waterVxMps;
  x[kAccX] = t.accelXMps2;
  x[kPosY] = t.position.yM;
  x[kCurY] = t.currentYMps;
  x[kVelY] = t.waterVyMps;
  x[kAccY] = t.accelYMps2;
  x[kLoranX] = loran_.errorXM();
  x[kLoranY] = loran_.errorYM();
  x[kLogBias] = speedlog_.errorMps();
  x[kHeadingBias] = gyro_.biasRad();
  x[kLogScale] = speedlog_.scaleError();
  if (scenario_.filter.shipMotion.enabled) {  // the ship model's x4, x8: along-track and turn rate
    const double vx = t.waterVxMps, vy = t.waterVyMps, v2 = vx * vx + vy * vy;
    const double r = std::sqrt(v2);
    x[kAlongAccel] = r > 0.0 ? (vx * t.accelXMps2 + vy * t.accelYMps2) / r : 0.0;
    x[kTurnRate] = v2 > 0.0 ? (vy * t.accelXMps2 - vx * t.accelYMps2) / v2 : 0.0;
  }
  return x;
}

void SimulationEngine::advanceTargetsTo(TimeUs t) {
  for (std::size_t i = 0; i < targets_.size(); ++i) {
    const auto& leave = scenario_.targets[i].leaveUs;
    if (!leave || t <= *leave) targets_[i].advanceTo(t);  // one gone stays where it left
  }
}

track::OwnShipInput SimulationEngine::ownShipInput() const {
  track::OwnShipInput in{drkf_->timeUs(), nav::groundStateOf(drkf_->belief()),
                         nav::groundCovarianceOf(drkf_->belief()), 0.0};
  in.convergenceRad = frame_.gridInfo({in.x[0], in.x[1]}).convergenceRad;
  return in;
}

TrackSnapshot trackSnapshotOf(const track::TrackManager& bank, const track::Track& t, TimeUs time,
                              double convergenceRad) {
  TrackSnapshot s;
  s.trackId = t.id;
  s.targetId = t.tag();
  s.status = t.status;
  s.dangerous = t.dangerous;
  s.manual = t.manual;
  s.manoeuvring = t.manoeuvring;
  s.kind = t.filter.kind();
  s.initiatedUs = t.initiatedUs;
  s.estimate = bank.beliefAt(t, time);
  s.kinematics = track::kinematicsOf(s.estimate, convergenceRad);
  s.radarUpdates = t.radarUpdates;
  s.lastNis = t.lastRadar.nis;
  return s;
}

void SimulationEngine::ownShipEpoch(TimeUs t, SimFrame& frame) {
  truth_.advanceTo(t);
  loran_.advanceTo(t);
  speedlog_.advanceTo(t);
  gyro_.advanceTo(t);
  const VesselTruth& tr = truth_.state();
  const SensorStates on = sensorStatesAt(scenario_, t);
  const std::size_t first = frame.measurements.size();
  for (std::size_t i = 0; i < clocks_.size(); ++i) {
    if (!clocks_[i].fitted || clocks_[i].nextUs != t) continue;
    clocks_[i].nextUs += clocks_[i].periodUs;
    const auto id = static_cast<SensorId>(i);
    if (!on.isOn(id)) continue;
    switch (id) {
      case SensorId::Gps:
        frame.measurements.emplace_back(
            gps_.measure(t, tr.position, tr.groundVxMps(), tr.groundVyMps(), truthGrid()));
        break;
      case SensorId::LoranC:
        frame.measurements.emplace_back(loran_.measure(t, tr.position));
        break;
      case SensorId::Speedlog:
        frame.measurements.emplace_back(speedlog_.measure(t, std::hypot(tr.groundVxMps(), tr.groundVyMps()),
                                                          std::hypot(tr.waterVxMps, tr.waterVyMps),
                                                          on.speedlogMode, truthGrid()));
        break;
      case SensorId::Gyro:
        frame.measurements.emplace_back(gyro_.measure(t, tr.headingRad, truthGrid()));
        break;
    }
  }
  const auto& m = frame.measurements;
  frame.updates.push_back(drkf_->update(t, std::span(m).subspan(first, m.size() - first)));
  nav::addToNisWindows(frame.updates.back(), nis_);  // online consistency per sensor
  // One DRKF feeds every TTKF (seed 000 figure 3); without a radar there is nothing to feed.
  if (scenario_.radar.fitted) manager_->feedOwnShip(ownShipInput());
}

void SimulationEngine::startSweep(TimeUs t, SimFrame& frame) {
  truth_.advanceTo(t);
  advanceTargetsTo(t);
  if (t > 0) {  // the previous sweep ends here
    manager_->endSweep(t);
    SweepSnapshot snap;
    snap.timeUs = t;
    snap.ownTruth = truth_.state();
    for (const auto& m : targets_) snap.targets.push_back(m.state());
    const double convergence = ownShipInput().convergenceRad;
    for (const auto& tr : manager_->tracks()) {
      snap.tracks.push_back(trackSnapshotOf(*manager_, tr, t, convergence));
      snap.tracks.back().aisMmsi = ais_->fusion().mmsiOfTrack(tr.id);
    }
    frame.sweeps.push_back(std::move(snap));
    matchRadar(t, frame);
  }
  const VesselTruth& own = truth_.state();
  const double gamma = truthGrid().convergenceRad;
  std::vector<PendingPlot> sweep;
  for (std::size_t i = 0; i < targets_.size(); ++i) {
    if (!scenario_.targets[i].presentAt(t)) continue;
    const auto& p = targets_[i].state().position;
    const double trueBearing = bearingOf(p.xM - own.position.xM, p.yM - own.position.yM) + gamma;
    sweep.push_back({radar_.beamTime(t, trueBearing), i, std::nullopt});
  }
  for (const auto& c : radar_.beginSweep(t)) sweep.push_back({c.timeUs, kClutter, c});
  std::stable_sort(sweep.begin(), sweep.end(),
                   [](const auto& a, const auto& b) { return a.timeUs < b.timeUs; });
  pending_.insert(pending_.end(), sweep.begin(), sweep.end());
  nextSweepUs_ = t + fromSeconds(scenario_.radar.sweepPeriodS);
}

void SimulationEngine::radarPlot(const PendingPlot& pp, SimFrame& frame) {
  truth_.advanceTo(pp.timeUs);
  advanceTargetsTo(pp.timeUs);
  if (!scenario_.radar.power.at(pp.timeUs)) return;
  std::optional<sensors::RadarPlot> plot = pp.plot;
  int source = -1;
  if (pp.target != kClutter) {
    if (!scenario_.targets[pp.target].presentAt(pp.timeUs)) return;  // left during the sweep
    const VesselTruth& own = truth_.state();
    const VesselTruth& tgt = targets_[pp.target].state();
    plot = radar_.measure(pp.timeUs, tgt.position.xM - own.position.xM, tgt.position.yM - own.position.yM,
                          truthGrid());
    source = scenario_.targets[pp.target].id;
  }
  if (!plot) return;
  frame.plots.push_back(*plot);
  frame.plotSources.push_back(source);
  // The tracker converts with the convergence at the estimated own-ship position; the source goes
  // along only for scoring (and for association in the paper's Known mode).
  const track::OwnShipInput ownEst = ownShipInput();
  const geo::GridInfo grid = frame_.gridInfo({ownEst.x[0], ownEst.x[1]});
  manager_->addPlot(track::toGrid(*plot, grid), source);
}

SimFrame SimulationEngine::step() {
  SimFrame frame;
  if (finished()) return frame;
  const TimeUs end = std::min(timeUs_ + scenario_.stepUs, scenario_.durationUs);

  // Events in time order; at equal times own-ship epochs first, then sweep starts, then plots.
  while (true) {
    TimeUs tOwn = kNever;
    for (const auto& c : clocks_)
      if (c.fitted) tOwn = std::min(tOwn, c.nextUs);
    const TimeUs tPlot = pending_.empty() ? kNever : pending_.front().timeUs;
    const TimeUs t = std::min({tOwn, nextSweepUs_, tPlot});
    if (t > end) break;
    manager_->setTrackerKind(trackerKindAt(scenario_.tracker, t));
    applyZonesAt(t);
    if (t == tOwn) {
      ownShipEpoch(t, frame);
    } else if (t == nextSweepUs_) {
      startSweep(t, frame);
    } else {
      const PendingPlot p = pending_.front();
      pending_.pop_front();
      radarPlot(p, frame);
    }
  }
  truth_.advanceTo(end);
  advanceTargetsTo(end);
  loran_.advanceTo(end);
  speedlog_.advanceTo(end);
  gyro_.advanceTo(end);
  drkf_->predictTo(end);
  timeUs_ = end;
  voyage_->step(end, *drkf_, truth_, frame_, frame);

  frame.timeUs = end;
  frame.truth = truth_.state();
  frame.trueState = trueState();
  for (std::size_t b = 0; b < nis_.size(); ++b) frame.noisierThanConfigured[b] = nis_[b].lastAbove();
  frame.shipMotion = scenario_.filter.shipMotion.enabled;
  frame.estimate = drkf_->belief();
  frame.sensors = sensorStatesAt(scenario_, end);
  frame.order = truth_.order();
  for (std::size_t i = 0; i < targets_.size(); ++i) {
    frame.targets.push_back(targets_[i].state());
    frame.targetPresent.push_back(scenario_.targets[i].presentAt(end) ? 1 : 0);
  }
  if (!ais_->idle()) {
    AisCycle c = ais_->step(end, targets_, frame.targetPresent, frame_, *manager_, ownShipInput());
    frame.aisReceived = std::move(c.received);
    frame.aisTargets = std::move(c.targets);
    frame.aisAssociations = std::move(c.associations);
    frame.aisEvents = std::move(c.events);
  }
  if (!manager_->tracks().empty()) {
    const double convergence = ownShipInput().convergenceRad;
    for (const auto& t : manager_->tracks()) {
      frame.tracks.push_back(trackSnapshotOf(*manager_, t, end, convergence));
      frame.tracks.back().aisMmsi = ais_->fusion().mmsiOfTrack(t.id);
    }
  }
  frame.trackEvents = manager_->takeEvents();
  frame.capacityWarning = manager_->capacityWarning();
  frame.zones = manager_->zones();
  for (const auto& u : frame.updates) deadReckoning_.addEpoch(u);
  for (const auto& r : frame.radarFixes)
    if (r.valid && r.update.applied()) deadReckoning_.addRadarFix(r.timeUs);
  frame.deadReckoning = deadReckoning_.evaluate(end);
  return frame;
}

void SimulationEngine::orderOwnShip(const HelmOrder& order) {
  KinematicEvent e;
  e.timeUs = commandTimeUs();
  e.order = order;
  e.order->headingRad = wrapTwoPi(order.headingRad);
  e.order->speedMps = std::clamp(order.speedMps, 0.0, limits::kMaxSpeedMps);  // what a saved file may hold
  if (!std::isfinite(e.order->headingRad) || !std::isfinite(e.order->speedMps)) return;
  if (!truth_.overrideFrom(e)) return;
  auto& events = scenario_.ownShip.schedule;
  while (!events.empty() && events.back().timeUs >= e.timeUs) events.pop_back();
  events.push_back(e);
}

bool SimulationEngine::orderTarget(int targetId, const HelmOrder& order) {
  KinematicEvent e;
  e.timeUs = commandTimeUs();
  e.order = order;
  e.order->headingRad = wrapTwoPi(order.headingRad);
  e.order->speedMps = std::clamp(order.speedMps, 0.0, limits::kMaxSpeedMps);
  if (!std::isfinite(e.order->headingRad) || !std::isfinite(e.order->speedMps)) return false;
  for (std::size_t i = 0; i < scenario_.targets.size(); ++i) {
    TargetSpec& t = scenario_.targets[i];
    if (t.id != targetId || !t.presentAt(timeUs_)) continue;
    if (!targets_[i].overrideFrom(e)) return false;
    auto& events = t.motion.schedule;
    while (!events.empty() && events.back().timeUs >= e.timeUs) events.pop_back();
    events.push_back(e);
    return true;
  }
  return false;
}

void SimulationEngine::setSensorPower(SensorId id, bool on) {
  const TimeUs t = commandTimeUs();
  switch (id) {
    case SensorId::Gps:
      if (scenario_.gps.fitted) scenario_.gps.power.overrideFrom(t, on);
      break;
    case SensorId::LoranC:
      if (scenario_.loran.fitted) scenario_.loran.power.overrideFrom(t, on);
      break;
    case SensorId::Speedlog:
      if (scenario_.speedlog.fitted) scenario_.speedlog.power.overrideFrom(t, on);
      break;
    case SensorId::Gyro:
      if (scenario_.gyro.fitted) scenario_.gyro.power.overrideFrom(t, on);
      break;
  }
}

void SimulationEngine::setSpeedlogMode(sensors::SpeedlogMode mode) {
  if (scenario_.speedlog.fitted) scenario_.speedlog.mode.overrideFrom(commandTimeUs(), mode);
}

RadarPicture SimulationEngine::sweepPicture(TimeUs t, std::optional<double> lastHeadingRad, bool matchNow) {
  // The picture of the sweep that ends at t, simulated from the true motion.
  const RadarMatchingSpec& m = scenario_.radarMatching;
  const double T = scenario_.radar.sweepPeriodS;
  const VesselTruth& tr = truth_.state();
  static const radar::Coastline kNoCoast{std::vector<radar::CoastSegment>{}};
  const radar::Coastline& coast = coast_ ? *coast_ : kNoCoast;
  radar::SweepPose truePose;
  truePose.startUs = t - fromSeconds(T);
  truePose.periodS = T;
  truePose.velocity = {tr.groundVxMps(), tr.groundVyMps()};
  truePose.turnRateRadPerS = lastHeadingRad ? angleDiff(tr.headingRad, *lastHeadingRad) / T : 0.0;
  truePose.position = est::Vec<2>(tr.position.xM, tr.position.yM) - truePose.velocity * T;
  truePose.headingRad = tr.headingRad - truePose.turnRateRadPerS * T;
  std::vector<radar::RadarTarget> targets;
  for (std::size_t i = 0; i < targets_.size(); ++i) {
    if (!scenario_.targets[i].presentAt(t)) continue;
    const auto& p = targets_[i].state().position;
    targets.push_back({est::Vec<2>(p.xM, p.yM), 25.0});
  }
  const radar::RadarImageParams ip = imageParamsOf(m);
  const auto image = std::make_shared<const radar::PolarImage>(
      radar::simulateRadarImage(coast, targets, truePose, ip, matchNow ? radarImageRng_ : radarDisplayRng_));
  // The estimated pose over the same sweep: the DRKF's position, velocity over ground and heading
  // (the direction of the velocity through the water) at t, turning as below.
  const auto& x = drkf_->belief().x;
  const est::Vec<2> estPos(x[est::drkf::kPosX], x[est::drkf::kPosY]);
  const est::Vec<3> motion = est::drkf::sweepMotionOf(x, scenario_.filter.shipMotion.enabled);
  radar::SweepPose estPose;
  estPose.startUs = truePose.startUs;
  estPose.periodS = T;
  estPose.velocity = motion.head<2>();
  estPose.position = estPos - estPose.velocity * T;
  // The heading turns during the sweep as the estimated acceleration turns the velocity through the
  // water: d/dt atan2(vx, vy) = (vy ax - vx ay) / |v|^2. Without it a fix taken in a turn would carry
  // the sweep's mean heading, half a sweep old (1 deg at 1 deg/s and 2 s).
  const double vx = x[est::drkf::kVelX], vy = x[est::drkf::kVelY];
  estPose.turnRateRadPerS = std::hypot(vx, vy) > 0.5 ? motion[2] : 0.0;
  estPose.headingRad = bearingOf(vx, vy) - estPose.turnRateRadPerS * T;
  return RadarPicture{t, image, estPose, ip.maxRangeM};
}

void SimulationEngine::matchRadar(TimeUs t, SimFrame& frame) {
  // Seed 004 (docs/radar_matching.md): the picture of the sweep that ends at t, matched to the chart
  // from the DRKF's estimate and applied to it as a fix at t.
  const RadarMatchingSpec& m = scenario_.radarMatching;
  const std::optional<double> lastHeading = lastSweepHeadingRad_;
  lastSweepHeadingRad_ = truth_.state().headingRad;
  if (!scenario_.radar.power.at(t)) return;
  const bool matchNow = m.active.at(t) && coast_ && !coast_->empty() && ++sweepIndex_ % m.everySweeps == 0;
  if (!matchNow && !picturesWanted_) return;
  frame.radarPicture = sweepPicture(t, lastHeading, matchNow);
  if (!matchNow) return;
  const radar::PolarImage& image = *frame.radarPicture->image;
  const radar::SweepPose& estPose = frame.radarPicture->estimatedPose;
  const est::Vec<2> estPos(drkf_->belief().x[est::drkf::kPosX], drkf_->belief().x[est::drkf::kPosY]);
  const double T = scenario_.radar.sweepPeriodS;
  const radar::RadarImageParams ip = imageParamsOf(m);
  const std::vector<radar::EchoPoint> echoes = radar::extractEchoes(image, ip.azStepRad(), {});
  radar::MatchParams mp;
  mp.rejectDistanceM = m.rejectDistanceM;
  // An echo point's error: the sensor's, plus the picture's own resolution (a range bin; half the
  // beam width, over which the half-power rule places a shore that is not square to the beam).
  mp.rangeSdM = std::hypot(ip.rangeSdM, ip.binM());
  mp.bearingSdRad = std::hypot(ip.bearingSdRad, 0.5 * ip.beamWidthRad);
  const radar::MatchResult r = radar::matchEchoes(echoes, estPose, *coast_, mp);
  RadarFixReport rep;
  // Where each echo point came from (the simulator's record of what lit its bins), for scoring.
  for (std::size_t i = 0; i < echoes.size(); ++i) {
    const bool vessel = echoes[i].source == radar::BinSource::Target;
    const bool noise = echoes[i].source == radar::BinSource::Noise;
    rep.vesselEchoes += vessel ? 1 : 0;
    rep.clutterEchoes += noise ? 1 : 0;
    if ((vessel || noise) && i < r.usedMask.size() && r.usedMask[i]) ++rep.spuriousUsed;
  }
  rep.timeUs = t;
  rep.echoes = r.echoes;
  rep.used = r.used;
  rep.valid = r.valid;
  const est::Mat<2> Pp = r.covariance.topLeftCorner<2, 2>();
  const double worstPositionVar = 0.5 * (Pp.trace() + std::hypot(Pp(0, 0) - Pp(1, 1), 2.0 * Pp(0, 1)));
  rep.informative = r.valid && worstPositionVar <= m.maxFixSdM * m.maxFixSdM &&
                    r.covariance(2, 2) <= std::pow(degToRad(m.maxFixHeadingSdDeg), 2);
  if (r.valid) {
    rep.correction = r.correction;
    rep.covariance = r.covariance;
    const est::Vec<3> z(estPos[0] + r.correction[0], estPos[1] + r.correction[1],
                        wrapTwoPi(estPose.headingAt(T) + r.correction[2]));
    rep.fixPosition = z.head<2>();
    rep.fixHeadingRad = z[2];
    // The fix moves with the velocity and turn rate the picture was placed with (drkf_radar_fix.h).
    rep.assumedMotion = est::Vec<3>(estPose.velocity[0], estPose.velocity[1], estPose.turnRateRadPerS);
    rep.motionSensitivity = r.motionSensitivity;
    // Errors persisting from sweep to sweep: the long-run variance (radar_matching.error_correlation).
    const double rho = m.errorCorrelation;
    if (rep.informative)
      rep.update = drkf_->updateRadarFix(t, z, r.covariance * ((1.0 + rho) / (1.0 - rho)),
                                         r.motionSensitivity, rep.assumedMotion);
    rep.echoPoints = r.echoPoints;
    rep.rawEchoPoints = r.rawEchoPoints;
    rep.rmsNormalizedResidual = r.rmsNormalizedResidual;
    rep.chartPoints = r.chartPoints;
  }
  frame.radarFixes.push_back(std::move(rep));
}

void SimulationEngine::setTrackerKind(track::TrackerKind kind) {
  auto& changes = scenario_.tracker.kindChanges;
  const TimeUs t = commandTimeUs();
  while (!changes.empty() && changes.back().first >= t) changes.pop_back();
  changes.emplace_back(t, kind);
}

void SimulationEngine::applyZonesAt(TimeUs t) {
  const auto [zones, change] = zonesAt(scenario_.tracker, t);
  if (change == zonesApplied_) return;
  manager_->setZones(*zones);
  zonesApplied_ = change;
}

bool SimulationEngine::setAcquisitionZones(const std::vector<track::AcquisitionZone>& zones) {
  if (!std::all_of(zones.begin(), zones.end(), track::validZone)) return false;
  auto& changes = scenario_.tracker.zoneChanges;
  const TimeUs t = commandTimeUs();
  while (!changes.empty() && changes.back().first >= t) changes.pop_back();
  changes.emplace_back(t, zones);
  zonesApplied_ = -2;  // the next event applies whatever is in force then
  return true;
}

void SimulationEngine::setRadarMatching(bool on) {
  scenario_.radarMatching.active.overrideFrom(commandTimeUs(), on);
}

void SimulationEngine::setRadarPower(bool on) {
  if (scenario_.radar.fitted) scenario_.radar.power.overrideFrom(commandTimeUs(), on);
}

std::optional<int> SimulationEngine::addTarget(TargetSpec target) {
  const auto taken = [this](int id) {
    return std::any_of(scenario_.targets.begin(), scenario_.targets.end(),
                       [id](const TargetSpec& t) { return t.id == id; });
  };
  if (target.id < 0 || taken(target.id)) {
    target.id = 1;
    for (const auto& t : scenario_.targets) target.id = std::max(target.id, t.id + 1);
  }
  if (target.name.empty()) target.name = "target " + std::to_string(target.id);
  target.appearUs = commandTimeUs();
  const auto& m = target.motion;
  // The scenario's own limits (scenario_limits.h), so that a saved scenario reads back.
  const auto inside = [](double v, const limits::Range& r) {
    return std::isfinite(v) && v >= r.lo && v <= r.hi;
  };
  if (!inside(m.initialPosition.xM, limits::kPositionM) ||
      !inside(m.initialPosition.yM, limits::kPositionM) ||
      !inside(std::hypot(m.initialVelocityMps[0], m.initialVelocityMps[1]), limits::kSpeedMps) ||
      !m.schedule.empty() || (target.ais && !target.ais->check().empty()))
    return std::nullopt;
  if (target.ais)
    for (const auto& t : scenario_.targets)
      if (t.ais && t.ais->mmsi == target.ais->mmsi) return std::nullopt;
  const std::size_t index = scenario_.targets.size();
  targets_.emplace_back(m, est::GaussMarkov{0.0, 1.0}, Rng(seed_, kStreamTargetBase + index),
                        target.appearUs);
  scenario_.targets.push_back(std::move(target));
  ais_->addTarget(index, scenario_.targets.back(), timeUs_);
  return scenario_.targets.back().id;
}

bool SimulationEngine::extendTo(TimeUs t) {
  if (t <= timeUs_ || toSeconds(t) > limits::kMaxDurationS) return false;
  scenario_.durationUs = std::max(scenario_.durationUs, t);
  return true;
}

}  // namespace reckoner::sim
