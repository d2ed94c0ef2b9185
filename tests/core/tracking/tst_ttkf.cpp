#include <QTest>

#include <Eigen/Eigenvalues>

#include "common/angles.h"
#include "support/compare_near.h"
#include "support/drkf_fixtures.h"
#include "tracking/track_manager.h"

using namespace reckoner;
using namespace reckoner::track;
namespace tk = reckoner::est::ttkf;

namespace {
std::shared_ptr<const TtkfContext> context(OwnShipFeed feed = OwnShipFeed::Marginal) {
  TtkfConfig c;
  c.process = {{0.05, 0.1}, {0.07, 0.1}};
  c.feed = feed;
  return std::make_shared<const TtkfContext>(c);
}

/// A random joint belief (positive definite, fully correlated).
tk::Belief randomBelief(std::uint64_t seed) {
  Rng rng(seed, 1);
  tk::Belief b;
  tk::Covariance L;
  for (int i = 0; i < 144; ++i) L(i) = rng.normal();
  b.P = L * L.transpose() + tk::Covariance::Identity();
  for (int i = 0; i < 12; ++i) b.x[i] = rng.normal(0.0, 10.0);
  return b;
}

/// Mean and covariance of the rest given the own-ship states at v.
std::pair<est::Vec<8>, est::Mat<8>> conditional(const tk::Belief& b, const est::Vec<4>& v) {
  const est::Mat<4> Pvv = b.P.topLeftCorner<4, 4>();
  const Eigen::Matrix<double, 8, 4> Prv = b.P.bottomLeftCorner<8, 4>();
  const Eigen::Matrix<double, 8, 4> K = Prv * Pvv.inverse();
  return {b.x.tail<8>() + K * (v - b.x.head<4>()), b.P.bottomRightCorner<8, 8>() - K * Prv.transpose()};
}

OwnShipInput ownInput(TimeUs t, std::uint64_t seed) {
  Rng rng(seed, 2);
  OwnShipInput o;
  o.timeUs = t;
  for (int i = 0; i < 4; ++i) o.x[i] = rng.normal(0.0, 5.0);
  est::Mat<4> L;
  for (int i = 0; i < 16; ++i) L(i) = rng.normal();
  o.P = L * L.transpose() + est::Mat<4>::Identity();
  return o;
}
}  // namespace

