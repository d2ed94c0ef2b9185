// Routes in the window (docs/gui.md "Routes"; issue 21, MSC.232(82) 11.3): a route made by clicks on the
// chart in Route edit mode, a waypoint dragged, one inserted on a leg and one deleted through the
// chart's context menu, undo and redo; the route table's cells edited (good values proposed through the
// library, bad ones refused with a message) and its selection following the chart's; the library saved
// and read again by a new window (RECKONER_ROUTE_DIR in a temporary directory), the active route
// remembered; RTZ and GPX files imported, a broken one refused naming the file; and the route check on
// the NOAA cell US5WA22M (from ../shared/data/enc, skipped without it): a route across land has its
// land finding on the right leg, the finding selected centres the chart and shows its pick report.
// Screenshots: screenshots/route_edit.png and screenshots/route_check.png.
#include <QAction>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QSignalSpy>
#include <QTableView>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBrowser>
#include <QUndoStack>
#include <algorithm>
#include <tuple>

#include "common/units.h"
#include "geo/geodesic.h"
#include "geo/route.h"
#include "io/text_format.h"
#include "main_window_test_helpers.h"
#include "support/compare_near.h"
#include "support/route_fixtures.h"
#include "ui/map/route_overlay.h"
#include "ui/panels/route_panel.h"
#include "ui/panels/route_table_model.h"
#include "ui/route_library.h"

using namespace reckoner;
using namespace reckoner::ui;
using namespace reckoner::ui::test;

namespace {

const QString kTacoma = QStringLiteral(RECKONER_SHARED_DIR "/data/enc/US5WA22M");

geo::GeoPoint geoPointAt(const EcdisView& v, QPointF p) {
  const charts::LatLon ll = v.viewport().toLatLon({p.x(), p.y()});
  return {ll.latDeg, ll.lonDeg};
}

/// Metres between two positions (geodesic).
double metresBetween(const geo::GeoPoint& a, const geo::GeoPoint& b) {
  return geo::rangeBearing(a, b).rangeM;
}

const geo::Route& shown(const MainWindow& w) {
  const geo::Route* r = w.routeLibrary()->currentRoute();
  if (!r) qFatal("no route shown");
  return *r;
}

QAction* action(const MainWindow& w, const char* name) {
  auto* a = w.findChild<QAction*>(QString::fromLatin1(name));
  if (!a) qFatal("no action %s", name);
  return a;
}

/// Triggers the chart's context-menu action `name` at widget point `at`; false when the menu lacks it.
bool triggerContextAction(MainWindow& w, QPointF at, const char* name) {
  QMenu* menu = w.chart()->buildContextMenu(at);
  auto* a = menu->findChild<QAction*>(QString::fromLatin1(name));
  if (a) a->trigger();
  menu->close();
  return a != nullptr;
}

void dragOnChart(EcdisView* v, QPointF from, QPointF to) {
  QTest::mousePress(v, Qt::LeftButton, {}, from.toPoint());
  for (int i = 1; i <= 4; ++i) QTest::mouseMove(v, (from + (to - from) * (i / 4.0)).toPoint());
  QTest::mouseRelease(v, Qt::LeftButton, {}, to.toPoint());
}

geo::Route routeOf(const std::vector<geo::GeoPoint>& points, double xtlNm) {
  return reckoner::test::routeOf(points, xtlNm, "Across the point");
}

void writeFile(const QString& path, const QByteArray& text) {
  QFile f(path);
  QVERIFY(f.open(QIODevice::WriteOnly));
  f.write(text);
}

}  // namespace

class TestRouteWindow : public QObject {
  Q_OBJECT
  QTemporaryDir dir_;
  int libraries_ = 0;

  /// A route directory of its own for the next window.
  QString freshRouteDir() {
    QString path = dir_.filePath(QStringLiteral("routes%1").arg(++libraries_));
    qputenv("RECKONER_ROUTE_DIR", path.toLocal8Bit());
    return path;
  }

 private slots:
  void initTestCase() {
    isolateFromTheUser("tst_route_window");
    QVERIFY(dir_.isValid());
  }

