// reckoner-bench: a live feed of 10,000 sentences per second, mixed NMEA and AIS, for 60 s (issue 19;
// RECKONER_BENCH_FEED_S shortens it) over loopback UDP into the connections hub (its own I/O thread)
// and from there, batch by batch on this thread as the window's would, through the live session.
// Reported: sentences sent, delivered and dropped; AIS messages sent and decoded; own-ship rows; the
// time of each batch on the consuming thread (p50, p99, max: what the GUI thread would spend); the
// hub's peak queue; resident memory after the first 10 s and at the end. Figures in
// docs/performance.md.
#include <benchmark/benchmark.h>

#include <QCoreApplication>
#include <QElapsedTimer>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "common/angles.h"
#include "common/percentile.h"
#include "common/units.h"
#include "connection_hub.h"
#include "io/nmea.h"
#include "live_stream.h"
#include "sim/live_session.h"
#include "source_config.h"

namespace {
using namespace reckoner;

void BM_LiveFeed10kPerSecond(benchmark::State& state) {
  // getenv is unsafe only beside setenv, which nothing in this program calls.
  const char* env = std::getenv("RECKONER_BENCH_FEED_S");  // NOLINT(concurrency-mt-unsafe)
  const int seconds = env ? std::max(1, std::atoi(env)) : 60;
  const int perSecond = static_cast<int>(state.range(0));
  for (auto _ : state) {
    const sockaddr_in to = bench::freeLoopbackPort();
    conn::ConnectionHub hub;
    hub.add(conn::parseSource("udp://127.0.0.1:" + std::to_string(ntohs(to.sin_port)) + "?name=feed"));
    hub.start();
    while (hub.status().front().state != conn::State::Connected) QCoreApplication::processEvents();

    std::atomic<bool> done{false};
    std::atomic<long> sent{0};
    int aisSent = 0;
    std::thread sender([&] {
      bench::sendStream(to, seconds, perSecond, nullptr, sent, aisSent);
      done = true;
    });

    const sim::LiveOptions options;
    sim::LiveSession session(options);
    std::vector<double> batchMs;
    long delivered = 0, rows = 0, aisDecoded = 0;
    double rss10 = 0.0, rssPeak = 0.0;
    QElapsedTimer run;
    run.start();
    const auto consume = [&] {
      QElapsedTimer t;
      t.start();
      const auto lines = hub.take();
      for (const conn::ReceivedLine& l : lines) session.nmea(l.line, l.receivedUtc, l.source);
      rows += static_cast<long>(session.takeOwnRows().size());
      aisDecoded += static_cast<long>(session.takeAisMessages().size());
      delivered += static_cast<long>(lines.size());
      if (!lines.empty()) batchMs.push_back(static_cast<double>(t.nsecsElapsed()) / 1e6);
    };
    while (!done) {
      std::this_thread::sleep_for(std::chrono::milliseconds(16));  // a frame of the window
      consume();
      if (rss10 == 0.0 && run.elapsed() > 10000) rss10 = bench::residentMb();
      rssPeak = std::max(rssPeak, bench::residentMb());
    }
    sender.join();
    // the last datagrams: until the hub has delivered what was sent (or two idle seconds)
    QElapsedTimer idle;
    idle.start();
    while (delivered + static_cast<long>(hub.counters().dropped) < sent && idle.elapsed() < 2000) {
      const long before = delivered;
      std::this_thread::sleep_for(std::chrono::milliseconds(16));
      consume();
      if (delivered != before) idle.restart();
    }
    hub.stop();
    consume();
    session.finish();
    rows += static_cast<long>(session.takeOwnRows().size());

    const auto st = hub.status().front();
    state.counters["sent"] = static_cast<double>(sent);
    state.counters["delivered"] = static_cast<double>(delivered);
    state.counters["lost"] = static_cast<double>(sent - delivered);
    state.counters["dropped"] = static_cast<double>(hub.counters().dropped);
    state.counters["bad"] = static_cast<double>(st.errors());
    state.counters["ais_sent"] = aisSent;
    state.counters["ais_decoded"] = static_cast<double>(aisDecoded);
    state.counters["own_rows"] = static_cast<double>(rows);
    state.counters["batch_p50_ms"] = percentileNearestRank(batchMs, 0.50);
    state.counters["batch_p99_ms"] = percentileNearestRank(batchMs, 0.99);
    state.counters["batch_max_ms"] =
        batchMs.empty() ? 0.0 : *std::max_element(batchMs.begin(), batchMs.end());
    state.counters["peak_queue"] = static_cast<double>(hub.counters().peakQueued);
    state.counters["rss_10s_mb"] = rss10;
    state.counters["rss_peak_mb"] = rssPeak;
    state.counters["rss_end_mb"] = bench::residentMb();
  }
}
BENCHMARK(BM_LiveFeed10kPerSecond)->Arg(10000)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace
