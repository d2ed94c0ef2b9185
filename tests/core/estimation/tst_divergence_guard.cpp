// The divergence guard on its own (estimation/divergence_guard.h): what it calls a broken covariance,
// and when its NIS window trips (docs/consistency.md, "Divergence guards").
#include <QTest>

#include <cmath>

#include "common/rng.h"
#include "estimation/chi_square.h"
#include "estimation/divergence_guard.h"
#include "support/compare_near.h"

using namespace reckoner;
using est::DivergenceGuard;
using est::DivergenceReason;

namespace {

struct NisRun {
  long trips = 0;
  long firstTripAt = -1;  ///< updates before the first trip (-1: none)
  double peakMeanPerDof = 0.0;
};

/// `updates` NIS values of `dof` innovations whose true variance is `varianceRatio` times what the
/// filter claims; the guard is reset (as the filter's restart would) after every trip.
NisRun runNis(double varianceRatio, int dof, long updates, std::uint64_t seed) {
  Rng rng(seed, 3);
  DivergenceGuard g;
  NisRun r;
  const double sd = std::sqrt(varianceRatio);
  for (long k = 0; k < updates; ++k) {
    double nis = 0.0;
    for (int d = 0; d < dof; ++d) {
      const double e = sd * rng.normal();
      nis += e * e;
    }
    if (g.addNis(nis, dof)) {
      ++r.trips;
      if (r.firstTripAt < 0) r.firstTripAt = k + 1;
      if (g.reason() != DivergenceReason::Nis) r.trips = -1000000;  // reported by the callers' checks
      g.reset();
    }
  }
  r.peakMeanPerDof = g.peakWindowMeanPerDof();
  return r;
}

}  // namespace

