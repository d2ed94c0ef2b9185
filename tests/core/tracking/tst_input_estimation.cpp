// Seed 001: the relative-state EKF with bearing and range, and input-estimation manoeuvre detection.
#include <QTest>

#include <algorithm>
#include <cmath>

#include "common/angles.h"
#include "common/rng.h"
#include "estimation/chi_square.h"
#include "estimation/ekf.h"
#include "studies/seed001.h"
#include "support/compare_near.h"
#include "support/numeric_jacobian.h"
#include "tracking/input_estimation.h"

using namespace reckoner;
namespace rp = est::relpolar;

namespace {
std::vector<std::vector<studies::Seed001Sample>> monteCarlo(const studies::Seed001Scenario& sc,
                                                            const track::InputEstimationConfig& cfg,
                                                            int runs) {
  std::vector<std::vector<studies::Seed001Sample>> all;
  all.reserve(static_cast<std::size_t>(std::max(runs, 0)));
  for (int r = 0; r < runs; ++r)
    all.push_back(studies::runSeed001(sc, cfg, 1000 + static_cast<std::uint64_t>(r)));
  return all;
}
/// The paper's accuracy (range < 8%, course < 3 deg, speed < 3 m/s) as Monte Carlo means from a
/// sample on; the first miss is printed.
bool withinPapersLimits(const std::vector<studies::Seed001SampleStats>& stats, int fromSample) {
  for (const auto& s : stats) {
    if (s.index < fromSample) continue;
    if (!(s.meanRangeErrorPct < 8.0 && s.meanCourseErrorDeg < 3.0 && s.meanSpeedErrorMps < 3.0)) {
      qWarning("sample %d: %.3f%% %.2f deg %.2f m/s", s.index, s.meanRangeErrorPct, s.meanCourseErrorDeg,
               s.meanSpeedErrorMps);
      return false;
    }
  }
  return true;
}
}  // namespace

class TestInputEstimation : public QObject {
  Q_OBJECT
 private slots:
  void bearingRangeJacobianMatchesNumeric() {
    const rp::BearingRangeModel m;
    // Ordinary, due north (the 359 -> 1 degree crossing just west of it), close, and far.
    for (const rp::State& x : {rp::State(3.0, -2.0, 4000.0, -2500.0), rp::State(1.0, 1.0, -0.5, 30000.0),
                               rp::State(0.0, 0.0, 30.0, 40.0), rp::State(5.0, 5.0, -39000.0, -1000.0)}) {
      const auto numeric = est::numericJacobian<2, rp::kStateDim>(
          [&m](const rp::State& s) { return m.h(s); }, x,
          [&m](const est::Vec<2>& a, const est::Vec<2>& b) { return m.residual(a, b); });
      const double err = (numeric - m.jacobian(x)).cwiseAbs().maxCoeff();
      QVERIFY2(err < 1e-6, qPrintable(QString("Jacobian error %1").arg(err)));
    }
    // The bearing residual wraps: 359 deg measured against 1 deg predicted is -2 deg.
    RK_COMPARE_NEAR(m.residual({degToRad(359.0), 0.0}, {degToRad(1.0), 0.0})[0], degToRad(-2.0), 1e-12);
  }

  void noiseFreeStraightLineIsFollowedExactly() {
    // GIVEN exact measurements of a straight-running target from a moving observer THEN the filter's
    // state is the truth: this pins the observer-displacement term (eq. 4 with its sign corrected).
    track::InputEstimationConfig cfg;
    cfg.bearingSdRad = 1e-9;
    cfg.rangeSdM = 1e-6;
    cfg.processNoiseQ = 0.0;
    cfg.correction = track::InputEstimationConfig::Correction::None;
    track::InputEstimationEkf f(cfg);
    const double ovx = 10.0, ovy = 12.0, tvx = -3.0, tvy = 4.0;
    for (int k = 0; k < 8; ++k) {
      const double t = 60.0 * k;
      const double ox = ovx * t, oy = ovy * t, tx = 2000.0 + tvx * t, ty = 25000.0 + tvy * t;
      f.measure(fromSeconds(t), bearingOf(tx - ox, ty - oy), std::hypot(tx - ox, ty - oy), ox, oy);
    }
    const auto& x = f.belief().x;
    const double t = 420.0;
    RK_COMPARE_NEAR(x[rp::kVx], tvx, 1e-6);
    RK_COMPARE_NEAR(x[rp::kVy], tvy, 1e-6);
    RK_COMPARE_NEAR(x[rp::kRx], 2000.0 + tvx * t - ovx * t, 1e-3);
    RK_COMPARE_NEAR(x[rp::kRy], 25000.0 + tvy * t - ovy * t, 1e-3);
    QVERIFY(!f.manoeuvring());
  }