  void routeMadeByClicksDraggedInsertedDeletedAndUndone() {
    freshRouteDir();
    MainWindow w(freshOptions());
    showAndWait(w);
    EcdisView* v = w.chart();
    // WHEN Route > Edit route is switched on and the chart is clicked three times
    action(w, "routeEdit")->trigger();
    QVERIFY(v->routeOverlay()->editing());
    QCOMPARE(w.routeLibrary()->count(), 1);  // a new route to edit
    const QPointF clicks[] = {{0.08 * v->width(), 0.48 * v->height()},
                              {0.22 * v->width(), 0.62 * v->height()},
                              {0.52 * v->width(), 0.66 * v->height()}};
    for (const QPointF& p : clicks) QTest::mouseClick(v, Qt::LeftButton, {}, p.toPoint());
    // THEN the route has three waypoints where the clicks were, named WP1..WP3, and no pick report
    QCOMPARE(shown(w).waypoints.size(), std::size_t{3});
    for (std::size_t k = 0; k < 3; ++k) {
      RK_COMPARE_NEAR(metresBetween(shown(w).waypoints[k].position, geoPointAt(*v, clicks[k])), 0.0,
                      2.0 * v->viewport().metresPerPixel());
      QCOMPARE(shown(w).waypoints[k].name, "WP" + std::to_string(k + 1));
    }
    QCOMPARE(w.routePanel()->model()->rowCount(), 3);
    // WHEN WP2 is dragged THEN it is where it was dropped
    const QPointF to = clicks[1] + QPointF(30.0, 40.0);
    dragOnChart(v, clicks[1], to);
    RK_COMPARE_NEAR(metresBetween(shown(w).waypoints[1].position, geoPointAt(*v, to)), 0.0,
                    2.0 * v->viewport().metresPerPixel());
    QCOMPARE(w.routePanel()->table()->currentIndex().row(), 1);  // the table follows the chart
    // WHEN a waypoint is inserted on the first leg from the context menu THEN it lies on that leg
    const QPointF mid = (clicks[0] + to) / 2.0;
    QVERIFY(triggerContextAction(w, mid, "routeInsertWaypoint"));
    QCOMPARE(shown(w).waypoints.size(), std::size_t{4});
    QCOMPARE(shown(w).waypoints[1].name, std::string("WP4"));
    geo::Route oldLeg = shown(w);
    oldLeg.waypoints.erase(oldLeg.waypoints.begin() + 1);
    RK_COMPARE_NEAR(geo::legFix(oldLeg, 1, shown(w).waypoints[1].position).crossTrackM, 0.0, 1.0);
    // WHEN WP3 (the last) is deleted from the context menu THEN three are left
    QVERIFY(triggerContextAction(w, clicks[2], "routeDeleteWaypoint"));
    QCOMPARE(shown(w).waypoints.size(), std::size_t{3});
    QCOMPARE(shown(w).waypoints.back().name, std::string("WP2"));
    // Undo brings the deleted waypoint back, redo deletes it again
    action(w, "routeUndo")->trigger();
    QCOMPARE(shown(w).waypoints.size(), std::size_t{4});
    action(w, "routeRedo")->trigger();
    QCOMPARE(shown(w).waypoints.size(), std::size_t{3});
    action(w, "routeUndo")->trigger();
    QCOMPARE(shown(w).waypoints.size(), std::size_t{4});
    // A click on a waypoint selects it (and adds none)
    QTest::mouseClick(v, Qt::LeftButton, {}, clicks[2].toPoint());
    QCOMPARE(shown(w).waypoints.size(), std::size_t{4});
    QCOMPARE(v->routeOverlay()->selectedWaypoint().value_or(99), std::size_t{3});
    // The check runs after the edits; with planned speeds the table gives the time
    auto* model = w.routePanel()->model();
    QVERIFY(model->setData(model->index(1, RouteTableModel::Speed), QStringLiteral("10"), Qt::EditRole));
    QVERIFY(w.routePanel()->totals()->text().contains(QStringLiteral("at the planned speeds")));
    QTRY_VERIFY_WITH_TIMEOUT(!w.routeCheckPending(), kTimeoutMs);
    QVERIFY(w.routePanel()->checkSummary()->text().contains(QStringLiteral("leg")));
    v->routeOverlay()->setSelectedWaypoint(2);
    saveWindowShot(w, QStringLiteral("route_edit"));
    w.setPalette(charts::Palette::Night);
    saveWindowShot(w, QStringLiteral("route_edit_night"));
    w.setPalette(charts::Palette::Day);
    // Escape leaves the mode, and the menu's check mark follows
    v->setFocus();
    QTest::keyClick(v, Qt::Key_Escape);
    QVERIFY(!v->routeOverlay()->editing());
    QVERIFY(!action(w, "routeEdit")->isChecked());
    // Out of edit mode a click adds nothing
    QTest::mouseClick(v, Qt::LeftButton, {}, QPoint(v->width() / 3, v->height() / 2));
    QCOMPARE(shown(w).waypoints.size(), std::size_t{4});
  }

