#include "studies/comparison.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <stdexcept>

#include "common/angles.h"
#include "io/error_line.h"
#include "sim/scenario_run.h"
#include "sim/simulation_engine.h"
#include "tracking/coupled_drttkf.h"
#include "tracking/track_manager.h"

// The studies drive the engine and score its runs: the engine's names unqualified here.
using namespace reckoner::sim;

namespace reckoner::studies {
namespace {
namespace tk = est::ttkf;
using Clock = std::chrono::steady_clock;

double microseconds(Clock::duration d) {
  return std::chrono::duration<double, std::micro>(d).count();
}

struct Sums {
  double pos2 = 0, vel2 = 0, nees = 0;
  long n = 0;
  void add(const est::Vec<4>& err, const est::Mat<4>& P) {
    pos2 += err.head<2>().squaredNorm();
    vel2 += err.tail<2>().squaredNorm();
    nees += est::nees<4>(err, P);
    ++n;
  }
};

struct RunOutcome {
  Sums dec, cpl;
  double decUs = 0, cplUs = 0, seconds = 0;
  double decPropUs = 0, cplPropUs = 0;
  int dim = 0;
};

track::OwnShipInput ownInput(const est::drkf::Belief& b, TimeUs t) {
  return {t, nav::groundStateOf(b), nav::groundCovarianceOf(b), 0.0};
}

/// Own ship's events of one frame, in time order (at equal times: epochs, then sweep ends, then plots).
enum class EventKind { Epoch, SweepEnd, Plot };
struct FrameEvent {
  TimeUs t;
  EventKind kind;
  std::size_t index;  ///< into the frame's updates, sweeps or plots
};

std::vector<FrameEvent> eventsOf(const SimFrame& f) {
  std::vector<FrameEvent> events;
  for (std::size_t i = 0; i < f.updates.size(); ++i)
    events.push_back({f.updates[i].timeUs, EventKind::Epoch, i});
  for (std::size_t i = 0; i < f.sweeps.size(); ++i)
    events.push_back({f.sweeps[i].timeUs, EventKind::SweepEnd, i});
  for (std::size_t i = 0; i < f.plots.size(); ++i) events.push_back({f.plots[i].timeUs, EventKind::Plot, i});
  std::stable_sort(events.begin(), events.end(), [](const FrameEvent& a, const FrameEvent& b) {
    return a.t != b.t ? a.t < b.t : static_cast<int>(a.kind) < static_cast<int>(b.kind);
  });
  return events;
}

track::TrackManagerConfig knownAssociationConfig(const Scenario& s) {
  track::TrackManagerConfig tmc = trackManagerConfigFor(s.tracker, s.radar.sweepPeriodS);
  tmc.association = track::Association::Known;
  return tmc;
}

track::CoupledConfig coupledConfig(const Scenario& s, const nav::DrkfConfig& own) {
  track::CoupledConfig cc;
  cc.own = own;
  cc.targetAcceleration = s.tracker.targetAcceleration;
  cc.gateProbability = s.tracker.gateProbability;
  cc.initialSpeedSdMps = s.tracker.initialSpeedSdMps;
  return cc;
}

/// One run of the comparison: the decoupled filters (the DRKF feeding a bank of TTKFs with known
/// association) and the coupled filter on the same engine's streams, timed and scored against truth.
class ComparisonRun {
 public:
  ComparisonRun(const Scenario& s, std::uint64_t seed)
      : s_(s),
        engine_(s, seed),
        frame_(engine_.frame()),
        ownConfig_(drkfConfigFor(s)),
        dec_(ownConfig_, frame_, engine_.drkf().belief(), 0),
        bank_(knownAssociationConfig(s)),
        cpl_(coupledConfig(s, ownConfig_), frame_, engine_.drkf().belief(), 0) {}

  /// Runs the scenario to its end; with `timePropagation`, also times one covariance propagation.
  RunOutcome run(bool timePropagation) {
    while (!engine_.finished()) {
      const SimFrame f = engine_.step();
      for (const FrameEvent& e : eventsOf(f)) {
        if (e.kind == EventKind::Epoch)
          onEpoch(f, e.t);
        else if (e.kind == EventKind::SweepEnd)
          onSweepEnd(e.t);
        else
          onPlot(f, e.index);
      }
      // Errors at the frame time (an own-ship epoch when step and sensor rates agree).
      if (!f.updates.empty() && f.updates.back().timeUs == f.timeUs) scoreTargets(f);
    }
    out_.seconds = toSeconds(s_.durationUs);
    out_.dim = cpl_.dim();
    if (timePropagation) timeOnePropagation();
    return out_;
  }

