// The anti-grounding look-ahead end to end (issue 21): the simulation (own ship with GPS, speedlog
// and gyro; the DRKF), the look-ahead's sampled paths against the charts (charts/route/chart_safety.h),
// the SAFETY CONTOUR AHEAD alert through the alert feed and manager, and grounding.
//  - Heading for the safety contour: the alert comes at least the look-ahead time (6 min) before own
//    ship's true position crosses the contour, in every run: on a straight contour (a synthetic cell)
//    and on the 9.1 m contour of the real NOAA cell US5WA22M (Commencement Bay, Tacoma).
//  - Running parallel to a straight contour at twice the cross-track sd of the look-ahead's position at
//    its horizon: no alert in at least 95% of the runs.
//  - Consistency both ways: the predicted position at the horizon against where the true ship is then
//    (its NEES, 2 dof), so that neither the alert's promptness nor its quietness comes from an sd that
//    is too large or too small.
//  - A ship that sails on over the contour runs aground on the charted shallows and stops, and the
//    GROUNDED alarm is raised.
// RECKONER_AG_RUNS (environment) sets the runs of each case (default 8); docs/routes.md has 100.
#include <QTest>

#include <cmath>
#include <cstdlib>
#include <memory>

#include "alerts/alert_manager.h"
#include "charts/route/chart_safety.h"
#include "charts/s57/s57_loader.h"
#include "common/angles.h"
#include "common/units.h"
#include "sim/alert_feed.h"
#include "sim/sensor_profile.h"
#include "sim/simulation_engine.h"
#include "support/compare_near.h"
#include "support/drkf_fixtures.h"

using namespace reckoner;

