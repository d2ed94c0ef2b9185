// The hypothesiser and its gate on their own: stub predictions (relative position, velocity and
// covariance set by hand) against hand-made plots; the spatial index against the brute force; and the
// predictor's relative block against the TTKF's full prediction.
#include <QTest>

#include <algorithm>
#include <cmath>

#include "common/angles.h"
#include "common/rng.h"
#include "support/compare_near.h"
#include "tracking/cpa.h"
#include "tracking/hypothesiser.h"
#include "tracking/track_predictor.h"

using namespace reckoner;
using namespace reckoner::track;

namespace {
constexpr double kGate = 9.0;
constexpr double kRangeVarM2 = 100.0;
constexpr double kBearingVarRad2 = 1e-4;  // 100 m^2 across the beam at 1000 m

/// A plot east of own ship (bearing 90 degrees) at t seconds: its Cartesian covariance is
/// diag(kRangeVarM2, rangeM^2 kBearingVarRad2).
GridPlot plotEast(double tS, double rangeM) {
  return {fromSeconds(tS), rangeM, kPi / 2.0, kRangeVarM2, kBearingVarRad2};
}

/// A stub prediction: target at (x, y) relative to own ship, moving (vx, vy) relative, with
/// position variance pVar and velocity variance vVar on each axis, uncorrelated.
RelativePrediction stub(double x, double y, double vx, double vy, double pVar, double vVar) {
  RelativePrediction p;
  p.rel << x, y, vx, vy;
  p.P = est::Vec<4>(pVar, pVar, vVar, vVar).asDiagonal();
  return p;
}
}  // namespace

