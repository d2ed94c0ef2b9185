// GIVEN / WHEN / THEN behaviour of CPA/TCPA, the optimal assignment and the ARPA track manager.
#include <QTest>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>

#include "common/angles.h"
#include "common/rng.h"
#include "support/compare_near.h"
#include "support/numeric_jacobian.h"
#include "tracking/assignment.h"
#include "tracking/coupled_drttkf.h"
#include "tracking/cpa.h"
#include "tracking/track_manager.h"

using namespace reckoner;
using namespace reckoner::track;
namespace tk = reckoner::est::ttkf;

namespace {
/// Own ship at (0, 0) heading north at 5 m/s at time t, precise.
OwnShipInput ownAt(TimeUs t, double vy = 5.0) {
  OwnShipInput o;
  o.timeUs = t;
  o.x << 0.0, vy * toSeconds(t), 0.0, vy;
  o.P = est::Vec<4>(1.0, 1.0, 0.01, 0.01).asDiagonal();
  return o;
}

/// A plot of a target at grid position (x, y) seen from own ship o at time t (noise-free).
GridPlot plotOf(TimeUs t, const OwnShipInput& o, double x, double y) {
  const double dx = x - o.x[0] - o.x[2] * toSeconds(t - o.timeUs);
  const double dy = y - o.x[1] - o.x[3] * toSeconds(t - o.timeUs);
  return {t, std::hypot(dx, dy), wrapTwoPi(bearingOf(dx, dy)), 100.0, std::pow(degToRad(0.5), 2)};
}

TrackManagerConfig config() {
  TrackManagerConfig c;
  c.filter.process = {{0.02, 0.1}, {0.05, 0.05}};
  c.filter.initialSpeedSdMps = 8.0;
  c.sweepPeriodS = 2.0;
  return c;
}

/// Drives a manager through sweeps of 2 s with own-ship inputs every second. targets(t) gives the
/// true positions; seen(k, i) whether target i is detected in sweep k. Plots are noise-free unless
/// rng is given. Returns after `sweeps` sweeps.
void drive(TrackManager& m, int sweeps,
           const std::function<std::vector<std::array<double, 2>>(double)>& targets,
           const std::function<bool(int, std::size_t)>& seen = {}, int firstSweep = 0) {
  for (int k = firstSweep; k < firstSweep + sweeps; ++k) {
    const TimeUs t0 = static_cast<TimeUs>(k) * 2'000'000;
    for (int s = 0; s < 2; ++s) {
      const TimeUs ts = t0 + TimeUs{s} * 1'000'000;
      m.feedOwnShip(ownAt(ts));
      if (s == 1) continue;  // one plot per target per sweep, half a second after the sweep start
      const auto now = targets(toSeconds(ts) + 0.5);
      std::vector<std::pair<TimeUs, GridPlot>> plots;
      for (std::size_t i = 0; i < now.size(); ++i) {
        if (seen && !seen(k, i)) continue;
        const OwnShipInput o = ownAt(ts);
        const GridPlot p = plotOf(ts + 500'000, o, now[i][0], now[i][1]);
        plots.push_back({p.timeUs, p});
      }
      for (std::size_t i = 0; i < plots.size(); ++i) m.addPlot(plots[i].second, static_cast<int>(i));
    }
    m.endSweep(t0 + 2'000'000);
  }
}

int countEvents(const std::vector<TrackEvent>& e, TrackEvent::Kind k) {
  return static_cast<int>(
      std::count_if(e.begin(), e.end(), [k](const TrackEvent& x) { return x.kind == k; }));
}
}  // namespace

class TestTrackManagement : public QObject {
  Q_OBJECT
 private slots:
  // ---- CPA / TCPA
  void cpaOfASimpleCrossing() {
    // Target 1852 m north, moving east relative at 5 m/s: CPA now, 1852 m; target 4 km east moving
    // west at 4 m/s with 1 km north offset: TCPA 1000 s, CPA 1000 m.
    const est::Mat<4> P = est::Mat<4>::Identity();
    Cpa c = cpaOf(est::Vec<4>(0.0, 1852.0, 5.0, 0.0), P);
    QVERIFY(c.defined);
    RK_COMPARE_NEAR(c.tcpaS, 0.0, 1e-9);
    RK_COMPARE_NEAR(c.cpaM, 1852.0, 1e-9);
    c = cpaOf(est::Vec<4>(4000.0, 1000.0, -4.0, 0.0), P);
    RK_COMPARE_NEAR(c.tcpaS, 1000.0, 1e-9);
    RK_COMPARE_NEAR(c.cpaM, 1000.0, 1e-9);
    // Opening target: negative TCPA (the closest approach is past).
    QVERIFY(cpaOf(est::Vec<4>(4000.0, 1000.0, 4.0, 0.0), P).tcpaS < 0.0);
    // No relative motion: CPA is the present range, undefined TCPA.
    c = cpaOf(est::Vec<4>(300.0, 400.0, 0.0, 0.0), P);
    QVERIFY(!c.defined);
    QCOMPARE(c.cpaM, 500.0);
    RK_COMPARE_NEAR(c.sdCpaM, 1.0, 1e-12);
  }
  void cpaJacobianMatchesNumeric() {
    for (const est::Vec<4>& rel :
         {est::Vec<4>(4000.0, 1000.0, -4.0, 0.3), est::Vec<4>(-2500.0, 7000.0, 3.0, -6.0),
          est::Vec<4>(10.0, -300.0, 0.5, 2.0)}) {
      const auto f = [](const est::Vec<4>& x) {
        const Cpa c = cpaOf(x, est::Mat<4>::Identity());
        return est::Vec<2>(c.cpaM, c.tcpaS);
      };
      const est::MatRC<2, 4> J = cpaJacobian(rel), N = est::numericJacobian<2, 4>(f, rel);
      QVERIFY2((J - N).cwiseAbs().maxCoeff() < 1e-5 * std::max(1.0, N.cwiseAbs().maxCoeff()),
               qPrintable(QString::number((J - N).cwiseAbs().maxCoeff())));
    }
  }
  void cpaStandardDeviationsMatchMonteCarlo() {
    // GIVEN a relative state and covariance WHEN samples are drawn THEN the spread of CPA and TCPA
    // matches the first-order sds (small covariance: linear regime).
    const est::Vec<4> rel(6000.0, 2000.0, -5.0, -0.5);
    est::Mat<4> P = est::Vec<4>(400.0, 400.0, 0.01, 0.01).asDiagonal();
    P(0, 2) = P(2, 0) = 0.5;
    const Cpa c = cpaOf(rel, P);
    const Eigen::LLT<est::Mat<4>> llt(P);
    const est::Mat<4> L = llt.matrixL();
    Rng rng(11, 1);
    double s1 = 0, s2 = 0, t1 = 0, t2 = 0;
    constexpr int n = 20000;
    for (int i = 0; i < n; ++i) {
      est::Vec<4> z;
      for (int k = 0; k < 4; ++k) z[k] = rng.normal();
      const Cpa d = cpaOf(rel + L * z, P);
      s1 += d.cpaM;
      s2 += d.cpaM * d.cpaM;
      t1 += d.tcpaS;
      t2 += d.tcpaS * d.tcpaS;
    }
    const double sdC = std::sqrt(s2 / n - std::pow(s1 / n, 2)), sdT = std::sqrt(t2 / n - std::pow(t1 / n, 2));
    RK_COMPARE_NEAR(sdC / c.sdCpaM, 1.0, 0.05);
    RK_COMPARE_NEAR(sdT / c.sdTcpaS, 1.0, 0.05);
  }
  void cpaSpreadOnACollisionCourse() {
    // GIVEN a head-on geometry (CPA 0) WHEN the CPA of draws from the covariance is taken THEN the
    // reported sd is the RMS of those CPAs (the first-order gradient would say 0).
    const est::Vec<4> rel(0.0, 8000.0, 0.0, -10.0);
    const est::Mat<4> P = est::Vec<4>(400.0, 400.0, 0.01, 0.01).asDiagonal();
    const Cpa c = cpaOf(rel, P);
    QVERIFY(c.cpaM < 1e-9);
    const Eigen::LLT<est::Mat<4>> llt(P);
    const est::Mat<4> L = llt.matrixL();
    Rng rng(12, 1);
    double s2 = 0;
    constexpr int n = 20000;
    for (int i = 0; i < n; ++i) {
      est::Vec<4> z;
      for (int k = 0; k < 4; ++k) z[k] = rng.normal();
      s2 += std::pow(cpaOf(rel + L * z, P).cpaM, 2);
    }
    RK_COMPARE_NEAR(std::sqrt(s2 / n) / c.sdCpaM, 1.0, 0.05);
  }
  void kinematicsInTrueTerms() {
    tk::Belief b;
    b.x.setZero();
    b.x[tk::kOwnVy] = 5.0;
    b.x[tk::kTgtX] = 1000.0;
    b.x[tk::kTgtVx] = 5.0;  // target east at 5 m/s, own north at 5 m/s
    b.P = tk::Covariance::Identity() * 0.01;
    const auto k = kinematicsOf(b, degToRad(1.0));
    RK_COMPARE_NEAR(radToDeg(k.trueCourseRad), 91.0, 1e-9);
    RK_COMPARE_NEAR(k.speedMps, 5.0, 1e-12);
    RK_COMPARE_NEAR(radToDeg(k.relativeCourseRad), 136.0, 1e-9);  // (5, -5) relative: 135 + 1
    RK_COMPARE_NEAR(k.relativeSpeedMps, std::sqrt(50.0), 1e-12);
    RK_COMPARE_NEAR(radToDeg(k.trueBearingRad), 91.0, 1e-9);
    RK_COMPARE_NEAR(k.sdSpeedMps, 0.1, 1e-12);
  }

