// GIVEN / WHEN / THEN behaviour of the chart view widget (offscreen): the worker renders the embedded
// chart, a drag pans and a wheel step zooms about the cursor at once from the cached image, a click
// reports the features there, and a burst of view changes renders only the views still wanted.
#include <QApplication>
#include <QMouseEvent>
#include <QSignalSpy>
#include <QTest>
#include <QWheelEvent>
#include <cmath>

#include "charts/s57/s57_loader.h"
#include "common/angles.h"
#include "support/compare_near.h"
#include "ui/bridge/radar_raster.h"
#include "ui/map/chart_view.h"

using namespace reckoner;

namespace {
// Conditions are waited for, never time; the limit only ends a test that would otherwise hang, so it
// is generous (a render on a machine loaded by a parallel build takes several times longer).
constexpr int kTimeoutMs = 60000;

charts::LatLon local(double xKm, double yKm) {  // the default chart's own frame (resources/charts)
  return {49.5 + yKm / 110.57, -29.5 + xKm / (111.32 * std::cos(degToRad(49.5)))};
}

void send(QWidget& w, QEvent::Type type, QPointF at, Qt::MouseButtons buttons) {
  QMouseEvent e(type, at, w.mapToGlobal(at), Qt::LeftButton, buttons, Qt::NoModifier);
  QCoreApplication::sendEvent(&w, &e);
}

bool near(const charts::ScreenPoint& a, double x, double y) {
  return std::abs(a.x - x) < 0.5 && std::abs(a.y - y) < 0.5;
}
}  // namespace