  void tableCellsEditedAndRefused() {
    freshRouteDir();
    MainWindow w(freshOptions());
    showAndWait(w);
    EcdisView* v = w.chart();
    const geo::GeoPoint a = geoPointAt(*v, {0.3 * v->width(), 0.3 * v->height()});
    const geo::GeoPoint b = geoPointAt(*v, {0.6 * v->width(), 0.4 * v->height()});
    const geo::GeoPoint c = geoPointAt(*v, {0.5 * v->width(), 0.7 * v->height()});
    w.routeLibrary()->add(routeOf({a, b, c}, 0.1));
    RouteTableModel* model = w.routePanel()->model();
    QCOMPARE(model->rowCount(), 3);
    w.findChild<QDockWidget*>(QStringLiteral("routeDock"))->raise();
    QTRY_VERIFY_WITH_TIMEOUT(w.routePanel()->table()->isVisible(), kTimeoutMs);
    QCOMPARE(model->index(1, RouteTableModel::Latitude).data().toString(),
             QString::fromStdString(io::formatLatitude(b.latDeg)));
    // GIVEN the latitude typed into the table as the window writes it
    const double newLat = b.latDeg + 0.004;
    QTableView* table = w.routePanel()->table();
    const QModelIndex lat = model->index(1, RouteTableModel::Latitude);
    table->setCurrentIndex(lat);
    table->edit(lat);
    auto* editor = table->findChild<QLineEdit*>();
    QVERIFY(editor);
    editor->selectAll();
    QTest::keyClicks(editor, QString::fromStdString(io::formatLatitude(newLat)));
    QTest::keyClick(editor, Qt::Key_Return);  // the delegate commits from the event loop
    QTRY_VERIFY_WITH_TIMEOUT(shown(w).waypoints[1].position.latDeg != b.latDeg, kTimeoutMs);
    // THEN the waypoint moved there (to the 0.001' written) and the chart shows it
    RK_COMPARE_NEAR(shown(w).waypoints[1].position.latDeg, newLat, 0.001 / 60.0);
    RK_COMPARE_NEAR(v->routeOverlay()->route()->waypoints[1].position.latDeg, newLat, 0.001 / 60.0);
    // Degrees alone, other cells: longitude, XTL, radius, speed, geometry
    QVERIFY(model->setData(model->index(2, RouteTableModel::Longitude),
                           QString::number(c.lonDeg + 0.01, 'f', 6), Qt::EditRole));
    RK_COMPARE_NEAR(shown(w).waypoints[2].position.lonDeg, c.lonDeg + 0.01, 1e-6);  // typed to 6 decimals
    QVERIFY(model->setData(model->index(1, RouteTableModel::PortXtl), QStringLiteral("0.25"), Qt::EditRole));
    RK_COMPARE_NEAR(shown(w).waypoints[1].leg.portXtlNm, 0.25, 1e-12);
    QVERIFY(model->setData(model->index(1, RouteTableModel::Radius), QStringLiteral("0.3"), Qt::EditRole));
    RK_COMPARE_NEAR(shown(w).waypoints[1].turnRadiusNm.value_or(-1.0), 0.3, 1e-12);
    QVERIFY(model->setData(model->index(2, RouteTableModel::Geometry), QStringLiteral("Great circle"),
                           Qt::EditRole));
    QVERIFY(shown(w).waypoints[2].leg.geometry == geo::LegGeometry::GreatCircle);
    QVERIFY(model->setData(model->index(2, RouteTableModel::Speed), QStringLiteral("12.5"), Qt::EditRole));
    RK_COMPARE_NEAR(shown(w).waypoints[2].leg.plannedSpeedKn.value_or(0.0), 12.5, 1e-12);
    QVERIFY(w.routePanel()->totals()->text().contains(QStringLiteral("1 leg(s) without one")));
    // WHEN bad values are typed THEN each is refused with a message naming the field; nothing changes
    const geo::Route before = shown(w);
    const std::pair<int, const char*> bad[] = {
        {RouteTableModel::Latitude, "95°00.000'N"}, {RouteTableModel::Longitude, "12x"},
        {RouteTableModel::PortXtl, "-1"},           {RouteTableModel::Speed, "fast"},
        {RouteTableModel::Geometry, "zigzag"},      {RouteTableModel::Name, ""}};
    for (const auto& [column, text] : bad) {
      QVERIFY(!model->setData(model->index(1, column), QString::fromUtf8(text), Qt::EditRole));
      QVERIFY2(w.lastError().startsWith(QStringLiteral("WP2 ")), qPrintable(w.lastError()));
    }
    QVERIFY(w.lastError().contains(QStringLiteral("name")));
    QVERIFY(shown(w) == before);
    // WP2 typed onto WP1 would make a leg of length 0: refused
    QVERIFY(model->setData(model->index(1, RouteTableModel::Latitude), QString::number(a.latDeg, 'g', 17),
                           Qt::EditRole));
    QVERIFY(!model->setData(model->index(1, RouteTableModel::Longitude), QString::number(a.lonDeg, 'g', 17),
                            Qt::EditRole));
    QVERIFY2(w.lastError().contains(QStringLiteral("length 0")), qPrintable(w.lastError()));
    // Selecting a row selects the waypoint on the chart
    table->selectRow(2);
    QCOMPARE(v->routeOverlay()->selectedWaypoint().value_or(99), std::size_t{2});
  }