  // ---- coupled filter
  void coupledFilterWithoutTargetsIsTheDrkf() {
    // GIVEN the coupled filter and a DRKF from the same belief WHEN fed the same samples THEN with no
    // target they agree exactly; a target's initiation puts it at the plot with own position's
    // covariance plus the converted plot's.
    nav::DrkfConfig dc;
    dc.process.current = {0.1, 0.1};
    dc.process.acceleration = {0.05, 0.1};
    dc.process.loranError = {30.0, 0.25};
    dc.process.speedlogError = {0.1, 0.5};
    const geo::LocalFrame frame(47.0, -122.0);
    est::drkf::Belief b;
    b.x.setZero();
    b.x[est::drkf::kVelY] = 5.0;
    b.P = nav::initialCovariance(dc.process, 10.0, 0.3);
    nav::Drkf d(dc, frame, b, 0);
    CoupledConfig cc;
    cc.own = dc;
    CoupledDrttkf c(cc, frame, b, 0);
    for (int k = 1; k <= 5; ++k) {
      const TimeUs t = k * kMicrosPerSecond;
      const std::vector<sensors::OwnShipSample> s{
          sensors::GpsSample{t, {0.3 * k, 5.0 * k + 1.0}, 25.0, true, 0.0, 5.0, 0.01},
          sensors::GyroSample{t, 0.01, 1e-4}};
      d.update(t, s);
      c.updateOwnShip(t, s);
    }
    QVERIFY((c.ownShip().x - d.belief().x).cwiseAbs().maxCoeff() < 1e-9);
    QVERIFY((c.ownShip().P - d.belief().P).cwiseAbs().maxCoeff() < 1e-9);
    const GridPlot p{5 * kMicrosPerSecond, 1000.0, 0.0, 100.0, 1e-4};
    QCOMPARE(c.updateRadar(7, p).status, est::UpdateStatus::Accepted);
    QCOMPARE(c.dim(), est::drkf::kStateDim + 6);  // 13 own-ship states (11 of seed 000, 2 calibration)
    QCOMPARE(c.indexOf(7), 0);
    RK_COMPARE_NEAR(c.target(0)[1], d.belief().x[est::drkf::kPosY] + 1000.0, 1e-9);
    const double expectVarX = d.belief().P(est::drkf::kPosX, est::drkf::kPosX) + 1e-4 * 1000.0 * 1000.0;
    RK_COMPARE_NEAR(c.targetCovariance(0)(0, 0), expectVarX, 1e-6);
    // A second plot updates it and shrinks its position variance.
    const double before = c.targetCovariance(0)(1, 1);
    QCOMPARE(c.updateRadar(7, {7 * kMicrosPerSecond, 1000.0 - 10.0, 0.0, 100.0, 1e-4}).status,
             est::UpdateStatus::Accepted);
    QVERIFY(c.targetCovariance(0)(1, 1) < before + 200.0);
  }

