// reckoner-bench: speed of the estimation core (Google Benchmark). Figures go to docs/performance.md.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <vector>

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QPainter>
#include <QStandardPaths>
#include <QTimer>

#include "charts/render/chart_renderer.h"
#include "charts/s57/s57_loader.h"
#include "charts/world/gshhg.h"
#include "charts/world/world_data.h"
#include "common/angles.h"
#include "common/rng.h"
#include "files/scenario_json.h"
#include "gui_timing.h"
#include "navigation/drkf.h"
#include "radar/chart_matching.h"
#include "resources/embedded.h"
#include "sim/scenario_run.h"
#include "support/radar_fixtures.h"
#include "tracking/track_manager.h"
#include "ui/main_window.h"

namespace {

using namespace reckoner;
namespace dk = est::drkf;

nav::DrkfConfig benchConfig(bool calibration = false, bool ship = false) {
  nav::DrkfConfig c;
  c.process.ship.enabled = ship;  // the realistic profile's ship motion model (drkf_process.h)
  if (calibration) {  // the realistic profile's heading bias and log scale states (docs/sensor_profiles.md)
    c.process.headingBias = {degToRad(1.0), 1.0 / 3600.0};
    c.process.logScale = {0.02, 1.0 / 7200.0};
  }
  c.process.current = {std::sqrt(0.1), 0.125};
  c.process.acceleration = {0.5, 1.0};
  c.process.loranError = {std::sqrt(1100.0), 0.25};
  c.process.speedlogError = {std::sqrt(0.025), 0.5};
  return c;
}

/// Noise-free samples of a ship steaming at (6, 6) m/s through still water, for epoch t (seconds).
std::vector<sensors::OwnShipSample> samplesAt(TimeUs t, bool deadReckoning) {
  const double s = toSeconds(t);
  std::vector<sensors::OwnShipSample> out;
  if (!deadReckoning) {
    out.emplace_back(sensors::GpsSample{t, {6.0 * s, 6.0 * s}, 1600.0, true, 6.0, 6.0, 0.5});
    out.emplace_back(sensors::LoranSample{t, {6.0 * s, 6.0 * s}, 25.0});
  }
  out.emplace_back(sensors::SpeedlogSample{t, std::hypot(6.0, 6.0), sensors::SpeedlogMode::GroundLock, 0.01});
  out.emplace_back(sensors::GyroSample{t, degToRad(45.0), degToRad(1.0) * degToRad(1.0)});
  return out;
}

nav::Drkf makeFilter(bool calibration = false, bool ship = false) {
  const nav::DrkfConfig c = benchConfig(calibration, ship);
  dk::Belief b;
  b.x.setZero();
  b.x[dk::kVelX] = b.x[dk::kVelY] = 6.0;
  b.P = nav::initialCovariance(c.process, 30.0, 0.5);
  // A frame on the central meridian: convergence zero, so the noise-free samples are exact.
  return nav::Drkf(c, geo::LocalFrame(49.0, -123.0), b, 0);
}

void cycle(benchmark::State& state, bool deadReckoning, bool calibration = false, bool ship = false) {
  nav::Drkf f = makeFilter(calibration, ship);
  // Precompute a long sample sequence so the loop times only the filter.
  constexpr int kEpochs = 4096;
  std::vector<std::vector<sensors::OwnShipSample>> epochs;
  for (int k = 1; k <= kEpochs; ++k) epochs.push_back(samplesAt(k * kMicrosPerSecond, deadReckoning));
  int k = 0;
  TimeUs base = 0;
  for (auto _ : state) {
    if (k == kEpochs) {  // restart the filter (not timed) so the state stays consistent with the samples
      state.PauseTiming();
      f = makeFilter(calibration, ship);
      k = 0;
      base = 0;
      state.ResumeTiming();
    }
    const auto& e = epochs[static_cast<std::size_t>(k++)];
    auto r = f.update(sensors::timeOf(e.front()) + base, e);
    benchmark::DoNotOptimize(r);
  }
  state.counters["rows"] = deadReckoning ? 2 : 8;
}

void BM_DrkfCycleAllSensors(benchmark::State& state) {
  cycle(state, false);
}
BENCHMARK(BM_DrkfCycleAllSensors);

/// The same with the heading-bias and log-scale states modelled (13 states all uncertain).
void BM_DrkfCycleAllSensorsCalibrated(benchmark::State& state) {
  cycle(state, false, true);
}
BENCHMARK(BM_DrkfCycleAllSensorsCalibrated);

/// And with the ship motion model (the realistic profile's process: nonlinear, linearised per step).
void BM_DrkfCycleAllSensorsShipMotion(benchmark::State& state) {
  cycle(state, false, true, true);
}
BENCHMARK(BM_DrkfCycleAllSensorsShipMotion);

void BM_DrkfCycleDeadReckoning(benchmark::State& state) {
  cycle(state, true);
}
BENCHMARK(BM_DrkfCycleDeadReckoning);

void BM_DrkfPredictOnly(benchmark::State& state) {
  nav::Drkf f = makeFilter();
  TimeUs t = 0;
  for (auto _ : state) {
    t += kMicrosPerSecond;
    benchmark::DoNotOptimize(f.predictTo(t));
  }
}
BENCHMARK(BM_DrkfPredictOnly);

void BM_VanLoanDiscretisation(benchmark::State& state) {
  const dk::ProcessModel model(benchConfig().process);
  double dt = 1.0;
  for (auto _ : state) {
    dt += 1e-9;  // defeat any caching
    auto d = model.discretise(dt);
    benchmark::DoNotOptimize(d);
  }
}
BENCHMARK(BM_VanLoanDiscretisation);

void BM_GridConvergence(benchmark::State& state) {
  const geo::LocalFrame frame(47.27, -122.45);
  double x = 0.0;
  for (auto _ : state) {
    x += 1.0;
    auto g = frame.gridInfo({x, 1000.0});
    benchmark::DoNotOptimize(g);
  }
}
BENCHMARK(BM_GridConvergence);

track::TtkfConfig ttkfConfig() {
  track::TtkfConfig c;
  c.process = {{0.05, 0.1}, {0.1, 0.1}};
  return c;
}

track::OwnShipInput ownAt(double tS) {
  track::OwnShipInput o;
  o.timeUs = fromSeconds(tS);
  o.x << 0.0, 5.0 * tS, 0.0, 5.0;
  o.P = est::Vec<4>(25.0, 25.0, 0.04, 0.04).asDiagonal();
  return o;
}

/// A target 4 km east steaming north at 3 m/s, seen from own ship steaming north at 5 m/s.
track::GridPlot plotAt(double tS) {
  const double dx = 4000.0, dy = (3.0 - 5.0) * tS + 1000.0;
  return {fromSeconds(tS), std::hypot(dx, dy), bearingOf(dx, dy), 100.0, degToRad(1.0) * degToRad(1.0)};
}

/// One TTKF cycle as the paper runs it: predict to the plot time (2 s sweep) and apply range and
/// azimuth. Restarted (untimed) every 4096 cycles.
void BM_TtkfCycle(benchmark::State& state) {
  const auto ctx = std::make_shared<const track::TtkfContext>(ttkfConfig());
  auto fresh = [&] { return track::Ttkf::initiate(ctx, ownAt(0.0), plotAt(0.0)); };
  track::Ttkf f = fresh();
  int k = 0;
  for (auto _ : state) {
    if (++k == 4096) {
      state.PauseTiming();
      f = fresh();
      k = 1;
      state.ResumeTiming();
    }
    auto r = f.updateRadar(plotAt(2.0 * k + 0.37));  // beam times are not whole seconds
    benchmark::DoNotOptimize(r);
  }
}
BENCHMARK(BM_TtkfCycle);

/// Feeding the DRKF output to one TTKF (marginal replacement, with the prediction to that time).
void BM_TtkfOwnShipFeed(benchmark::State& state) {
  const auto ctx = std::make_shared<const track::TtkfContext>(ttkfConfig());
  track::Ttkf f = track::Ttkf::initiate(ctx, ownAt(0.0), plotAt(0.0));
  double t = 0.0;
  for (auto _ : state) {
    t += 1.0;
    auto r = f.feedOwnShip(ownAt(t));
    benchmark::DoNotOptimize(r);
  }
}
BENCHMARK(BM_TtkfOwnShipFeed);

/// A whole radar sweep of an ARPA with `n` established tracks and `n` plots (plus clutter when the
/// second argument is set): association (gating, clustering, optimal assignment), n radar updates, two
/// own-ship inputs to every track (1 Hz DRKF, 2 s sweep) and the end-of-sweep bookkeeping. The targets
/// sit on a jittered 1.2 km grid around own ship, steaming at up to 8 m/s.
void BM_RadarSweep(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const int clutter = static_cast<int>(state.range(1));
  track::TrackManagerConfig c;
  c.filter = ttkfConfig();
  c.kind = static_cast<track::TrackerKind>(state.range(2));
  c.capacity = std::max<std::size_t>(n + 100, 1000);
  c.manualAcquireRadiusM = 300.0;
  track::TrackManager m(c);
  Rng rng(42, 1);
  const auto side = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(n))));
  std::vector<std::array<double, 4>> targets;  // x, y, vx, vy
  for (std::size_t i = 0; i < n; ++i) {
    const double x = (static_cast<double>(i % side) - static_cast<double>(side) / 2.0) * 1200.0 +
                     300.0 * rng.uniform() + 600.0;
    const std::size_t row = i / side;
    const double y =
        (static_cast<double>(row) - static_cast<double>(side) / 2.0) * 1200.0 + 300.0 * rng.uniform() + 600.0;
    targets.push_back({x, y, 8.0 * (rng.uniform() - 0.5), 8.0 * (rng.uniform() - 0.5)});
  }
  const double sdB = degToRad(0.5);
  int sweep = 0;
  auto runSweep = [&] {
    const double t0 = 2.0 * sweep++;
    std::vector<std::pair<double, track::GridPlot>> plots;
    const auto add = [&](double t, double dx, double dy) {
      const double r = std::hypot(dx, dy) + 10.0 * rng.normal();
      const double b = wrapTwoPi(bearingOf(dx, dy) + sdB * rng.normal());
      plots.push_back({t, {fromSeconds(t), r, b, 100.0, sdB * sdB}});
    };
    for (const auto& tg : targets) {
      const double b = wrapTwoPi(bearingOf(tg[0], tg[1] - 5.0 * t0));
      const double t = t0 + b / kTwoPi * 2.0;
      add(t, tg[0] + tg[2] * t, tg[1] + tg[3] * t - 5.0 * t);
    }
    for (int k = 0; k < clutter; ++k) {
      const double b = kTwoPi * rng.uniform(), r = 25000.0 * std::sqrt(rng.uniform());
      add(t0 + b / kTwoPi * 2.0, r * std::sin(b), r * std::cos(b));
    }
    std::sort(plots.begin(), plots.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    m.feedOwnShip(ownAt(t0));
    bool fedMid = false;
    for (const auto& [t, p] : plots) {
      if (!fedMid && t >= t0 + 1.0) {
        m.feedOwnShip(ownAt(t0 + 1.0));
        fedMid = true;
      }
      m.addPlot(p);
    }
    if (!fedMid) m.feedOwnShip(ownAt(t0 + 1.0));
    m.endSweep(fromSeconds(t0 + 2.0));
  };
  for (int k = 0; k < 6; ++k) runSweep();  // acquire and confirm
  for (auto _ : state) runSweep();
  state.counters["tracks"] = static_cast<double>(m.activeCount());
  state.counters["largest_cluster"] = static_cast<double>(m.counters().largestCluster);
}
// Tracks, clutter plots, filter (track::TrackerKind: 0 ekf, 1 ekf-ie, 2 abg, 3 imm).
BENCHMARK(BM_RadarSweep)
    ->Args({1000, 0, 0})
    ->Args({1000, 200, 0})
    ->Args({100, 0, 0})
    ->Args({1000, 0, 1})
    ->Args({1000, 0, 2})
    ->Args({1000, 0, 3})
    ->Unit(benchmark::kMillisecond);