class TestHypothesiser : public QObject {
  Q_OBJECT
 private slots:
  void batchHoldsOffsetsTimesAndTheMovingFrame() {
    const PlotBatch b({plotEast(10.0, 1000.0), {fromSeconds(12.0), 500.0, 0.0, 400.0, 4e-4}},
                      est::Vec<2>(0.0, 5.0));
    QCOMPARE(b.size(), std::size_t{2});
    RK_COMPARE_NEAR(b.offsetM[0][0], 1000.0, 1e-9);
    RK_COMPARE_NEAR(b.offsetM[0][1], 0.0, 1e-9);
    RK_COMPARE_NEAR(b.offsetM[1][1], 500.0, 1e-9);
    RK_COMPARE_NEAR(b.sinceRefS[1], 2.0, 1e-12);
    RK_COMPARE_NEAR(b.movingM[1][1], 500.0 + 5.0 * 2.0, 1e-9);
    RK_COMPARE_NEAR(b.spanS, 2.0, 1e-12);
    RK_COMPARE_NEAR(b.maxRangeVarM2, 400.0, 0.0);
    RK_COMPARE_NEAR(b.maxBearingVarRad2, 4e-4, 0.0);
    // Plot 0 east: range noise along x, bearing noise along y.
    RK_COMPARE_NEAR(b.offsetCovM2[0](0, 0), kRangeVarM2, 1e-9);
    RK_COMPARE_NEAR(b.offsetCovM2[0](1, 1), 1000.0 * 1000.0 * kBearingVarRad2, 1e-6);
  }
  void admitGivesTheMissCostAndTheGateRadius() {
    const Hypothesiser h(kGate, fromSeconds(1.0));
    const PlotBatch b({plotEast(0.0, 1000.0)}, est::Vec<2>::Zero());
    const auto g = h.admit(7, 0, stub(1000.0, 0.0, 0.0, 0.0, 100.0, 1.0), b);
    QVERIFY(g.has_value());
    QCOMPARE(g->track, std::size_t{7});
    // Crr = P + R at the track's range and bearing = diag(200, 200); one plot: no time span.
    RK_COMPARE_NEAR(g->missCost, kGate + std::log(200.0 * 200.0), 1e-9);
    RK_COMPARE_NEAR(g->radiusM, std::sqrt(kGate * 200.0), 1e-9);
  }
  void aTrackWithoutAPositiveCovarianceSitsTheRoundOut() {
    const Hypothesiser h(kGate, fromSeconds(1.0));
    const PlotBatch b({plotEast(0.0, 1000.0)}, est::Vec<2>::Zero());
    QVERIFY(!h.admit(0, 0, stub(1000.0, 0.0, 0.0, 0.0, -500.0, 1.0), b).has_value());
  }
  void costIsTheSquaredDistancePlusLogDet() {
    const Hypothesiser h(kGate, fromSeconds(1.0));
    const PlotBatch b({plotEast(0.0, 1010.0)}, est::Vec<2>::Zero());
    const auto g = h.admit(0, 0, stub(1000.0, 0.0, 0.0, 0.0, 100.0, 1.0), b);
    QVERIFY(g.has_value());
    // C = diag(100 + 100, 100 + 1010^2 1e-4); d^2 = 10^2 / 200.
    const double cy = 100.0 + 1010.0 * 1010.0 * kBearingVarRad2;
    const auto c = h.cost(*g, b, 0);
    QVERIFY(c.has_value());
    RK_COMPARE_NEAR(*c, 100.0 / 200.0 + std::log(200.0 * cy), 1e-9);
  }
  void thePredictionMovesAlongTheRelativeVelocity() {
    const Hypothesiser h(kGate, fromSeconds(1.0));
    // Plot 1, 2 s after plot 0, where the track will be: d^2 = 0; C grows with dt^2 Pvv.
    const PlotBatch b({plotEast(0.0, 3000.0), plotEast(2.0, 1010.0)}, est::Vec<2>::Zero());
    const auto g = h.admit(0, 0, stub(1000.0, 0.0, 5.0, 0.0, 100.0, 1.0), b);
    QVERIFY(g.has_value());
    const double cx = 100.0 + 4.0 * 1.0 + kRangeVarM2;
    const double cy = 100.0 + 4.0 * 1.0 + 1010.0 * 1010.0 * kBearingVarRad2;
    const auto c = h.cost(*g, b, 1);
    QVERIFY(c.has_value());
    RK_COMPARE_NEAR(*c, std::log(cx * cy), 1e-9);
    QVERIFY(!h.cost(*g, b, 0).has_value());  // 2000 m away
  }
  void thePlotJustOutsideTheGateIsRefused() {
    const Hypothesiser h(kGate, fromSeconds(1.0));
    // d^2 = e^2 / 200: inside for e = 42 (8.82), outside for e = 43 (9.245).
    const auto cost = [&](double e) {
      const PlotBatch b({plotEast(0.0, 1000.0 + e)}, est::Vec<2>::Zero());
      // The stub's position covariance makes C = diag(200, 200) at this plot's range.
      RelativePrediction p = stub(1000.0, 0.0, 0.0, 0.0, 100.0, 1.0);
      p.P(1, 1) = 200.0 - (1000.0 + e) * (1000.0 + e) * kBearingVarRad2;
      const auto g = h.admit(0, 0, p, b);
      return g ? h.cost(*g, b, 0) : std::nullopt;
    };
    QVERIFY(cost(42.0).has_value());
    QVERIFY(!cost(43.0).has_value());
  }
  void oneTrackTakesOnePlotPerSweep() {
    const Hypothesiser h(kGate, fromSeconds(1.0));
    QVERIFY(!h.mayTake(0, fromSeconds(1.0)));
    QVERIFY(h.mayTake(0, fromSeconds(1.0) + 1));
  }
  void hypothesiseSkipsTakenPlotsAndRecentTracks() {
    const Hypothesiser h(kGate, fromSeconds(1.0));
    const PlotBatch b({plotEast(10.0, 1000.0), plotEast(10.5, 1005.0)}, est::Vec<2>::Zero());
    const auto g0 = h.admit(0, 0, stub(1000.0, 0.0, 0.0, 0.0, 100.0, 1.0), b);
    const auto g1 = h.admit(1, fromSeconds(9.6), stub(1000.0, 0.0, 0.0, 0.0, 100.0, 1.0), b);
    QVERIFY(g0 && g1);
    const HypothesisTable t = h.hypothesise({*g0, *g1}, b, {1, 0});
    QCOMPARE(t.plots, std::size_t{2});
    QCOMPARE(t.missCost.size(), std::size_t{2});
    RK_COMPARE_NEAR(t.missCost[1], g1->missCost, 0.0);
    // Plot 0 is taken; track 1 was updated 0.9 s before plot 1 (within the gap): only (0, 1).
    QCOMPARE(t.pairs.size(), std::size_t{1});
    QCOMPARE(t.pairs[0].track, std::size_t{0});
    QCOMPARE(t.pairs[0].plot, std::size_t{1});
  }
  void theSpatialIndexFindsEveryPairTheBruteForceFinds() {
    // 400 plots over 40 km, 30 tracks with gates of a few hundred metres: the index is used.
    Rng rng(17, 1);
    std::vector<GridPlot> plots;
    plots.reserve(400);
    for (int j = 0; j < 400; ++j)
      plots.push_back(
          {fromSeconds(0.005 * j), 1000.0 + 39000.0 * rng.uniform(), 2.0 * kPi * rng.uniform(), 400.0, 1e-6});
    const PlotBatch b(plots, est::Vec<2>(3.0, -4.0));
    const Hypothesiser h(kGate, fromSeconds(1.0));
    std::vector<GatedTrack> tracks;
    for (int i = 0; i < 30; ++i) {
      const est::Vec<2> at = b.offsetM[13 * static_cast<std::size_t>(i)];
      const auto g = h.admit(static_cast<std::size_t>(i), -fromSeconds(10.0),
                             stub(at[0] + 30.0, at[1] - 20.0, 4.0, 1.0, 900.0, 4.0), b);
      QVERIFY(g.has_value());
      tracks.push_back(*g);
    }
    const std::vector<char> taken(plots.size(), 0);
    const HypothesisTable t = h.hypothesise(tracks, b, taken);
    std::vector<std::pair<std::size_t, std::size_t>> got, want;
    for (const auto& p : t.pairs) got.emplace_back(p.track, p.plot);
    for (std::size_t i = 0; i < tracks.size(); ++i)
      for (std::size_t j = 0; j < plots.size(); ++j)
        if (h.cost(tracks[i], b, j)) want.emplace_back(i, j);
    std::sort(got.begin(), got.end());
    QVERIFY(want.size() >= tracks.size());  // each track at least its own plot
    QCOMPARE(got, want);
  }
  void predictorGivesTheTtkfsRelativeStateAtTRef() {
    TtkfConfig fc;
    fc.process = {{0.02, 0.1}, {0.05, 0.05}};
    fc.initialSpeedSdMps = 8.0;
    const auto ctx = std::make_shared<const TtkfContext>(fc);
    OwnShipInput own;
    own.timeUs = 0;
    own.x << 0.0, 0.0, 0.0, 5.0;
    own.P = est::Vec<4>(1.0, 1.0, 0.01, 0.01).asDiagonal();
    const TrackFilter f(TrackerKind::Ekf, Ttkf::initiate(ctx, own, {0, 2000.0, 1.0, 100.0, 1e-5}));
    const TimeUs tRef = fromSeconds(3.0);
    RelativePredictor predictor(*ctx, tRef);
    const RelativePrediction p = predictor.predict(f);
    const est::ttkf::Belief full = f.predicted(tRef);
    const Eigen::Matrix<double, 4, est::ttkf::kStateDim> A = relativeSelector();
    const est::Vec<4> rel = A * full.x;
    const est::Mat<4> P = A * full.P * A.transpose();
    RK_COMPARE_NEAR(p.lagS, 0.0, 0.0);
    for (int i = 0; i < 4; ++i) {
      RK_COMPARE_NEAR(p.rel[i], rel[i], 1e-9 * (1.0 + std::abs(rel[i])));
      for (int k = 0; k < 4; ++k) RK_COMPARE_NEAR(p.P(i, k), P(i, k), 1e-9 * (1.0 + std::abs(P(i, k))));
    }
  }
};

QTEST_APPLESS_MAIN(TestHypothesiser)
#include "tst_hypothesiser.moc"