  // ---- optimal assignment
  void assignmentIsOptimalNotGreedy() {
    // Greedy takes (0,0) at cost 1 and then row 1 must miss (cost 10): total 11. Optimal: (0,1) +
    // (1,0) = 2 + 2 = 4.
    const double inf = std::numeric_limits<double>::infinity();
    const auto sol = solveAssignment({1.0, 2.0, 2.0, inf}, 2, 2, {10.0, 10.0});
    QCOMPARE(sol, (std::vector<int>{1, 0}));
    // A row whose best pair costs more than missing stays unassigned.
    QCOMPARE(solveAssignment({5.0}, 1, 1, {3.0}), std::vector<int>{-1});
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, solveAssignment({1.0}, 1, 2, {1.0}));
  }
  void assignmentMatchesBruteForce() {
    Rng rng(3, 1);
    for (int trial = 0; trial < 300; ++trial) {
      const std::size_t rows = 1 + static_cast<std::size_t>(rng.uniform() * 5);
      const std::size_t cols = 1 + static_cast<std::size_t>(rng.uniform() * 5);
      std::vector<double> cost(rows * cols), miss(rows);
      for (auto& c : cost)
        c = rng.uniform() < 0.3 ? std::numeric_limits<double>::infinity() : 10.0 * rng.uniform();
      for (auto& m : miss) m = 6.0 * rng.uniform();
      const auto total = [&](const std::vector<int>& a) {
        double s = 0;
        for (std::size_t i = 0; i < rows; ++i)
          s += a[i] < 0 ? miss[i] : cost[i * cols + static_cast<std::size_t>(a[i])];
        return s;
      };
      // Brute force over every partial injection rows -> cols.
      double best = std::numeric_limits<double>::infinity();
      std::vector<int> cur(rows, -1);
      std::function<void(std::size_t, std::vector<bool>&)> rec = [&](std::size_t i, std::vector<bool>& used) {
        if (i == rows) {
          best = std::min(best, total(cur));
          return;
        }
        cur[i] = -1;
        rec(i + 1, used);
        for (std::size_t j = 0; j < cols; ++j) {
          if (used[j] || !std::isfinite(cost[i * cols + j])) continue;
          used[j] = true;
          cur[i] = static_cast<int>(j);
          rec(i + 1, used);
          used[j] = false;
        }
        cur[i] = -1;
      };
      std::vector<bool> used(cols, false);
      rec(0, used);
      const auto sol = solveAssignment(cost, rows, cols, miss);
      std::vector<bool> taken(cols, false);
      for (int j : sol) {
        if (j < 0) continue;
        QVERIFY(!taken[static_cast<std::size_t>(j)]);
        taken[static_cast<std::size_t>(j)] = true;
      }
      const test::NearContext at(QString("trial %1").arg(trial));
      RK_COMPARE_NEAR(total(sol), best, 1e-9);
      // The sparse clustered solver gives the same total.
      GnnProblem g(rows, cols, miss);
      for (std::size_t i = 0; i < rows; ++i)
        for (std::size_t j = 0; j < cols; ++j) g.addPair(i, j, cost[i * cols + j]);
      RK_COMPARE_NEAR(total(g.solve()), best, 1e-9);
    }
  }