namespace {

constexpr double kSpeedMps = 5.144;  // 10 kn
constexpr double kContourLonDeg = -122.40;
constexpr double kLatDeg = 47.30;
constexpr double kSafetyContourM = 9.0;

int runsPerCase() {
  // getenv is unsafe only beside setenv, which nothing in this program calls.
  const char* env = std::getenv("RECKONER_AG_RUNS");  // NOLINT(concurrency-mt-unsafe)
  return env ? std::max(1, std::atoi(env)) : 8;
}

/// The first run's index (RECKONER_AG_FIRST, default 0): one run of a long series again.
int firstRun() {
  // getenv is unsafe only beside setenv, which nothing in this program calls.
  const char* env = std::getenv("RECKONER_AG_FIRST");  // NOLINT(concurrency-mt-unsafe)
  return env ? std::max(0, std::atoi(env)) : 0;
}

charts::ChartFeature area(const char* cls, double drval1, double lon0, double lon1) {
  charts::ChartFeature f;
  f.objectClass = cls;
  f.lnam = std::string(cls) + std::to_string(lon0);
  f.attributes.push_back({"DRVAL1", drval1});
  f.geometry.primitive = charts::Primitive::Area;
  f.geometry.parts = {{{kLatDeg - 0.2, lon0},
                       {kLatDeg - 0.2, lon1},
                       {kLatDeg + 0.2, lon1},
                       {kLatDeg + 0.2, lon0},
                       {kLatDeg - 0.2, lon0}}};
  f.geometry.polygonStarts = {0};
  for (const auto& p : f.geometry.parts[0]) f.geometry.bounds.add(p);
  return f;
}

/// Deep water (20 m) west of the contour's meridian, 5 m east of it, land further east.
charts::CellPtr straightContourCell() {
  charts::CellInfo info;
  info.name = "XX5CONTR";
  std::vector<charts::ChartFeature> f{area("DEPARE", 20.0, kContourLonDeg - 0.2, kContourLonDeg),
                                      area("DEPARE", 5.0, kContourLonDeg, kContourLonDeg + 0.01),
                                      area("DEPARE", 1.0, kContourLonDeg + 0.01, kContourLonDeg + 0.02),
                                      area("LNDARE", 0.0, kContourLonDeg + 0.02, kContourLonDeg + 0.2)};
  return std::make_shared<const charts::ChartCell>(info, std::move(f));
}

sim::Scenario scenarioAt(const geo::GeoPoint& start, double courseTrueDeg, double durationS) {
  sim::Scenario s = test::builtinScenario("default");
  sim::applySensorProfile(s, sim::SensorProfile::Realistic);  // the errors and the filter of a real ship
  s.name = "anti-grounding";
  s.origin = start;
  s.durationUs = fromSeconds(durationS);
  s.targets.clear();
  s.radar.fitted = false;
  s.loran.fitted = false;
  s.gps.power = StepSchedule<bool>{true};
  s.speedlog.power = StepSchedule<bool>{true};
  s.speedlog.mode = StepSchedule<sensors::SpeedlogMode>{sensors::SpeedlogMode::GroundLock};
  s.gyro.power = StepSchedule<bool>{true};
  s.current = {0.05, 1.0 / 3600.0};  // a tidal stream: 0.1 kn sd, changing over an hour
  const geo::LocalFrame frame(start.latDeg, start.lonDeg);
  const double c = degToRad(courseTrueDeg) - frame.gridInfo({0.0, 0.0}).convergenceRad;
  s.ownShip.initialPosition = {0.0, 0.0};
  s.ownShip.initialVelocityMps = {kSpeedMps * std::sin(c), kSpeedMps * std::cos(c)};
  s.ownShip.initialHeadingRad.reset();
  s.ownShip.schedule.clear();
  s.filter.initialPositionSdM = 5.0;
  s.filter.initialVelocitySdMps = 0.1;
  s.voyage.lookAheadPeriodS = 2.0;
  s.voyage.safetyContourM = kSafetyContourM;
  s.voyage.draughtM = 3.0;
  return s;
}

std::shared_ptr<const charts::ChartSafety> guardOf(const charts::CellPtr& cell) {
  charts::AntiGroundingSettings g;
  g.safety.safetyContourM = kSafetyContourM;
  g.draughtM = 3.0;
  return std::make_shared<const charts::ChartSafety>(std::vector<charts::CellPtr>{cell}, g);
}

bool unsafeAt(const charts::ChartSafety& guard, const geo::GeoPoint& p) {
  std::vector<std::uint32_t> in;
  guard.hazards().containing(charts::toMercator({p.latDeg, p.lonDeg}), in);
  return std::any_of(in.begin(), in.end(), [&](std::uint32_t h) {
    const auto k = guard.hazards().hazards()[h].kind;
    return k == charts::HazardKind::SafetyContour || k == charts::HazardKind::Land;
  });
}

struct RunResult {
  double alertS = -1.0;  ///< when SAFETY CONTOUR AHEAD was first raised after the warm-up (-1: never)
  double crossS = -1.0;  ///< when the true position first crossed the contour (-1: never)
  double groundedS = -1.0;
  std::string groundedOn;
  double neesAtHorizon = -1.0;  ///< of the prediction made at neesAtS against the truth a horizon later
  double crossTrackSdAtHorizonM = 0.0;
};

constexpr double kWarmUpS = 120.0;  // the filter converges from its initial uncertainty

RunResult run(const sim::Scenario& s, std::uint64_t seed,
              const std::shared_ptr<const charts::ChartSafety>& guard, double neesAtS = -1.0) {
  sim::SimulationEngine engine(s, seed);
  engine.setChartGuard(guard);
  sim::AlertFeed feed(sim::alertFeedSettingsFor(s));
  alerts::AlertManager manager;
  RunResult r;
  std::optional<nav::LookAheadPrediction> held;
  bool warmUpAlert = false;
  while (!engine.finished()) {
    const sim::SimFrame f = engine.step();
    feed.feed(f, manager);
    const double t = toSeconds(f.timeUs);
    const bool alerting = manager.find({alerts::AlertKind::SafetyContourAhead, 0}) != nullptr;
    if (t <= kWarmUpS) {
      warmUpAlert = alerting;  // still raised at the end of the warm-up: no alert time to measure
    } else if (r.alertS < 0 && alerting) {
      r.alertS = warmUpAlert ? -2.0 : t;
    }
    const geo::GeoPoint truth = engine.frame().toGeodetic(f.truth.position);
    if (r.crossS < 0 && unsafeAt(*guard, truth)) r.crossS = t;
    if (r.groundedS < 0 && f.grounded) {
      r.groundedS = t;
      r.groundedOn = f.grounded->what;
    }
    if (neesAtS > 0 && !held && t >= neesAtS) {
      held = nav::predictLookAhead(engine.drkf(), s.voyage.lookAhead);
      r.crossTrackSdAtHorizonM = std::sqrt(held->covariance.back()(0, 0));
    }
    if (held && t >= toSeconds(held->t0Us) + held->timesS.back() && r.neesAtHorizon < 0) {
      const est::Vec<2> e(f.truth.position.xM - held->mean.back().xM,
                          f.truth.position.yM - held->mean.back().yM);
      r.neesAtHorizon = e.dot(held->covariance.back().ldlt().solve(e));
    }
  }
  return r;
}

}  // namespace

