#include "studies/own_ship_filters.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <utility>

#include "common/percentile.h"
#include "estimation/ekf.h"

// The studies drive the engine and score its runs: the engine's names unqualified here.
using namespace reckoner::sim;

namespace reckoner::studies {
const char* ownShipFilterName(OwnShipFilter f) {
  switch (f) {
    case OwnShipFilter::Drkf:
      return "drkf";
    case OwnShipFilter::Geodetic:
      return "geodetic";
    case OwnShipFilter::Lsq:
      return "lsq";
  }
  return "?";
}

std::optional<OwnShipFilter> ownShipFilterFromName(std::string_view name) {
  for (int i = 0; i < kOwnShipFilterCount; ++i)
    if (name == ownShipFilterName(static_cast<OwnShipFilter>(i))) return static_cast<OwnShipFilter>(i);
  return std::nullopt;
}

namespace {
nav::GeodeticKf makeGeodetic(const Scenario& scenario, const est::drkf::Belief& start,
                             const geo::LocalFrame& geo) {
  const est::Vec<4> g0 = nav::groundStateOf(start);
  const est::Mat<4> C0 = nav::groundCovarianceOf(start);
  const double sdPos = std::sqrt(0.5 * (C0(0, 0) + C0(1, 1)));
  const double sdVel = std::sqrt(0.5 * (C0(2, 2) + C0(3, 3)));
  const geo::GridInfo gi0 = geo.gridInfo({g0[0], g0[1]});
  // Grid velocity -> true east and north: rotate by the convergence, unscale.
  const double c = std::cos(gi0.convergenceRad), s = std::sin(gi0.convergenceRad);
  const double vE = (c * g0[2] + s * g0[3]) / gi0.scale, vN = (-s * g0[2] + c * g0[3]) / gi0.scale;
  const est::GaussMarkov& a = scenario.filter.acceleration;
  nav::GeodeticKfConfig gc;
  // White acceleration giving the Gauss-Markov acceleration's velocity change over its correlation
  // time: 2 sigma^2 / beta^2 (beta tau - 1 + e^-beta tau) at tau = 1 / beta, divided by tau.
  gc.accelerationQ = std::max(2.0 * std::exp(-1.0) * a.sigma * a.sigma / a.betaPerS, 1e-8);
  gc.minSpeedMps = scenario.filter.minSpeedMps;
  gc.gateProbability = scenario.filter.gateProbability;
  gc.gateReopenS = scenario.filter.gateReopenS;
  return nav::GeodeticKf(gc, nav::GeodeticKf::initialBelief(geo, {g0[0], g0[1]}, sdPos, vE, vN, sdVel), 0);
}

nav::LsqNavigator makeLsq(const est::drkf::Belief& start) {
  est::Gaussian<2> p0;
  p0.x = nav::groundStateOf(start).head<2>();
  p0.P = nav::groundCovarianceOf(start).topLeftCorner<2, 2>();
  return nav::LsqNavigator(nav::LsqNavigatorConfig{}, p0, 0);
}
}  // namespace

Seed002Filters::Seed002Filters(const Scenario& scenario, const est::drkf::Belief& drkfStart,
                               const geo::LocalFrame& frame)
    : frame_(frame), geodetic_(makeGeodetic(scenario, drkfStart, frame)), lsq_(makeLsq(drkfStart)) {}

void Seed002Filters::feed(const SimFrame& f) {
  geodeticRows_ = 0;
  std::size_t i = 0;
  while (i < f.measurements.size()) {
    const TimeUs t = sensors::timeOf(f.measurements[i]);
    std::size_t j = i;
    while (j < f.measurements.size() && sensors::timeOf(f.measurements[j]) == t) ++j;
    const std::span<const sensors::OwnShipSample> epoch(f.measurements.data() + i, j - i);
    geodeticRows_ += geodetic_.update(t, epoch, frame_).rowsApplied();
    lsq_.update(t, epoch, frame_);
    i = j;
  }
  geodetic_.predictTo(f.timeUs);
  timeUs_ = f.timeUs;
}

est::Gaussian<4> Seed002Filters::ground(OwnShipFilter f) const {
  if (f == OwnShipFilter::Geodetic) return geodetic_.groundInGrid(frame_);
  est::Gaussian<4> g = lsq_.ground();
  if (lsq_.timeUs() < timeUs_)  // carry the dead-reckoned position to the frame's time
    g.x.head<2>() += g.x.tail<2>() * toSeconds(timeUs_ - lsq_.timeUs());
  return g;
}

OwnShipFilterRun runOwnShipFilters(const Scenario& scenario, std::uint64_t seed) {
  const auto start = std::chrono::steady_clock::now();
  SimulationEngine engine(scenario, seed);
  const geo::LocalFrame& geo = engine.frame();
  OwnShipFilterRun out;
  RunResult& run = out.drkf;
  run.seed = seed;
  Seed002Filters seed002(scenario, engine.drkf().belief(), geo);
  while (!engine.finished()) {
    const SimFrame f = engine.step();
    run.rows.push_back(makeRow(f, geo, engine.drkf().config().process));
    appendSweepRows(f, scenario, geo, run.trackRows, run.targetRows);
    seed002.feed(f);
    OwnShipRow d = groundRow(f, {nav::groundStateOf(f.estimate), nav::groundCovarianceOf(f.estimate)}, geo);
    d.rowsApplied = run.rows.back().rowsApplied;
    out.rows[static_cast<std::size_t>(OwnShipFilter::Drkf)].push_back(d);
    OwnShipRow g = groundRow(f, seed002.ground(OwnShipFilter::Geodetic), geo);
    g.rowsApplied = seed002.geodeticRowsApplied();
    out.rows[static_cast<std::size_t>(OwnShipFilter::Geodetic)].push_back(g);
    out.rows[static_cast<std::size_t>(OwnShipFilter::Lsq)].push_back(
        groundRow(f, seed002.ground(OwnShipFilter::Lsq), geo));
  }
  run.counters = engine.drkf().counters();
  run.trackCounters = engine.trackers().counters();
  run.deadReckoning = engine.deadReckoning().intervals();
  run.wallTimeS = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

std::vector<OwnShipFilterRun> runOwnShipFiltersMonteCarlo(const Scenario& scenario, int runs, int threads,
                                                          std::uint64_t baseSeed) {
  std::vector<OwnShipFilterRun> all(static_cast<std::size_t>(std::max(0, runs)));
  parallelRuns(runs, threads, [&](int i) {
    all[static_cast<std::size_t>(i)] = runOwnShipFilters(scenario, baseSeed + static_cast<std::uint64_t>(i));
  });
  return all;
}

OwnShipFilterStats summariseOwnShipFilters(const std::vector<OwnShipFilterRun>& runs, TimeUs fromUs,
                                           const est::ChiSquareBounds& band) {
  OwnShipFilterStats out{};
  for (int k = 0; k < kOwnShipFilterCount; ++k) {
    std::array<double, 2> se{}, ve{};
    std::array<std::vector<double>, 2> errors;
    std::map<TimeUs, std::pair<double, int>> neesAt;
    std::map<TimeUs, int> phaseAt;
    for (const auto& r : runs) {
      for (const auto& row : r.rows[static_cast<std::size_t>(k)]) {
        if (row.timeUs < fromUs) continue;
        const int ph = row.sensors.isOn(sensors::SensorId::Gps) ? 0 : 1;
        se[static_cast<std::size_t>(ph)] += row.positionErrorM() * row.positionErrorM();
        ve[static_cast<std::size_t>(ph)] += row.velocityErrorMps() * row.velocityErrorMps();
        errors[static_cast<std::size_t>(ph)].push_back(row.positionErrorM());
        auto& n = neesAt[row.timeUs];
        n.first += row.nees;
        ++n.second;
        phaseAt[row.timeUs] = ph;
      }
    }
    auto& st = out[static_cast<std::size_t>(k)];
    std::array<long, 2> times{};
    for (const auto& [t, v] : neesAt) {
      auto& p = st[static_cast<std::size_t>(phaseAt[t])];
      const double m = v.first / v.second;
      p.meanNees += m;
      p.shareInBand += band.contains(m) ? 1.0 : 0.0;
      ++times[static_cast<std::size_t>(phaseAt[t])];
    }
    for (std::size_t ph = 0; ph < 2; ++ph) {
      auto& p = st[ph];
      p.rows = static_cast<long>(errors[ph].size());
      if (p.rows == 0) continue;
      const auto n = static_cast<double>(p.rows);
      p.positionRmseM = std::sqrt(se[ph] / n);
      p.velocityRmseMps = std::sqrt(ve[ph] / n);
      p.meanNees /= static_cast<double>(times[ph]);
      p.shareInBand /= static_cast<double>(times[ph]);
      p.p95PositionErrorM = percentile95(std::move(errors[ph]));
    }
  }
  return out;
}

}  // namespace reckoner::studies