class TestDivergenceGuard : public QObject {
  Q_OBJECT
 private slots:
  void healthyCovariancesPass() {
    // GIVEN covariances a filter may hold: the identity, states in metres beside states in radians
    // (diagonal 1e6 to 1e-12), strong correlation, and a state known exactly (zero row)
    est::Mat<3> P = est::Mat<3>::Identity();
    QVERIFY(est::checkCovariance<3>(P, nullptr, 1e-6, 1e-12).ok());
    P = est::Vec<3>(1e6, 1e-12, 4.0).asDiagonal();
    QVERIFY(est::checkCovariance<3>(P, nullptr, 1e-6, 1e-12).ok());
    P << 4.0, 1.99, 0.0, 1.99, 1.0, 0.0, 0.0, 0.0, 9.0;  // correlation 0.995
    const auto h = est::checkCovariance<3>(P, nullptr, 1e-6, 1e-12);
    QVERIFY(h.ok());
    RK_COMPARE_NEAR(h.minPivot, 1.0 - 0.995 * 0.995, 1e-12);
    P = est::Vec<3>(1.0, 0.0, 2.0).asDiagonal();
    QVERIFY(est::checkCovariance<3>(P, nullptr, 1e-6, 1e-12).ok());
  }
  void brokenCovariancesFail() {
    // GIVEN each way a covariance breaks WHEN checked THEN it fails for that reason
    est::Mat<3> P;
    P << 1.0, 2.0, 0.0, 2.0, 1.0, 0.0, 0.0, 0.0, 1.0;  // eigenvalues 3, -1, 1
    auto h = est::checkCovariance<3>(P, nullptr, 1e-6, 1e-12);
    QVERIFY(h.finite && h.symmetric && !h.positiveDefinite && !h.ok());
    P = est::Mat<3>::Identity();
    P(0, 0) = -1e-3;  // a negative variance
    QVERIFY(!est::checkCovariance<3>(P, nullptr, 1e-6, 1e-12).ok());
    P = est::Mat<3>::Identity();
    P(0, 1) = 0.1;  // not symmetric
    h = est::checkCovariance<3>(P, nullptr, 1e-6, 1e-12);
    QVERIFY(h.finite && !h.symmetric && !h.ok());
    P = est::Mat<3>::Identity();
    P(2, 2) = std::nan("");
    QVERIFY(!est::checkCovariance<3>(P, nullptr, 1e-6, 1e-12).finite);
    P << 1.0, 1.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0;  // singular: two states one
    QVERIFY(!est::checkCovariance<3>(P, nullptr, 1e-6, 1e-12).positiveDefinite);
    // ... but a state the caller masks out (modelled as exactly known) is not judged
    P = est::Mat<3>::Identity();
    P(1, 1) = -1.0;
    const std::array<bool, 3> keep{true, false, true};
    QVERIFY(est::checkCovariance<3>(P, &keep, 1e-6, 1e-12).ok());
  }
  void guardTripsOnceAndCountsItsReset() {
    DivergenceGuard g;
    est::Mat<2> bad;
    bad << 1.0, 2.0, 2.0, 1.0;
    QVERIFY(!g.checkCovariance<2>(est::Mat<2>::Identity()));
    QVERIFY(g.checkCovariance<2>(bad));
    QVERIFY(g.diverged());
    QCOMPARE(g.reason(), DivergenceReason::Covariance);
    QVERIFY(!g.checkCovariance<2>(bad));  // already marked: trips once
    g.reset();
    QVERIFY(!g.diverged());
    QCOMPARE(g.resets().covariance, 1L);
    QCOMPARE(g.resets().total(), 1L);
    // A disabled guard never trips.
    est::DivergenceGuardConfig off;
    off.enabled = false;
    DivergenceGuard quiet(off);
    QVERIFY(!quiet.checkCovariance<2>(bad));
    for (int k = 0; k < 100; ++k) QVERIFY(!quiet.addNis(1e6, 2));
  }
  void consistentInnovationsNeverTrip() {
    // GIVEN innovations drawn with exactly the covariance the filter claims (1, 2 and 8 dof) WHEN
    // 10^6 updates pass the default guard (30 updates, mean NIS per dof >= 4 above the 99.9% band,
    // 10 in a row) THEN it never trips; the largest window mean per dof is printed as the margin.
    for (const int dof : {1, 2, 8}) {
      const NisRun r = runNis(1.0, dof, 1'000'000, 11 + static_cast<std::uint64_t>(dof));
      qInfo("dof %d: %ld trips in 10^6 consistent updates, largest window mean NIS per dof %.2f", dof,
            r.trips, r.peakMeanPerDof);
      QCOMPARE(r.trips, 0L);
      QVERIFY(r.peakMeanPerDof < 3.0);
    }
    // The chance that one window of 30 consistent 2-dof updates lies above 4 per dof, from the
    // distribution itself: under 1e-30.
    QVERIFY(1.0 - est::chiSquareCdf(4.0 * 60.0, 60.0) < 1e-30);
  }
  void mildlyOptimisticFiltersDoNotTrip() {
    // GIVEN innovations twice as large in variance as claimed (the NEES of the paper's manoeuvring
    // runs reaches about twice its bound) THEN no trip either: the guard is for divergence, the
    // SENSOR NOISE caution for inconsistency.
    const NisRun r = runNis(2.0, 2, 200'000, 5);
    qInfo("variance x2: %ld trips in 2e5 updates, largest window mean per dof %.2f", r.trips,
          r.peakMeanPerDof);
    QCOMPARE(r.trips, 0L);
  }
  void farLargerInnovationsTripWithinAWindow() {
    // GIVEN innovations whose variance is 30 and 100 times what the filter claims THEN the guard trips
    // once the window is full and has been far above for 10 updates: 39 updates for 2 dof.
    for (const double ratio : {30.0, 100.0}) {
      const NisRun r = runNis(ratio, 2, 1000, 9);
      qInfo("variance x%.0f: first trip after %ld updates, %ld trips in 1000", ratio, r.firstTripAt, r.trips);
      QVERIFY(r.firstTripAt >= 39 && r.firstTripAt <= 60);
      QVERIFY(r.trips >= 15);
    }
  }
  void oneWildValueCannotCarryAWindow() {
    // GIVEN a consistent stream with one NIS of 10^9 (a wild fix) THEN no trip: each value counts at
    // most its 99.99% quantile.
    Rng rng(3, 1);
    DivergenceGuard g;
    for (int k = 0; k < 200; ++k) {
      const double a = rng.normal(), b = rng.normal();
      QVERIFY(!g.addNis(k == 50 ? 1e9 : a * a + b * b, 2));
    }
    QVERIFY(!g.diverged());
    QVERIFY(!g.addNis(std::nan(""), 2));
    QVERIFY(!g.addNis(5.0, 0));
  }
};

QTEST_APPLESS_MAIN(TestDivergenceGuard)
#include "tst_divergence_guard.moc"