 private:
  void onEpoch(const SimFrame& f, TimeUs t) {
    std::vector<sensors::OwnShipSample> samples;
    for (const auto& m : f.measurements)
      if (sensors::timeOf(m) == t) samples.push_back(m);
    auto t0 = Clock::now();
    dec_.update(t, samples);
    bank_.feedOwnShip(ownInput(dec_.belief(), t));
    auto t1 = Clock::now();
    cpl_.updateOwnShip(t, samples);
    auto t2 = Clock::now();
    out_.decUs += microseconds(t1 - t0);
    out_.cplUs += microseconds(t2 - t1);
  }

  void onSweepEnd(TimeUs t) {
    auto t0 = Clock::now();
    bank_.endSweep(t);
    out_.decUs += microseconds(Clock::now() - t0);
  }

  void onPlot(const SimFrame& f, std::size_t index) {
    const auto& p = f.plots[index];
    const int tag = f.plotSources[index];
    firstSeen_.emplace(tag, p.timeUs);
    auto t0 = Clock::now();
    const auto ownD = nav::groundStateOf(dec_.belief());
    bank_.addPlot(track::toGrid(p, frame_.gridInfo({ownD[0], ownD[1]})), tag);
    auto t1 = Clock::now();
    const auto ownC = cpl_.ownShip().x;
    cpl_.updateRadar(tag,
                     track::toGrid(p, frame_.gridInfo({ownC[est::drkf::kPosX], ownC[est::drkf::kPosY]})));
    auto t2 = Clock::now();
    out_.decUs += microseconds(t1 - t0);
    out_.cplUs += microseconds(t2 - t1);
  }

  /// Each target's errors in both filters, from 60 s after its first plot on.
  void scoreTargets(const SimFrame& f) {
    for (std::size_t i = 0; i < s_.targets.size(); ++i) {
      const int tag = s_.targets[i].id;
      const auto seen = firstSeen_.find(tag);
      if (seen == firstSeen_.end() || f.timeUs < seen->second + 60 * kMicrosPerSecond) continue;
      const VesselTruth& tr = f.targets[i];
      const est::Vec<4> truth(tr.position.xM, tr.position.yM, tr.groundVxMps(), tr.groundVyMps());
      for (const auto& t : bank_.tracks()) {
        if (t.tag() != tag || !t.active()) continue;
        const tk::Belief b = bank_.beliefAt(t, f.timeUs);
        out_.dec.add(truth - b.x.segment<4>(tk::kTgtX), b.P.block<4, 4>(tk::kTgtX, tk::kTgtX));
      }
      const int k = cpl_.indexOf(tag);
      if (k >= 0)
        out_.cpl.add(truth - cpl_.target(k).head<4>(), cpl_.targetCovariance(k).topLeftCorner<4, 4>());
    }
  }

  /// One covariance propagation over 1 s: the coupled joint state against the DRKF plus every TTKF.
  void timeOnePropagation() {
    constexpr int reps = 20;
    track::CoupledDrttkf c = cpl_;
    auto t0 = Clock::now();
    for (int r = 1; r <= reps; ++r) c.predictTo(cpl_.timeUs() + r * kMicrosPerSecond);
    out_.cplPropUs = microseconds(Clock::now() - t0) / reps;
    nav::Drkf d = dec_;
    std::vector<track::Ttkf> filters;
    for (const auto& t : bank_.tracks())
      if (const auto* f = t.filter.ttkf()) filters.push_back(*f);
    t0 = Clock::now();
    for (int r = 1; r <= reps; ++r) {
      d.predictTo(dec_.timeUs() + r * kMicrosPerSecond);
      for (auto& f : filters) f.predictTo(dec_.timeUs() + r * kMicrosPerSecond);
    }
    out_.decPropUs = microseconds(Clock::now() - t0) / reps;
  }

