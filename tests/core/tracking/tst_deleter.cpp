// The deleter on its own: the loss rule (seen in 5 of the last 10 sweeps) on hand-made hit/miss
// sequences, and the hold of a lost track.
#include <QTest>

#include <string>

#include "tracking/deleter.h"
#include "tracking/sweep_history.h"

using namespace reckoner;
using namespace reckoner::track;

namespace {
/// The sweep (1-based) after which the deleter declares the track lost, 0 if never; seen lists the
/// sweeps oldest first: 'x' seen, '.' missed.
int lostAfter(const HitsInWindowDeleter& rule, const std::string& seen) {
  std::uint32_t history = 0;
  int sweeps = 0;
  for (const char c : seen) {
    history = recordSweep(history, c == 'x');
    ++sweeps;
    if (rule.lost(history, sweeps)) return sweeps;
  }
  return 0;
}
}  // namespace

class TestDeleter : public QObject {
  Q_OBJECT
 private slots:
  void fiveMissesOfTenAreKept() {
    const HitsInWindowDeleter rule(5, 10, 60.0);
    QCOMPARE(lostAfter(rule, "xxxxxxxxxx"), 0);
    QCOMPARE(lostAfter(rule, "xxxxx....."), 0);
    QCOMPARE(lostAfter(rule, "x.x.x.x.x.x.x.x.x.x."), 0);
  }
  void theSixthMissInTenLosesTheTrack() {
    const HitsInWindowDeleter rule(5, 10, 60.0);
    QCOMPARE(lostAfter(rule, "xxxxx......"), 11);  // sweeps 2 to 11 hold six misses
    QCOMPARE(lostAfter(rule, "xxxxxxxxxx..x..x..x.."), 18);
  }
  void aYoungTrackIsJudgedOnTheSweepsItHas() {
    const HitsInWindowDeleter rule(5, 10, 60.0);
    QCOMPARE(lostAfter(rule, "x....."), 0);   // 5 misses of 6
    QCOMPARE(lostAfter(rule, "x......"), 7);  // 6 misses of 7
  }
  void missesOlderThanTheWindowAreForgotten() {
    const HitsInWindowDeleter rule(5, 10, 60.0);
    // Five early misses, then ten hits, then five misses: never more than five in any ten.
    QCOMPARE(lostAfter(rule, "x.....xxxxxxxxxx....."), 0);
  }
  void oneOfOneLosesOnTheFirstMiss() {
    const HitsInWindowDeleter rule(1, 1, 0.0);
    QCOMPARE(lostAfter(rule, "xxx.x"), 4);
  }
  void aLostTrackIsHeldForTheHoldTime() {
    const HitsInWindowDeleter rule(5, 10, 60.0);
    const TimeUs lost = 10'000'000;
    QVERIFY(!rule.expired(lost, lost));
    QVERIFY(!rule.expired(lost, lost + 59'999'999));
    QVERIFY(rule.expired(lost, lost + 60'000'000));
    const HitsInWindowDeleter noHold(5, 10, 0.0);
    QVERIFY(noHold.expired(lost, lost));
  }
};

QTEST_APPLESS_MAIN(TestDeleter)
#include "tst_deleter.moc"
