#include "tracking/track_manager.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>

#include "common/angles.h"
#include "estimation/chi_square.h"
#include "geo/grid_index.h"
#include "tracking/assignment.h"

namespace reckoner::track {
namespace tk = est::ttkf;
namespace {

std::uint32_t lowBits(int n) {
  return n >= 32 ? 0xFFFFFFFFu : ((1u << n) - 1u);
}

/// Cartesian covariance of a polar plot offset (range r, bearing b clockwise from north).
est::Mat<2> polarToCartesianCov(double r, double b, double varR, double varB) {
  const double s = std::sin(b), c = std::cos(b);
  est::Mat<2> J;
  J << s, r * c, c, -r * s;
  return J * est::Vec<2>(varR, varB).asDiagonal() * J.transpose();
}

/// d^T C^-1 d and log det C for a 2x2 covariance; nullopt if C is not positive definite.
std::optional<std::pair<double, double>> mahalanobis2(const est::Vec<2>& d, const est::Mat<2>& C) {
  const double det = C(0, 0) * C(1, 1) - C(0, 1) * C(1, 0);
  if (!(C(0, 0) > 0.0) || !(det > 0.0) || !std::isfinite(det)) return std::nullopt;
  const double q = (C(1, 1) * d[0] * d[0] - 2.0 * C(0, 1) * d[0] * d[1] + C(0, 0) * d[1] * d[1]) / det;
  return std::make_pair(q, std::log(det));
}
}  // namespace

const char* trackStatusName(TrackStatus s) {
  switch (s) {
    case TrackStatus::Tentative:
      return "tentative";
    case TrackStatus::Confirmed:
      return "confirmed";
    case TrackStatus::Lost:
      return "lost";
  }
  return "?";
}

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
  }
  return "?";
}

bool AcquisitionZone::contains(double rangeM, double trueBearingRad) const {
  if (rangeM < minRangeM || rangeM > maxRangeM) return false;
  const double span = wrapTwoPi(toBearingRad - fromBearingRad);
  if (span == 0.0) return true;
  return wrapTwoPi(trueBearingRad - fromBearingRad) <= span;
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
    if (!(z.minRangeM >= 0.0) || !(z.maxRangeM > z.minRangeM) || !std::isfinite(z.fromBearingRad) ||
        !std::isfinite(z.toBearingRad))
      return "acquisition zones need 0 <= min range < max range and finite bearings";
  return {};
}

int Track::tag() const {
  const int n = std::min(tagCount, static_cast<int>(recentTags.size()));
  if (n == 0) return -1;
  int best = -1, bestCount = 0;
  // Walk from the most recent so that ties go to the latest.
  for (int k = 0; k < n; ++k) {
    const int idx = (tagCount - 1 - k) % static_cast<int>(recentTags.size());
    const int cand = recentTags[static_cast<std::size_t>(idx)];
    int count = 0;
    for (int m = 0; m < n; ++m) count += recentTags[static_cast<std::size_t>(m)] == cand ? 1 : 0;
    if (count > bestCount) {
      best = cand;
      bestCount = count;
    }
  }
  return best;
}

