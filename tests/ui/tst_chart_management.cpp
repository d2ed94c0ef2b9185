// Chart management in the window (issue 18): charts opened from the File menu are shown at once
// (zoomed to their coverage, following own ship switched off and said so), a second folder does not
// jump back to own ship, the chart list names the open cells with their scale and edition and zooms to
// one, the coverage outlines are drawn, the context menu zooms to the cells under the point, zooming
// keeps to the overscale cap and the world view, the overscale note keeps clear of the cursor/EBL/VRM
// readout, and the cursor readout is a number anywhere. The NOAA cells come from ../shared/data/enc
// (never copied here); tests that need them skip when it is absent.
#include <QAction>
#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QMenu>
#include <QStatusBar>
#include <QTest>
#include <QWheelEvent>
#include <cmath>

#include "charts/render/chart_extent.h"
#include "files/scenario_json.h"
#include "main_window_test_helpers.h"
#include "resources/embedded.h"
#include "support/compare_near.h"
#include "ui/map/range_scale.h"
#include "ui/panels/chart_list_panel.h"

using namespace reckoner;
using namespace reckoner::ui;
using namespace reckoner::ui::test;

namespace {

const QString kEnc = QStringLiteral(RECKONER_SHARED_DIR "/data/enc");

QString cellFolder(const char* name) {
  return kEnc + QLatin1Char('/') + QLatin1String(name);
}

bool encPresent() {
  return QDir(cellFolder("US5WA22M")).exists() && QDir(cellFolder("US5BOSCC")).exists() &&
         QDir(cellFolder("US4MD81M")).exists();
}

/// Opens `path` the way File > Open ENC does once its dialog has answered, and waits for the load.
void openFromTheFileMenu(MainWindow& w, const QString& path) {
  w.openCharts(path);
  QVERIFY(w.chartsLoading());
  QTRY_VERIFY_WITH_TIMEOUT(!w.chartsLoading(), kTimeoutMs);
  QVERIFY2(!w.chart()->cells().empty(), qPrintable(w.lastError()));
}

/// Whether the whole box lies on the chart widget (its four corners inside the widget).
bool boxOnScreen(const charts::Viewport& v, const charts::Bounds& b) {
  for (const charts::LatLon p :
       {charts::LatLon{b.minLatDeg, b.minLonDeg}, charts::LatLon{b.minLatDeg, b.maxLonDeg},
        charts::LatLon{b.maxLatDeg, b.minLonDeg}, charts::LatLon{b.maxLatDeg, b.maxLonDeg}}) {
    const charts::ScreenPoint s = v.toScreen(p);
    if (s.x < 0 || s.y < 0 || s.x > v.width() || s.y > v.height()) return false;
  }
  return true;
}

/// The share of the widget's width or height (the larger) the box spans: 1 = edge to edge.
double boxShare(const charts::Viewport& v, const charts::Bounds& b) {
  const charts::ScreenPoint a = v.toScreen({b.maxLatDeg, b.minLonDeg});
  const charts::ScreenPoint c = v.toScreen({b.minLatDeg, b.maxLonDeg});
  return std::max(std::abs(c.x - a.x) / v.width(), std::abs(c.y - a.y) / v.height());
}

/// Waits until a frame newer than `sequence` has arrived and the window shows it (its repaint tick
/// has run: following own ship would have moved the view then).
void waitForNextFrame(MainWindow& w, quint64 sequence) {
  RK_WAIT_VERIFY(w.history().latest().sequence > sequence && !w.refreshPending());
}

QAction* actionNamed(QWidget& w, const char* name) {
  return w.findChild<QAction*>(QString::fromLatin1(name));
}

void wheel(QWidget& w, QPointF at, int steps) {
  for (int i = 0; i < std::abs(steps); ++i) {
    QWheelEvent e(at, w.mapToGlobal(at), QPoint(), QPoint(0, steps > 0 ? 120 : -120), Qt::NoButton,
                  Qt::NoModifier, Qt::NoScrollPhase, false);
    QCoreApplication::sendEvent(&w, &e);
  }
}

void moveMouse(QWidget& w, QPointF at) {
  QMouseEvent e(QEvent::MouseMove, at, w.mapToGlobal(at), Qt::NoButton, Qt::NoButton, Qt::NoModifier);
  QCoreApplication::sendEvent(&w, &e);
}

/// The widget point of a lat/lon.
QPointF widgetAt(const ChartView& v, charts::LatLon p) {
  const charts::ScreenPoint s = v.viewport().toScreen(p);
  return {s.x, s.y};
}

}  // namespace