  void libraryKeepsRoutesAndTheActiveOne() {
    const QString routeDir = freshRouteDir();
    geo::Route made;
    {
      MainWindow w(freshOptions());
      showAndWait(w);
      EcdisView* v = w.chart();
      made =
          routeOf({geoPointAt(*v, {200, 200}), geoPointAt(*v, {400, 260}), geoPointAt(*v, {500, 500})}, 0.2);
      made.waypoints[1].leg.plannedSpeedKn = 11.0;
      w.routeLibrary()->add(made);
      QVERIFY(w.saveRoute());
      QVERIFY(QFile::exists(routeDir + QStringLiteral("/Across the point.rtz")));
      QSignalSpy active(w.routeLibrary(), &RouteLibrary::activeRouteChanged);
      action(w, "routeActivateAction")->trigger();
      QCOMPARE(active.count(), 1);
      QCOMPARE(active.front().front().value<geo::Route>(), made);
      QVERIFY(w.routeLibrary()->names().front() == QStringLiteral("Across the point"));
      // an edit of the active route is announced too
      QVERIFY(w.routePanel()->model()->setData(w.routePanel()->model()->index(2, RouteTableModel::Speed),
                                               QStringLiteral("9"), Qt::EditRole));
      QCOMPARE(active.count(), 2);
      QVERIFY(w.routeLibrary()->names().front().endsWith(QLatin1Char('*')));  // edited, not saved
      action(w, "routeUndo")->trigger();                                      // back as saved
    }
    // WHEN a new window opens on the same directory THEN it has the route, equal, and it is active
    MainWindow w(freshOptions());
    showAndWait(w);
    QCOMPARE(w.routeLibrary()->count(), 1);
    QCOMPARE(w.routeLibrary()->at(0).route, made);
    QCOMPARE(w.routeLibrary()->active(), 0);
    QVERIFY(w.routeLibrary()->activeRoute());
    QVERIFY(w.routePanel()->routeList()->currentText().contains(QStringLiteral("(active)")));
    QVERIFY(w.chart()->routeOverlay()->isActive());
  }