TrackManager::TrackManager(const TrackManagerConfig& config)
    : config_(config), ctx_(std::make_shared<const TtkfContext>(config.filter)), assocGate_(ctx_->radarGate) {
  if (const std::string problem = config.check(); !problem.empty())
    throw std::invalid_argument("track manager: " + problem);
  inputThreshold_ = est::chiSquareQuantile(1.0 - config.inputEstimationPfa, 2.0);
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

std::vector<TrackEvent> TrackManager::takeEvents() {
  std::vector<TrackEvent> out;
  out.swap(events_);
  return out;
}

tk::Belief TrackManager::beliefAt(const Track& t, TimeUs time) const {
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

bool TrackManager::applyPlot(Track& t, const GridPlot& plot, int tag) {
  const bool ie = t.filter.kind() == TrackerKind::EkfInputEstimation;
  Ttkf::RadarDetail detail;
  t.lastRadar = t.filter.updateRadar(plot, ie ? &detail : nullptr);
  if (!t.lastRadar.applied()) return false;
  if (ie)
    estimateInput(t, *t.filter.ttkf(), plot.timeUs, detail);
  else if (t.filter.kind() == TrackerKind::Imm)
    setManoeuvring(t, t.filter.modelManoeuvring(), plot.timeUs);
  ++t.radarUpdates;
  ++counters_.plotsAssociated;
  t.seenThisSweep = true;
  t.lastPlotUs = plot.timeUs;
  t.lastUpdate = t.filter.belief();
  t.recentTags[static_cast<std::size_t>(t.tagCount % static_cast<int>(t.recentTags.size()))] = tag;
  ++t.tagCount;
  return true;
}

void TrackManager::setManoeuvring(Track& t, bool flag, TimeUs time) {
  if (flag && !t.manoeuvring) event(TrackEvent::Kind::Manoeuvre, time, t.id);
  t.manoeuvring = flag;
}

void TrackManager::estimateInput(Track& t, Ttkf& filter, TimeUs time, const Ttkf::RadarDetail& detail) {
  // Seed 001's input estimation around the TTKF (docs/manoeuvres.md): one window entry per radar
  // update. Between radar updates the own-ship feed also updates the filter; its effect on the
  // target's response to the input is neglected (it conditions the own-ship states).
  const TimeUs dtUs = time - t.lastRadarUs;
  const double dt = toSeconds(dtUs);
  t.lastRadarUs = time;
  if (dtUs <= 0) return;
  InputWindow<tk::kStateDim>::Entry e;
  e.Phi = filter.transition(dtUs);
  e.G.setZero();
  e.G(tk::kTgtX, 0) = e.G(tk::kTgtY, 1) = 0.5 * dt * dt;
  e.G(tk::kTgtVx, 0) = e.G(tk::kTgtVy, 1) = dt;
  e.H = detail.H;
  e.S = t.lastRadar.S;
  e.innovation = t.lastRadar.innovation;
  const Eigen::LDLT<est::Mat<2>> ldlt(e.S);
  e.W = ldlt.solve(e.H * detail.priorP).transpose();
  t.inputWindow.push(e);
  const auto est = t.inputWindow.estimate();
  if (!est.tested) return;
  if (est.d < inputThreshold_) {
    t.manoeuvring = false;
    return;
  }
  if (!filter.correct(est.M * est.u, est.M * est.L * est.M.transpose())) return;
  t.inputWindow.clear();
  setManoeuvring(t, true, time);
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

bool TrackManager::inZones(const GridPlot& plot) const {
  if (config_.zones.empty()) return true;
  const double trueBearing = plot.bearingRad + (lastOwn_ ? lastOwn_->convergenceRad : 0.0);
  for (const auto& z : config_.zones)
    if (z.contains(plot.rangeM, trueBearing)) return true;
  return false;
}

bool TrackManager::onLand(const GridPlot& plot, const OwnShipInput& own) const {
  if (!land_) return false;
  const double dtS = toSeconds(plot.timeUs - own.timeUs);
  const est::Vec<2> at(own.x[0] + own.x[2] * dtS + plot.rangeM * std::sin(plot.bearingRad),
                       own.x[1] + own.x[3] * dtS + plot.rangeM * std::cos(plot.bearingRad));
  return land_->contains(at);
}

std::optional<int> TrackManager::startTrack(const OwnShipInput& own, const GridPlot& plot, int tag,
                                            bool manual) {
  if (active_ >= config_.capacity) {
    ++counters_.plotsRefusedFull;
    if (!fullThisSweep_) event(TrackEvent::Kind::CapacityFull, plot.timeUs, 0);
    fullThisSweep_ = true;
    return std::nullopt;
  }
  std::optional<TrackFilter> filter;
  try {
    switch (config_.kind) {
      case TrackerKind::Ekf:
      case TrackerKind::EkfInputEstimation:
        filter.emplace(config_.kind, Ttkf::initiate(ctx_, own, plot));
        break;
      case TrackerKind::AlphaBetaGamma:
        filter.emplace(AbgTrackFilter(ctx_, config_.abg, own, plot));
        break;
      case TrackerKind::Imm:
        filter.emplace(ImmTrackFilter(ctx_, config_.imm, own, plot));
        break;
    }
  } catch (const std::invalid_argument&) {
    return std::nullopt;  // degenerate geometry (a plot on own ship)
  }
  Track t(nextId_++, std::move(*filter));
  if (config_.kind == TrackerKind::EkfInputEstimation)
    t.inputWindow = InputWindow<tk::kStateDim>(config_.inputEstimationWindow);
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

void TrackManager::associateRound(TrackStatus status, std::vector<char>& taken) {
  const OwnShipInput& own = *lastOwn_;
  const TimeUs tRef = pending_.front().plot.timeUs;
  const std::size_t nPlots = pending_.size();
  const est::Vec<2> ownVel = own.x.segment<2>(2);

  // Plots: offset from own ship, its Cartesian covariance, and a position in a frame moving with own
  // ship's estimated velocity from tRef (for the spatial index).
  std::vector<est::Vec<2>> offset(nPlots), fixed(nPlots);
  std::vector<est::Mat<2>> Rxy(nPlots);
  std::vector<double> dt(nPlots);
  double span = 0.0, maxVarR = 0.0, maxVarB = 0.0;
  for (std::size_t j = 0; j < nPlots; ++j) {
    const GridPlot& p = pending_[j].plot;
    offset[j] = {p.rangeM * std::sin(p.bearingRad), p.rangeM * std::cos(p.bearingRad)};
    Rxy[j] = polarToCartesianCov(p.rangeM, p.bearingRad, p.rangeVarM2, p.bearingVarRad2);
    dt[j] = toSeconds(p.timeUs - tRef);
    fixed[j] = offset[j] + ownVel * dt[j];
    span = std::max(span, dt[j]);
    maxVarR = std::max(maxVarR, p.rangeVarM2);
    maxVarB = std::max(maxVarB, p.bearingVarRad2);
  }

  // Candidate tracks and their relative state (r, v) at tRef.
  struct Candidate {
    std::size_t track;
    est::Vec<4> rel;
    est::Mat<4> P;
    double radius;
    double missCost;
  };
  std::vector<Candidate> cands;
  cands.reserve(tracks_.size());
  const TimeUs minGap = fromSeconds(0.5 * config_.sweepPeriodS);
  static const Eigen::Matrix<double, 4, tk::kStateDim> A = relativeSelector();  // rel = A x
  struct StepCache {
    TimeUs step;
    Eigen::Matrix<double, 4, tk::kStateDim> APhi;
    est::Mat<4> AQAt;
  };
  std::vector<StepCache> steps;
  // The gate radius (for the spatial index) and the cost of a miss of a candidate.
  const auto addCandidate = [&](Candidate& c, double lag) {
    const double range = c.rel.head<2>().norm();
    const double bearing = bearingOf(c.rel[0], c.rel[1]);
    const est::Mat<2> Rt = polarToCartesianCov(range, bearing, maxVarR, maxVarB);
    const est::Mat<2> Crr = c.P.topLeftCorner<2, 2>() + Rt;
    const double lmaxR = 0.5 * (Crr.trace() + std::hypot(Crr(0, 0) - Crr(1, 1), 2.0 * Crr(0, 1)));
    const est::Mat<2> Pvv = c.P.bottomRightCorner<2, 2>();
    const double lmaxV = 0.5 * (Pvv.trace() + std::hypot(Pvv(0, 0) - Pvv(1, 1), 2.0 * Pvv(0, 1)));
    const double speed = (c.rel.tail<2>() + ownVel).norm();
    c.radius = std::sqrt(assocGate_ * lmaxR) + (speed + std::sqrt(assocGate_ * lmaxV)) * (span + lag);
    const auto m = mahalanobis2(est::Vec<2>::Zero(), Crr);
    if (!m || !std::isfinite(c.radius)) return false;
    c.missCost = assocGate_ + m->second;
    return true;
  };
  for (std::size_t i = 0; i < tracks_.size(); ++i) {
    const Track& t = tracks_[i];
    if (t.status != status || pending_.back().plot.timeUs - t.lastPlotUs <= minGap) continue;
    const Ttkf* ttkf = t.filter.ttkf();
    if (!ttkf) {
      // abg and imm: their own prediction to tRef (never behind it: they sit at their last plot and
      // own ship's last input, both before the pending plots).
      const tk::Belief b = t.filter.predicted(tRef);
      Candidate c{i, A * b.x, A * b.P * A.transpose(), 0.0, 0.0};
      c.P = 0.5 * (c.P + c.P.transpose()).eval();
      if (addCandidate(c, 0.0)) cands.push_back(c);
      continue;
    }
    // Only the relative position and velocity at tRef are needed: (A Phi) x and (A Phi) P (A Phi)^T +
    // A Q A^T, with one discretisation per distinct time step (most tracks share the last own-ship
    // time), far cheaper than predicting all 12 states.
    const TimeUs from = ttkf->timeUs();
    const TimeUs step = std::max<TimeUs>(0, tRef - from);
    auto it =
        std::find_if(steps.begin(), steps.end(), [step](const StepCache& sc) { return sc.step == step; });
    if (it == steps.end()) {
      const auto& d = ctx_->discrete(step);
      steps.push_back({step, A.lazyProduct(d.Phi.dense()), A.lazyProduct(d.Q).lazyProduct(A.transpose())});
      it = steps.end() - 1;
    }
    const tk::Belief& b = ttkf->belief();
    const Eigen::Matrix<double, 4, tk::kStateDim> APhiP = it->APhi.lazyProduct(b.P);
    Candidate c{i, it->APhi * b.x, APhiP.lazyProduct(it->APhi.transpose()) + it->AQAt, 0.0, 0.0};
    // The filter may sit later than tRef (a plot just after an own-ship input): carry it back.
    const double lag = toSeconds(from > tRef ? from - tRef : 0);
    c.rel.head<2>() -= c.rel.tail<2>() * lag;
    if (addCandidate(c, lag)) cands.push_back(c);
  }

  GnnProblem problem(cands.size(), nPlots, [&] {
    std::vector<double> miss;
    miss.reserve(cands.size());
    for (const auto& c : cands) miss.push_back(c.missCost);
    return miss;
  }());
  if (!cands.empty()) {
    // Spatial index of the plots: a uniform grid with the median gate radius as its cell.
    std::vector<double> radii;
    radii.reserve(cands.size());
    for (const auto& c : cands) radii.push_back(c.radius);
    std::nth_element(radii.begin(), radii.begin() + static_cast<std::ptrdiff_t>(radii.size() / 2),
                     radii.end());
    const double cell = std::clamp(radii[radii.size() / 2], 50.0, 20000.0);
    std::vector<geo::GridBox> points;
    points.reserve(nPlots);
    for (std::size_t j = 0; j < nPlots; ++j)
      points.push_back({fixed[j][0], fixed[j][1], fixed[j][0], fixed[j][1]});
    const geo::GridIndex grid(cell, points);
    std::vector<std::size_t> near;
    for (std::size_t ci = 0; ci < cands.size(); ++ci) {
      const Candidate& c = cands[ci];
      const Track& t = tracks_[c.track];
      near.clear();
      const double cells = std::ceil(c.radius / cell);
      if ((2 * cells + 1) * (2 * cells + 1) > static_cast<double>(nPlots)) {
        for (std::size_t j = 0; j < nPlots; ++j) near.push_back(j);
      } else {
        const auto n = static_cast<std::int64_t>(cells);
        const auto cx = grid.cellOf(c.rel[0]);
        const auto cy = grid.cellOf(c.rel[1]);
        for (std::int64_t ix = cx - n; ix <= cx + n; ++ix)
          for (std::int64_t iy = cy - n; iy <= cy + n; ++iy)
            for (const std::uint32_t j : grid.cell(ix, iy)) near.push_back(j);
      }
      for (std::size_t j : near) {
        if (taken[j] || pending_[j].plot.timeUs - t.lastPlotUs <= minGap) continue;
        const double d = dt[j];
        const est::Vec<2> pred = c.rel.head<2>() + c.rel.tail<2>() * d;
        const est::Mat<2> Prv = c.P.block<2, 2>(0, 2);
        est::Mat<2> C = c.P.topLeftCorner<2, 2>() + d * (Prv + Prv.transpose()) +
                        d * d * c.P.bottomRightCorner<2, 2>() + Rxy[j];
        const auto m = mahalanobis2(offset[j] - pred, C);
        if (m && m->first <= assocGate_) problem.addPair(ci, j, m->first + m->second);
      }
    }
  }
  const std::vector<int> sol = problem.solve();
  counters_.largestCluster = std::max(counters_.largestCluster, problem.largestCluster());

  // Apply in plot time order; a plot that the exact polar update still rejects is used by nobody.
  std::vector<int> trackOfPlot(nPlots, -1);
  for (std::size_t ci = 0; ci < cands.size(); ++ci)
    if (sol[ci] >= 0) trackOfPlot[static_cast<std::size_t>(sol[ci])] = static_cast<int>(cands[ci].track);
  for (std::size_t j = 0; j < nPlots; ++j) {
    if (trackOfPlot[j] < 0) continue;
    taken[j] = 1;
    applyPlot(tracks_[static_cast<std::size_t>(trackOfPlot[j])], pending_[j].plot, pending_[j].tag);
  }
}

void TrackManager::associatePending() {
  if (pending_.empty()) return;
  std::stable_sort(pending_.begin(), pending_.end(),
                   [](const Pending& a, const Pending& b) { return a.plot.timeUs < b.plot.timeUs; });
  // Confirmed tracks choose first, so a tentative track (often started by clutter next to a target)
  // never takes a plot that an established track can explain.
  std::vector<char> taken(pending_.size(), 0);
  associateRound(TrackStatus::Confirmed, taken);
  associateRound(TrackStatus::Tentative, taken);
  const OwnShipInput& own = *lastOwn_;
  for (std::size_t j = 0; j < pending_.size(); ++j) {
    if (taken[j]) continue;
    const Pending& p = pending_[j];
    const bool land = config_.autoAcquire && onLand(p.plot, own);
    counters_.plotsOnLand += land ? 1 : 0;
    if (config_.autoAcquire && inZones(p.plot) && !land) {
      startTrack(own, p.plot, p.tag, false);
    } else {
      free_.push_back({p.plot, p.tag, own, sweep_});
    }
  }
  pending_.clear();
}

void TrackManager::updateDanger(Track& t, TimeUs now) {
  const bool was = t.dangerous;
  if (t.status != TrackStatus::Confirmed) {
    t.dangerous = false;
    return;
  }
  const Cpa c = kinematicsOf(t.filter.belief(), 0.0).cpa;
  t.dangerous = c.cpaM <= config_.dangerCpaM && c.tcpaS >= 0.0 && c.tcpaS <= config_.dangerTcpaS;
  if (t.dangerous && !was) event(TrackEvent::Kind::Dangerous, now, t.id);
}

void TrackManager::endSweep(TimeUs t) {
  associatePending();
  const int M = config_.confirmHits, N = config_.confirmSweeps;
  const int keepMisses = config_.keepSweeps - config_.keepHits;
  for (auto& tr : tracks_) {
    if (!tr.active()) continue;
    tr.history = (tr.history << 1) | (tr.seenThisSweep ? 1u : 0u);
    tr.seenThisSweep = false;
    ++tr.sweeps;
    if (tr.status == TrackStatus::Tentative) {
      const int hits = std::popcount(tr.history & lowBits(std::min(tr.sweeps, N)));
      if (hits >= M) {
        tr.status = TrackStatus::Confirmed;
        ++counters_.tracksConfirmed;
        event(TrackEvent::Kind::Confirmed, t, tr.id);
      } else if (hits + (N - tr.sweeps) < M) {
        tr.status = TrackStatus::Lost;  // marked for removal below as dropped
        tr.lostUs = -1;
      }
    } else {
      const int window = std::min(tr.sweeps, config_.keepSweeps);
      const int misses = window - std::popcount(tr.history & lowBits(window));
      if (misses > keepMisses) {
        tr.status = TrackStatus::Lost;
        tr.lostUs = t;
        tr.dangerous = false;
        --active_;
        ++counters_.tracksLost;
        event(TrackEvent::Kind::Lost, t, tr.id);
      }
    }
    if (tr.status == TrackStatus::Confirmed) updateDanger(tr, t);
  }
  const TimeUs hold = fromSeconds(config_.lostHoldS);
  std::erase_if(tracks_, [&](const Track& tr) {
    if (tr.status != TrackStatus::Lost) return false;
    if (tr.lostUs < 0) {  // a tentative track that can no longer reach M of N
      --active_;
      ++counters_.tracksDropped;
      event(TrackEvent::Kind::Dropped, t, tr.id);
      return true;
    }
    if (t - tr.lostUs >= hold) {
      event(TrackEvent::Kind::Removed, t, tr.id);
      return true;
    }
    return false;
  });
  ++sweep_;
  std::erase_if(free_, [&](const FreePlot& f) { return f.sweep < sweep_ - 1; });
  if (capacityWarning_ &&
      static_cast<double>(active_) < config_.capacityWarningFraction * static_cast<double>(config_.capacity))
    capacityWarning_ = false;
  fullThisSweep_ = false;
}

std::optional<int> TrackManager::acquire(double xGridM, double yGridM) {
  associatePending();
  std::size_t best = free_.size();
  double bestD = config_.manualAcquireRadiusM;
  for (std::size_t k = 0; k < free_.size(); ++k) {
    const FreePlot& f = free_[k];
    const double dtS = toSeconds(f.plot.timeUs - f.own.timeUs);
    const double x = f.own.x[0] + f.own.x[2] * dtS + f.plot.rangeM * std::sin(f.plot.bearingRad);
    const double y = f.own.x[1] + f.own.x[3] * dtS + f.plot.rangeM * std::cos(f.plot.bearingRad);
    const double d = std::hypot(x - xGridM, y - yGridM);
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
  event(TrackEvent::Kind::Cancelled, now, id);
  tracks_.erase(it);
  return true;
}

void TrackManager::cancelAll() {
  while (!tracks_.empty()) cancel(tracks_.back().id);
}

}  // namespace reckoner::track