/// One simulated hour at 1 Hz: truth, four sensors, DRKF and output rows (with geodetic conversion).
void BM_OneHourRun(benchmark::State& state) {
  sim::Scenario s =
      files::parseScenario(resources::findScenario("matched-model")->text, "builtin:matched-model");
  s.durationUs = 3600 * kMicrosPerSecond;
  for (auto _ : state) {
    auto r = sim::runScenario(s, 1);
    benchmark::DoNotOptimize(r);
  }
}
BENCHMARK(BM_OneHourRun)->Unit(benchmark::kMillisecond);

/// Loading US5WA22M with its four updates through GDAL into the chart model (../shared must be present).
void BM_LoadChartUS5WA22M(benchmark::State& state) {
  const std::string cell = RECKONER_SHARED_DIR "/data/enc/US5WA22M/US5WA22M.000";
  if (!std::filesystem::exists(cell)) {
    state.SkipWithError("../shared/data/enc is absent");
    return;
  }
  for (auto _ : state) {
    auto c = charts::loadCell(cell);
    benchmark::DoNotOptimize(c);
  }
}
BENCHMARK(BM_LoadChartUS5WA22M)->Unit(benchmark::kMillisecond);

/// A full redraw of US5WA22M at 1920x1080, 1:22 000 (the harbour and its approaches), day, standard
/// display (/1: all), from the prepared (Mercator-projected) cell, as a chart view redraws after a zoom;
/// second argument 1: over the world background (the default), 0: over plain NODTA.
void BM_RenderFullUS5WA22M(benchmark::State& state) {
  const std::string path = RECKONER_SHARED_DIR "/data/enc/US5WA22M/US5WA22M.000";
  if (!std::filesystem::exists(path)) {
    state.SkipWithError("../shared/data/enc is absent");
    return;
  }
  const std::vector<charts::CellPtr> cells{charts::loadCell(path)};
  const charts::Viewport view({47.278, -122.453}, 22000, 1920, 1080);
  QImage image(1920, 1080, QImage::Format_ARGB32_Premultiplied);
  charts::ChartRenderer renderer;
  renderer.prepare(cells[0]);
  renderer.setWorldBackground(state.range(1) != 0);
  charts::MarinerSettings settings;
  settings.category =
      state.range(0) == 0 ? charts::DisplayCategory::Standard : charts::DisplayCategory::Other;
  for (auto _ : state) {
    auto st = renderer.render(image, cells, view, settings);
    benchmark::DoNotOptimize(st);
  }
}
BENCHMARK(BM_RenderFullUS5WA22M)->Args({0, 1})->Args({1, 1})->Args({0, 0})->Unit(benchmark::kMillisecond);