class TestAntiGrounding : public QObject {
  Q_OBJECT

 private slots:
  void headingForAStraightContour() {
    const auto guard = guardOf(straightContourCell());
    // 3.4 km west of the contour, heading east: the true crossing some 660 s on
    const geo::GeoPoint start{kLatDeg, kContourLonDeg - 0.045};
    const sim::Scenario s = scenarioAt(start, 90.0, 760.0);
    double minLead = 1e9, maxLead = 0.0;
    for (int i = 0; i < runsPerCase(); ++i) {
      const RunResult r = run(s, 100 + static_cast<std::uint64_t>(i), guard);
      QVERIFY2(
          r.crossS > 0 && r.alertS > 0,
          qPrintable(QStringLiteral("run %1: crossing %2 s, alert %3 s").arg(i).arg(r.crossS).arg(r.alertS)));
      minLead = std::min(minLead, r.crossS - r.alertS);
      maxLead = std::max(maxLead, r.crossS - r.alertS);
      QVERIFY2(r.crossS - r.alertS >= s.voyage.lookAhead.horizonS,
               qPrintable(
                   QStringLiteral("run %1: alert %2 s before the crossing").arg(i).arg(r.crossS - r.alertS)));
    }
    qInfo("straight contour: %d runs, alert %.0f to %.0f s before the true crossing (look-ahead %.0f s)",
          runsPerCase(), minLead, maxLead, s.voyage.lookAhead.horizonS);
  }

  void headingForTheContourOfARealChart() {
    const auto guard =
        guardOf(charts::loadCell(std::string(RECKONER_SHARED_DIR) + "/data/enc/US5WA22M/US5WA22M.000"));
    // mid Commencement Bay, heading 225 for the south-west shore and its 9.1 m contour (some 3 km off)
    const sim::Scenario s = scenarioAt({47.3035, -122.4497}, 225.0, 1000.0);
    double minLead = 1e9;
    int groundedFirst = 0;
    for (int i = firstRun(); i < firstRun() + runsPerCase(); ++i) {
      const RunResult r = run(s, 200 + static_cast<std::uint64_t>(i), guard);
      // Unsafe water reached: the contour crossed or, where a charted danger outside it lies on the
      // way, the grounding on it (the ship stops there and never crosses).
      const bool grounded = r.groundedS > 0 && (r.crossS < 0 || r.groundedS < r.crossS);
      const double hitS = grounded ? r.groundedS : r.crossS;
      groundedFirst += grounded ? 1 : 0;
      if (grounded)
        qInfo("run %d: aground at %.0f s on %s before the contour", i, r.groundedS, r.groundedOn.c_str());
      QVERIFY2(hitS > 0 && r.alertS > 0,
               qPrintable(QStringLiteral("run %1: crossing %2 s, alert %3 s, aground %4 s")
                              .arg(i)
                              .arg(r.crossS)
                              .arg(r.alertS)
                              .arg(r.groundedS)));
      minLead = std::min(minLead, hitS - r.alertS);
      QVERIFY2(hitS - r.alertS >= s.voyage.lookAhead.horizonS,
               qPrintable(QStringLiteral("run %1: alert %2 s before %3")
                              .arg(i)
                              .arg(hitS - r.alertS)
                              .arg(grounded ? QString::fromStdString("grounding on " + r.groundedOn)
                                            : QStringLiteral("the crossing"))));
    }
    qInfo(
        "US5WA22M: %d runs, the alert at least %.0f s before the true crossing (%d of them grounded first on "
        "a "
        "charted danger outside the contour)",
        runsPerCase(), minLead, groundedFirst);
  }

