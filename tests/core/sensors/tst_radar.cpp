#include <QTest>

#include "common/angles.h"
#include "sensors/radar.h"
#include "support/compare_near.h"

using namespace reckoner;
using namespace reckoner::sensors;

class TestRadar : public QObject {
  Q_OBJECT
 private slots:
  void beamPassesBearingsInOrder() {
    RadarSpec spec;
    spec.sweepPeriodS = 2.0;
    RadarSimulator radar(spec, Rng(1, kStreamRadar), Rng(1, kStreamClutter));
    QCOMPARE(radar.beamTime(10 * kMicrosPerSecond, 0.0), 10 * kMicrosPerSecond);
    QCOMPARE(radar.beamTime(10 * kMicrosPerSecond, degToRad(90.0)), 10 * kMicrosPerSecond + 500'000);
    QCOMPARE(radar.beamTime(0, degToRad(-90.0)), TimeUs{1'500'000});  // 270 deg
  }
  void noiseMatchesTableThree() {
    RadarSpec spec;  // 10 m, 1 deg
    RadarSimulator radar(spec, Rng(2, kStreamRadar), Rng(2, kStreamClutter));
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
    RK_COMPARE_NEAR(sr / n, 0.0, 0.3);
    RK_COMPARE_NEAR(std::sqrt(srr / n), 10.0, 0.2);
    RK_COMPARE_NEAR(sb / n, 0.0, degToRad(0.03));
    RK_COMPARE_NEAR(std::sqrt(sbb / n), degToRad(1.0), degToRad(0.02));
  }
  void detectionProbabilityAndRange() {
    RadarSpec spec;
    spec.detectionProbability = 0.9;
    spec.maxRangeM = 10000.0;
    RadarSimulator radar(spec, Rng(3, kStreamRadar), Rng(3, kStreamClutter));
    int seen = 0;
    for (int i = 0; i < 10000; ++i) seen += radar.measure(i, 0.0, 5000.0, {0.0, 1.0}).has_value();
    RK_COMPARE_NEAR(seen / 10000.0, 0.9, 0.01);
    QVERIFY(!radar.measure(0, 0.0, 10001.0, {0.0, 1.0}).has_value());
  }
  void a823ErrorBudgetHasItsBiasSpreadAndSteps() {
    // GIVEN the A.823(19) budget: 20 m, 0.05 + 0.03 deg, +-0.05 backlash, 0.02 NM / 0.2 deg steps,
    // gyro 0.5 deg calibration with 0.12 deg scatter per sweep
    RadarSpec spec;
    spec.rangeSdM = 20.0;
    spec.bearingSdRad = degToRad(std::hypot(0.05, 0.03));
    spec.bearingBacklashRad = degToRad(0.05);
    spec.rangeQuantumM = 0.02 * 1852.0;
    spec.bearingQuantumRad = degToRad(0.2);
    spec.gyroCalibrationRad = degToRad(0.5);
    spec.gyroScatterSdRad = degToRad(0.12);
    RadarSimulator radar(spec, Rng(4, kStreamRadar), Rng(4, kStreamClutter));
    const geo::GridInfo grid{0.0, 1.0};
    constexpr int n = 40000;
    double sb = 0, sbb = 0, sr = 0, srr = 0;
    for (int i = 0; i < n; ++i) {
      radar.beginSweep(i);
      // WHEN a target at a bearing and range that fall between quantisation steps is measured
      const double b0 = degToRad(37.13), r0 = 9876.5;
      const auto p = radar.measure(i, r0 * std::sin(b0), r0 * std::cos(b0), grid);
      QVERIFY(p.has_value());
      // THEN every plot lies on the quantisation grid
      const double steps = p->rangeM / spec.rangeQuantumM;
      RK_COMPARE_NEAR(steps, std::round(steps), 1e-9);
      const double bsteps = p->bearingRad / spec.bearingQuantumRad;
      RK_COMPARE_NEAR(bsteps, std::round(bsteps), 1e-6);
      const double eb = angleDiff(p->bearingRad, b0), er = p->rangeM - r0;
      sb += eb;
      sbb += eb * eb;
      sr += er;
      srr += er * er;
    }
    // AND the bearing error has the calibration error as its mean and the summed variances as spread
    const double mb = sb / n, vb = sbb / n - mb * mb;
    RK_COMPARE_NEAR(radToDeg(mb), 0.5, 0.005);
    RK_COMPARE_NEAR(vb / spec.plotBearingVarRad2(), 1.0, 0.04);
    const double mr = sr / n, vr = srr / n - mr * mr;
    RK_COMPARE_NEAR(mr, 0.0, 0.5);
    RK_COMPARE_NEAR(vr / spec.plotRangeVarM2(), 1.0, 0.04);
    // AND the assumed variances add up the zero-mean terms only
    const double expectB = std::pow(degToRad(0.05), 2) + std::pow(degToRad(0.03), 2) +
                           std::pow(degToRad(0.05), 2) / 3 + std::pow(degToRad(0.2), 2) / 12 +
                           std::pow(degToRad(0.12), 2);
    RK_COMPARE_NEAR(spec.plotBearingVarRad2() / expectB, 1.0, 1e-12);
  }
  void clutterIsPoissonAndUniformInArea() {
    RadarSpec spec;
    spec.maxRangeM = 6000.0;
    spec.clutterMaxRangeM = 3000.0;
    spec.minRangeM = 100.0;
    spec.clutterPerKm2 = 2.0;
    RadarSimulator radar(spec, Rng(5, kStreamRadar), Rng(5, kStreamClutter));
    const double area = kPi * (3.0 * 3.0 - 0.1 * 0.1);
    constexpr int sweeps = 3000;
    double n1 = 0, n2 = 0, r2 = 0, total = 0;
    for (int k = 0; k < sweeps; ++k) {
      const TimeUs t0 = static_cast<TimeUs>(k) * 2'000'000;
      const auto plots = radar.beginSweep(t0);
      n1 += static_cast<double>(plots.size());
      n2 += static_cast<double>(plots.size() * plots.size());
      for (std::size_t i = 0; i < plots.size(); ++i) {
        const auto& p = plots[i];
        QVERIFY(p.rangeM >= 100.0 && p.rangeM <= 3000.0);
        QCOMPARE(p.timeUs, radar.beamTime(t0, p.bearingRad));  // on the beam, in time order
        if (i > 0) QVERIFY(p.timeUs >= plots[i - 1].timeUs);
        r2 += p.rangeM * p.rangeM;
        ++total;
      }
    }
    const double mean = n1 / sweeps, var = n2 / sweeps - mean * mean, expect = 2.0 * area;
    RK_COMPARE_NEAR(mean / expect, 1.0, 0.01);
    RK_COMPARE_NEAR(var / expect, 1.0, 0.06);  // Poisson
    // uniform in area: E[r^2] = (rmin^2 + rmax^2) / 2
    RK_COMPARE_NEAR(r2 / total / ((100.0 * 100.0 + 3000.0 * 3000.0) / 2.0), 1.0, 0.01);
  }
  void poissonHasItsMeanForLargeMeans() {
    Rng rng(6, 1);
    double s = 0, ss = 0;
    constexpr int n = 4000;
    for (int i = 0; i < n; ++i) {
      const double k = poisson(rng, 700.0);  // beyond where exp(-mean) underflows in one step
      s += k;
      ss += k * k;
    }
    RK_COMPARE_NEAR(s / n, 700.0, 2.0);
    RK_COMPARE_NEAR((ss / n - (s / n) * (s / n)) / 700.0, 1.0, 0.1);
    QCOMPARE(poisson(rng, 0.0), 0);
  }
  void invalidSpecsAreNamed() {
    RadarSpec spec;
    QVERIFY(spec.check().empty());
    spec.minRangeM = spec.maxRangeM;
    QVERIFY(spec.check().find("min_range") != std::string::npos);
    spec = {};
    spec.clutterPerKm2 = -1;
    QVERIFY(spec.check().find("clutter") != std::string::npos);
  }
};

QTEST_APPLESS_MAIN(TestRadar)
#include "tst_radar.moc"