class TestChartManagement : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() { isolateFromTheUser("tst_chart_management"); }

  void openingUS5WA22MFromTheFileMenuShowsItInOneStep() {
    if (!encPresent()) QSKIP("../shared/data/enc is not here");
    // GIVEN the first view: own ship in the fictional harbour, following it
    MainWindow w(freshOptions());
    showAndWait(w);
    QVERIFY(w.chart()->overlay().followOwnShip);
    const quint64 before = w.history().latest().sequence;
    // WHEN US5WA22M is opened from the File menu
    openFromTheFileMenu(w, cellFolder("US5WA22M"));
    QCOMPARE(w.chart()->cells().front()->info().name, std::string("US5WA22M"));
    // THEN the view shows the whole cell, zoomed to it (it spans most of the chart's width or height)
    const charts::Bounds cover = w.chart()->cells().front()->coverageBounds();
    const charts::Viewport shown = w.chart()->viewport();
    QVERIFY(boxOnScreen(shown, cover));
    qInfo("US5WA22M shown at 1:%.0f, spanning %.0f%% of the chart", shown.scaleDenominator(),
          100.0 * boxShare(shown, cover));
    QVERIFY(boxShare(shown, cover) > 0.8);
    // AND following own ship is off, and the status bar says how to get back
    QVERIFY(!w.chart()->overlay().followOwnShip);
    QVERIFY(!actionNamed(w, "followOwnShip")->isChecked());
    const QString said = w.statusBar()->currentMessage();
    QVERIFY2(said.contains(QStringLiteral("US5WA22M")) && said.contains(QStringLiteral("Centre on own ship")),
             qPrintable(said));
    // AND nothing more was needed: the frames that follow (the worker answers the new charts with
    // one) leave the view where it is
    waitForNextFrame(w, before);
    runUntil(w, simTime(w) + 20.0);
    RK_COMPARE_NEAR(w.chart()->viewport().centre().latDeg, shown.centre().latDeg, 1e-12);
    RK_COMPARE_NEAR(w.chart()->viewport().centre().lonDeg, shown.centre().lonDeg, 1e-12);
    RK_COMPARE_NEAR(w.chart()->viewport().scaleDenominator(), shown.scaleDenominator(), 1e-9);
    saveWindowShot(w, QStringLiteral("charts-us5wa22m-opened"));
    // AND Centre on own ship (Home) goes back and follows again
    actionNamed(w, "centreOwnShip")->trigger();
    QVERIFY(w.chart()->overlay().followOwnShip);
    QVERIFY(actionNamed(w, "followOwnShip")->isChecked());
    const auto& x = w.history().latest().frame.estimate.x;
    const QPointF own = w.chart()->gridToWidget(x[est::drkf::kPosX], x[est::drkf::kPosY]);
    RK_COMPARE_NEAR(own.x(), w.chart()->width() / 2.0, 1.0);
    RK_COMPARE_NEAR(own.y(), w.chart()->height() / 2.0, 1.0);
  }

  void aSecondFolderDoesNotJumpBackToOwnShip() {
    if (!encPresent()) QSKIP("../shared/data/enc is not here");
    MainWindow w(freshOptions());
    showAndWait(w);
    openFromTheFileMenu(w, cellFolder("US5WA22M"));
    // WHEN a second folder is opened and the run goes on
    const quint64 before = w.history().latest().sequence;
    openFromTheFileMenu(w, cellFolder("US5BOSCC"));
    waitForNextFrame(w, before);
    runUntil(w, simTime(w) + 30.0);
    // THEN the view is on Boston, not back on own ship
    const charts::Bounds boston = w.chart()->cells().front()->coverageBounds();
    QCOMPARE(w.chart()->cells().front()->info().name, std::string("US5BOSCC"));
    QVERIFY(boxOnScreen(w.chart()->viewport(), boston));
    QVERIFY(boxShare(w.chart()->viewport(), boston) > 0.8);
    // AND charts that already cover the view's centre leave the view as it is
    w.chart()->zoomAbout(2.0, QPointF(w.chart()->width() / 2.0, w.chart()->height() / 2.0));
    const charts::Viewport here = w.chart()->viewport();
    openFromTheFileMenu(w, cellFolder("US5BOSCC") + QStringLiteral("/US5BOSCC.000"));
    RK_COMPARE_NEAR(w.chart()->viewport().scaleDenominator(), here.scaleDenominator(), 1e-9);
    RK_COMPARE_NEAR(w.chart()->viewport().centre().latDeg, here.centre().latDeg, 1e-12);
    QVERIFY2(w.statusBar()->currentMessage().contains(QStringLiteral("the view is on them")),
             qPrintable(w.statusBar()->currentMessage()));
  }

  void theChartListNamesTheCellsAndZoomsToOne() {
    if (!encPresent()) QSKIP("../shared/data/enc is not here");
    MainWindow w(freshOptions());
    showAndWait(w);
    openFromTheFileMenu(w, kEnc);
    ChartListPanel* list = w.chartList();
    QVERIFY(list);
    const int rows = list->table()->rowCount();
    QCOMPARE(static_cast<std::size_t>(rows), w.chart()->cells().size());
    QVERIFY(rows >= 4);
    // THEN each row gives the cell's metadata, the largest scale first
    int tacoma = -1;
    for (int r = 0; r < rows; ++r) {
      const charts::CellPtr c = list->cellAt(r);
      const auto text = [&](int col) { return list->table()->item(r, col)->text(); };
      QCOMPARE(text(ChartListPanel::Name), QString::fromStdString(c->info().name));
      QCOMPARE(text(ChartListPanel::Features), QString::number(c->features().size()));
      QVERIFY(QRegularExpression(QStringLiteral("^\\d{4}-\\d{2}-\\d{2}$"))
                  .match(text(ChartListPanel::Issued))
                  .hasMatch());
      if (r > 0) QVERIFY(list->cellAt(r - 1)->info().compilationScale <= c->info().compilationScale);
      if (c->info().name == "US5WA22M") tacoma = r;
    }
    QVERIFY(tacoma >= 0);
    const auto cell = [&](int col) { return list->table()->item(tacoma, col)->text(); };
    QCOMPARE(cell(ChartListPanel::Band), QStringLiteral("5 Harbour"));
    QCOMPARE(cell(ChartListPanel::Scale), QStringLiteral("1:15") + QChar(0x2009) + QStringLiteral("000"));
    QCOMPARE(cell(ChartListPanel::Edition), QStringLiteral("40"));
    QCOMPARE(cell(ChartListPanel::Update), QStringLiteral("4"));
    // AND the list is in the dock column, brought forward by the load
    auto* dock = w.findChild<QDockWidget*>(QStringLiteral("chartDock"));
    QVERIFY(dock && dock->isVisible() && !dock->isFloating());
    QCOMPARE(w.dockWidgetArea(dock), Qt::RightDockWidgetArea);
    // AND all four cells are in view, and each (too small to see at this scale) has its outline box
    for (const auto& c : w.chart()->cells()) QVERIFY(boxOnScreen(w.chart()->viewport(), c->coverageBounds()));
    saveWindowShot(w, QStringLiteral("charts-all-four-outlined"));
    // WHEN a row is double-clicked THEN the view shows that cell
    emit list->table()->cellDoubleClicked(tacoma, 0);
    const charts::Bounds cover = list->cellAt(tacoma)->coverageBounds();
    QVERIFY(boxOnScreen(w.chart()->viewport(), cover));
    QVERIFY(boxShare(w.chart()->viewport(), cover) > 0.8);
    // AND the cursor over the cell highlights its row and names it
    const QPointF cursorAt = widgetAt(*w.chart(), {47.27, -122.42});  // Commencement Bay
    moveMouse(*w.chart(), cursorAt);
    QVERIFY(list->rowUnderCursor(tacoma));
    for (int r = 0; r < rows; ++r)
      if (r != tacoma) QVERIFY(!list->rowUnderCursor(r));
    QVERIFY2(list->underCursorLabel()->text().contains(QStringLiteral("US5WA22M")),
             qPrintable(list->underCursorLabel()->text()));
    QVERIFY(list->table()->item(tacoma, 0)->font().bold());
    saveWindowShot(w, QStringLiteral("charts-list-tacoma-under-cursor"));
    // AND when the chart moves under the still cursor (to the coarsest cell, the last row) the
    // highlight follows: Tacoma is no longer under it, and the rows lit are the cells there now
    emit list->table()->cellDoubleClicked(rows - 1, 0);
    const auto there = w.chart()->cellsAt(cursorAt);
    QVERIFY(!list->rowUnderCursor(tacoma));
    for (int r = 0; r < rows; ++r)
      QCOMPARE(list->rowUnderCursor(r),
               std::find(there.begin(), there.end(), list->cellAt(r)) != there.end());
    // AND "Zoom to chart" zooms to the selected cells (Boston's two)
    list->table()->clearSelection();
    for (int r = 0; r < rows; ++r)
      if (list->cellAt(r)->info().name.rfind("US5BOS", 0) == 0)
        list->table()->selectionModel()->select(list->table()->model()->index(r, 0),
                                                QItemSelectionModel::Select | QItemSelectionModel::Rows);
    QCOMPARE(list->selectedCells().size(), std::size_t(2));
    QVERIFY(list->zoomButton()->isEnabled());
    list->zoomButton()->click();
    const charts::Bounds boston = charts::coverageOf(list->selectedCells());
    QVERIFY(boxOnScreen(w.chart()->viewport(), boston));
    QVERIFY(boxShare(w.chart()->viewport(), boston) > 0.8);
    saveWindowShot(w, QStringLiteral("charts-boston-outlines"));
  }

  void theOutlinesAreDrawnAndCanBeSwitchedOff() {
    if (!encPresent()) QSKIP("../shared/data/enc is not here");
    MainWindow w(freshOptions());
    showAndWait(w);
    openFromTheFileMenu(w, cellFolder("US5WA22M"));
    RK_WAIT_VERIFY(settled(w));
    // The outline's magenta, counted on the chart with outlines on and off.
    const charts::Rgb m = charts::defaultColours().colour(charts::Palette::Day, "CHMGD");
    const auto magenta = [&] {
      const QImage img = w.chart()->grab().toImage();
      int n = 0;
      for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
          const QRgb p = img.pixel(x, y);
          n += std::abs(qRed(p) - m.r) + std::abs(qGreen(p) - m.g) + std::abs(qBlue(p) - m.b) < 90 ? 1 : 0;
        }
      return n;
    };
    QAction* toggle = actionNamed(w, "chartOutlines");
    QVERIFY(toggle && toggle->isChecked());
    const int on = magenta();
    toggle->trigger();
    QVERIFY(!w.chart()->showOutlines());
    const int off = magenta();
    // THEN the outline adds about its perimeter on screen (the box spans > 80% one way)
    const int side = std::min(w.chart()->width(), w.chart()->height());
    qInfo("magenta pixels: %d with outlines, %d without", on, off);
    QVERIFY(on - off > side);
    toggle->trigger();
    QVERIFY(w.chart()->showOutlines());
  }

  void theContextMenuZoomsToTheCellsUnderThePoint() {
    if (!encPresent()) QSKIP("../shared/data/enc is not here");
    MainWindow w(freshOptions());
    showAndWait(w);
    openFromTheFileMenu(w, cellFolder("US5WA22M"));
    // GIVEN a close look somewhere in the cell
    w.chart()->setView({47.27, -122.42}, 5000);
    QMenu* menu = w.chart()->buildContextMenu(QPointF(w.chart()->width() / 2.0, w.chart()->height() / 2.0));
    auto* zoom = menu->findChild<QAction*>(QStringLiteral("zoomToChart_US5WA22M"));
    QVERIFY(zoom);
    QCOMPARE(zoom->text(), QStringLiteral("Zoom to chart US5WA22M"));
    QVERIFY(menu->findChild<QAction*>(QStringLiteral("showAllCharts")));
    // WHEN chosen THEN the whole cell is in view
    zoom->trigger();
    const charts::Bounds cover = w.chart()->cells().front()->coverageBounds();
    QVERIFY(boxOnScreen(w.chart()->viewport(), cover));
    QVERIFY(boxShare(w.chart()->viewport(), cover) > 0.8);
    delete menu;
    // AND off the cell there is no such item
    w.chart()->setView({0.0, 0.0}, 50000);
    menu = w.chart()->buildContextMenu(QPointF(w.chart()->width() / 2.0, w.chart()->height() / 2.0));
    QVERIFY(!menu->findChild<QAction*>(QStringLiteral("zoomToChart_US5WA22M")));
    delete menu;
  }

  void zoomingInStopsAtEightTimesTheChartsScale() {
    if (!encPresent()) QSKIP("../shared/data/enc is not here");
    MainWindow w(freshOptions());
    showAndWait(w);
    openFromTheFileMenu(w, cellFolder("US5WA22M"));
    // WHEN the wheel zooms in 40 steps over the middle of the cell
    const QPointF mid(w.chart()->width() / 2.0, w.chart()->height() / 2.0);
    w.chart()->setView({47.27, -122.42}, 20000);
    wheel(*w.chart(), mid, 40);
    // THEN it stops at 1:15 000 / 8, where the render says "OVERSCALE x8.0"
    RK_COMPARE_NEAR(w.chart()->viewport().scaleDenominator(), 15000.0 / charts::kMaxOverscale, 1e-9);
    RK_WAIT_VERIFY(settled(w));
    RK_COMPARE_NEAR(w.chart()->lastRenderStats().overscale, charts::kMaxOverscale, 1e-9);
    QVERIFY(!w.chart()->lastRenderStats().overscaleNote.isEmpty());
    // AND zooming out works again from there, and panning keeps the scale
    wheel(*w.chart(), mid, -1);
    RK_COMPARE_NEAR(w.chart()->viewport().scaleDenominator(), 1875.0 * 1.25, 1e-6);
    // AND off the charts zooming in stops at 1:2000
    w.chart()->setView({47.5, -130.0}, 50000);
    wheel(*w.chart(), mid, 40);
    RK_COMPARE_NEAR(w.chart()->viewport().scaleDenominator(), charts::kLargestScaleWithoutChart, 1e-9);
    // AND zooming out stops at the world: 360 degrees of longitude across the chart
    wheel(*w.chart(), mid, -200);
    const charts::Viewport world = w.chart()->viewport();
    const double left = world.toLatLon({0.0, world.height() / 2.0}).lonDeg;
    const double right = world.toLatLon({static_cast<double>(world.width()), world.height() / 2.0}).lonDeg;
    RK_COMPARE_NEAR(right - left, 360.0, 1e-6);
  }

  void theRangeBoxAndKeysKeepToTheCap() {
    if (!encPresent()) QSKIP("../shared/data/enc is not here");
    // GIVEN own ship in Chesapeake Bay on US4MD81M (1:80 000: the cap is 1:10 000)
    const resources::EmbeddedFile* f = resources::findScenario("default");
    QVERIFY(f);
    sim::Scenario s = files::parseScenario(f->text, "builtin:default");
    s.origin = {38.7, -76.42};
    MainWindow w(freshOptions());
    showAndWait(w);
    openFromTheFileMenu(w, cellFolder("US4MD81M"));
    w.loadScenario(s, QStringLiteral("chesapeake"));
    RK_WAIT_VERIFY(!w.history().empty() && w.chart()->frame() &&
                   std::abs(w.chart()->frame()->origin().latDeg - 38.7) < 1e-9 && !w.refreshPending());
    // WHEN the shortest range is chosen THEN the chart stops at 1:10 000 (a longer range shows)
    w.chart()->setRangeNm(0.25);
    RK_COMPARE_NEAR(w.chart()->viewport().scaleDenominator(), 80000.0 / charts::kMaxOverscale, 1e-9);
    QVERIFY(displayedRangeNm(w.chart()->viewport()) > 0.25);
    // AND '+' from 1.5 NM goes no further in than the cap either
    w.chart()->setRangeNm(1.5);
    w.chart()->setFocus();
    for (int i = 0; i < 4; ++i) QTest::keyClick(w.chart(), Qt::Key_Plus);
    RK_COMPARE_NEAR(w.chart()->viewport().scaleDenominator(), 10000.0, 1e-9);
  }

  void theOverscaleNoteKeepsClearOfTheReadout() {
    // GIVEN a 1024 x 768 window on the embedded chart (1:20 000), the cursor on the chart, an EBL and
    // a VRM, zoomed in to 1:5000
    MainWindow w(freshOptions());
    showAndWait(w, QSize(1024, 768));
    EcdisView* chart = w.chart();
    const QPointF mid(chart->width() / 2.0, chart->height() / 2.0);
    chart->centreOnOwnShip();
    chart->setView(chart->viewport().centre(), 5000);
    chart->buildContextMenu(mid + QPointF(120, -80))
        ->findChild<QAction*>(QStringLiteral("eblVrm"))
        ->trigger();
    moveMouse(*chart, QPointF(60, 40));
    RK_WAIT_VERIFY(settled(w));
    // THEN the render notes the overscale, below the readout box and clear of it
    const charts::RenderStats& st = chart->lastRenderStats();
    RK_COMPARE_NEAR(st.overscale, 4.0, 1e-9);
    const QRect readout = chart->readoutRect();
    QVERIFY(!readout.isEmpty());
    QVERIFY(readout.height() > 30);  // cursor, EBL and VRM lines
    qInfo("readout (%d,%d %dx%d), overscale note (%.0f,%.0f %.0fx%.0f)", readout.x(), readout.y(),
          readout.width(), readout.height(), st.overscaleNote.x(), st.overscaleNote.y(),
          st.overscaleNote.width(), st.overscaleNote.height());
    QVERIFY(!st.overscaleNote.isEmpty());
    QVERIFY(!st.overscaleNote.intersects(QRectF(readout)));
    QVERIFY(QRectF(chart->rect()).contains(st.overscaleNote));
    // AND it keeps clear of the fictional chart's notice at the bottom left
    QVERIFY(st.notForNavigation);
    saveWindowShot(w, QStringLiteral("charts-overscale-note-and-readout"));
    // AND the long line of the add-target mode does not reach it either
    chart->buildContextMenu(mid)->findChild<QAction*>(QStringLiteral("addTarget"))->trigger();
    QVERIFY(chart->addingTarget());
    QVERIFY(!st.overscaleNote.intersects(QRectF(chart->readoutRect())));
    QTest::keyClick(chart, Qt::Key_Escape);
  }

  void theCursorReadoutIsANumberEvenAtTheAntipode() {
    MainWindow w(freshOptions());
    showAndWait(w);
    const auto& x = w.history().latest().frame.estimate.x;
    const geo::GeoPoint own = w.chart()->frame()->toGeodetic({x[est::drkf::kPosX], x[est::drkf::kPosY]});
    for (const charts::LatLon far :
         {charts::LatLon{-own.latDeg, own.lonDeg + 180.0},
          charts::LatLon{-own.latDeg + 0.01, own.lonDeg - 179.99}, charts::LatLon{47.27, -122.42}}) {
      w.chart()->setView(far, 50000);
      const QString text =
          w.chart()->cursorText(QPointF(w.chart()->width() / 2.0, w.chart()->height() / 2.0));
      qInfo("cursor at %.2f %.2f: %s", far.latDeg, far.lonDeg, qPrintable(text));
      QVERIFY2(!text.contains(QStringLiteral("nan"), Qt::CaseInsensitive), qPrintable(text));
      QVERIFY2(text.contains(QStringLiteral(" NM")), qPrintable(text));
    }
  }
};

QTEST_MAIN(TestChartManagement)
#include "tst_chart_management.moc"
