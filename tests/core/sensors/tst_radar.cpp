#include <QTest>

#include "common/angles.h"
#include "sensors/radar.h"

using namespace reckoner;
using namespace reckoner::sensors;

class TestRadar : public QObject {
  Q_OBJECT
 private slots:
  void beamPassesBearingsInOrder() {
    RadarSpec spec;
    spec.sweepPeriodS = 2.0;
    RadarSimulator radar(spec, Rng(1, kStreamRadar));
    QCOMPARE(radar.beamTime(10 * kMicrosPerSecond, 0.0), 10 * kMicrosPerSecond);
    QCOMPARE(radar.beamTime(10 * kMicrosPerSecond, degToRad(90.0)), 10 * kMicrosPerSecond + 500'000);
    QCOMPARE(radar.beamTime(0, degToRad(-90.0)), TimeUs{1'500'000});  // 270 deg
  }
  void noiseMatchesTableThree() {
    RadarSpec spec;  // 10 m, 1 deg
    RadarSimulator radar(spec, Rng(2, kStreamRadar));
    const geo::GridInfo grid{degToRad(0.5), 0.9996};
    constexpr int n = 20000;
    double sr = 0, srr = 0, sb = 0, sbb = 0;
    for (int i = 0; i < n; ++i) {
      const auto p = radar.measure(i, 3000.0, 4000.0, grid);  // grid range 5000, grid bearing atan2(3, 4)
      QVERIFY(p.has_value());
      const double er = p->rangeM - 5000.0 / 0.9996;
      const double eb =
          angleDiff(p->bearingRad, std::atan2(3.0, 4.0) + degToRad(0.5));  // true = grid + gamma
      sr += er;
      srr += er * er;
      sb += eb;
      sbb += eb * eb;
    }
    QVERIFY(std::abs(sr / n) < 0.3);
    QVERIFY(std::abs(std::sqrt(srr / n) - 10.0) < 0.2);
    QVERIFY(std::abs(sb / n) < degToRad(0.03));
    QVERIFY(std::abs(std::sqrt(sbb / n) - degToRad(1.0)) < degToRad(0.02));
  }
  void detectionProbabilityAndRange() {
    RadarSpec spec;
    spec.detectionProbability = 0.9;
    spec.maxRangeM = 10000.0;
    RadarSimulator radar(spec, Rng(3, kStreamRadar));
    int seen = 0;
    for (int i = 0; i < 10000; ++i) seen += radar.measure(i, 0.0, 5000.0, {0.0, 1.0}).has_value();
    QVERIFY2(std::abs(seen / 10000.0 - 0.9) < 0.01, qPrintable(QString::number(seen)));
    QVERIFY(!radar.measure(0, 0.0, 10001.0, {0.0, 1.0}).has_value());
  }
};

QTEST_APPLESS_MAIN(TestRadar)
#include "tst_radar.moc"
