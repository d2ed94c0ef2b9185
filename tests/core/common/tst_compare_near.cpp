// RK_COMPARE_NEAR passes inside the tolerance and fails outside it, on NaN and infinity, and on a
// tolerance that is not a finite non-negative number; each failure is expected here (QEXPECT_FAIL), so a
// macro that stopped failing would make this test fail. A NearContext names its scope in the failure.
#include <QTest>

#include <limits>
#include <string>

#include "support/compare_near.h"

class TestCompareNear : public QObject {
  Q_OBJECT
 private slots:
  void passesInside() {
    RK_COMPARE_NEAR(1.0 + 1e-10, 1.0, 1e-9);
    RK_COMPARE_NEAR(-5.0, -5.5, 0.5);  // the bound itself is inside
    RK_COMPARE_NEAR(3, 3, 0);
  }
  void failsOutside() {
    QEXPECT_FAIL("", "0.1 apart with tolerance 0.05", Abort);
    RK_COMPARE_NEAR(1.1, 1.0, 0.05);
  }
  void failsOnNaN() {
    QEXPECT_FAIL("", "NaN is near nothing", Abort);
    RK_COMPARE_NEAR(std::numeric_limits<double>::quiet_NaN(), 0.0, 1e300);
  }
  void failsOnInfinity() {
    const double inf = std::numeric_limits<double>::infinity();
    QEXPECT_FAIL("", "infinity is near nothing, not even itself", Abort);
    RK_COMPARE_NEAR(inf, inf, 1.0);
  }
  void contextsNestAndEndWithTheirScope() {
    using reckoner::test::NearContext;
    QCOMPARE(NearContext::describe(), std::string());
    {
      const NearContext scenario(QStringLiteral("scenario head-on"));
      for (int i = 0; i < 2; ++i) {
        const NearContext at(QString("i = %1").arg(i));
        QCOMPARE(NearContext::describe(),
                 std::string("\n   Context: scenario head-on; i = ") + std::to_string(i));
      }
      QCOMPARE(NearContext::describe(), std::string("\n   Context: scenario head-on"));
    }
    QCOMPARE(NearContext::describe(), std::string());
  }
  void failsWithAContext() {
    const reckoner::test::NearContext at(QStringLiteral("F(2,3)"));
    QEXPECT_FAIL("", "the failure also names F(2,3)", Abort);
    RK_COMPARE_NEAR(1.1, 1.0, 0.05);
  }
  void failsOnBadTolerance() {
    QEXPECT_FAIL("", "a negative tolerance", Abort);
    RK_COMPARE_NEAR(1.0, 1.0, -1.0);
  }
};

QTEST_GUILESS_MAIN(TestCompareNear)
#include "tst_compare_near.moc"
