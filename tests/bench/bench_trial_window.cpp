// The ECDIS window with the AIS picture and the trial manoeuvre on (issue 20): the AIS harbour (40
// radar targets, 30 of them with AIS) plus 170 more AIS vessels 13-20 NM out, beyond the radar, so 200
// stations in all; the trial display switched on (Tracking > Trial manoeuvre) so that every frame
// carries the trial of 240 targets and its danger sectors; run at 10x for 10 s of wall time after a
// 1 s warm-up. The GUI thread's times per frame arrival, repaint and plot refresh as percentiles.
#include <benchmark/benchmark.h>

#include <QAction>
#include <QEventLoop>
#include <QTimer>

#include <cmath>

#include "common/angles.h"
#include "common/rng.h"
#include "common/units.h"
#include "files/scenario_json.h"
#include "gui_timing.h"
#include "resources/embedded.h"
#include "ui/main_window.h"

namespace reckoner {
namespace {

void waitMs(int ms) {
  QEventLoop loop;
  QTimer::singleShot(ms, &loop, &QEventLoop::quit);
  loop.exec();
}

sim::Scenario harbourWith200Ais() {
  sim::Scenario s = files::parseScenario(resources::findScenario("ais-harbour")->text, "ais-harbour");
  Rng rng(20, 1);
  int stations = 0;
  for (const auto& t : s.targets) stations += t.ais.has_value();
  for (int id = 1000; stations < 200; ++id, ++stations) {
    sim::TargetSpec t;
    t.id = id;
    t.name = "far " + std::to_string(id);
    const double r = nmToMetres(13.0 + 7.0 * rng.uniform()), b = kTwoPi * rng.uniform();
    const double c = kTwoPi * rng.uniform(), v = knotsToMps(4.0 + 12.0 * rng.uniform());
    t.motion.initialPosition = {r * std::sin(b), r * std::cos(b)};
    t.motion.initialVelocityMps = {v * std::sin(c), v * std::cos(c)};
    auto a = sensors::AisTransmitterSpec::defaults(rng.uniform() < 0.7 ? sensors::AisStationClass::A
                                                                       : sensors::AisStationClass::B);
    a.mmsi = 244000000u + static_cast<std::uint32_t>(id);
    a.toBowM = 60, a.toSternM = 20, a.toPortM = 6, a.toStarboardM = 6;
    t.ais = a;
    s.targets.push_back(t);
  }
  return s;
}

void BM_EcdisWindowTrial40Radar200Ais(benchmark::State& state) {
  ui::MainWindowOptions options;
  options.sound = false;
  options.restoreSession = false;
  options.askToSaveOnClose = false;
  ui::MainWindow w(options);
  w.resize(1600, 1000);
  w.show();
  w.loadScenario(harbourWith200Ais(), QStringLiteral("bench"));
  waitMs(1500);
  auto* trial = w.findChild<QAction*>(QStringLiteral("trialManoeuvre"));
  for (auto _ : state) {
    w.setRate(10.0);
    waitMs(3000);  // tracks confirmed, stations heard
    if (trial && !trial->isChecked()) trial->trigger();
    waitMs(1000);
    w.clearGuiTimings();
    QElapsedTimer wall;
    wall.start();
    waitMs(10000);
    const double elapsed = static_cast<double>(wall.nsecsElapsed()) * 1e-9;
    w.setRate(0.0);
    state.SetIterationTime(elapsed);
    bench::guiTimingCounters(w, state);
    const ui::LiveFrame& live = w.history().latest();
    state.counters["tracks"] = static_cast<double>(live.frame.tracks.size());
    state.counters["ais_targets"] = live.aisTargets ? static_cast<double>(live.aisTargets->size()) : 0.0;
    state.counters["trial_targets"] = live.trial ? static_cast<double>(live.trial->targets.size()) : 0.0;
  }
}
BENCHMARK(BM_EcdisWindowTrial40Radar200Ais)->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);

}  // namespace
}  // namespace reckoner
