// Guard zones drawn and edited on the chart (issue 18, section 2): which edge of a zone a point is on,
// how dragging each edge changes the zone; and in the window, a zone added from the context menu, its
// outer arc dragged out with the mouse, reaching the engine, recorded in the saved scenario, and
// deleted again.
#include <QFile>
#include <QMenu>
#include <QTemporaryDir>
#include <QTest>

#include "common/angles.h"
#include "common/units.h"
#include "files/scenario_json.h"
#include "main_window_test_helpers.h"
#include "support/compare_near.h"
#include "ui/map/guard_zones.h"

using namespace reckoner;
using namespace reckoner::ui;
using namespace reckoner::ui::test;

namespace {

/// North up, one pixel per metre, own ship at (500, 500).
PolarMap simpleMap() {
  PolarMap m;
  m.toWidget = [](double r, double b) { return QPointF(500.0 + r * std::sin(b), 500.0 - r * std::cos(b)); };
  m.fromWidget = [](QPointF p) {
    const double dx = p.x() - 500.0, dy = 500.0 - p.y();
    return std::pair{std::hypot(dx, dy), wrapTwoPi(std::atan2(dx, dy))};
  };
  return m;
}

bool frameZonesAre(const MainWindow& w, std::size_t n) {
  return !w.refreshPending() && w.history().latest().frame.zones.size() == n;
}

void trigger(EcdisView* v, QPointF at, const char* name) {
  QMenu* menu = v->buildContextMenu(at);
  QAction* a = menu->findChild<QAction*>(QString::fromLatin1(name));
  QVERIFY2(a, name);
  a->trigger();
  delete menu;
}

}  // namespace

