// The voyage in the window (docs/gui.md "Route monitoring"; issue 21): a route made active in the
// library goes to the simulation, own ship follows it under Route > Follow route and the Voyage dock
// shows the leg, the cross-track distance and the ETAs; a helm order takes the ship off track control
// (the menu follows); a course ordered for the embedded chart's shore raises SAFETY CONTOUR AHEAD with
// the look-ahead area on the chart, well before the ship reaches the shoal, where it grounds (the
// GROUNDED alarm and the banner). Screenshots: screenshots/voyage_follow.png, voyage_lookahead.png and
// voyage_aground.png.
#include <QAction>
#include <QDockWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <algorithm>

#include "geo/local_frame.h"
#include "main_window_test_helpers.h"
#include "support/compare_near.h"
#include "support/route_fixtures.h"
#include "ui/panels/voyage_panel.h"
#include "ui/route_library.h"

using namespace reckoner;
using namespace reckoner::ui;
using namespace reckoner::ui::test;

namespace {

QAction* action(const MainWindow& w, const char* name) {
  auto* a = w.findChild<QAction*>(QString::fromLatin1(name));
  if (!a) qFatal("no action %s", name);
  return a;
}

void raiseDock(MainWindow& w, const char* name) {
  if (auto* d = w.findChild<QDockWidget*>(QString::fromLatin1(name))) d->raise();
}

bool alerting(const MainWindow& w, alerts::AlertKind kind) {
  const auto& shown = w.history().latest().alerts;
  return std::any_of(shown.begin(), shown.end(), [&](const alerts::Alert& a) { return a.id.kind == kind; });
}
}  // namespace

