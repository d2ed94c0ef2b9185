// The one row builder (sim/run_rows.h): own-ship, track, radar-fix and plot rows of a SimFrame, checked
// against the frame itself with sums written here, and the engine's dead-reckoning flag against the
// rule recomputed from the frames' update reports.
#include <QTest>

#include <Eigen/LU>
#include <cmath>

#include "common/angles.h"
#include "files/scenario_json.h"
#include "navigation/dr_horizon.h"
#include "resources/embedded.h"
#include "sim/run_rows.h"
#include "sim/scenario_run.h"
#include "support/compare_near.h"

using namespace reckoner;
using namespace reckoner::sim;

namespace {
Scenario builtin(const char* name) {
  const auto* f = resources::findScenario(name);
  if (!f) qFatal("no built-in scenario %s", name);
  return files::parseScenario(f->text, std::string("builtin:") + name);
}

/// e^T P^-1 e by an explicit inverse (not the LDLT the builder uses).
template <int N>
double neesByInverse(const est::Vec<N>& e, const est::Mat<N>& P) {
  return e.dot(P.inverse() * e);
}
}  // namespace

class TestRunRows : public QObject {
  Q_OBJECT
 private slots:
  void ownShipRowsAreTheFramesFigures() {
    // GIVEN the default scenario's engine WHEN 60 steps are turned into rows THEN each row holds the
    // frame's truth over ground, the DRKF's ground state and the square roots of its covariance, the
    // DRKF NEES and the rows applied; the detail row the current, Loran-C and log states with their sds
    // and the 95% radius.
    const Scenario s = builtin("default");
    SimulationEngine e(s, 1);
    const auto& process = e.drkf().config().process;
    for (int k = 0; k < 60; ++k) {
      const SimFrame f = e.step();
      const OwnShipRow r = makeRow(f, e.frame(), process);
      const OwnShipDetailRow d = ownShipDetailRow(f);
      using namespace est::drkf;
      const auto& x = f.estimate.x;
      const auto& P = f.estimate.P;
      const auto& t = f.trueState;
      QCOMPARE(r.timeUs, f.timeUs);
      QCOMPARE(r.trueXM, f.truth.position.xM);
      RK_COMPARE_NEAR(r.trueVxMps, t[kVelX] + t[kCurX], 1e-12);
      RK_COMPARE_NEAR(r.estVyMps, x[kVelY] + x[kCurY], 1e-12);
      RK_COMPARE_NEAR(r.sdXM, std::sqrt(P(kPosX, kPosX)), 1e-12);
      RK_COMPARE_NEAR(r.sdVxMps,
                      std::sqrt(P(kVelX, kVelX) + P(kCurX, kCurX) + P(kVelX, kCurX) + P(kCurX, kVelX)), 1e-9);
      QCOMPARE(r.nees, nav::drkfNees(t - x, P, process));
      int rows = 0;
      for (const auto& u : f.updates) rows += u.dim;
      QCOMPARE(r.rowsApplied, rows);
      QCOMPARE(d.estCurrentXMps, x[kCurX]);
      QCOMPARE(d.trueLoranYM, t[kLoranY]);
      RK_COMPARE_NEAR(d.sdLogBiasMps, std::sqrt(P(kLogBias, kLogBias)), 1e-15);
      QCOMPARE(d.error95M, nav::positionError95M(f.estimate));
    }
  }

  void trackRowsCarryBothNeesUnderTheirOwnNames() {
    // GIVEN the matched-model tracking scenario WHEN its sweeps are turned into rows THEN the CSV's
    // rows (appendSweepRows) and the window's (trackRow, one track at a time) are the same; a track
    // that follows a target has the 12-state nees of the whole TTKF state and positionVelocityNees4 of
    // the target's position and velocity (each checked with an explicit inverse), and the track's
    // manoeuvre flag; a track of clutter has neither NEES.
    const Scenario s = builtin("ttkf-matched");
    SimulationEngine e(s, 2);
    int withTruth = 0;
    while (!e.finished() && e.timeUs() < fromSeconds(300.0)) {
      const SimFrame f = e.step();
      std::vector<TrackRow> csv;
      std::vector<TargetSweepRow> targets;
      appendSweepRows(f, e.scenario(), e.frame(), csv, targets);
      std::size_t k = 0;
      for (const SweepSnapshot& sw : f.sweeps) {
        QCOMPARE(targets.size() % s.targets.size(), std::size_t{0});
        for (const TrackSnapshot& t : sw.tracks) {
          const TrackRow r = trackRow(sw, t, e.scenario().targets, e.frame());
          QVERIFY(k < csv.size());
          const TrackRow& c = csv[k++];
          QCOMPARE(r.trackId, c.trackId);
          QVERIFY((std::isnan(r.nees) && std::isnan(c.nees)) || r.nees == c.nees);
          QCOMPARE(r.estLatDeg, c.estLatDeg);
          QCOMPARE(r.manoeuvring, t.manoeuvring);
          if (!r.hasTruth) {
            QVERIFY(std::isnan(r.nees) && std::isnan(r.positionVelocityNees4));
            continue;
          }
          ++withTruth;
          namespace tk = est::ttkf;
          std::size_t i = 0;
          while (e.scenario().targets[i].id != t.targetId) ++i;
          const VesselTruth& v = sw.targets[i];
          const est::Vec<tk::kStateDim> e12 = trueTrackState(sw.ownTruth, v) - t.estimate.x;
          RK_COMPARE_NEAR(r.nees, neesByInverse<tk::kStateDim>(e12, t.estimate.P), 1e-6 * (1.0 + r.nees));
          const est::Vec<4> e4(v.position.xM - r.estXM, v.position.yM - r.estYM, v.groundVxMps() - r.estVxMps,
                               v.groundVyMps() - r.estVyMps);
          est::Mat<4> P4;
          const int idx[4] = {tk::kTgtX, tk::kTgtY, tk::kTgtVx, tk::kTgtVy};
          for (int a = 0; a < 4; ++a)
            for (int b = 0; b < 4; ++b) P4(a, b) = t.estimate.P(idx[a], idx[b]);
          RK_COMPARE_NEAR(r.positionVelocityNees4, neesByInverse<4>(e4, P4),
                          1e-6 * (1.0 + r.positionVelocityNees4));
        }
      }
      QCOMPARE(k, csv.size());
    }
    QVERIFY2(withTruth > 100, qPrintable(QString("%1 track rows with truth").arg(withTruth)));
  }