class TestGuardZones : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() { isolateFromTheUser("tst_guard_zones"); }

  void eachEdgeIsFoundAndMovesItsOwnBound() {
    const PolarMap m = simpleMap();
    const std::vector<track::AcquisitionZone> zones{{100.0, 300.0, degToRad(0.0), degToRad(90.0)}};
    const auto hit = [&](double r, double bDeg) {
      return hitZone(zones, m.toWidget(r, degToRad(bDeg)), m).edge;
    };
    QCOMPARE(hit(300.0, 45.0), ZoneEdge::Outer);
    QCOMPARE(hit(303.0, 45.0), ZoneEdge::Outer);
    QCOMPARE(hit(100.0, 45.0), ZoneEdge::Inner);
    QCOMPARE(hit(200.0, 0.0), ZoneEdge::From);
    QCOMPARE(hit(200.0, 90.0), ZoneEdge::To);
    QCOMPARE(hit(200.0, 45.0), ZoneEdge::Inside);
    QCOMPARE(hit(200.0, 180.0), ZoneEdge::None);
    QCOMPARE(hit(400.0, 45.0), ZoneEdge::None);
    // A whole ring has no sides
    const std::vector<track::AcquisitionZone> ring{{0.0, 300.0, 0.0, 0.0}};
    QCOMPARE(hitZone(ring, m.toWidget(150.0, 1.0), m).edge, ZoneEdge::Inside);
    QCOMPARE(hitZone(ring, m.toWidget(300.0, 4.0), m).edge, ZoneEdge::Outer);

    const track::AcquisitionZone z = zones[0];
    RK_COMPARE_NEAR(movedZone(z, ZoneEdge::Outer, 500.0, 0.0, 0.0, 20.0).maxRangeM, 500.0, 1e-9);
    RK_COMPARE_NEAR(movedZone(z, ZoneEdge::Outer, 50.0, 0.0, 0.0, 20.0).maxRangeM, 120.0, 1e-9);  // min + 20
    RK_COMPARE_NEAR(movedZone(z, ZoneEdge::Inner, 250.0, 0.0, 0.0, 20.0).minRangeM, 250.0, 1e-9);
    RK_COMPARE_NEAR(movedZone(z, ZoneEdge::Inner, 10.0, 0.0, 0.0, 20.0).minRangeM, 0.0, 1e-9);  // to own ship
    RK_COMPARE_NEAR(movedZone(z, ZoneEdge::To, 0.0, degToRad(120.0), 0.0, 20.0).toBearingRad, degToRad(120.0),
                    1e-12);
    RK_COMPARE_NEAR(movedZone(z, ZoneEdge::From, 0.0, degToRad(-30.0), 0.0, 20.0).fromBearingRad,
                    degToRad(330.0), 1e-12);
    const track::AcquisitionZone turned =
        movedZone(z, ZoneEdge::Inside, 0.0, degToRad(60.0), degToRad(45.0), 20.0);
    RK_COMPARE_NEAR(turned.fromBearingRad, degToRad(15.0), 1e-12);
    RK_COMPARE_NEAR(turned.toBearingRad, degToRad(105.0), 1e-12);
    const track::AcquisitionZone added = zoneAt(1000.0, degToRad(10.0), 50.0);
    QVERIFY(added.contains(1000.0, degToRad(10.0)));
    QVERIFY(!added.contains(1000.0, degToRad(40.0)));
    QVERIFY(track::validZone(added));
  }

  void anOfficerDrawsAZoneDragsItAndDeletesIt() {
    MainWindow w(freshOptions());
    showAndWait(w);
    runUntil(w, 10.0);
    EcdisView* v = w.chart();
    QVERIFY(w.history().latest().frame.zones.empty());
    auto m = v->polarMap();
    QVERIFY(m);
    // GIVEN a new zone 1 NM ahead on 090
    const double range = nmToMetres(1.0);
    trigger(v, m->toWidget(range, degToRad(90.0)), "newZone");
    QTRY_VERIFY_WITH_TIMEOUT(frameZonesAre(w, 1), kTimeoutMs);
    track::AcquisitionZone z = w.history().latest().frame.zones.front();
    RK_COMPARE_NEAR(z.maxRangeM, 1.2 * range, 1.0);
    QVERIFY(z.contains(range, degToRad(90.0)));
    QVERIFY(w.isWindowModified());
    // WHEN its outer arc is dragged out by 60 px
    m = v->polarMap();
    const QPoint grab = m->toWidget(z.maxRangeM, degToRad(90.0)).toPoint();
    const QPoint drop = grab + QPoint(60, 0);
    const double expected = m->fromWidget(drop).first;
    QTest::mousePress(v, Qt::LeftButton, {}, grab);
    QTest::mouseMove(v, grab + QPoint(30, 0));
    QVERIFY(!v->shownZones().empty());
    QTest::mouseMove(v, drop);
    QTest::mouseRelease(v, Qt::LeftButton, {}, drop);
    // THEN the engine's zone has the new outer range (a drag, not a pan: the view did not move)
    QTRY_VERIFY_WITH_TIMEOUT(
        frameZonesAre(w, 1) && std::abs(w.history().latest().frame.zones.front().maxRangeM - expected) < 1.0,
        kTimeoutMs);
    RK_COMPARE_NEAR(v->polarMap()->toWidget(0.0, 0.0).x(), m->toWidget(0.0, 0.0).x(), 1e-6);
    saveWindowShot(w, QStringLiteral("guard-zone"));
    // AND the saved scenario holds the zone as dragged (both edits at the paused time: one change)
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("zones.json"));
    QVERIFY(w.saveScenario(path));
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const sim::Scenario saved = files::parseScenario(f.readAll().toStdString(), path.toStdString());
    QCOMPARE(saved.tracker.zoneChanges.size(), std::size_t(1));
    RK_COMPARE_NEAR(saved.tracker.zoneChanges.back().second.front().maxRangeM, expected, 1.0);
    // WHEN deleted from the context menu THEN the tracker acquires everywhere again
    runUntil(w, 12.0);
    trigger(v, v->polarMap()->toWidget(range, degToRad(90.0)), "deleteZone");
    QTRY_VERIFY_WITH_TIMEOUT(frameZonesAre(w, 0), kTimeoutMs);
  }
};

QTEST_MAIN(TestGuardZones)
#include "tst_guard_zones.moc"
