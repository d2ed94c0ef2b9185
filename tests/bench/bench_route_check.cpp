// The route check against a real NOAA cell (issue 21): 10,000 legs of 0.2 to 2 NM in random directions
// inside US5WA22M (Tacoma), cross-track limits 0.1 NM, safety contour 10 m. The hazards are indexed once
// (BM_RouteHazardsBuild times that); a check then costs each leg's corridor pieces against the grid.
#include <benchmark/benchmark.h>

#include <GeographicLib/Geodesic.hpp>
#include <random>
#include <string>

#include "charts/route/route_check.h"
#include "charts/s57/s57_loader.h"

using namespace reckoner;

namespace {

const std::string kCell = std::string(RECKONER_SHARED_DIR) + "/data/enc/US5WA22M/US5WA22M.000";

charts::CellPtr tacoma() {
  static const charts::CellPtr cell = charts::loadCell(kCell);
  return cell;
}

/// A route of `legs` legs, a random walk inside the cell's box (waypoints reflected back into it).
geo::Route randomRoute(std::size_t legs) {
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> brg(0.0, 360.0), len(370.0, 3704.0);
  geo::Route r;
  geo::GeoPoint p{47.28, -122.45};
  for (std::size_t i = 0; i <= legs; ++i) {
    geo::Waypoint w;
    w.id = static_cast<int>(i + 1);
    w.position = p;
    r.waypoints.push_back(w);
    geo::GeoPoint q;
    GeographicLib::Geodesic::WGS84().Direct(p.latDeg, p.lonDeg, brg(rng), len(rng), q.latDeg, q.lonDeg);
    if (q.latDeg < 47.235 || q.latDeg > 47.32) q.latDeg = 2 * p.latDeg - q.latDeg;
    if (q.lonDeg < -122.545 || q.lonDeg > -122.36) q.lonDeg = 2 * p.lonDeg - q.lonDeg;
    p = q;
  }
  return r;
}

void BM_RouteHazardsBuild(benchmark::State& state) {
  const charts::CellPtr cell = tacoma();
  for (auto _ : state) {
    const charts::ChartHazards h({cell}, charts::SafetySettings{});
    benchmark::DoNotOptimize(h.edgeCount());
  }
}
BENCHMARK(BM_RouteHazardsBuild)->Unit(benchmark::kMillisecond);

void BM_RouteCheck10000Legs(benchmark::State& state) {
  const charts::ChartHazards hazards({tacoma()}, charts::SafetySettings{});
  const geo::Route route = randomRoute(10000);
  std::size_t findings = 0;
  for (auto _ : state) {
    const auto f = charts::checkRoute(route, hazards);
    findings = f.size();
    benchmark::DoNotOptimize(f.data());
  }
  state.counters["legs"] = static_cast<double>(route.legCount());
  state.counters["findings"] = static_cast<double>(findings);
  state.counters["edges"] = static_cast<double>(hazards.edgeCount());
}
BENCHMARK(BM_RouteCheck10000Legs)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