class TestVoyageWindow : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() {
    isolateFromTheUser("tst_voyage_window");
    qputenv("RECKONER_ROUTE_DIR", dir_.path().toUtf8());
  }

  void followsTheActiveRouteAndShowsItsMonitoring() {
    MainWindow w(freshOptions());
    showAndWait(w);
    runUntil(w, 10.0);
    // From own ship 1.2 km east, then 2.4 km north: open water north of the approach.
    const auto& x = w.history().latest().frame.estimate.x;
    const double x0 = x[est::drkf::kPosX], y0 = x[est::drkf::kPosY];
    const geo::LocalFrame& grid = *w.chart()->frame();
    geo::Route r = reckoner::test::routeOf({grid.toGeodetic({x0, y0}), grid.toGeodetic({x0 + 1200.0, y0}),
                                            grid.toGeodetic({x0 + 1200.0, y0 + 2400.0})},
                                           0.1, "Test approach");
    r.waypoints[1].turnRadiusNm = 0.2;
    RouteLibrary* lib = w.routeLibrary();
    QVERIFY(!w.isWindowModified());  // no route yet: nothing for a save to keep
    lib->setActive(lib->add(r));
    QVERIFY(w.isWindowModified());  // the scenario records the route now followed
    action(w, "followRouteAction")->setChecked(true);
    // The route shown is checked against the chart: nothing on it.
    w.checkRoute();
    for (const charts::RouteFinding& f : w.routeFindings()) {
      qInfo("route check: leg %zu %s %s", f.leg, charts::hazardKindName(f.kind), f.objectClass.c_str());
      QVERIFY(!charts::isDangerous(f.kind));
    }
    runUntil(w, 12.0);
    QTRY_VERIFY_WITH_TIMEOUT(w.history().latest().route && w.history().latest().followingRoute, kTimeoutMs);
    QVERIFY2(w.voyagePanel()->routeText().contains(QStringLiteral("Test approach")),
             qPrintable(w.voyagePanel()->routeText()));
    // Through the turn at B onto the second leg; the ship keeps to the track.
    runUntil(w, 420.0);
    RK_WAIT_VERIFY(settled(w));
    const auto& status = w.history().latest().frame.route;
    QVERIFY(status.has_value());
    QCOMPARE(status->to, std::size_t(2));
    qInfo("at %.0f s: leg to C, XTD %.1f m (sd %.1f m), %.0f m to go; panel: %s / %s", simTime(w),
          status->crossTrackM, status->crossTrackSdM, status->distanceToWaypointM,
          qPrintable(w.voyagePanel()->routeText()), qPrintable(w.voyagePanel()->crossTrackText()));
    RK_COMPARE_NEAR(status->crossTrackM, 0.0, 60.0);  // m: the autopilot holds the track
    QVERIFY(!status->offTrack);
    QVERIFY(!status->arrived);
    QCOMPARE(w.voyagePanel()->etaTable()->rowCount(), 1);
    QVERIFY(w.voyagePanel()->routeText().contains(QStringLiteral("WP2 → WP3")));
    QVERIFY(w.voyagePanel()->routeText().contains(QStringLiteral("track control")));
    raiseDock(w, "voyageDock");
    saveWindowShot(w, QStringLiteral("voyage_follow"));
    // A helm order takes the ship off track control; the route stays monitored.
    w.controller()->orderOwnShip(degToRad(300.0), knotsToMps(10.0));
    runUntil(w, 440.0);
    QTRY_VERIFY_WITH_TIMEOUT(!action(w, "followRouteAction")->isChecked(), kTimeoutMs);
    QVERIFY(w.history().latest().route);
    QVERIFY(!w.history().latest().followingRoute);
    lib->setActive(-1);
    QTRY_VERIFY_WITH_TIMEOUT(!w.history().latest().route, kTimeoutMs);
    QVERIFY(w.lastError().isEmpty());
  }

  void aCourseForTheShoreIsAlertedBeforeTheShipGrounds() {
    MainWindow w(freshOptions());
    showAndWait(w);
    runUntil(w, 10.0);
    QTRY_VERIFY_WITH_TIMEOUT(w.history().latest().lookAhead != nullptr, kTimeoutMs);
    QVERIFY(!alerting(w, alerts::AlertKind::SafetyContourAhead));
    // Due south for the mainland at 10 kn, as a new user would order it.
    w.controller()->orderOwnShip(degToRad(180.0), knotsToMps(10.0));
    double alertS = -1.0, groundedS = -1.0;
    for (double t = 20.0; t < 1800.0 && groundedS < 0.0; t += 10.0) {
      runUntil(w, t);
      if (alertS < 0.0 && alerting(w, alerts::AlertKind::SafetyContourAhead)) {
        alertS = simTime(w);
        RK_WAIT_VERIFY(settled(w));
        QVERIFY2(w.voyagePanel()->lookAheadText().contains(QStringLiteral("%")),
                 qPrintable(w.voyagePanel()->lookAheadText()));
        raiseDock(w, "voyageDock");
        saveWindowShot(w, QStringLiteral("voyage_lookahead"));
      }
      if (w.history().latest().aground) groundedS = simTime(w);
    }
    qInfo("SAFETY CONTOUR AHEAD at %.0f s, aground at %.0f s on %s", alertS, groundedS,
          w.history().latest().aground ? w.history().latest().aground->what.c_str() : "-");
    QVERIFY(alertS > 0.0);
    QVERIFY(groundedS > 0.0);
    // The contour lies some 0.3 km off the 5 m line the ship grounds on: at 10 kn the alert must come
    // the look-ahead time (6 min) before the contour, so well over 6 min before the grounding.
    QVERIFY2(groundedS - alertS >= 360.0, qPrintable(QString("%1 s").arg(groundedS - alertS)));
    QTRY_VERIFY_WITH_TIMEOUT(alerting(w, alerts::AlertKind::Grounded), kTimeoutMs);
    RK_WAIT_VERIFY(settled(w));
    QVERIFY2(w.voyagePanel()->groundingText().startsWith(QStringLiteral("AGROUND")),
             qPrintable(w.voyagePanel()->groundingText()));
    // The ship stays where she grounded.
    const sim::VesselTruth at = w.history().latest().frame.truth;
    runUntil(w, simTime(w) + 60.0);
    const sim::VesselTruth later = w.history().latest().frame.truth;
    RK_COMPARE_NEAR(std::hypot(later.position.xM - at.position.xM, later.position.yM - at.position.yM), 0.0,
                    0.01);
    saveWindowShot(w, QStringLiteral("voyage_aground"));
  }

 private:
  QTemporaryDir dir_;
};

QTEST_MAIN(TestVoyageWindow)
#include "tst_voyage_window.moc"