  void withoutAManoeuvreTheStatisticIsChiSquareAndTheFilterConsistent() {
    // GIVEN the paper's scenario without a turn, 100 runs, two-point initialisation WHEN input
    // estimation tests every window THEN d(u) is chi-square with 2 dof (mean 2; exceeds the 90% point
    // 4.61 in about 10% of the tests) and the NEES of the state is inside its bounds.
    track::InputEstimationConfig cfg;
    cfg.paperInitialCovariance = false;
    cfg.correction = track::InputEstimationConfig::Correction::None;  // observe d, change nothing
    const auto runs = monteCarlo(studies::Seed001Scenario{}, cfg, 100);
    double sumD = 0.0;
    int tests = 0, over = 0;
    for (const auto& run : runs)
      for (const auto& s : run)
        if (s.tested && s.index >= 6) {
          sumD += s.d;
          ++tests;
          over += s.d >= est::chiSquareQuantile(0.9, 2.0) ? 1 : 0;
        }
    const double meanD = sumD / tests, rate = static_cast<double>(over) / tests;
    qInfo("d(u) from sample 6 on: mean %.2f over %d tests, %.1f%% above 4.61", meanD, tests, 100.0 * rate);
    QVERIFY2(meanD > 1.7 && meanD < 2.5, qPrintable(QString::number(meanD)));
    QVERIFY2(rate > 0.06 && rate < 0.15, qPrintable(QString::number(rate)));
    // The paper's accuracy from the 6th sample on, as Monte Carlo means (docs/manoeuvres.md).
    const auto stats = studies::summariseSeed001(runs);
    QVERIFY(withinPapersLimits(stats, 6));
  }

  void stateNeesIsConsistentOnAStraightTrack_data() {
    QTest::addColumn<double>("bearingSdDeg");
    QTest::addColumn<int>("firstSample");
    // Where the linearisation holds (0.3 deg at 30 km: the cross-range sd, 160 m, is small against the
    // range) the NEES is inside its bounds from the 4th sample. At the paper's 1 deg (520 m) this EKF
    // is over-confident (mean NEES 6.3 to 7 against 4), as EKFs with polar measurements are at large
    // cross-range uncertainty: measured and written down in docs/manoeuvres.md, not asserted here.
    QTest::newRow("0.3 deg, 30 km") << 0.3 << 4;
  }
  void stateNeesIsConsistentOnAStraightTrack() {
    // Matched model (white acceleration as the filter assumes, here zero), two-point start: the 4-state
    // NEES averaged over 100 runs lies inside its 99% chi-square bounds.
    QFETCH(double, bearingSdDeg);
    QFETCH(int, firstSample);
    track::InputEstimationConfig cfg;
    cfg.bearingSdRad = degToRad(bearingSdDeg);
    cfg.paperInitialCovariance = false;
    cfg.correction = track::InputEstimationConfig::Correction::None;
    cfg.processNoiseQ = 0.0;  // the truth runs straight: the matched model has no process noise
    const int runs = 100;
    std::vector<double> sum(40, 0.0);
    std::vector<int> n(40, 0);
    for (int r = 0; r < runs; ++r) {
      track::InputEstimationEkf f(cfg);
      Rng rng(77, static_cast<std::uint64_t>(r));
      const double ovx = 14.0, ovy = 6.5, tvx = 5.1, tvy = -0.9;
      for (int k = 0; k < 20; ++k) {
        const double t = 80.0 * k;
        const double ox = ovx * t, oy = ovy * t, tx = tvx * t, ty = 30000.0 + tvy * t;
        const double b = wrapTwoPi(bearingOf(tx - ox, ty - oy) + rng.normal(0.0, cfg.bearingSdRad));
        const double range = std::hypot(tx - ox, ty - oy) + rng.normal(0.0, cfg.rangeSdM);
        f.measure(fromSeconds(t), b, range, ox, oy);
        if (!f.initialised() || k < 3) continue;
        const rp::State truth(tvx, tvy, tx - ox, ty - oy);
        sum[static_cast<std::size_t>(k)] += est::nees<4>(truth - f.belief().x, f.belief().P);
        ++n[static_cast<std::size_t>(k)];
      }
    }
    const double lo = est::chiSquareQuantile(0.005, 4.0 * runs) / runs;
    const double hi = est::chiSquareQuantile(0.995, 4.0 * runs) / runs;
    int outside = 0;
    for (std::size_t k = static_cast<std::size_t>(firstSample - 1); k < 20; ++k) {
      const double mean = sum[k] / n[k];
      if (mean < lo || mean > hi) {
        ++outside;
        qInfo("sample %zu: mean NEES %.2f outside [%.2f, %.2f]", k + 1, mean, lo, hi);
      }
    }
    QVERIFY2(outside <= 1, qPrintable(QString("%1 samples outside the bounds").arg(outside)));
  }