  void rtzAndGpxImported() {
    const QString routeDir = freshRouteDir();
    MainWindow w(freshOptions());
    showAndWait(w);
    const QString rtz = dir_.filePath(QStringLiteral("harbour.rtz"));
    writeFile(rtz,
              "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
              "<route xmlns=\"http://www.cirm.org/RTZ/1/1\" version=\"1.1\">\n"
              "  <routeInfo routeName=\"Harbour approach\"/>\n"
              "  <waypoints>\n"
              "    <defaultWaypoint radius=\"0.3\"/>\n"
              "    <waypoint id=\"1\" name=\"Fairway\"><position lat=\"47.30\" lon=\"-122.47\"/></waypoint>\n"
              "    <waypoint id=\"2\" name=\"Turn\"><position lat=\"47.29\" lon=\"-122.45\"/>\n"
              "      <leg portsideXTD=\"0.05\" starboardXTD=\"0.08\" speedMax=\"8\" "
              "geometryType=\"Orthodrome\"/></waypoint>\n"
              "    <waypoint id=\"3\" name=\"Berth\"><position lat=\"47.27\" lon=\"-122.44\"/><leg "
              "speedMax=\"5\"/></waypoint>\n"
              "  </waypoints>\n"
              "</route>\n");
    QVERIFY2(w.importRoute(rtz), qPrintable(w.lastError()));
    QCOMPARE(shown(w).name, std::string("Harbour approach"));
    QCOMPARE(shown(w).waypoints.size(), std::size_t{3});
    RK_COMPARE_NEAR(shown(w).waypoints[1].leg.starboardXtlNm, 0.08, 1e-12);
    QVERIFY(shown(w).waypoints[1].leg.geometry == geo::LegGeometry::GreatCircle);
    QVERIFY(QFile::exists(routeDir + QStringLiteral("/Harbour approach.rtz")));  // kept in the library
    const QString gpx = dir_.filePath(QStringLiteral("plotter.gpx"));
    writeFile(gpx,
              "<?xml version=\"1.0\"?>\n"
              "<gpx version=\"1.1\" creator=\"a plotter\" xmlns=\"http://www.topografix.com/GPX/1/1\">\n"
              "  <rte><name>Plotter route</name>\n"
              "    <rtept lat=\"47.28\" lon=\"-122.50\"><name>A</name></rtept>\n"
              "    <rtept lat=\"47.27\" lon=\"-122.48\"><name>B</name></rtept>\n"
              "  </rte>\n"
              "</gpx>\n");
    QVERIFY2(w.importRoute(gpx), qPrintable(w.lastError()));
    QCOMPARE(w.routeLibrary()->count(), 2);
    QCOMPARE(shown(w).name, std::string("Plotter route"));
    QCOMPARE(shown(w).waypoints.back().name, std::string("B"));
    RK_COMPARE_NEAR(shown(w).waypoints.back().position.lonDeg, -122.48, 1e-12);
    // A broken file is refused with its name and the reason; the library is unchanged
    const QString broken = dir_.filePath(QStringLiteral("broken.rtz"));
    writeFile(broken, "<route version=\"1.1\"><waypoints><waypoint id=\"1\"></route>");
    QVERIFY(!w.importRoute(broken));
    QVERIFY2(w.lastError().contains(QStringLiteral("broken.rtz")), qPrintable(w.lastError()));
    QCOMPARE(w.routeLibrary()->count(), 2);
    // The library's list switches the route shown
    w.routePanel()->routeList()->setCurrentIndex(0);
    emit w.routePanel()->routeList()->activated(0);
    QCOMPARE(shown(w).name, std::string("Harbour approach"));
  }

