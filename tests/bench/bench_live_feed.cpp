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
#include "sim/live_session.h"
#include "source_config.h"
#include "support/ais_corpus.h"

namespace {
using namespace reckoner;

double residentMb() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

/// One second of the stream: own ship (RMC, GGA, VTG and ten HDT: a ship steaming east at 10 kn off
/// 47 N 122 W) and AIS lines from the project's corpus up to `perSecond` sentences; aisMessages
/// counts the AIS messages in it (the corpus's type 5 is two fragments, kept together).
void secondOfStream(int s, int perSecond, std::vector<std::string>& out, int& aisMessages) {
  out.clear();
  const int hh = (s / 3600) % 24, mm = (s / 60) % 60, ss = s % 60;
  // a minute of longitude is cos(latitude) nautical miles
  const double lonMin = 30.0 + knotsToMps(10.0) * s / (kMetresPerNauticalMile * std::cos(degToRad(47.5)));
  const int lonDeg = 122 - static_cast<int>(lonMin / 60.0);
  const double lonM = std::fmod(lonMin, 60.0);
  char b[160];
  std::snprintf(b, sizeof b, "GPRMC,%02d%02d%02d.00,A,4730.0000,N,%03d%07.4f,W,10.0,90.0,011226,,,A", hh, mm,
                ss, lonDeg, 60.0 - lonM);
  out.push_back(io::nmea::withChecksum(b));
  std::snprintf(b, sizeof b, "GPGGA,%02d%02d%02d.00,4730.0000,N,%03d%07.4f,W,1,09,0.9,10.0,M,-20.0,M,,", hh,
                mm, ss, lonDeg, 60.0 - lonM);
  out.push_back(io::nmea::withChecksum(b));
  out.push_back(io::nmea::withChecksum("GPVTG,90.0,T,,M,10.0,N,18.5,K,A"));
  for (int i = 0; i < 10; ++i) out.push_back(io::nmea::withChecksum("HEHDT,90.0,T"));
  static const std::vector<std::string> corpus = test::ais::corpus();
  int messages = 0;
  std::size_t k = 0;
  while (static_cast<int>(out.size()) < perSecond - 1) {
    const std::string& l = corpus[k % corpus.size()];
    out.push_back(l);
    // a first fragment of two ("!AIVDM,2,1,") is completed by the next line of the corpus
    if (l.compare(0, 11, "!AIVDM,2,1,") == 0) {
      out.push_back(corpus[(k + 1) % corpus.size()]);
      ++k;
    }
    ++messages;
    ++k;
  }
  aisMessages += messages;
}

void BM_LiveFeed10kPerSecond(benchmark::State& state) {
  const char* env = std::getenv("RECKONER_BENCH_FEED_S");
  const int seconds = env ? std::max(1, std::atoi(env)) : 60;
  const int perSecond = static_cast<int>(state.range(0));
  for (auto _ : state) {
    const int fd = ::socket(AF_INET, SOCK_DGRAM, 0);
    sockaddr_in to{};
    to.sin_family = AF_INET;
    to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    {
      // a free port: bound, read back, released
      const int probe = ::socket(AF_INET, SOCK_DGRAM, 0);
      sockaddr_in any = to;
      ::bind(probe, reinterpret_cast<sockaddr*>(&any), sizeof any);
      socklen_t len = sizeof any;
      ::getsockname(probe, reinterpret_cast<sockaddr*>(&any), &len);
      to.sin_port = any.sin_port;
      ::close(probe);
    }
    conn::ConnectionHub hub;
    hub.add(conn::parseSource("udp://127.0.0.1:" + std::to_string(ntohs(to.sin_port)) + "?name=feed"));
    hub.start();
    while (hub.status().front().state != conn::State::Connected) QCoreApplication::processEvents();

    std::atomic<bool> done{false};
    std::atomic<long> sent{0};
    int aisSent = 0;
    std::thread sender([&] {
      std::vector<std::string> lines;
      QElapsedTimer clock;
      clock.start();
      for (int s = 0; s < seconds; ++s) {
        secondOfStream(s, perSecond, lines, aisSent);
        // in 100 bursts over the second, each burst no earlier than its time
        for (std::size_t i = 0; i < lines.size(); ++i) {
          const qint64 due = s * 1000LL + static_cast<qint64>(i * 1000 / lines.size());
          while (clock.elapsed() < due) std::this_thread::sleep_for(std::chrono::microseconds(500));
          const std::string d = lines[i] + "\r\n";
          ::sendto(fd, d.data(), d.size(), 0, reinterpret_cast<const sockaddr*>(&to), sizeof to);
          sent.fetch_add(1, std::memory_order_relaxed);
        }
      }
      done = true;
    });

    sim::LiveSession session(sim::LiveOptions{});
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
      if (rss10 == 0.0 && run.elapsed() > 10000) rss10 = residentMb();
      rssPeak = std::max(rssPeak, residentMb());
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
    ::close(fd);

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
    state.counters["rss_end_mb"] = residentMb();
  }
}
BENCHMARK(BM_LiveFeed10kPerSecond)->Arg(10000)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace
