// reckoner-bench: the ECDIS window in Live mode (issue 19) on 10,000 sentences per second of mixed NMEA
// and AIS over loopback UDP for 60 s (RECKONER_BENCH_FEED_S shortens it), 2000 AIS targets among them
// (class A position reports of our own encoding, each every 2 s, moving), the rest own ship and the AIS
// corpus: the GUI thread's time per frame arrival, per repaint (panels, the AIS and target tables, the
// chart with own ship and 2000 AIS symbols) and per plot refresh, as percentiles; what the hub
// delivered; the AIS table's size; resident memory after 10 s and at the end. Figures in
// docs/performance.md.
#include <benchmark/benchmark.h>

#include <QApplication>
#include <QEventLoop>
#include <QSettings>
#include <QStandardPaths>
#include <QTimer>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include "common/angles.h"
#include "common/percentile.h"
#include "common/units.h"
#include "live_stream.h"
#include "support/ais_corpus.h"
#include "ui/main_window.h"
#include "ui/panels/connections_dialog.h"

namespace {
using namespace reckoner;

constexpr int kTargets = 2000;

/// Second s's reports of half the targets (each reports every 2 s): a 40 x 50 grid 0.2 NM apart around
/// 47.5 N 122.4 W, each on its own course at 3 to 10 kn.
std::vector<std::string> targetReports(int s) {
  std::vector<std::string> out;
  out.reserve(kTargets / 2);
  const double lat0 = 47.5 - 20 * 0.2 / 60.0, lon0 = -122.4 - 25 * 0.2 / (60.0 * std::cos(degToRad(47.5)));
  for (int i = s % 2; i < kTargets; i += 2) {
    const double cog = (i * 37) % 360, sog = 3.0 + i % 8;
    const double d = knotsToMps(sog) * s;
    const int row = i / 50;  // rows of 50 targets, 0.2' apart
    const double lat = lat0 + row * 0.2 / 60.0 + d * std::cos(degToRad(cog)) / 111200.0;
    const double lon =
        lon0 + (i % 50) * 0.2 / (60.0 * std::cos(degToRad(47.5))) + d * std::sin(degToRad(cog)) / 75100.0;
    out.push_back(test::ais::sentence(
        test::ais::classA(1, 367000000 + i, 0, 0, static_cast<int>(sog * 10), std::llround(lon * 600000.0),
                          std::llround(lat * 600000.0), static_cast<int>(cog * 10), static_cast<int>(cog))));
  }
  return out;
}

void waitMs(int ms) {
  QEventLoop loop;
  QTimer::singleShot(ms, &loop, &QEventLoop::quit);
  loop.exec();
}

void BM_EcdisWindowLive10kPerSecond2000Ais(benchmark::State& state) {
  // getenv is unsafe only beside setenv, which nothing in this program calls.
  const char* env = std::getenv("RECKONER_BENCH_FEED_S");  // NOLINT(concurrency-mt-unsafe)
  const int seconds = env ? std::max(5, std::atoi(env)) : 60;
  // The bench's own settings (never the user's): one UDP connection.
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName(QStringLiteral("ReckonerBench"));
  QCoreApplication::setApplicationName(QStringLiteral("live-window"));
  const sockaddr_in to = bench::freeLoopbackPort();
  {
    QSettings settings;
    settings.clear();
    ui::saveConnections(settings, {conn::parseSource("udp://127.0.0.1:" + std::to_string(ntohs(to.sin_port)) +
                                                     "?name=feed")});
  }
  for (auto _ : state) {
    ui::MainWindowOptions options;
    options.sound = false;
    options.restoreSession = false;
    options.askToSaveOnClose = false;
    ui::MainWindow w(options);
    w.resize(1600, 1000);
    w.show();
    waitMs(1500);  // chart loaded and rendered
    w.startLive();
    while (w.hub()->status().front().state != conn::State::Connected) waitMs(10);
    std::atomic<bool> done{false};
    std::atomic<long> sent{0};
    int aisSent = 0;
    std::thread sender([&] {
      bench::sendStream(to, seconds, static_cast<int>(state.range(0)), targetReports, sent, aisSent);
      done = true;
    });
    waitMs(3000);  // own ship started, the first view fitted
    w.clearGuiTimings();
    double rss10 = 0.0;
    QElapsedTimer run;
    run.start();
    while (!done) {
      waitMs(100);
      if (rss10 == 0.0 && run.elapsed() > 10000) rss10 = bench::residentMb();
    }
    sender.join();
    waitMs(1000);
    const auto timings = w.guiTimings();
    using Kind = ui::MainWindow::GuiTiming::Kind;
    std::vector<double> all, repaint;
    std::array<double, 3> maxOf{};
    for (const auto& g : timings) {
      all.push_back(g.ms);
      if (g.kind == Kind::Repaint) repaint.push_back(g.ms);
      auto& m = maxOf[static_cast<std::size_t>(g.kind)];
      m = std::max(m, g.ms);
    }
    const conn::SourceStatus st = w.hub()->status().front();
    const ui::LiveFrame& live = w.history().latest();
    state.counters["sent"] = static_cast<double>(sent);
    state.counters["delivered"] = static_cast<double>(st.lines);
    state.counters["dropped"] = static_cast<double>(w.hub()->counters().dropped);
    state.counters["ais_targets"] = static_cast<double>(live.aisCounts.targets);
    state.counters["gui_p50_ms"] = percentileNearestRank(all, 0.50);
    state.counters["gui_p99_ms"] = percentileNearestRank(all, 0.99);
    state.counters["gui_max_ms"] = all.empty() ? 0.0 : *std::max_element(all.begin(), all.end());
    state.counters["repaint_p99_ms"] = percentileNearestRank(repaint, 0.99);
    state.counters["gui_events"] = static_cast<double>(all.size());
    state.counters["max_frame_ms"] = maxOf[static_cast<std::size_t>(Kind::Frame)];
    state.counters["max_repaint_ms"] = maxOf[static_cast<std::size_t>(Kind::Repaint)];
    state.counters["max_plots_ms"] = maxOf[static_cast<std::size_t>(Kind::Plots)];
    state.counters["rss_10s_mb"] = rss10;
    state.counters["rss_end_mb"] = bench::residentMb();
    w.stopLive();
  }
}
BENCHMARK(BM_EcdisWindowLive10kPerSecond2000Ais)
    ->Arg(10000)
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

}  // namespace