  void radarFixRowAcrossNorth() {
    // GIVEN a fix at heading 359 deg, 10 m east and 5 m north of the truth, whose heading is 1 deg, and
    // a diagonal covariance WHEN made a row THEN the truth heading is 361 deg (within pi of the fix's),
    // the sds are the covariance's, and the NEES is (10/4)^2 + (5/5)^2 + (2 deg / 1 deg)^2.
    SimFrame f;
    f.timeUs = fromSeconds(40.0);
    f.truth.position = {100.0, 200.0};
    f.truth.headingRad = degToRad(1.0);
    RadarFixReport r;
    r.timeUs = f.timeUs;
    r.valid = r.informative = true;
    r.fixPosition = est::Vec<2>(110.0, 205.0);
    r.fixHeadingRad = degToRad(359.0);
    r.covariance = est::Vec<3>(16.0, 25.0, std::pow(degToRad(1.0), 2)).asDiagonal();
    r.update.status = est::UpdateStatus::Accepted;
    r.update.nis = 1.5;
    r.update.dim = 3;
    const RadarFixRow row = radarFixRow(r, f);
    QVERIFY(row.applied);
    RK_COMPARE_NEAR(radToDeg(row.trueHeadingRad), 361.0, 1e-9);
    RK_COMPARE_NEAR(row.sdXM, 4.0, 1e-12);
    RK_COMPARE_NEAR(radToDeg(row.sdHeadingRad), 1.0, 1e-12);
    RK_COMPARE_NEAR(row.nees, 6.25 + 1.0 + 4.0, 1e-9);
    QCOMPARE(row.nis, 1.5);
    QCOMPARE(row.dim, 3);
  }

  void plotsArePlacedFromTheEstimate() {
    // GIVEN an estimate 1 km east of the origin (grid north and true north differ there by the
    // convergence) and a plot 2 km away bearing 090 true WHEN placed THEN it lies 2 km from the estimate
    // along grid bearing 090 less the convergence.
    const geo::LocalFrame geo(49.0, -122.5);
    SimFrame f;
    f.estimate.x.setZero();
    f.estimate.x[est::drkf::kPosX] = 1000.0;
    sensors::RadarPlot p;
    p.rangeM = 2000.0;
    p.bearingRad = degToRad(90.0);
    f.plots.push_back(p);
    const auto placed = plotPositionsFromEstimate(f, geo);
    QCOMPARE(placed.size(), std::size_t{1});
    const double gamma = geo.gridInfo({1000.0, 0.0}).convergenceRad;
    QCOMPARE_GT(std::abs(gamma), 1e-4);
    RK_COMPARE_NEAR(placed[0].xM, 1000.0 + 2000.0 * std::cos(gamma), 1e-6);
    RK_COMPARE_NEAR(placed[0].yM, 2000.0 * std::sin(gamma), 1e-6);
  }

  void theEngineFlagsDeadReckoningByTheWindowsRule() {
    // GIVEN Baziw's test 1 (GPS on, then Loran-C only, then dead reckoning, then GPS back) WHEN run
    // THEN every frame's flag is "no GPS or Loran-C position applied in its block's latest update
    // within 3 s" (recomputed here from the update reports), and runScenario's intervals are the runs
    // of that flag: the CLI and the window read one decision.
    const Scenario s = builtin("table1-test1");
    SimulationEngine e(s, 1);
    std::array<std::optional<std::pair<double, bool>>, 2> last{};  // GPS, Loran-C: (time, applied)
    std::vector<std::pair<double, double>> runs;                   // [start, end) of the flag
    bool was = false;
    while (!e.finished()) {
      const SimFrame f = e.step();
      for (const auto& u : f.updates)
        for (int b : {0, 1}) {
          const est::BlockReport* r = u.block(b == 0 ? nav::kGpsPosition : nav::kLoranPosition);
          if (r) last[static_cast<std::size_t>(b)] = {{toSeconds(u.timeUs), est::isApplied(r->status)}};
        }
      const double t = toSeconds(f.timeUs);
      bool fix = false;
      for (const auto& l : last) fix = fix || (l && l->second && t - l->first <= 3.0);
      QCOMPARE(f.deadReckoning.active, !fix);
      if (!fix && !was) runs.push_back({t, -1.0});
      if (fix && was) runs.back().second = t;
      was = !fix;
    }
    QVERIFY(runs.size() >= 1);
    const RunResult run = runScenario(s, 1);
    QCOMPARE(run.deadReckoning.size(), runs.size());
    for (std::size_t i = 0; i < runs.size(); ++i) {
      QCOMPARE(toSeconds(run.deadReckoning[i].startUs), runs[i].first);
      QCOMPARE(run.deadReckoning[i].endUs ? toSeconds(*run.deadReckoning[i].endUs) : -1.0, runs[i].second);
    }
  }
};

QTEST_APPLESS_MAIN(TestRunRows)
#include "tst_run_rows.moc"