  void parallelAtTwoSd() {
    const auto guard = guardOf(straightContourCell());
    // the look-ahead's cross-track sd at its horizon, from a run far from any contour
    const sim::Scenario probe = scenarioAt({kLatDeg, kContourLonDeg - 0.1}, 0.0, kWarmUpS + 60.0);
    const RunResult p = run(probe, 1, guard, kWarmUpS);
    const double sdM = p.crossTrackSdAtHorizonM;
    QVERIFY(sdM > 1.0 && sdM < 200.0);
    const double metresPerDegLon = kSpeedMps / kSpeedMps * 111320.0 * std::cos(degToRad(kLatDeg));
    const geo::GeoPoint start{kLatDeg - 0.02, kContourLonDeg - 2.0 * sdM / metresPerDegLon};
    sim::Scenario s = scenarioAt(start, 0.0, 600.0);
    // no tidal stream: the ship's track over ground stays parallel (a stream across it would set her
    // towards the contour or away by tens of metres in ten minutes)
    s.current = {0.0, 1.0};
    int alerted = 0;
    double neesSum = 0.0;
    int neesCount = 0;
    for (int i = 0; i < runsPerCase(); ++i) {
      const RunResult r = run(s, 300 + static_cast<std::uint64_t>(i), guard, 200.0);
      alerted += r.alertS > 0 ? 1 : 0;
      if (r.neesAtHorizon >= 0) {
        neesSum += r.neesAtHorizon;
        ++neesCount;
      }
    }
    const double meanNees = neesSum / std::max(1, neesCount);
    qInfo(
        "parallel at 2 sd (%.1f m from the contour, sd at 6 min %.1f m): %d of %d runs alerted; the "
        "horizon's NEES %.2f (2 dof)",
        2.0 * sdM, sdM, alerted, runsPerCase(), meanNees);
    QVERIFY2(alerted <= runsPerCase() / 20,
             qPrintable(QStringLiteral("%1 of %2 runs alerted").arg(alerted).arg(runsPerCase())));
    // the sd neither much too small (NEES far above 2) nor absurdly large (far below)
    QVERIFY2(meanNees > 0.1 && meanNees < 6.0, qPrintable(QString::number(meanNees)));
  }

  void groundsAndStops() {
    const auto guard = guardOf(straightContourCell());
    // on over the contour into the 1 m shallows (draught 3 m)
    const sim::Scenario s = scenarioAt({kLatDeg, kContourLonDeg - 0.003}, 90.0, 300.0);
    sim::SimulationEngine engine(s, 7);
    engine.setChartGuard(guard);
    sim::AlertFeed feed(sim::alertFeedSettingsFor(s));
    alerts::AlertManager manager;
    std::optional<geo::GridPoint> at;
    while (!engine.finished()) {
      const sim::SimFrame f = engine.step();
      feed.feed(f, manager);
      if (f.grounded) {
        at = f.truth.position;
        QVERIFY(f.grounded->objectClass == "DEPARE");
        QCOMPARE(*f.grounded->depthM, 1.0);
        QVERIFY(manager.find({alerts::AlertKind::Grounded, 0}));
      }
      if (at) {
        QVERIFY(f.aground);
        RK_COMPARE_NEAR(f.truth.position.xM, at->xM, 1e-9);
        RK_COMPARE_NEAR(f.truth.groundVxMps(), 0.0, 1e-12);
      }
    }
    QVERIFY(at.has_value());
    const geo::GeoPoint g = engine.frame().toGeodetic(*at);
    QVERIFY(g.lonDeg > kContourLonDeg + 0.01);  // in the 1 m area, past the 5 m one
  }
};

QTEST_GUILESS_MAIN(TestAntiGrounding)
#include "tst_anti_grounding.moc"