/// The world background alone (no cell) at 1920x1080, from the shoreline loaded and projected once:
/// /0 the whole world at 1:100 000 000 (GSHHG crude, every bin), /1 Puget Sound at 1:700 000
/// (intermediate, one bin), /2 US5WA22M's view at 1:22 000 (what BM_RenderFullUS5WA22M/0/1 draws under
/// the cell). Needs Debian's gmt-gshhg-low.
void BM_RenderWorldBackground(benchmark::State& state) {
  if (!std::filesystem::exists(charts::world::gshhgPath(charts::world::ShoreResolution::Crude))) {
    state.SkipWithError("gmt-gshhg-low is not installed");
    return;
  }
  const charts::Viewport view = state.range(0) == 0 ? charts::Viewport({20.0, 0.0}, 1e8, 1920, 1080)
                                : state.range(0) == 1
                                    ? charts::Viewport({47.27, -122.45}, 700000, 1920, 1080)
                                    : charts::Viewport({47.278, -122.453}, 22000, 1920, 1080);
  QImage image(1920, 1080, QImage::Format_ARGB32_Premultiplied);
  charts::ChartRenderer renderer;
  renderer.render(image, {}, view, charts::MarinerSettings{});  // loads and projects the shoreline
  for (auto _ : state) {
    auto st = renderer.render(image, {}, view, charts::MarinerSettings{});
    benchmark::DoNotOptimize(st);
  }
}
BENCHMARK(BM_RenderWorldBackground)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

