// The stream-time policy of replay (sim/stream_time.h): which timestamps are clock errors, and the order
// in which the rest is replayed.
#include <QTest>

#include <algorithm>
#include <cstddef>
#include <vector>

#include "sim/stream_time.h"

using namespace reckoner;

namespace {
constexpr UtcUs kS = 1'000'000;
std::vector<UtcUs> seconds(std::initializer_list<double> s) {
  std::vector<UtcUs> out;
  for (double v : s) out.push_back(static_cast<UtcUs>(v * kS));
  return out;
}
std::vector<UtcUs> ramp(int n, double stepS, double startS = 1000.0) {
  std::vector<UtcUs> out;
  out.reserve(static_cast<std::size_t>(std::max(n, 0)));
  for (int i = 0; i < n; ++i) out.push_back(static_cast<UtcUs>((startS + i * stepS) * kS));
  return out;
}
int flagged(const std::vector<char>& f) {
  int n = 0;
  for (char c : f) n += c;
  return n;
}
}  // namespace

class TestStreamTime : public QObject {
  Q_OBJECT
 private slots:
  void loneJumpsAreFlagged() {
    // GIVEN a 1 Hz stream with one time 20 minutes ahead, one a year back and the first 4000 years on
    // THEN exactly those three are isolated jumps.
    auto t = ramp(100, 1.0);
    t[50] += 1200 * kS;
    t[70] -= 365LL * 86400 * kS;
    t[0] += 4000LL * 365 * 86400 * kS;
    const auto f = sim::isolatedTimeJumps(t, {});
    QCOMPARE(flagged(f), 3);
    QVERIFY(f[0] && f[50] && f[70]);
  }
  void gapsAndSparseStreamsAreNot() {
    // A real gap (both sides agree with their own neighbours), sonar pings every 80 s, a short file.
    auto gap = ramp(40, 1.0);
    for (std::size_t i = 20; i < gap.size(); ++i) gap[i] += 600 * kS;
    QCOMPARE(flagged(sim::isolatedTimeJumps(gap, {})), 0);
    QCOMPARE(flagged(sim::isolatedTimeJumps(ramp(40, 80.0), {})), 0);
    QCOMPARE(flagged(sim::isolatedTimeJumps(seconds({0.0, 500.0}), {})), 0);
    QCOMPARE(flagged(sim::isolatedTimeJumps(seconds({0.0, 1.0, 2.0, 900.0}), {})), 0);  // window not full
    QVERIFY(sim::isolatedTimeJumps({}, {}).empty());
  }
  void aFewConsecutiveWrongTimesAreFlaggedAll() {
    // Three sentences of one epoch share a wrong stamp: fewer than half a window, all flagged.
    auto t = ramp(60, 0.25);
    for (int i = 30; i < 33; ++i) t[static_cast<std::size_t>(i)] += 3600 * kS;
    QCOMPARE(flagged(sim::isolatedTimeJumps(t, {})), 3);
  }
  void replayOrderIsStableAndCountsTheLate() {
    const auto t = seconds({3, 1, 2, 2, 5, 4});
    long reordered = 0;
    const std::vector<char> drop{0, 0, 0, 0, 0, 1};
    const auto order = sim::replayOrder(t, drop, reordered);
    QCOMPARE(order, (std::vector<std::size_t>{1, 2, 3, 0, 4}));
    QCOMPARE(reordered, 3L);  // 1, 2 and 2 arrived after 3
  }
};

QTEST_APPLESS_MAIN(TestStreamTime)
#include "tst_stream_time.moc"