  const Scenario& s_;
  SimulationEngine engine_;
  const geo::LocalFrame& frame_;
  nav::DrkfConfig ownConfig_;
  nav::Drkf dec_;
  track::TrackManager bank_;
  track::CoupledDrttkf cpl_;
  RunOutcome out_;
  std::map<int, TimeUs> firstSeen_;
};

RunOutcome runOnce(const Scenario& s, std::uint64_t seed, bool timePropagation) {
  return ComparisonRun(s, seed).run(timePropagation);
}
}  // namespace

Scenario withTargetCount(const Scenario& s, int n) {
  if (s.targets.empty())
    throw std::invalid_argument("compare: scenario " + io::quoted(s.name) + " has no targets");
  Scenario out = s;
  out.targets.clear();
  const int m = static_cast<int>(s.targets.size());
  const int turns = (n + m - 1) / m;
  int nextId = 0;
  for (const auto& t : s.targets) nextId = std::max(nextId, t.id + 1);
  const auto& own = s.ownShip.initialPosition;
  for (int k = 0; k < n; ++k) {
    TargetSpec t = s.targets[static_cast<std::size_t>(k % m)];
    const int turn = k / m;
    if (turn > 0) {
      const double a = 2.0 * kPi * turn / turns, c = std::cos(a), sn = std::sin(a);
      const auto rot = [&](double x, double y) {
        return std::array<double, 2>{c * x + sn * y, -sn * x + c * y};
      };
      const auto p = rot(t.motion.initialPosition.xM - own.xM, t.motion.initialPosition.yM - own.yM);
      t.motion.initialPosition = {own.xM + p[0], own.yM + p[1]};
      t.motion.initialVelocityMps = rot(t.motion.initialVelocityMps[0], t.motion.initialVelocityMps[1]);
      t.motion.initialHeadingRad.reset();
      for (auto& ev : t.motion.schedule)
        if (ev.setVelocityMps) ev.setVelocityMps = rot((*ev.setVelocityMps)[0], (*ev.setVelocityMps)[1]);
      t.id = nextId++;
      t.name += " (copy)";
    }
    out.targets.push_back(t);
  }
  out.tracker.association = track::Association::Known;
  return out;
}

std::vector<ComparisonRow> compareCoupled(const Scenario& s, const std::vector<int>& counts, int runs,
                                          int threads, std::uint64_t seed) {
  if (!s.radar.fitted)
    throw std::invalid_argument("compare: scenario " + io::quoted(s.name) + " has no radar");
  if (runs <= 0 || threads <= 0) throw std::invalid_argument("compare: runs and threads must be positive");
  std::vector<ComparisonRow> rows;
  for (int n : counts) {
    if (n <= 0) throw std::invalid_argument("compare: target counts must be positive");
    const Scenario sn = withTargetCount(s, n);
    if (const std::string problem = checkScenarioForRows(sn); !problem.empty())
      throw std::invalid_argument("scenario " + io::quoted(sn.name) + ": " + problem);
    std::vector<RunOutcome> outs(static_cast<std::size_t>(runs));
    // Run 0 alone, so that its timings are not disturbed by the other threads.
    outs[0] = runOnce(sn, seed, true);
    parallelRuns(runs - 1, threads, [&](int i) {
      outs[static_cast<std::size_t>(i) + 1] = runOnce(sn, seed + static_cast<std::uint64_t>(i + 1), false);
    });
    Sums dec, cpl;
    for (const auto& o : outs) {
      dec.pos2 += o.dec.pos2, dec.vel2 += o.dec.vel2, dec.nees += o.dec.nees, dec.n += o.dec.n;
      cpl.pos2 += o.cpl.pos2, cpl.vel2 += o.cpl.vel2, cpl.nees += o.cpl.nees, cpl.n += o.cpl.n;
    }
    ComparisonRow r;
    r.targets = n;
    r.runs = runs;
    r.coupledDim = outs[0].dim;
    const auto safe = [](double a, long b) { return b > 0 ? a / static_cast<double>(b) : std::nan(""); };
    r.decoupledRmsePositionM = std::sqrt(safe(dec.pos2, dec.n));
    r.coupledRmsePositionM = std::sqrt(safe(cpl.pos2, cpl.n));
    r.decoupledRmseVelocityMps = std::sqrt(safe(dec.vel2, dec.n));
    r.coupledRmseVelocityMps = std::sqrt(safe(cpl.vel2, cpl.n));
    r.decoupledMeanNees = safe(dec.nees, dec.n);
    r.coupledMeanNees = safe(cpl.nees, cpl.n);
    r.decoupledUsPerCycle = outs[0].decUs / outs[0].seconds;
    r.coupledUsPerCycle = outs[0].cplUs / outs[0].seconds;
    r.decoupledPropagationUs = outs[0].decPropUs;
    r.coupledPropagationUs = outs[0].cplPropUs;
    const double N = 11.0 + 6.0 * n;
    r.eq10Ratio = N * N * N / (11.0 * 11.0 * 11.0 + n * 12.0 * 12.0 * 12.0);
    r.eq10SavingPct = (1.0 - 1.0 / r.eq10Ratio) * 100.0;
    rows.push_back(r);
  }
  return rows;
}

}  // namespace reckoner::studies