  void routeCheckOnUs5wa22m() {
    if (!QDir(kTacoma).exists()) QSKIP("../shared/data/enc/US5WA22M is not here");
    freshRouteDir();
    MainWindow w(freshOptions());
    showAndWait(w);
    w.openCharts(kTacoma);
    QTRY_VERIFY_WITH_TIMEOUT(!w.chartsLoading(), kTimeoutMs);
    QCOMPARE(w.chart()->cells().front()->info().name, std::string("US5WA22M"));
    // GIVEN a route whose second leg crosses the point south of the first waypoints (tst_route_check)
    w.routeLibrary()->add(routeOf({{47.300, -122.470}, {47.285, -122.460}, {47.250, -122.470}}, 0.05));
    action(w, "routeCheckAction")->trigger();
    // THEN land is found on leg 2 and not on leg 1, and the list shows every finding
    const auto& f = w.routeFindings();
    const auto landOn = [&](std::size_t leg) {
      return std::count_if(f.begin(), f.end(), [&](const charts::RouteFinding& x) {
        return x.leg == leg && x.kind == charts::HazardKind::Land && x.objectClass == "LNDARE";
      });
    };
    QCOMPARE(landOn(1), 0);
    QVERIFY(landOn(2) >= 1);
    QTableWidget* list = w.routePanel()->findingsTable();
    QCOMPARE(list->rowCount(), static_cast<int>(f.size()));
    qInfo("%zu findings; %s; hazards built in %.1f ms", f.size(),
          qPrintable(w.routePanel()->checkSummary()->text()), w.routeCheckCache().lastBuildMs());
    // WHEN the land finding is selected THEN the chart is centred on it and its pick report shown
    const auto land = std::find_if(
        f.begin(), f.end(), [](const charts::RouteFinding& x) { return x.kind == charts::HazardKind::Land; });
    const int row = static_cast<int>(land - f.begin());
    QVERIFY(list->item(row, 2)->text().contains(QStringLiteral("Land area")));
    QVERIFY(list->item(row, 0)->text().startsWith(QStringLiteral("2 WP2")));
    const charts::LatLon at = land->position;
    w.chart()->setView({47.276, -122.462}, 30000.0);
    list->setCurrentCell(row, 0);
    const charts::LatLon centre = w.chart()->viewport().centre();
    RK_COMPARE_NEAR(centre.latDeg, at.latDeg, 1e-9);
    RK_COMPARE_NEAR(centre.lonDeg, at.lonDeg, 1e-9);
    QCOMPARE(w.chart()->routeOverlay()->selectedFinding().value_or(99), static_cast<std::size_t>(row));
    const QString pick = w.findChild<QTextBrowser*>(QStringLiteral("pickReport"))->toPlainText();
    QVERIFY2(pick.contains(QStringLiteral("Land area")), qPrintable(pick));
    // The hazards are built once while the charts and the safety settings stay; a new contour rebuilds
    const int builds = w.routeCheckCache().builds();
    w.checkRoute();
    QCOMPARE(w.routeCheckCache().builds(), builds);
    charts::MarinerSettings s = w.chart()->settings();
    s.safetyContourM = 5.0;
    QVERIFY(w.setMarinerSettings(s));
    QTRY_VERIFY_WITH_TIMEOUT(!w.routeCheckPending(), kTimeoutMs);
    QCOMPARE(w.routeCheckCache().builds(), builds + 1);
    QVERIFY(w.routePanel()->checkSummary()->text().contains(QStringLiteral("safety contour 5 m")));
    // The picture: the whole route at 1:30 000, the land finding selected
    s.safetyContourM = 10.0;
    QVERIFY(w.setMarinerSettings(s));
    QTRY_VERIFY_WITH_TIMEOUT(!w.routeCheckPending(), kTimeoutMs);
    w.chart()->setView({47.276, -122.462}, 30000.0);
    const auto again =
        std::find_if(w.routeFindings().begin(), w.routeFindings().end(),
                     [](const charts::RouteFinding& x) { return x.kind == charts::HazardKind::Land; });
    w.chart()->routeOverlay()->setSelectedFinding(
        static_cast<std::size_t>(again - w.routeFindings().begin()));
    if (auto* d = w.findChild<QDockWidget*>(QStringLiteral("routeDock"))) d->raise();
    saveWindowShot(w, QStringLiteral("route_check"));
  }