class TestTtkf : public QObject {
  Q_OBJECT
 private slots:
  void marginalFeedKeepsTheConditionalAndSetsTheMarginal() {
    // GIVEN a correlated joint belief WHEN the DRKF's own-ship output is fed THEN own ship's marginal is
    // exactly the DRKF's and the distribution of everything else given own ship is unchanged.
    const tk::Belief b = randomBelief(3);
    Ttkf f(context(), b, 0);
    const OwnShipInput own = ownInput(0, 4);
    const auto rep = f.feedOwnShip(own);
    QCOMPARE(rep.status, est::UpdateStatus::Accepted);
    const auto& a = f.belief();
    QVERIFY((a.x.head<4>() - own.x).norm() < 1e-12);
    QVERIFY((a.P.topLeftCorner<4, 4>() - own.P).norm() < 1e-12);
    const est::Vec<4> probe(1.0, -2.0, 0.5, 0.25);
    const auto [m0, C0] = conditional(b, probe);
    const auto [m1, C1] = conditional(a, probe);
    QVERIFY2((m0 - m1).norm() < 1e-9 * m0.norm(), qPrintable(QString::number((m0 - m1).norm())));
    QVERIFY((C0 - C1).norm() < 1e-9 * C0.norm());
    QVERIFY(Eigen::SelfAdjointEigenSolver<tk::Covariance>(a.P).eigenvalues().minCoeff() > 0.0);
  }
  void measurementFeedIsSeed000sUpdate() {
    const tk::Belief b = randomBelief(5);
    Ttkf f(context(OwnShipFeed::Measurement), b, 0);
    const OwnShipInput own = ownInput(0, 6);
    f.feedOwnShip(own);
    tk::Belief expected = b;
    est::update(expected, tk::OwnShipModel(), own.x, own.P, 0.0);
    QVERIFY((f.belief().x - expected.x).norm() < 1e-12);
    QVERIFY((f.belief().P - expected.P).norm() < 1e-12);
    // Counting the same information again: own-ship variance ends below the DRKF's.
    QVERIFY(f.belief().P(0, 0) < own.P(0, 0));
  }
  void initiationFromOnePlot() {
    // GIVEN own ship at (100, 200) moving north WHEN a plot at 5 km bearing 030 arrives 0.6 s after
    // the own-ship estimate THEN the target lies there, correlated with own-ship position, velocity unknown.
    OwnShipInput own;
    own.timeUs = 0;
    own.x << 100.0, 200.0, 0.0, 5.0;
    own.P = est::Vec<4>(25.0, 25.0, 0.04, 0.04).asDiagonal();
    const GridPlot plot{600'000, 5000.0, degToRad(30.0), 100.0, std::pow(degToRad(1.0), 2)};
    const Ttkf f = Ttkf::initiate(context(), own, plot);
    const auto& b = f.belief();
    QCOMPARE(f.timeUs(), TimeUs{600'000});
    RK_COMPARE_NEAR(b.x[tk::kOwnY], 200.0 + 3.0, 1e-6);
    RK_COMPARE_NEAR(b.x[tk::kTgtX], 100.0 + 2500.0, 1e-6);
    RK_COMPARE_NEAR(b.x[tk::kTgtY], 203.0 + 5000.0 * std::cos(degToRad(30.0)), 1e-6);
    QCOMPARE(b.x[tk::kTgtVx], 0.0);
    RK_COMPARE_NEAR(b.P(tk::kTgtVx, tk::kTgtVx), 100.0, 1e-12);
    RK_COMPARE_NEAR(b.P(tk::kTgtX, tk::kOwnX), b.P(tk::kOwnX, tk::kOwnX), 1e-12);
    // Cross-range sd ~ 5000 m * 1 deg = 87 m on top of own ship's 5 m.
    const double crossRange = std::sqrt(b.P(tk::kTgtX, tk::kTgtX) * 0.75 + b.P(tk::kTgtY, tk::kTgtY) * 0.25 -
                                        2 * std::sqrt(0.75 * 0.25) * b.P(tk::kTgtX, tk::kTgtY));
    RK_COMPARE_NEAR(crossRange, std::hypot(5000.0 * degToRad(1.0), 5.0), 1.0);
  }
  void radarUpdatesAndGates() {
    OwnShipInput own;
    own.timeUs = 0;
    own.x << 0.0, 0.0, 0.0, 5.0;
    own.P = est::Vec<4>(25.0, 25.0, 0.04, 0.04).asDiagonal();
    const double rv = 100.0, bv = std::pow(degToRad(1.0), 2);
    Ttkf f = Ttkf::initiate(context(), own, {0, 4000.0, degToRad(45.0), rv, bv});
    const double before = f.belief().P(tk::kTgtVx, tk::kTgtVx);
    // A second plot 2 s later, consistent with a target moving east at 3 m/s.
    const double tx = 4000.0 * std::sin(degToRad(45.0)) + 6.0, ty = 4000.0 * std::cos(degToRad(45.0));
    const double ox = 0.0, oy = 10.0;
    const auto rep =
        f.updateRadar({2'000'000, std::hypot(tx - ox, ty - oy), bearingOf(tx - ox, ty - oy), rv, bv});
    QCOMPARE(rep.status, est::UpdateStatus::Accepted);
    QVERIFY(rep.nis < 10.0);
    QVERIFY(f.belief().P(tk::kTgtVx, tk::kTgtVx) < before);
    // A plot 3 km away from the track is gated out and changes nothing.
    const tk::Belief b = f.belief();
    const auto out = f.updateRadar({4'000'000, 7000.0, degToRad(45.0), rv, bv});
    QCOMPARE(out.status, est::UpdateStatus::RejectedGate);
    QCOMPARE(f.timeUs(), TimeUs{4'000'000});
    QVERIFY(!f.predictTo(3'000'000));
    QCOMPARE(f.updateRadar({3'000'000, 4000.0, 0.0, rv, bv}).status, est::UpdateStatus::RejectedStale);
    QVERIFY(b.P.allFinite());
  }
  void gridConversionOfPlots() {
    const sensors::RadarPlot p{5, 1000.0, degToRad(1.0), 100.0, 1e-4};
    const GridPlot g = toGrid(p, {degToRad(2.0), 0.9996});
    RK_COMPARE_NEAR(g.bearingRad, degToRad(359.0), 1e-12);
    RK_COMPARE_NEAR(g.rangeM, 999.6, 1e-9);
    RK_COMPARE_NEAR(g.rangeVarM2, 100.0 * 0.9996 * 0.9996, 1e-9);
  }
  void bankHoldsAThousandTracks() {
    // GIVEN a bank of capacity 1000 with known association WHEN 1001 targets are seen THEN 1000
    // tracks exist, the last plot is refused and counted, the warning was raised at 95%, and one
    // own-ship input reaches every track.
    TrackManagerConfig c;
    c.filter.process = {{0.05, 0.1}, {0.07, 0.1}};
    c.association = Association::Known;
    TrackManager bank(c);
    OwnShipInput own;
    own.timeUs = 0;
    own.x << 0.0, 0.0, 0.0, 5.0;
    own.P = est::Mat<4>::Identity();
    bank.feedOwnShip(own);
    for (int id = 0; id < 1001; ++id) bank.addPlot({1000, 1000.0 + id, degToRad(0.3 * id), 100.0, 1e-4}, id);
    QCOMPARE(bank.tracks().size(), std::size_t(1000));
    QCOMPARE(bank.counters().plotsRefusedFull, 1L);
    QVERIFY(bank.capacityWarning());
    const auto events = bank.takeEvents();
    QCOMPARE(std::count_if(events.begin(), events.end(),
                           [](const TrackEvent& e) { return e.kind == TrackEvent::Kind::CapacityWarning; }),
             1L);
    QCOMPARE(events.back().kind, TrackEvent::Kind::CapacityFull);
    own.timeUs = 1'000'000;
    bank.feedOwnShip(own);
    for (const auto& t : bank.tracks()) QCOMPARE(t.filter.timeUs(), TimeUs{1'000'000});
  }
  void badConfiguration() {
    TtkfConfig c;
    c.gateProbability = 1.5;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, TtkfContext{c});
    c = TtkfConfig{};
    c.initialSpeedSdMps = 0.0;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, TtkfContext{c});
    tk::Belief b;
    b.P = tk::Covariance::Zero();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, Ttkf(context(), b, 0));
  }
};

QTEST_APPLESS_MAIN(TestTtkf)
#include "tst_ttkf.moc"