  void theTurnIsDeclaredByTheNinthSample() {
    // GIVEN the target turning from 100 to 180 deg at 540 s (3 deg/s) THEN the manoeuvre is declared at
    // the 8th or 9th sample (the paper: 9th) in at least 95 of 100 runs.
    track::InputEstimationConfig cfg;
    cfg.paperInitialCovariance = false;
    studies::Seed001Scenario sc;
    sc.turn = studies::Seed001Scenario::Turn{};
    const auto runs = monteCarlo(sc, cfg, 100);
    const auto first = studies::firstDetections(runs, sc.turn->startS);
    const auto byNinth = std::count_if(first.begin(), first.end(), [](int k) { return k > 0 && k <= 9; });
    qInfo("declared by the 9th sample in %td of 100 runs", byNinth);
    QVERIFY(byNinth >= 95);
  }

  void withCorrectionsThePapersAccuracyHoldsAndTheTurnIsRecovered() {
    // GIVEN the paper's settings (s = 2, Pfa 0.01) with the default correction (re-filtering the
    // window with a velocity jump at its likeliest time) WHEN 100 runs go straight THEN the paper's
    // accuracy holds from the 7th sample on (mean errors; at the 6th the false alarms of samples 4 to 6,
    // 1-4% of runs each, lift the mean course error to 3.0-3.8 deg over three seed sets, against
    // 2.2-2.7 deg without corrections: docs/manoeuvres.md); and WHEN the target turns
    // 80 deg at 540 s THEN the course error after the declaration falls below 10 deg by the 13th sample
    // and 2 deg by the 20th, where the paper's correction (x += M u, P += M L M') leaves 28 and 9 deg.
    track::InputEstimationConfig cfg;
    const auto straight = studies::summariseSeed001(monteCarlo(studies::Seed001Scenario{}, cfg, 100));
    QVERIFY(withinPapersLimits(straight, 7));
    studies::Seed001Scenario sc;
    sc.turn = studies::Seed001Scenario::Turn{};
    const auto courseAt = [&](track::InputEstimationConfig::Correction c, int index) {
      track::InputEstimationConfig k = cfg;
      k.correction = c;
      for (const auto& s : studies::summariseSeed001(monteCarlo(sc, k, 100)))
        if (s.index == index) return s.meanCourseErrorDeg;
      return std::nan("");
    };
    using C = track::InputEstimationConfig::Correction;
    const double r13 = courseAt(C::Refilter, 13), r20 = courseAt(C::Refilter, 20);
    const double p13 = courseAt(C::Paper, 13), p20 = courseAt(C::Paper, 20);
    qInfo(
        "after the turn, mean course error at samples 13 and 20: re-filter %.1f and %.1f deg, paper %.1f and "
        "%.1f deg",
        r13, r20, p13, p20);
    QVERIFY(r13 < 10.0 && r20 < 2.0);
    QVERIFY(r13 < p13 && r20 < p20);
  }

  void badInputIsRefused() {
    track::InputEstimationConfig cfg;
    cfg.window = 0;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, track::InputEstimationEkf{cfg});
    cfg = {};
    track::InputEstimationEkf f(cfg);
    const auto s = f.measure(0, std::nan(""), 1000.0, 0.0, 0.0);
    QCOMPARE(s.update.status, est::UpdateStatus::RejectedNonFinite);
    QVERIFY(!f.initialised());
    f.measure(0, 0.1, 1000.0, 0.0, 0.0);
    f.measure(fromSeconds(10.0), 0.1, 1000.0, 0.0, 0.0);
    QVERIFY(f.initialised());
    const auto late = f.measure(fromSeconds(5.0), 0.1, 1000.0, 0.0, 0.0);  // older than the last
    QCOMPARE(late.update.status, est::UpdateStatus::RejectedNumerical);
  }
};

QTEST_APPLESS_MAIN(TestInputEstimation)
#include "tst_input_estimation.moc"