class TestChartView : public QObject {
  Q_OBJECT
 private slots:
  void radarPictureRasterPlacesEchoesFromThePose() {
    // GIVEN a 360 x 100 picture (10 m bins) with one lit bin at 90.5 deg relative, 505 m WHEN it is
    // rasterised from a pose at the origin heading north, and heading east THEN the echo lands east of
    // own ship, and south of it, in north-up pixels; nothing is drawn where nothing was seen.
    radar::PolarImage img;
    img.azimuths = 360;
    img.rangeBins = 100;
    img.binM = 10.0;
    img.bins.assign(std::size_t{360} * 100, 0);
    img.bins[90 * 100 + 50] = 1;
    radar::SweepPose pose;
    pose.periodS = 2.0;
    const ui::RadarRaster north = ui::rasteriseRadarPicture(img, pose, 2.0);
    QCOMPARE(north.mask.width(), 208);
    QCOMPARE(north.metresPerPixel, 10.0);
    const auto lit = [](const ui::RadarRaster& r, double x, double y) {
      const int half = r.mask.width() / 2;
      const int px = half + static_cast<int>(std::floor(x / r.metresPerPixel));
      const int py = half + static_cast<int>(std::floor(-y / r.metresPerPixel));
      return r.mask.constScanLine(py)[px] != 0;
    };
    const double a = degToRad(90.5);  // the bin's centre
    QVERIFY(lit(north, 505.0 * std::sin(a), 505.0 * std::cos(a)));
    QVERIFY(!lit(north, -505.0, 0.0));
    QVERIFY(!lit(north, 0.0, 505.0));
    pose.headingRad = kPi / 2;
    const ui::RadarRaster east = ui::rasteriseRadarPicture(img, pose, 2.0);
    QVERIFY(lit(east, 505.0 * std::sin(a + kPi / 2), 505.0 * std::cos(a + kPi / 2)));
    QVERIFY(!lit(east, 505.0, 0.0));
    int count = 0;
    for (int y = 0; y < east.mask.height(); ++y)
      for (int x = 0; x < east.mask.width(); ++x) count += east.mask.constScanLine(y)[x] ? 1 : 0;
    QVERIFY(count >= 1 && count <= 12);  // one bin: about its arc (8.8 m) by its depth (10 m)
    img.bins.resize(10);                 // inconsistent: a null raster, no crash
    QVERIFY(ui::rasteriseRadarPicture(img, pose, 2.0).isNull());
  }
  void rendersPansZoomsAndPicks() {
    ui::ChartView view;
    view.resize(800, 600);
    view.setCells({charts::loadCell(std::string(charts::kDefaultChartPath))});
    view.setView(local(0.6, -3.0), 30000);
    view.show();
    QTRY_VERIFY_WITH_TIMEOUT(
        view.renderedGeneration() == view.requestedGeneration() && !view.renderedImage().isNull(),
        kTimeoutMs);
    // THEN what is on screen is the chart: land south of the bay, the notice at the bottom
    QImage shot = view.grab().toImage();
    const charts::Rgb land = charts::defaultColours().colour(charts::Palette::Day, "LANDA");
    const charts::ScreenPoint onLand = view.viewport().toScreen(local(-1.0, -5.0));
    QCOMPARE(shot.pixel(static_cast<int>(onLand.x), static_cast<int>(onLand.y)) & 0xFFFFFF,
             qRgb(land.r, land.g, land.b) & 0xFFFFFF);
    if (qEnvironmentVariableIsSet("RECKONER_SAVE_PNG")) shot.save(qEnvironmentVariable("RECKONER_SAVE_PNG"));

    // WHEN dragged by (50, 30) px THEN the chart point under the mouse follows it, and before any new
    // render the cached image already shows it moved
    const charts::LatLon grabbed = view.viewport().toLatLon({400, 300});
    const QRgb before = shot.pixel(400, 300);
    send(view, QEvent::MouseButtonPress, {400, 300}, Qt::LeftButton);
    send(view, QEvent::MouseMove, {420, 312}, Qt::LeftButton);
    send(view, QEvent::MouseMove, {450, 330}, Qt::LeftButton);
    send(view, QEvent::MouseButtonRelease, {450, 330}, Qt::NoButton);
    QVERIFY(near(view.viewport().toScreen(grabbed), 450, 330));
    QCOMPARE(view.grab().toImage().pixel(450, 330), before);

    // WHEN the wheel turns one step in at (200, 150) THEN the scale is 1.25 times larger and the chart
    // point there stays put
    QTRY_VERIFY_WITH_TIMEOUT(view.renderedGeneration() == view.requestedGeneration(), kTimeoutMs);
    const double scale = view.viewport().scaleDenominator();
    const charts::LatLon anchor = view.viewport().toLatLon({200, 150});
    QWheelEvent wheel({200, 150}, view.mapToGlobal(QPointF(200, 150)), QPoint(), QPoint(0, 120), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QCoreApplication::sendEvent(&view, &wheel);
    RK_COMPARE_NEAR(view.viewport().scaleDenominator(), scale / 1.25, 1e-6 * scale);
    QVERIFY(near(view.viewport().toScreen(anchor), 200, 150));

    // WHEN the wreck is clicked (press and release without a drag) THEN its pick report arrives
    view.setView(local(2.8, 1.8), 10000);
    QSignalSpy picks(&view, &ui::ChartView::picked);
    const charts::ScreenPoint wreck = view.viewport().toScreen(local(2.8, 1.8));
    send(view, QEvent::MouseButtonPress, {wreck.x + 2, wreck.y + 1}, Qt::LeftButton);
    send(view, QEvent::MouseButtonRelease, {wreck.x + 2, wreck.y + 1}, Qt::NoButton);
    QCOMPARE(picks.count(), 1);
    const auto features = picks.at(0).at(0).value<std::vector<charts::PickedFeature>>();
    QVERIFY(!features.empty());
    QCOMPARE(features.front().className, std::string("Wreck"));
  }

  void aBurstOfViewChangesRendersOnlyWhatIsStillWanted() {
    ui::ChartView view;
    view.resize(1200, 900);
    view.setCells({charts::loadCell(std::string(charts::kDefaultChartPath))});
    view.show();
    QSignalSpy done(&view, &ui::ChartView::renderFinished);
    for (int k = 0; k < 30; ++k) view.setView(local(-3.0 + 0.2 * k, 0.0), 40000 - 500 * k);
    QTRY_VERIFY_WITH_TIMEOUT(view.renderedGeneration() == view.requestedGeneration(), kTimeoutMs);
    QVERIFY2(done.count() < 30, qPrintable(QString("%1 renders for 30 views").arg(done.count())));
    QVERIFY(near(view.viewport().toScreen(local(-3.0 + 0.2 * 29, 0.0)), 600, 450));
  }
};

int main(int argc, char** argv) {
  qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  qRegisterMetaType<std::vector<reckoner::charts::PickedFeature>>();
  TestChartView t;
  return QTest::qExec(&t, argc, argv);
}
#include "tst_chart_view.moc"