  // ---- track manager
  void tracksAreConfirmedAfterMOfN() {
    // GIVEN two targets seen every sweep WHEN swept THEN each gets one track, tentative for two
    // sweeps and confirmed at the third (3 of 5), with Acquired and Confirmed events.
    TrackManager m(config());
    const auto targets = [](double t) {
      return std::vector<std::array<double, 2>>{{3000.0 + 4.0 * t, 2000.0}, {-2000.0, 5000.0 - 3.0 * t}};
    };
    drive(m, 2, targets);
    QCOMPARE(m.tracks().size(), std::size_t(2));
    for (const auto& t : m.tracks()) QCOMPARE(t.status, TrackStatus::Tentative);
    drive(m, 1, targets, {}, 2);
    for (const auto& t : m.tracks()) QCOMPARE(t.status, TrackStatus::Confirmed);
    const auto ev = m.takeEvents();
    QCOMPARE(countEvents(ev, TrackEvent::Kind::Acquired), 2);
    QCOMPARE(countEvents(ev, TrackEvent::Kind::Confirmed), 2);
    drive(m, 30, targets, {}, 3);
    QCOMPARE(m.tracks().size(), std::size_t(2));
    QCOMPARE(m.counters().tracksStarted, 2L);
    for (const auto& t : m.tracks()) {
      const auto b = m.beliefAt(t, 66'000'000);
      const auto truth = targets(66.0)[static_cast<std::size_t>(t.tag())];
      QVERIFY(std::hypot(b.x[tk::kTgtX] - truth[0], b.x[tk::kTgtY] - truth[1]) < 30.0);
    }
  }
  void aTrackIsLostAfterTooManyMissesAndKeptForAWhile() {
    // GIVEN a confirmed track WHEN its target is seen in only 4 of the next sweeps' 10 THEN it is
    // declared lost (event), shown at its last position, and removed after the hold time.
    TrackManagerConfig c = config();
    c.lostHoldS = 10.0;
    TrackManager m(c);
    const auto targets = [](double t) {
      return std::vector<std::array<double, 2>>{{3000.0, 1000.0 + 5.0 * t}};
    };
    drive(m, 10, targets);
    QCOMPARE(m.tracks().front().status, TrackStatus::Confirmed);
    m.takeEvents();
    // Misses 5 in a row are tolerated (5 of 10 still seen) ...
    drive(
        m, 5, targets, [](int, std::size_t) { return false; }, 10);
    QCOMPARE(m.tracks().front().status, TrackStatus::Confirmed);
    // ... the sixth miss is not.
    drive(
        m, 1, targets, [](int, std::size_t) { return false; }, 15);
    QCOMPARE(m.tracks().front().status, TrackStatus::Lost);
    const auto ev = m.takeEvents();
    QCOMPARE(countEvents(ev, TrackEvent::Kind::Lost), 1);
    const auto last = m.beliefAt(m.tracks().front(), 40'000'000);
    QCOMPARE(last.x, m.tracks().front().lastUpdate.x);  // last position kept, not coasted on
    RK_COMPARE_NEAR(last.x[tk::kTgtY], 1000.0 + 5.0 * 19.5, 20.0);
    drive(
        m, 5, targets, [](int, std::size_t) { return false; }, 16);
    QVERIFY(m.tracks().empty());
    QCOMPARE(countEvents(m.takeEvents(), TrackEvent::Kind::Removed), 1);
  }
  void clutterTracksAreDroppedAndOnlyZonesAcquire() {
    // GIVEN random plots (clutter) each seen once WHEN swept THEN tentative tracks start from them and
    // are dropped without ever being confirmed.
    TrackManager m(config());
    Rng rng(5, 1);
    drive(m, 20, [&](double) {
      std::vector<std::array<double, 2>> v;
      v.reserve(5);
      for (int i = 0; i < 5; ++i)
        v.push_back({20000.0 * (rng.uniform() - 0.5), 20000.0 * (rng.uniform() - 0.5)});
      return v;
    });
    QCOMPARE(m.counters().tracksConfirmed, 0L);
    QCOMPARE(m.counters().tracksStarted, 100L);  // 5 plots a sweep, 20 sweeps
    // A tentative track is dropped as soon as 3 of 5 is out of reach (after its 4th sweep): all but
    // the youngest are gone.
    QCOMPARE(m.counters().tracksDropped + static_cast<long>(m.tracks().size()), 100L);
    QVERIFY(m.tracks().size() <= 15);
    // GIVEN an acquisition zone 000-090 deg within 5 km WHEN targets lie inside and outside THEN only
    // the one inside gets a track.
    TrackManagerConfig c = config();
    c.zones = {{0.0, 5000.0, 0.0, degToRad(90.0)}};
    TrackManager z(c);
    drive(z, 3, [](double) {
      return std::vector<std::array<double, 2>>{{2000.0, 2000.0}, {-2000.0, 2000.0}, {6000.0, 6000.0}};
    });
    QCOMPARE(z.tracks().size(), std::size_t(1));
    QCOMPARE(z.tracks().front().tag(), 0);
    QVERIFY(AcquisitionZone({0.0, 100.0, degToRad(350.0), degToRad(10.0)}).contains(50.0, degToRad(5.0)));
    QVERIFY(!AcquisitionZone({0.0, 100.0, degToRad(350.0), degToRad(10.0)}).contains(50.0, degToRad(20.0)));
  }
  void manualAcquisitionAndCancellation() {
    // GIVEN automatic acquisition off WHEN two targets are swept THEN no track starts; acquiring near
    // one starts a manual track on it, far from any plot nothing; cancel removes one, cancelAll all.
    TrackManagerConfig c = config();
    c.autoAcquire = false;
    TrackManager m(c);
    const auto targets = [](double t) {
      return std::vector<std::array<double, 2>>{{3000.0 + 2.0 * t, 2000.0}, {-2000.0, 5000.0}};
    };
    drive(m, 2, targets);
    QVERIFY(m.tracks().empty());
    QVERIFY(!m.acquire(10000.0, 10000.0).has_value());
    const auto id = m.acquire(3010.0, 1990.0);
    QVERIFY(id.has_value());
    QVERIFY(m.tracks().front().manual);
    QCOMPARE(m.tracks().front().tag(), 0);
    const auto id2 = m.acquire(-2000.0, 5000.0);
    QVERIFY(id2.has_value());
    drive(m, 4, targets, {}, 2);
    QCOMPARE(m.tracks().size(), std::size_t(2));
    for (const auto& t : m.tracks()) QCOMPARE(t.status, TrackStatus::Confirmed);
    QVERIFY(m.cancel(*id));
    QVERIFY(!m.cancel(*id));
    QCOMPARE(m.tracks().size(), std::size_t(1));
    m.cancelAll();
    QVERIFY(m.tracks().empty());
    QCOMPARE(m.activeCount(), std::size_t(0));
    QCOMPARE(countEvents(m.takeEvents(), TrackEvent::Kind::Cancelled), 2);
  }
  void crossingTargetsKeepTheirTracks() {
    // GIVEN two targets crossing 150 m apart at right angles, seen with Pd 0.9 and noise WHEN tracked
    // through the crossing THEN each track still follows its own target afterwards (GNN, no swap).
    TrackManager m(config());
    Rng rng(9, 2);
    const auto targets = [](double t) {
      return std::vector<std::array<double, 2>>{{-1500.0 + 6.0 * t, 4000.0},
                                                {150.0, 2500.0 + 6.0 * t + 5.0 * t * 0}};
    };
    drive(m, 150, targets, [&](int, std::size_t) { return rng.uniform() < 0.9; });
    int following = 0;
    for (const auto& t : m.tracks()) {
      if (t.status != TrackStatus::Confirmed) continue;
      const auto b = m.beliefAt(t, 300'000'000);
      const auto truth = targets(300.0)[static_cast<std::size_t>(t.tag())];
      following += std::hypot(b.x[tk::kTgtX] - truth[0], b.x[tk::kTgtY] - truth[1]) < 50.0;
      QCOMPARE(t.id, t.tag() + 1);  // first two tracks, in target order: no swap, no restart
    }
    QCOMPARE(following, 2);
  }
  void dangerousTargetIsFlagged() {
    // GIVEN a target closing head-on (CPA 0, TCPA ~ 10 min) and one passing 3 NM off WHEN tracked
    // THEN only the first is dangerous, with one Dangerous event.
    TrackManager m(config());
    const auto targets = [](double t) {
      return std::vector<std::array<double, 2>>{{0.0, 6000.0 - 5.0 * t}, {5556.0, 3000.0 - 5.0 * t}};
    };
    drive(m, 10, targets);
    int dangerous = 0;
    for (const auto& t : m.tracks()) {
      if (t.dangerous) {
        ++dangerous;
        QCOMPARE(t.tag(), 0);
      }
    }
    QCOMPARE(dangerous, 1);
    QCOMPARE(countEvents(m.takeEvents(), TrackEvent::Kind::Dangerous), 1);
  }
  void stalePlotsAndBadConfigurations() {
    TrackManager m(config());
    m.addPlot({0, 1000.0, 0.0, 100.0, 1e-4});  // before any own-ship input
    QCOMPARE(m.counters().plotsStale, 1L);
    m.feedOwnShip(ownAt(2'000'000));
    m.addPlot({1'000'000, 1000.0, 0.0, 100.0, 1e-4});  // older than the own-ship input
    QCOMPARE(m.counters().plotsStale, 2L);
    TrackManagerConfig c = config();
    c.confirmHits = 6;  // more than N
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, TrackManager{c});
    c = config();
    c.filter.gateProbability = 0.0;  // GNN without a gate
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, TrackManager{c});
    c = config();
    c.zones = {{5000.0, 1000.0, 0.0, 0.0}};
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, TrackManager{c});
  }
};

QTEST_APPLESS_MAIN(TestTrackManagement)
#include "tst_track_management.moc"
