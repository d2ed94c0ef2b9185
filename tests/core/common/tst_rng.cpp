#include <QTest>

#include "common/rng.h"
#include "support/compare_near.h"

using namespace reckoner;

class TestRng : public QObject {
  Q_OBJECT
 private slots:
  void sameSeedSameSequence() {
    Rng a(42, 7), b(42, 7);
    for (int i = 0; i < 1000; ++i) QCOMPARE(a.normal(), b.normal());
  }
  void streamsAndSeedsDiffer() {
    Rng a(42, 1), b(42, 2), c(43, 1);
    int same = 0;
    for (int i = 0; i < 100; ++i) {
      const auto x = a.nextU64();
      same += (x == b.nextU64()) + (x == c.nextU64());
    }
    QCOMPARE(same, 0);
  }
  void normalMoments() {
    Rng r(1, 1);
    constexpr int n = 400000;
    double sum = 0, sum2 = 0, sum4 = 0;
    for (int i = 0; i < n; ++i) {
      const double v = r.normal();
      sum += v;
      sum2 += v * v;
      sum4 += v * v * v * v;
    }
    const double mean = sum / n, var = sum2 / n - mean * mean;
    RK_COMPARE_NEAR(mean, 0.0, 0.01);
    RK_COMPARE_NEAR(var, 1.0, 0.01);
    RK_COMPARE_NEAR(sum4 / n, 3.0, 0.05);  // kurtosis of a normal is 3
  }
  void uniformOpenInterval() {
    Rng r(3, 3);
    double lo = 1, hi = 0, sum = 0;
    for (int i = 0; i < 100000; ++i) {
      const double u = r.uniform();
      lo = std::min(lo, u);
      hi = std::max(hi, u);
      sum += u;
    }
    QVERIFY(lo > 0.0 && hi < 1.0);
    RK_COMPARE_NEAR(sum / 100000, 0.5, 0.005);
  }
};

QTEST_APPLESS_MAIN(TestRng)
#include "tst_rng.moc"
