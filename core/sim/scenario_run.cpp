#include "sim/scenario_run.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <stdexcept>
#include <thread>

#include "common/angles.h"
#include "common/units.h"
#include "io/error_line.h"

namespace reckoner::sim {

double OwnShipRow::positionErrorM() const {
  return std::hypot(estXM - trueXM, estYM - trueYM);
}
double OwnShipRow::velocityErrorMps() const {
  return std::hypot(estVxMps - trueVxMps, estVyMps - trueVyMps);
}
double OwnShipRow::sdPositionM() const {
  return std::hypot(sdXM, sdYM);
}
bool OwnShipRow::positionWithin(double k) const {
  return std::abs(estXM - trueXM) <= k * sdXM && std::abs(estYM - trueYM) <= k * sdYM;
}

GroundEstimate groundEstimateOf(const est::drkf::Belief& b, const geo::LocalFrame& geo) {
  const est::Vec<4> g = nav::groundStateOf(b);
  const est::Mat<4> C = nav::groundCovarianceOf(b);
  const geo::GeoPoint ll = geo.toGeodetic({g[0], g[1]});
  return {g[0],
          g[1],
          g[2],
          g[3],
          std::sqrt(C(0, 0)),
          std::sqrt(C(1, 1)),
          std::sqrt(C(2, 2)),
          std::sqrt(C(3, 3)),
          ll.latDeg,
          ll.lonDeg};
}

TrackRow trackEstimateRow(TimeUs t, int trackId, int targetId, track::TrackStatus status, bool dangerous,
                          const est::ttkf::Belief& b, const track::TrackKinematics& k, double nis,
                          const geo::LocalFrame& geo) {
  namespace tk = est::ttkf;
  constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
  TrackRow r;
  r.timeUs = t;
  r.trackId = trackId;
  r.targetId = targetId;
  r.status = status;
  r.dangerous = dangerous;
  r.estXM = b.x[tk::kTgtX];
  r.estYM = b.x[tk::kTgtY];
  r.estVxMps = b.x[tk::kTgtVx];
  r.estVyMps = b.x[tk::kTgtVy];
  r.sdXM = std::sqrt(b.P(tk::kTgtX, tk::kTgtX));
  r.sdYM = std::sqrt(b.P(tk::kTgtY, tk::kTgtY));
  r.sdVxMps = std::sqrt(b.P(tk::kTgtVx, tk::kTgtVx));
  r.sdVyMps = std::sqrt(b.P(tk::kTgtVy, tk::kTgtVy));
  const geo::GeoPoint ll = geo.toGeodetic({r.estXM, r.estYM});
  r.estLatDeg = ll.latDeg;
  r.estLonDeg = ll.lonDeg;
  r.courseDeg = radToDeg(k.trueCourseRad);
  r.speedKn = mpsToKnots(k.speedMps);
  r.cpaNm = k.cpa.defined ? metresToNm(k.cpa.cpaM) : kNan;
  r.tcpaMin = k.cpa.defined ? k.cpa.tcpaS / 60.0 : kNan;
  r.nis = nis;
  r.nees = kNan;
  return r;
}

OwnShipRow groundRow(const SimFrame& f, const est::Gaussian<4>& g, const geo::LocalFrame& geo) {
  OwnShipRow r;
  r.timeUs = f.timeUs;
  r.trueXM = f.truth.position.xM;
  r.trueYM = f.truth.position.yM;
  r.trueVxMps = f.truth.groundVxMps();
  r.trueVyMps = f.truth.groundVyMps();
  r.estXM = g.x[0];
  r.estYM = g.x[1];
  r.estVxMps = g.x[2];
  r.estVyMps = g.x[3];
  r.sdXM = std::sqrt(g.P(0, 0));
  r.sdYM = std::sqrt(g.P(1, 1));
  r.sdVxMps = std::sqrt(g.P(2, 2));
  r.sdVyMps = std::sqrt(g.P(3, 3));
  const geo::GeoPoint ll = geo.toGeodetic({g.x[0], g.x[1]});
  r.estLatDeg = ll.latDeg;
  r.estLonDeg = ll.lonDeg;
  r.nees = est::nees<4>(est::Vec<4>(r.trueXM, r.trueYM, r.trueVxMps, r.trueVyMps) - g.x, g.P);
  r.sensors = f.sensors;
  return r;
}

OwnShipRow makeRow(const SimFrame& f, const geo::LocalFrame& geo, const est::drkf::ProcessParams& process) {
  OwnShipRow r = groundRow(f, {nav::groundStateOf(f.estimate), nav::groundCovarianceOf(f.estimate)}, geo);
  r.nees = nav::drkfNees(f.trueState - f.estimate.x, f.estimate.P, process);
  for (const auto& u : f.updates) r.rowsApplied += u.dim;
  return r;
}

double TrackRow::positionErrorM() const {
  return std::hypot(estXM - trueXM, estYM - trueYM);
}
double TrackRow::velocityErrorMps() const {
  return std::hypot(estVxMps - trueVxMps, estVyMps - trueVyMps);
}

void appendSweepRows(const SimFrame& f, const Scenario& scenario, const geo::LocalFrame& geo,
                     std::vector<TrackRow>& tracks, std::vector<TargetSweepRow>& targets) {
  namespace tk = est::ttkf;
  for (const SweepSnapshot& sw : f.sweeps) {
    for (std::size_t i = 0; i < scenario.targets.size(); ++i) {
      const auto& p = sw.targets[i].position;
      const double range = std::hypot(p.xM - sw.ownTruth.position.xM, p.yM - sw.ownTruth.position.yM);
      targets.push_back({sw.timeUs, scenario.targets[i].id,
                         range <= scenario.radar.maxRangeM && range >= scenario.radar.minRangeM, p.xM, p.yM});
    }
    for (const TrackSnapshot& t : sw.tracks) {
      TrackRow r = trackEstimateRow(sw.timeUs, t.trackId, t.targetId, t.status, t.dangerous, t.estimate,
                                    t.kinematics, t.lastNis, geo);
      const auto& x = t.estimate.x;
      const auto& P = t.estimate.P;
      std::size_t i = 0;
      while (i < scenario.targets.size() && scenario.targets[i].id != t.targetId) ++i;
      if (t.targetId >= 0 && i < scenario.targets.size()) {
        const VesselTruth& truth = sw.targets[i];
        r.hasTruth = true;
        r.trueXM = truth.position.xM;
        r.trueYM = truth.position.yM;
        r.trueVxMps = truth.groundVxMps();
        r.trueVyMps = truth.groundVyMps();
        r.nees = est::nees<tk::kStateDim>(trueTrackState(sw.ownTruth, truth) - x, P);
      }
      tracks.push_back(r);
    }
  }
}

RunResult runScenario(const Scenario& scenario, std::uint64_t seed) {
  const auto start = std::chrono::steady_clock::now();
  SimulationEngine engine(scenario, seed);
  RunResult result;
  result.seed = seed;
  result.rows.reserve(static_cast<std::size_t>(scenario.durationUs / scenario.stepUs + 1));
  while (!engine.finished()) {
    const SimFrame f = engine.step();
    result.rows.push_back(makeRow(f, engine.frame(), engine.drkf().config().process));
    appendSweepRows(f, scenario, engine.frame(), result.trackRows, result.targetRows);
  }
  result.counters = engine.drkf().counters();
  result.trackCounters = engine.trackers().counters();
  result.wallTimeS = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

void parallelRuns(int runs, int threads, const std::function<void(int)>& fn) {
  if (runs <= 0) return;
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(runs));
  std::atomic<int> next{0};
  auto worker = [&] {
    for (int i = next++; i < runs; i = next++) {
      try {
        fn(i);
      } catch (...) {
        errors[static_cast<std::size_t>(i)] = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  for (int k = 1; k < std::min(threads, runs); ++k) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
}

std::vector<RunResult> runMonteCarlo(const Scenario& scenario, int runs, int threads,
                                     std::uint64_t baseSeed) {
  if (runs <= 0) throw std::invalid_argument("Monte Carlo: runs must be positive");
  if (threads <= 0) throw std::invalid_argument("Monte Carlo: threads must be positive");
  if (const std::string problem = checkScenario(scenario); !problem.empty())
    throw std::invalid_argument("scenario " + io::quoted(scenario.name) + ": " + problem);
  std::vector<RunResult> results(static_cast<std::size_t>(runs));
  parallelRuns(runs, threads, [&](int i) {
    results[static_cast<std::size_t>(i)] = runScenario(scenario, baseSeed + static_cast<std::uint64_t>(i));
  });
  return results;
}

}  // namespace reckoner::sim