  void turnsThatDoNotFitListedWithoutCharts() {
    freshRouteDir();
    MainWindow w(freshOptions());
    showAndWait(w);
    // GIVEN the zigzag
    geo::Route route = reckoner::test::zigzagInCommencementBay();
    w.routeLibrary()->add(route);
    // WHEN it is checked with no chart open THEN the turns are listed all the same
    action(w, "routeCheckAction")->trigger();
    QTableWidget* list = w.routePanel()->findingsTable();
    QCOMPARE(list->rowCount(), 2);
    QVERIFY2(w.routePanel()->checkSummary()->text().contains(QStringLiteral("2 turn(s) that do not fit")),
             qPrintable(w.routePanel()->checkSummary()->text()));
    QCOMPARE(list->item(0, 0)->text(), QStringLiteral("at WP2"));
    QCOMPARE(list->item(1, 0)->text(), QStringLiteral("at WP4"));
    QCOMPARE(list->item(0, 1)->text(), QStringLiteral("turn does not fit"));
    QVERIFY2(list->item(0, 2)->text().startsWith(QStringLiteral("92° to port: radius 2.00 NM")),
             qPrintable(list->item(0, 2)->text()));
    QCOMPARE(list->item(0, 2)->toolTip(), list->item(0, 2)->text());
    // The chart draws each turn as it is sailed, dashed: it begins half the shorter leg before its
    // waypoint and ends as far along the next leg (not 2 NM back, off the leg's start)
    const RouteGeometry g = routeGeometry(route);
    QCOMPARE(g.turns.size(), std::size_t{2});  // WP3 is a corner
    for (const RouteGeometry::Turn& t : g.turns) {
      const std::size_t k = t.waypoint;
      const double half = 0.5 * std::min(geo::legLengthM(route, k), geo::legLengthM(route, k + 1));
      QVERIFY(!t.fits);
      for (const auto& [at, to, along] : {std::tuple{t.wheelOver, k, geo::legLengthM(route, k) - half},
                                          std::tuple{t.arc.back(), k + 1, half}}) {
        const geo::GeoPoint e = geo::legPoint(route, to, along);
        const charts::MercatorPoint m = charts::toMercator({e.latDeg, e.lonDeg});
        RK_COMPARE_NEAR(at.x, m.x, 1e-3);
        RK_COMPARE_NEAR(at.y, m.y, 1e-3);
      }
    }
    // WHEN a waypoint is inserted before WP2 and the turn at WP4 is chosen before the check runs again
    // THEN WP4 is selected where it now is (row 4), not the waypoint at its old index
    geo::Waypoint extra = route.waypoints[0];
    extra.id = 99;
    extra.name = "WP1a";
    extra.position = {47.295, -122.465};
    route.waypoints.insert(route.waypoints.begin() + 1, extra);
    QString error;
    QVERIFY2(w.routeLibrary()->edit(route, QStringLiteral("insert"), &error), qPrintable(error));
    QVERIFY(w.routeCheckPending());
    list->setCurrentCell(1, 0);
    QCOMPARE(w.chart()->routeOverlay()->selectedWaypoint().value_or(99), std::size_t{4});
    QCOMPARE(w.routePanel()->table()->currentIndex().row(), 4);
    // AND once the radius is one the legs have room for, nothing is listed for the turns
    route.defaultTurnRadiusNm = 0.1;
    QVERIFY2(w.routeLibrary()->edit(route, QStringLiteral("radius"), &error), qPrintable(error));
    w.checkRoute();
    QCOMPARE(list->rowCount(), 0);
    QVERIFY(!w.routePanel()->checkSummary()->text().contains(QStringLiteral("turn(s)")));
  }

  void turnsThatDoNotFitListedAfterTheFindings() {
    if (!QDir(kTacoma).exists()) QSKIP("../shared/data/enc/US5WA22M is not here");
    freshRouteDir();
    MainWindow w(freshOptions());
    showAndWait(w);
    w.routeLibrary()->add(reckoner::test::zigzagInCommencementBay());
    // WHEN the chart is open THEN the turns come after the findings, and choosing one selects its waypoint
    w.openCharts(kTacoma);
    QTRY_VERIFY_WITH_TIMEOUT(!w.chartsLoading(), kTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(!w.routeCheckPending(), kTimeoutMs);
    QTableWidget* list = w.routePanel()->findingsTable();
    const int findings = static_cast<int>(w.routeFindings().size());
    QVERIFY(findings > 0);  // the zigzag crosses the shoals off the point
    QCOMPARE(list->rowCount(), findings + 2);
    QCOMPARE(list->item(findings + 1, 0)->text(), QStringLiteral("at WP4"));
    list->setCurrentCell(0, 0);  // a finding first: its ring is selected
    QCOMPARE(w.chart()->routeOverlay()->selectedFinding().value_or(99), std::size_t{0});
    list->setCurrentCell(findings + 1, 0);
    QCOMPARE(w.chart()->routeOverlay()->selectedWaypoint().value_or(99), std::size_t{3});
    QCOMPARE(w.routePanel()->table()->currentIndex().row(), 3);
    QVERIFY(!w.chart()->routeOverlay()->selectedFinding());  // and the finding's is not
    // The picture: the first turn row chosen
    w.chart()->setView({47.292, -122.45}, 25000.0);
    if (auto* d = w.findChild<QDockWidget*>(QStringLiteral("routeDock"))) d->raise();
    list->setCurrentCell(findings, 0);
    saveWindowShot(w, QStringLiteral("route_turns"));
  }
};

QTEST_MAIN(TestRouteWindow)
#include "tst_route_window.moc"
