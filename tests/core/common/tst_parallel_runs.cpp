// The Monte Carlo pool (core/common/parallel_runs.h): every index once, the lowest failure rethrown
// after all have finished, and the light libraries it runs (grid, geodesic, NMEA, AIS) giving the same
// answers on four threads as on one. This is CI's ThreadSanitizer job (label tsan, docs/robustness.md
// "Sanitizers"): built without the engine, so the sanitizer build stays inside CI's budget; the engine
// itself on the pool is tst_parallel_engine, in the release job (label tsan-full).
// A plain program, not a Qt Test: QtTest's watchdog thread is stopped through Qt's own futexes, which
// TSan cannot see, and it reports the watchdog's teardown in every Qt Test it runs.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <variant>
#include <vector>

#include "common/parallel_runs.h"
#include "geo/geodesic.h"
#include "geo/local_frame.h"
#include "io/ais.h"
#include "io/nmea.h"
#include "support/ais_corpus.h"

using namespace reckoner;

namespace {

/// One run's work: a grid round trip through a frame shared by every thread, a geodesic, an NMEA
/// sentence and an AIS message decoded by the run's own decoder. Every value depends on i.
struct Answer {
  double east = 0.0, north = 0.0, lat = 0.0, lon = 0.0, rangeM = 0.0, bearingRad = 0.0, nmeaLat = 0.0;
  double aisLat = 0.0, aisLon = 0.0;
  long long mmsi = 0;
  bool operator==(const Answer&) const = default;
};

Answer work(int i, const geo::LocalFrame& frame) {
  Answer a;
  const double dLat = 0.001 * (i % 97), dLon = 0.0013 * (i % 89);
  const geo::GridPoint g = frame.toLocal({50.0 + dLat, -1.0 + dLon});
  a.east = g.xM;
  a.north = g.yM;
  const geo::GeoPoint back = frame.toGeodetic(g);
  a.lat = back.latDeg;
  a.lon = back.lonDeg;
  const geo::RangeBearing rb = geo::rangeBearing({50.0, -1.0}, {50.0 + dLat, -1.0 + dLon});
  a.rangeM = rb.rangeM;
  a.bearingRad = rb.trueBearingRad;
  char body[96];
  std::snprintf(body, sizeof body, "GPGLL,50%02d.%03d,N,00100.000,W,120000.00,A,A", i % 60, i % 1000);
  const io::nmea::ParseResult p = io::nmea::parse(io::nmea::withChecksum(body));
  if (p.sentence)
    if (const auto* gll = std::get_if<io::nmea::Gll>(&p.sentence->body)) a.nmeaLat = gll->latDeg;
  io::AisDecoder decoder;
  const long long mmsi = 232000000LL + i;
  const auto m = decoder.feed(test::ais::sentence(
      test::ais::classA(1, mmsi, 0, 0, 100 + i % 50, static_cast<long long>((-1.0 + dLon) * 600000.0),
                        static_cast<long long>((50.0 + dLat) * 600000.0), 900, 90)));
  if (m) {
    a.mmsi = m->mmsi;
    a.aisLat = m->latDeg.value_or(NAN);
    a.aisLon = m->lonDeg.value_or(NAN);
  }
  return a;
}

int failures = 0;

void check(bool ok, const char* what, int line) {
  if (ok) return;
  std::fprintf(stderr, "FAIL line %d: %s\n", line, what);
  ++failures;
}
#define CHECK(cond) check((cond), #cond, __LINE__)

void everyIndexRunsExactlyOnce() {
  for (const int threads : {1, 2, 4, 16}) {
    constexpr int kRuns = 2000;
    std::vector<int> hits(kRuns, 0);
    std::atomic<int> total{0};
    parallelRuns(kRuns, threads, [&](int i) {
      ++hits[static_cast<std::size_t>(i)];  // each index its own slot
      ++total;
    });
    CHECK(total.load() == kRuns);
    CHECK(std::all_of(hits.begin(), hits.end(), [](int h) { return h == 1; }));
  }
}

void noRunsAndOneThreadStayOnTheCallersThread() {
  int calls = 0;
  parallelRuns(0, 4, [&](int) { ++calls; });
  parallelRuns(-3, 4, [&](int) { ++calls; });
  CHECK(calls == 0);
  const std::thread::id caller = std::this_thread::get_id();
  std::vector<std::thread::id> ids(10);
  parallelRuns(10, 1, [&](int i) { ids[static_cast<std::size_t>(i)] = std::this_thread::get_id(); });
  CHECK(std::all_of(ids.begin(), ids.end(), [&](std::thread::id id) { return id == caller; }));
}

void theLowestFailingIndexIsRethrownAfterEveryRunHasFinished() {
  std::vector<int> done(64, 0);
  std::string caught;
  try {
    parallelRuns(64, 4, [&](int i) {
      if (i == 41 || i == 17 || i == 60) throw std::runtime_error("run " + std::to_string(i));
      done[static_cast<std::size_t>(i)] = 1;
    });
  } catch (const std::runtime_error& e) {
    caught = e.what();
  }
  CHECK(caught == "run 17");
  CHECK(std::count(done.begin(), done.end(), 1) == 61);
}

void theLightLibrariesGiveOnFourThreadsWhatTheyGiveOnOne() {
  const geo::LocalFrame frame(50.0, -1.0);
  constexpr int kRuns = 400;
  std::vector<Answer> serial(kRuns), parallel(kRuns);
  for (int i = 0; i < kRuns; ++i) serial[static_cast<std::size_t>(i)] = work(i, frame);
  parallelRuns(kRuns, 4, [&](int i) { parallel[static_cast<std::size_t>(i)] = work(i, frame); });
  int differ = 0, undone = 0;
  for (int i = 0; i < kRuns; ++i) {
    const Answer& s = serial[static_cast<std::size_t>(i)];
    if (!(s == parallel[static_cast<std::size_t>(i)])) ++differ;
    // The work was done, not defaulted.
    if (s.mmsi != 232000000LL + i || !std::isfinite(s.rangeM) || !std::isfinite(s.east) ||
        !std::isfinite(s.aisLat) || s.nmeaLat < 50.0)
      ++undone;
  }
  CHECK(differ == 0);
  CHECK(undone == 0);
}

}  // namespace

int main() {
  const std::pair<const char*, void (*)()> tests[] = {
      {"everyIndexRunsExactlyOnce", everyIndexRunsExactlyOnce},
      {"noRunsAndOneThreadStayOnTheCallersThread", noRunsAndOneThreadStayOnTheCallersThread},
      {"theLowestFailingIndexIsRethrownAfterEveryRunHasFinished",
       theLowestFailingIndexIsRethrownAfterEveryRunHasFinished},
      {"theLightLibrariesGiveOnFourThreadsWhatTheyGiveOnOne",
       theLightLibrariesGiveOnFourThreadsWhatTheyGiveOnOne},
  };
  for (const auto& [name, fn] : tests) {
    const int before = failures;
    fn();
    std::printf("%s %s\n", failures == before ? "PASS" : "FAIL", name);
  }
  std::printf("%d failure(s)\n", failures);
  return failures == 0 ? 0 : 1;
}