/// Reading and assembling one GSHHG file (the one-off cost of a resolution's first view): /0 crude,
/// /1 low, /2 intermediate.
void BM_LoadGshhg(benchmark::State& state) {
  const auto r = static_cast<charts::world::ShoreResolution>(state.range(0));
  const std::string path = charts::world::gshhgPath(r);
  if (!std::filesystem::exists(path)) {
    state.SkipWithError("gmt-gshhg-low is not installed");
    return;
  }
  for (auto _ : state) {
    auto s = charts::world::loadGshhg(path, r);
    benchmark::DoNotOptimize(s);
  }
}
BENCHMARK(BM_LoadGshhg)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

/// A pan frame from the cache: the last rendered 1920x1080 image drawn shifted by a drag of (37, -23)
/// px into the window's back buffer while the worker renders the new view.
void BM_PanFromCache(benchmark::State& state) {
  const charts::Viewport before({47.278, -122.453}, 22000, 1920, 1080);
  const charts::ScreenPoint moved = before.toScreen(before.centre());
  const charts::Viewport after(before.toLatLon({moved.x - 37, moved.y + 23}), 22000, 1920, 1080);
  QImage cached(1920, 1080, QImage::Format_ARGB32_Premultiplied);
  cached.fill(QColor(120, 170, 220));
  QImage target(1920, 1080, QImage::Format_ARGB32_Premultiplied);
  for (auto _ : state) {
    QPainter p(&target);
    charts::drawFromCache(p, cached, before, after, QColor(167, 181, 185));
    p.end();
    benchmark::DoNotOptimize(target.constBits());
  }
}
BENCHMARK(BM_PanFromCache)->Unit(benchmark::kMillisecond);

// The ECDIS window at 100x with 40 targets (issue 5): the GUI thread's time per frame arrival, per
// overlay/table repaint (<= 30 Hz) and per plot refresh (2 Hz), as percentiles over 10 s of wall
// time after a 1 s warm-up; and whether the simulation worker keeps up with the rate.
void BM_EcdisWindow100x40Targets(benchmark::State& state) {
  sim::Scenario s =
      files::parseScenario(resources::findScenario(resources::kDefaultScenario)->text, "default");
  Rng rng(42, 1);
  const auto own = s.ownShip.initialPosition;
  for (int id = 4; s.targets.size() < 40; ++id) {
    sim::TargetSpec t;
    t.id = id;
    const double r = 1500.0 + 9500.0 * rng.uniform(), b = 2.0 * kPi * rng.uniform();
    const double c = 2.0 * kPi * rng.uniform(), v = 2.0 + 7.0 * rng.uniform();
    t.motion.initialPosition = {own.xM + r * std::sin(b), own.yM + r * std::cos(b)};
    t.motion.initialVelocityMps = {v * std::sin(c), v * std::cos(c)};
    s.targets.push_back(t);
  }
  s.durationUs = std::int64_t{4} * 3600 * kMicrosPerSecond;
  ui::MainWindowOptions options;
  options.sound = false;
  options.restoreSession = false;
  ui::MainWindow w(options);
  w.resize(1600, 1000);
  w.show();
  w.loadScenario(s, QStringLiteral("bench"));
  const auto waitMs = [](int ms) {
    QEventLoop loop;
    QTimer::singleShot(ms, &loop, &QEventLoop::quit);
    loop.exec();
  };
  waitMs(1500);  // chart loaded and rendered
  for (auto _ : state) {
    w.setRate(100.0);
    waitMs(1000);
    w.clearGuiTimings();
    const double t0 = toSeconds(w.history().latest().frame.timeUs);
    QElapsedTimer wall;
    wall.start();
    waitMs(10000);
    const double elapsed = static_cast<double>(wall.nsecsElapsed()) * 1e-9;
    const double t1 = toSeconds(w.history().latest().frame.timeUs);
    w.setRate(0.0);
    state.SetIterationTime(elapsed);
    bench::guiTimingCounters(w, state);
    state.counters["sim_rate"] = (t1 - t0) / elapsed;
    state.counters["tracks"] = static_cast<double>(w.history().latest().frame.tracks.size());
  }
}
/// Seed 004: one radar image (4096 azimuths x 1024 range bins) to a position and heading correction:
/// echo extraction (segmentation, front contours, aggregation to ~200 points) and the matching
/// against the chart contours from a pose 40 m and 1 deg off. The image is simulated once, outside
/// the timing.
void BM_RadarImageMatching(benchmark::State& state) {
  const radar::Coastline coast = test::syntheticHarbour();
  const radar::SweepPose truth = test::harbourPose();
  radar::RadarImageParams p;
  Rng rng(5, 0);
  const radar::PolarImage img = radar::simulateRadarImage(coast, {}, truth, p, rng);
  radar::SweepPose guess = truth;
  guess.position += est::Vec<2>(30.0, -25.0);
  guess.headingRad -= degToRad(1.0);
  int used = 0;
  for (auto _ : state) {
    const auto echoes = radar::extractEchoes(img, p.azStepRad(), {});
    const auto m = radar::matchEchoes(echoes, guess, coast, {});
    used = m.used;
    benchmark::DoNotOptimize(m.correction);
  }
  state.counters["echoes_used"] = used;
}
BENCHMARK(BM_RadarImageMatching)->Unit(benchmark::kMillisecond);

/// The simulation of that image (casting 4096 beams against the contours, targets none).
void BM_RadarImageSimulation(benchmark::State& state) {
  const radar::Coastline coast = test::syntheticHarbour();
  const radar::SweepPose truth = test::harbourPose();
  radar::RadarImageParams p;
  Rng rng(5, 0);
  for (auto _ : state)
    benchmark::DoNotOptimize(radar::simulateRadarImage(coast, {}, truth, p, rng).bins.data());
}
BENCHMARK(BM_RadarImageSimulation)->Unit(benchmark::kMillisecond);

BENCHMARK(BM_EcdisWindow100x40Targets)->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);

}  // namespace

int main(int argc, char** argv) {
  // Chart rendering draws text and the window benchmark shows widgets: a QApplication, offscreen.
  qputenv("QT_QPA_PLATFORM", "offscreen");
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName(QStringLiteral("ReckonerBench"));
  int qargc = 1;
  QApplication app(qargc, argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
