#include "tracking/track_manager.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "estimation/chi_square.h"
#include "estimation/ekf.h"
#include "tracking/data_associator.h"
#include "tracking/sweep_history.h"
#include "tracking/track_predictor.h"

namespace reckoner::track {

const char* trackEventName(TrackEvent::Kind k) {
  using K = TrackEvent::Kind;
  switch (k) {
    case K::Acquired:
      return "acquired";
    case K::Confirmed:
      return "confirmed";
    case K::Lost:
      return "lost";
    case K::Dropped:
      return "dropped";
    case K::Removed:
      return "removed";
    case K::Cancelled:
      return "cancelled";
    case K::Dangerous:
      return "dangerous";
    case K::Manoeuvre:
      return "manoeuvre";
    case K::CapacityWarning:
      return "capacity_warning";
    case K::CapacityFull:
      return "capacity_full";
    case K::FilterReset:
      return "filter_reset";
  }
  return "?";
}

std::string TrackManagerConfig::check() const {
  if (capacity == 0) return "capacity must be positive";
  if (inputEstimationWindow < 1 || inputEstimationWindow > 100)
    return "input estimation window must lie in [1, 100]";
  if (!(inputEstimationPfa > 0.0 && inputEstimationPfa < 1.0))
    return "input estimation false-alarm probability must lie in (0, 1)";
  if (const std::string p = abg.check(); !p.empty()) return "alpha-beta-gamma: " + p;
  if (const std::string p = imm.check(); !p.empty()) return "IMM: " + p;
  if (!(capacityWarningFraction > 0.0 && capacityWarningFraction <= 1.0))
    return "capacity warning fraction must lie in (0, 1]";
  if (confirmSweeps < 1 || confirmSweeps > 32 || confirmHits < 1 || confirmHits > confirmSweeps)
    return "confirmation needs 1 <= M <= N <= 32";
  if (keepSweeps < 1 || keepSweeps > 32 || keepHits < 1 || keepHits > keepSweeps)
    return "track keeping needs 1 <= hits <= sweeps <= 32";
  if (!(lostHoldS >= 0.0) || !(manualAcquireRadiusM > 0.0) || !(sweepPeriodS > 0.0))
    return "lost hold must be >= 0, acquisition radius and sweep period positive";
  if (!(dangerCpaM >= 0.0) || !(dangerTcpaS >= 0.0)) return "danger limits must be >= 0";
  if (association == Association::Nearest && !(filter.gateProbability > 0.0))
    return "nearest-neighbour association needs a gate (gate probability > 0)";
  for (const auto& z : zones)
    if (!validZone(z)) return "acquisition zones need 0 <= min range < max range and finite bearings";
  return {};
}

bool TrackManager::setZones(const std::vector<AcquisitionZone>& zones) {
  if (!std::all_of(zones.begin(), zones.end(), validZone)) return false;
  config_.zones = zones;
  return true;
}

namespace {
TtkfConfig fusedConfig(const TrackManagerConfig& c) {
  TtkfConfig f = c.filter;
  f.process.targetAcceleration = c.fusedTargetAcceleration;
  return f;
}
}  // namespace

TrackManager::TrackManager(const TrackManagerConfig& config)
    : config_(config),
      ctx_(std::make_shared<const TtkfContext>(config.filter)),
      fusedCtx_(std::make_shared<const TtkfContext>(fusedConfig(config))),
      hypothesiser_(ctx_->radarGate, fromSeconds(0.5 * config.sweepPeriodS)),
      filters_{ctx_, config.abg, config.imm},
      confirmation_(config.confirmHits, config.confirmSweeps),
      deleter_(config.keepHits, config.keepSweeps, config.lostHoldS) {
  if (const std::string problem = config.check(); !problem.empty())
    throw std::invalid_argument("track manager: " + problem);
  updater_ = TrackUpdater(est::chiSquareQuantile(1.0 - config.inputEstimationPfa, 2.0));
  tracks_.reserve(std::min<std::size_t>(config.capacity, 4096));
}

std::size_t TrackManager::activeCount() const {
  return active_;
}

const Track* TrackManager::find(int id) const {
  for (const auto& t : tracks_)
    if (t.id == id) return &t;
  return nullptr;
}

est::UpdateReport<4> TrackManager::fuseTargetState(int trackId, TimeUs t, const est::Vec<4>& z,
                                                   const est::Mat<4>& R, double gate, double adaptNis) {
  for (auto& tr : tracks_) {
    if (tr.id != trackId || !tr.active()) continue;
    est::UpdateReport<4> rep = tr.filter.updateTargetState(t, z, R, gate, adaptNis);  // returned: moved
    if (!rep.applied() || !tr.guard.checkCovariance<est::ttkf::kStateDim>(tr.filter.belief().P)) return rep;
    // Broken between radar updates: back to the belief right after the last radar update (judged
    // healthy then), so that the gate can still take the plot the filter restarts on.
    if (Ttkf* f = tr.filter.ttkf();
        f && tr.lastUpdate.x.allFinite() && est::isPositiveDefinite(tr.lastUpdate.P)) {
      Ttkf back(f->context(), tr.lastUpdate, tr.lastPlotUs);
      if (lastOwn_ && lastOwn_->timeUs >= tr.lastPlotUs) back.feedOwnShip(*lastOwn_);
      *f = std::move(back);
    }
    return rep;
  }
  return {};
}

void TrackManager::setFused(int trackId, bool fused) {
  for (auto& tr : tracks_)
    if (tr.id == trackId)
      if (Ttkf* f = tr.filter.ttkf()) {
        f->setContext(fused ? fusedCtx_ : ctx_);
        if (fused) f->restartTargetAcceleration();
      }
}

std::vector<TrackEvent> TrackManager::takeEvents() {
  std::vector<TrackEvent> out;
  out.swap(events_);
  return out;
}

est::ttkf::Belief TrackManager::beliefAt(const Track& t, TimeUs time) const {
  if (t.status == TrackStatus::Lost) return t.lastUpdate;
  return t.filter.predicted(time);
}

void TrackManager::feedOwnShip(const OwnShipInput& own) {
  associatePending();
  lastOwn_ = own;
  for (auto& t : tracks_)
    if (t.active()) t.filter.feedOwnShip(own);
}

void TrackManager::addPlot(const GridPlot& plot, int tag) {
  ++counters_.plots;
  if (!lastOwn_ || plot.timeUs < lastOwn_->timeUs) {
    ++counters_.plotsStale;
    return;
  }
  if (config_.association == Association::Known) {
    associateKnown(plot, tag);
    return;
  }
  pending_.push_back({plot, tag});
}

// The tracker loop, once per sweep: associate (predict, hypothesise and gate, choose, update), start
// tracks on the plots left over, then per track record the sweep, confirm or drop (M of N), lose
// (hits in the last sweeps) and judge the danger; remove what is over.
void TrackManager::endSweep(TimeUs t) {
  associatePending();
  for (auto& tr : tracks_) {
    if (!tr.active()) continue;
    tr.history = recordSweep(tr.history, tr.seenThisSweep);
    tr.seenThisSweep = false;
    ++tr.sweeps;
    if (tr.status == TrackStatus::Tentative)
      judgeTentative(tr, t);
    else if (deleter_.lost(tr.history, tr.sweeps))
      loseTrack(tr, t);
    if (tr.status == TrackStatus::Confirmed) updateDanger(tr, t);
  }
  removeDroppedAndExpired(t);
  ++sweep_;
  std::erase_if(free_, [&](const FreePlot& f) { return f.sweep < sweep_ - 1; });
  updateCapacityWarning();
  fullThisSweep_ = false;
}

void TrackManager::associatePending() {
  if (pending_.empty()) return;
  std::stable_sort(pending_.begin(), pending_.end(),
                   [](const Pending& a, const Pending& b) { return a.plot.timeUs < b.plot.timeUs; });
  std::vector<GridPlot> plots;
  plots.reserve(pending_.size());
  for (const Pending& p : pending_) plots.push_back(p.plot);
  const PlotBatch batch(plots, lastOwn_->x.segment<2>(2));
  // Confirmed tracks choose first, so a tentative track (often started by clutter next to a target)
  // never takes a plot that an established track can explain.
  std::vector<char> taken(pending_.size(), 0);
  associateRound(TrackStatus::Confirmed, batch, taken);
  associateRound(TrackStatus::Tentative, batch, taken);
  initiateFromUnassociated(taken);
  pending_.clear();
}

void TrackManager::associateRound(TrackStatus status, const PlotBatch& batch, std::vector<char>& taken) {
  const std::vector<GatedTrack> gated = predictAndAdmit(status, batch);
  const PlotAssignment chosen = associateNearest(hypothesiser_.hypothesise(gated, batch, taken));
  counters_.largestCluster = std::max(counters_.largestCluster, chosen.largestCluster);
  // Apply in plot time order; a plot that the exact polar update still rejects is used by nobody.
  for (std::size_t j = 0; j < batch.size(); ++j) {
    const int g = chosen.trackOfPlot[j];
    if (g < 0) continue;
    taken[j] = 1;
    applyPlot(tracks_[gated[static_cast<std::size_t>(g)].track], pending_[j].plot, pending_[j].tag);
  }
}

std::vector<GatedTrack> TrackManager::predictAndAdmit(TrackStatus status, const PlotBatch& batch) const {
  RelativePredictor predictor(*ctx_, batch.timeUs.front());
  std::vector<GatedTrack> gated;
  gated.reserve(tracks_.size());
  for (std::size_t i = 0; i < tracks_.size(); ++i) {
    const Track& t = tracks_[i];
    if (t.status != status || !hypothesiser_.mayTake(t.lastPlotUs, batch.timeUs.back())) continue;
    if (auto g = hypothesiser_.admit(i, t.lastPlotUs, predictor.predict(t.filter), batch))
      gated.push_back(*g);
  }
  return gated;
}

void TrackManager::initiateFromUnassociated(const std::vector<char>& taken) {
  const OwnShipInput& own = *lastOwn_;
  for (std::size_t j = 0; j < pending_.size(); ++j) {
    if (taken[j]) continue;
    const Pending& p = pending_[j];
    const bool land = config_.autoAcquire && plotOnLand(land_.get(), p.plot, own);
    counters_.plotsOnLand += land ? 1 : 0;
    const bool heldBack =
        !cancelled_.empty() && cancelled_.holdsBack(plotGridPosition(p.plot, own), p.plot.timeUs);
    if (config_.autoAcquire && inAcquisitionZones(config_.zones, p.plot, own.convergenceRad) && !land &&
        !heldBack) {
      startTrack(own, p.plot, p.tag, false);
    } else {
      free_.push_back({p.plot, p.tag, own, sweep_});
    }
  }
}

void TrackManager::associateKnown(const GridPlot& plot, int tag) {
  if (tag < 0) return;
  for (auto& t : tracks_) {
    if (t.active() && t.recentTags[0] == tag) {
      applyPlot(t, plot, tag);
      return;
    }
  }
  startTrack(*lastOwn_, plot, tag, false);
}

void TrackManager::applyPlot(Track& t, const GridPlot& plot, int tag) {
  const PlotUpdate u = updater_.apply(t, plot, tag);
  if (u.manoeuvreDeclared) event(TrackEvent::Kind::Manoeuvre, plot.timeUs, t.id);
  if (u.applied) ++counters_.plotsAssociated;
  guardAfterPlot(t, plot, tag);
}

void TrackManager::guardAfterPlot(Track& t, const GridPlot& plot, int tag) {
  const est::UpdateReport<2>& r = t.lastRadar;
  if (r.applied() || r.status == est::UpdateStatus::RejectedGate) t.guard.addNis(r.nis, r.dim);
  // The IMM's own (combined) covariance: the 12-state belief it shows derives the acceleration from
  // the turn rate and the velocity, so that one is singular by construction.
  if (const ImmTrackFilter* imm = t.filter.imm())
    t.guard.checkCovariance<est::ct::kStateDim>(imm->filter().combined().P);
  else
    t.guard.checkCovariance<est::ttkf::kStateDim>(t.filter.belief().P);
  if (!t.guard.diverged()) return;
  const est::DivergenceReason why = t.guard.reason();
  if (!restartFilter(t, plot, tag)) return;
  t.guard.reset();
  counters_.filterResets +=
      why == est::DivergenceReason::Covariance ? est::DivergenceCounts{1, 0} : est::DivergenceCounts{0, 1};
  events_.push_back({TrackEvent::Kind::FilterReset, plot.timeUs, t.id, why});
}

bool TrackManager::restartFilter(Track& t, const GridPlot& plot, int tag) {
  // The plot was associated with the track before its update revealed the divergence: the track's
  // newest measurement, and the one its new filter starts on (as a new track starts on its first).
  if (!lastOwn_ || plot.timeUs < lastOwn_->timeUs) return false;
  std::optional<TrackFilter> f = filters_.start(t.filter.kind(), *lastOwn_, plot);
  if (!f) return false;
  t.filter = std::move(*f);
  if (t.filter.kind() == TrackerKind::EkfInputEstimation)
    t.inputWindow = InputWindow<est::ttkf::kStateDim>(config_.inputEstimationWindow);
  t.manoeuvring = false;
  t.lastRadarUs = t.lastPlotUs = plot.timeUs;
  t.seenThisSweep = true;
  t.lastUpdate = t.filter.belief();
  if (!t.lastRadar.applied()) {  // the plot now counts as used
    t.recentTags[static_cast<std::size_t>(t.tagCount % static_cast<int>(t.recentTags.size()))] = tag;
    ++t.tagCount;
    ++t.radarUpdates;
  }
  return true;
}

std::optional<int> TrackManager::startTrack(const OwnShipInput& own, const GridPlot& plot, int tag,
                                            bool manual) {
  if (active_ >= config_.capacity) {
    ++counters_.plotsRefusedFull;
    if (!fullThisSweep_) event(TrackEvent::Kind::CapacityFull, plot.timeUs, 0);
    fullThisSweep_ = true;
    return std::nullopt;
  }
  std::optional<TrackFilter> filter = filters_.start(config_.kind, own, plot);
  if (!filter) return std::nullopt;
  Track t(nextId_++, std::move(*filter));
  t.guard = est::DivergenceGuard(config_.guard);
  if (config_.kind == TrackerKind::EkfInputEstimation)
    t.inputWindow = InputWindow<est::ttkf::kStateDim>(config_.inputEstimationWindow);
  t.lastRadarUs = plot.timeUs;
  t.manual = manual;
  t.initiatedUs = plot.timeUs;
  t.lastPlotUs = plot.timeUs;
  t.seenThisSweep = true;
  t.lastUpdate = t.filter.belief();
  t.recentTags[0] = tag;
  t.tagCount = 1;
  tracks_.push_back(std::move(t));
  ++active_;
  ++counters_.tracksStarted;
  event(TrackEvent::Kind::Acquired, plot.timeUs, tracks_.back().id);
  if (!capacityWarning_ && static_cast<double>(active_) >=
                               config_.capacityWarningFraction * static_cast<double>(config_.capacity)) {
    capacityWarning_ = true;
    event(TrackEvent::Kind::CapacityWarning, plot.timeUs, 0);
  }
  return tracks_.back().id;
}

void TrackManager::judgeTentative(Track& t, TimeUs now) {
  switch (confirmation_.verdict(t.history, t.sweeps)) {
    case MofNConfirmation::Verdict::Confirm:
      t.status = TrackStatus::Confirmed;
      ++counters_.tracksConfirmed;
      event(TrackEvent::Kind::Confirmed, now, t.id);
      break;
    case MofNConfirmation::Verdict::Drop:
      t.status = TrackStatus::Lost;  // marked for removal as dropped (removeDroppedAndExpired)
      t.lostUs = -1;
      break;
    case MofNConfirmation::Verdict::Undecided:
      break;
  }
}

void TrackManager::loseTrack(Track& t, TimeUs now) {
  t.status = TrackStatus::Lost;
  t.lostUs = now;
  t.dangerous = false;
  --active_;
  ++counters_.tracksLost;
  event(TrackEvent::Kind::Lost, now, t.id);
}

void TrackManager::removeDroppedAndExpired(TimeUs now) {
  std::erase_if(tracks_, [&](const Track& tr) {
    if (tr.status != TrackStatus::Lost) return false;
    if (tr.lostUs < 0) {  // a tentative track that can no longer reach M of N
      --active_;
      ++counters_.tracksDropped;
      event(TrackEvent::Kind::Dropped, now, tr.id);
      return true;
    }
    if (deleter_.expired(tr.lostUs, now)) {
      event(TrackEvent::Kind::Removed, now, tr.id);
      return true;
    }
    return false;
  });
}

void TrackManager::updateDanger(Track& t, TimeUs now) {
  const bool was = t.dangerous;
  if (t.status != TrackStatus::Confirmed) {
    t.dangerous = false;
    return;
  }
  const Cpa c = kinematicsOf(t.filter.belief(), 0.0).cpa;
  t.dangerous = withinDangerLimits(c, config_.dangerCpaM, config_.dangerTcpaS);
  if (t.dangerous && !was) event(TrackEvent::Kind::Dangerous, now, t.id);
}

void TrackManager::updateCapacityWarning() {
  if (capacityWarning_ &&
      static_cast<double>(active_) < config_.capacityWarningFraction * static_cast<double>(config_.capacity))
    capacityWarning_ = false;
}

std::optional<int> TrackManager::acquire(double xGridM, double yGridM) {
  associatePending();
  std::size_t best = free_.size();
  double bestD = config_.manualAcquireRadiusM;
  for (std::size_t k = 0; k < free_.size(); ++k) {
    const est::Vec<2> at = plotGridPosition(free_[k].plot, free_[k].own);
    const double d = std::hypot(at[0] - xGridM, at[1] - yGridM);
    if (d <= bestD) {
      bestD = d;
      best = k;
    }
  }
  if (best == free_.size()) return std::nullopt;
  const FreePlot f = free_[best];
  free_.erase(free_.begin() + static_cast<std::ptrdiff_t>(best));
  const auto id = startTrack(f.own, f.plot, f.tag, true);
  if (id && lastOwn_ && lastOwn_->timeUs > f.plot.timeUs) tracks_.back().filter.feedOwnShip(*lastOwn_);
  return id;
}

bool TrackManager::cancel(int id) {
  const auto it = std::find_if(tracks_.begin(), tracks_.end(), [id](const Track& t) { return t.id == id; });
  if (it == tracks_.end()) return false;
  if (it->active()) --active_;
  const TimeUs now = lastOwn_ ? lastOwn_->timeUs : 0;
  if (it->active()) {
    namespace tk = est::ttkf;
    const tk::Belief b = it->filter.belief();
    cancelled_.add({b.x[tk::kTgtX], b.x[tk::kTgtY]}, {b.x[tk::kTgtVx], b.x[tk::kTgtVy]},
                   b.P.block<2, 2>(tk::kTgtX, tk::kTgtX), b.P.block<2, 2>(tk::kTgtVx, tk::kTgtVx), now);
  }
  event(TrackEvent::Kind::Cancelled, now, id);
  tracks_.erase(it);
  return true;
}

void TrackManager::setDangerLimits(double cpaM, double tcpaS) {
  if (!std::isfinite(cpaM) || !std::isfinite(tcpaS) || cpaM < 0.0 || tcpaS < 0.0) return;
  config_.dangerCpaM = cpaM;
  config_.dangerTcpaS = tcpaS;
}

void TrackManager::cancelAll() {
  while (!tracks_.empty()) cancel(tracks_.back().id);
}

}  // namespace reckoner::track
