// The chart's display modes (issue 18), each checked as the officer meets it: north-up, course-up and
// head-up with the north arrow; true motion with reset and relative motion, centred and off-centred;
// a pan stops following own ship and C brings it back; the CCRP as own ship's reference; the vector
// time and true/relative vectors; targets' past positions; labels that never overlap; units switched
// everywhere and remembered; the helm order always shown, on screen and typed; status messages beside
// the cursor readout. Screenshots go to screenshots/ for a person to look at.
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QSettings>
#include <QStatusBar>
#include <QTableView>
#include <QTest>
#include <QTextBrowser>
#include <QWheelEvent>
#include <cmath>

#include "common/angles.h"
#include "common/units.h"
#include "main_window_test_helpers.h"
#include "support/compare_near.h"
#include "ui/common/display_units.h"
#include "ui/map/label_placer.h"
#include "ui/map/range_scale.h"
#include "ui/panels/own_ship_panel.h"
#include "ui/panels/target_table_model.h"

using namespace reckoner;
using namespace reckoner::ui;
using namespace reckoner::ui::test;

namespace {

QComboBox* combo(MainWindow& w, const char* name) {
  return w.findChild<QComboBox*>(QString::fromLatin1(name));
}

void choose(QComboBox* box, int i) {
  box->setCurrentIndex(i);
  emit box->activated(i);
}

QAction* action(MainWindow& w, const char* name) {
  return w.findChild<QAction*>(QString::fromLatin1(name));
}

/// Paints the chart now (the labels and the indications are placed while painting).
void paintNow(MainWindow& w) {
  w.chart()->repaint();
}

/// The label that reads `text` in the last paint, or none.
std::optional<QRectF> labelBox(const EcdisView& v, const QString& text) {
  for (const auto& l : v.placedLabels())
    if (l.text == text) return l.box;
  return std::nullopt;
}

std::optional<QString> labelStartingWith(const EcdisView& v, const QString& prefix) {
  for (const auto& l : v.placedLabels())
    if (l.text.startsWith(prefix)) return l.text;
  return std::nullopt;
}

/// The estimated position of own ship (grid m).
geo::GridPoint ownEstimate(const MainWindow& w) {
  const auto& x = w.history().latest().frame.estimate.x;
  return {x[est::drkf::kPosX], x[est::drkf::kPosY]};
}

/// Pixels of the image within `radius` of `c` whose colour is within `tol` of `colour`.
int pixelsNear(const QImage& img, QPointF c, double radius, QColor colour, int tol) {
  int n = 0;
  for (int y = int(c.y() - radius); y <= int(c.y() + radius); ++y)
    for (int x = int(c.x() - radius); x <= int(c.x() + radius); ++x) {
      if (x < 0 || y < 0 || x >= img.width() || y >= img.height()) continue;
      if (std::hypot(x - c.x(), y - c.y()) > radius) continue;
      const QColor p = img.pixelColor(x, y);
      if (std::abs(p.red() - colour.red()) <= tol && std::abs(p.green() - colour.green()) <= tol &&
          std::abs(p.blue() - colour.blue()) <= tol)
        ++n;
    }
  return n;
}

/// The table's text of a track's cell.
QString cellText(MainWindow& w, int trackId, int column) {
  const int row = w.targetModel()->rowOf(trackId);
  return row < 0 ? QString() : w.targetModel()->index(row, column).data().toString();
}

/// The typed order of 045.0 deg 12.5 kn standing: out-of-range values are refused with a message and
/// the order unchanged; in m/s the speed is typed in m/s and an empty course keeps the course.
void typedOrdersAreCheckedAndInDisplayUnits(MainWindow& w) {
  OwnShipPanel* panel = w.ownShipPanel();
  EcdisView* v = w.chart();
  panel->courseEdit()->setText(QStringLiteral("400"));
  QTest::keyClick(panel->courseEdit(), Qt::Key_Return);
  QVERIFY2(panel->orderError().contains(QStringLiteral("0 to 360")), qPrintable(panel->orderError()));
  panel->courseEdit()->setText(QStringLiteral("90"));
  panel->speedEdit()->setText(QStringLiteral("55"));
  QTest::keyClick(panel->speedEdit(), Qt::Key_Return);
  QVERIFY2(panel->orderError().contains(QStringLiteral("0 to 40.0")), qPrintable(panel->orderError()));
  panel->speedEdit()->setText(QStringLiteral("fast"));
  QVERIFY(!panel->applyTypedOrder());
  RK_COMPARE_NEAR(radToDeg(v->orderedCourseSpeed().first), 45.0, 1e-3);  // (as the frame carries it)
  // AND in m/s the speed is typed in m/s
  w.setDisplayUnits({DistanceUnit::NauticalMiles, SpeedUnit::MetresPerSecond});
  panel->courseEdit()->clear();
  panel->speedEdit()->setText(QStringLiteral("5"));
  QVERIFY(panel->applyTypedOrder());
  RK_COMPARE_NEAR(v->orderedCourseSpeed().second, 5.0, 1e-9);
  RK_COMPARE_NEAR(radToDeg(v->orderedCourseSpeed().first), 45.0, 1e-3);  // the course kept
}

}  // namespace

class TestDisplayModes : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() { isolateFromTheUser("tst_display_modes"); }
  void init() { QSettings().clear(); }  // every test from the first-run settings

  void theFormattingModuleGivesEachUnit() {
    const DisplayUnits nmKn;
    const DisplayUnits kmMps{DistanceUnit::Kilometres, SpeedUnit::MetresPerSecond};
    QCOMPARE(formatDistance(nmToMetres(1.5), nmKn), QStringLiteral("1.50 NM"));
    QCOMPARE(formatDistance(nmToMetres(1.5), kmMps), QStringLiteral("2.78 km"));  // 2778 m
    QCOMPARE(formatSpeed(knotsToMps(12.0), nmKn), QStringLiteral("12.0 kn"));
    QCOMPARE(formatSpeed(knotsToMps(12.0), kmMps), QStringLiteral("6.2 m/s"));  // 6.17 m/s
    RK_COMPARE_NEAR(mpsFrom(speedIn(7.3, SpeedUnit::Knots), SpeedUnit::Knots), 7.3, 1e-12);
    RK_COMPARE_NEAR(metresFrom(distanceIn(4321.0, DistanceUnit::Kilometres), DistanceUnit::Kilometres),
                    4321.0, 1e-9);
    QCOMPARE(formatBearing(degToRad(45.0)), QStringLiteral("045.0°"));
    QCOMPARE(formatBearing(degToRad(359.97)), QStringLiteral("000.0°"));  // never "360.0"
    QCOMPARE(formatBearing(degToRad(-1.0)), QStringLiteral("359.0°"));
    QCOMPARE(formatCourseSpeed(degToRad(45.0), knotsToMps(12.0), nmKn), QStringLiteral("045.0° 12.0 kn"));
  }

  void labelsBesideSymbolsCloseTogetherNeverOverlap() {
    // GIVEN two targets 8 px apart with three-digit labels ("116" and "130") and own ship beside them
    const QSizeF text(20.0, 13.0);
    const QPointF a(300.0, 200.0), b(308.0, 201.0), own(330.0, 200.0);
    std::vector<QRectF> symbols{QRectF(a - QPointF(7, 7), QSizeF(14, 14)),
                                QRectF(b - QPointF(7, 7), QSizeF(14, 14)),
                                QRectF(own - QPointF(11, 11), QSizeF(22, 22))};
    const auto boxes = placeLabels({{a, 7.0, text}, {b, 7.0, text}}, symbols, QRectF(0, 0, 800, 600));
    // THEN their boxes are apart (by the placer's 2 px gap at least) and cover no symbol
    QCOMPARE(boxes.size(), std::size_t{2});
    QVERIFY2(!boxes[0].adjusted(-1, -1, 1, 1).intersects(boxes[1]), "the two labels touch");
    for (const QRectF& box : boxes)
      for (const QRectF& s : symbols) QVERIFY(!box.intersects(s));
    // AND a crowd around one point still gets boxes of its own, all inside the view
    std::vector<LabelRequest> crowd;
    crowd.reserve(12);
    for (int i = 0; i < 12; ++i) {
      const int row = i / 3, column = i % 3;
      crowd.push_back({QPointF(400 + column * 3, 300 + row * 3), 7.0, text});
    }
    const auto many = placeLabels(crowd, {}, QRectF(0, 0, 800, 600));
    for (std::size_t i = 0; i < many.size(); ++i) {
      QVERIFY(QRectF(0, 0, 800, 600).contains(many[i]));
      for (std::size_t j = i + 1; j < many.size(); ++j) QVERIFY(!many[i].intersects(many[j]));
    }
  }

  void northUpCourseUpAndHeadUp() {
    MainWindow w(freshOptions());
    showAndWait(w);
    EcdisView* v = w.chart();
    runUntil(w, 20.0);
    // North-up: no rotation, no north arrow
    QCOMPARE(v->viewport().rotationRad(), 0.0);
    QVERIFY(v->modeLines().front().startsWith(QStringLiteral("N UP")));
    paintNow(w);
    QVERIFY(!v->northArrowAt());
    saveWindowShot(w, QStringLiteral("orientation-north-up"));
    // WHEN course-up is chosen THEN the course over ground is up (within the 5 degree stabilisation)
    choose(combo(w, "orientation"), 1);
    QCOMPARE(v->overlay().orientation, Orientation::CourseUp);
    const auto& x = w.history().latest().frame.estimate.x;
    const double gamma = v->frame()->gridInfo(ownEstimate(w)).convergenceRad;
    const double cog = wrapTwoPi(
        bearingOf(x[est::drkf::kVelX] + x[est::drkf::kCurX], x[est::drkf::kVelY] + x[est::drkf::kCurY]) +
        gamma);
    RK_COMPARE_NEAR(radToDeg(angleDiff(v->viewport().rotationRad(), cog)), 0.0, 5.0);
    QVERIFY(v->modeLines().front().startsWith(QStringLiteral("C UP")));
    paintNow(w);
    QVERIFY(v->northArrowAt());
    saveWindowShot(w, QStringLiteral("orientation-course-up"));
    // WHEN head-up is chosen (key O from course-up) and the ship turns 60 degrees to starboard
    w.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&w));
    QTest::keyClick(v, Qt::Key_O);
    QCOMPARE(v->overlay().orientation, Orientation::HeadUp);
    QCOMPARE(combo(w, "orientation")->currentIndex(), 2);
    const double before = v->headingTrueRad();
    RK_COMPARE_NEAR(radToDeg(angleDiff(v->viewport().rotationRad(), before)), 0.0, 0.06);
    const auto [course, speed] = v->orderedCourseSpeed();
    v->requestOrder(course + degToRad(60.0), speed);
    for (const double t : {40.0, 60.0, 120.0}) {
      runUntil(w, 20.0 + t);
      // THEN at every frame the chart's up direction is the heading (the filter's), which is the
      // true heading within a few degrees
      const double heading = v->headingTrueRad();
      const double truth = wrapTwoPi(w.history().latest().frame.truth.headingRad + gamma);
      qInfo("T+%.0f: rotation %.2f deg, heading %.2f deg (truth %.2f)", 20.0 + t,
            radToDeg(v->viewport().rotationRad()), radToDeg(heading), radToDeg(truth));
      RK_COMPARE_NEAR(radToDeg(angleDiff(v->viewport().rotationRad(), heading)), 0.0, 0.06);
      RK_COMPARE_NEAR(radToDeg(angleDiff(heading, truth)), 0.0, 3.0);
    }
    RK_COMPARE_NEAR(radToDeg(angleDiff(v->viewport().rotationRad(), before)), 60.0, 5.0);
    QVERIFY(v->modeLines().front().startsWith(QStringLiteral("H UP")));
    // AND the north arrow is on a disc of the panel colour with a bold arrow in the text colour
    paintNow(w);
    QVERIFY(v->northArrowAt());
    const QImage img = v->grab().toImage();
    const int dark = pixelsNear(img, *v->northArrowAt(), 20.0, Qt::black, 60);
    const int light = pixelsNear(img, *v->northArrowAt(), 20.0, Qt::white, 40);
    qInfo("north arrow: %d dark and %d light pixels", dark, light);
    QVERIFY(dark >= 60);
    QVERIFY(light >= 300);
    saveWindowShot(w, QStringLiteral("orientation-head-up"));
    // AND it is remembered
    MainWindow again(freshOptions());
    QCOMPARE(again.chart()->overlay().orientation, Orientation::HeadUp);
  }

  void relativeMotionHoldsOwnShipAndTrueMotionResets() {
    MainWindow w(freshOptions());
    showAndWait(w);
    EcdisView* v = w.chart();
    v->setRangeNm(1.5);
    runUntil(w, 10.0);
    // True motion: own ship moves over the screen
    const QPointF tm0 = v->ccrpWidget();
    runUntil(w, 40.0);
    const double moved = QLineF(tm0, v->ccrpWidget()).length();
    qInfo("true motion: own ship moved %.1f px in 30 s", moved);
    QVERIFY(moved > 10.0);
    // AND R resets it to the centre at once
    w.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&w));
    QTest::keyClick(v, Qt::Key_R);
    RK_COMPARE_NEAR(v->ccrpWidget().x(), v->width() / 2.0, 0.5);
    RK_COMPARE_NEAR(v->ccrpWidget().y(), v->height() / 2.0, 0.5);
    // WHEN relative motion is chosen THEN own ship stays at the centre while it moves 300 m and more
    choose(combo(w, "motion"), 1);
    QVERIFY(v->modeLines().front().contains(QStringLiteral("RM")));
    const geo::GridPoint g0 = ownEstimate(w);
    for (const double t : {70.0, 100.0, 130.0}) {
      runUntil(w, t);
      RK_COMPARE_NEAR(v->ccrpWidget().x(), v->width() / 2.0, 0.5);
      RK_COMPARE_NEAR(v->ccrpWidget().y(), v->height() / 2.0, 0.5);
    }
    const geo::GridPoint g1 = ownEstimate(w);
    QVERIFY(std::hypot(g1.xM - g0.xM, g1.yM - g0.yM) > 300.0);
    // WHEN off-centred in head-up THEN own ship stays half the range below the centre, looking ahead
    action(w, "offCentred")->trigger();
    choose(combo(w, "orientation"), 2);
    const QPointF place(v->width() / 2.0, v->height() / 2.0 + 0.25 * std::min(v->width(), v->height()));
    for (const double t : {160.0, 190.0}) {
      runUntil(w, t);
      RK_COMPARE_NEAR(v->ccrpWidget().x(), place.x(), 0.5);
      RK_COMPARE_NEAR(v->ccrpWidget().y(), place.y(), 0.5);
    }
    QVERIFY(v->modeLines().front().contains(QStringLiteral("RM off-centred")));
    // AND a wheel zoom keeps it there
    QWheelEvent wheel(QPointF(40, 40), v->mapToGlobal(QPointF(40, 40)), {}, QPoint(0, 120), Qt::NoButton, {},
                      Qt::NoScrollPhase, false);
    QApplication::sendEvent(v, &wheel);
    RK_COMPARE_NEAR(v->ccrpWidget().x(), place.x(), 0.5);
    RK_COMPARE_NEAR(v->ccrpWidget().y(), place.y(), 0.5);
    v->setRangeNm(1.5);
    saveWindowShot(w, QStringLiteral("relative-motion-off-centred"));
    // AND M goes back to true motion
    QTest::keyClick(v, Qt::Key_M);
    QCOMPARE(v->overlay().motion, Motion::True);
  }

  void aPanStopsFollowingAndCBringsOwnShipBack() {
    MainWindow w(freshOptions());
    showAndWait(w);
    EcdisView* v = w.chart();
    v->setRangeNm(1.5);
    runUntil(w, 10.0);
    QAction* follow = action(w, "followOwnShip");
    QVERIFY(follow && follow->isChecked());
    // WHEN the officer drags the chart (away from the handle and own ship)
    const QPoint from(v->width() / 5, v->height() * 4 / 5);
    QVERIFY(QLineF(*v->handlePosition(), from).length() > 30.0);
    QTest::mousePress(v, Qt::LeftButton, {}, from);
    QTest::mouseMove(v, from + QPoint(40, -30));
    QTest::mouseMove(v, from + QPoint(120, -90));
    QTest::mouseRelease(v, Qt::LeftButton, {}, from + QPoint(120, -90));
    // THEN following is off, the toggle unchecked, the chart says so, and time running leaves the view
    QVERIFY(!v->overlay().followOwnShip);
    QVERIFY(!follow->isChecked());
    QVERIFY(v->modeLines().join(' ').contains(QStringLiteral("NOT FOLLOWING")));
    const charts::LatLon panned = v->viewport().centre();
    runUntil(w, 240.0);  // far enough for true motion to have reset
    QCOMPARE(v->viewport().centre().latDeg, panned.latDeg);
    QCOMPARE(v->viewport().centre().lonDeg, panned.lonDeg);
    // WHEN C is pressed THEN own ship is centred and followed again
    w.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&w));
    QTest::keyClick(v, Qt::Key_C);
    QVERIFY(v->overlay().followOwnShip);
    QVERIFY(follow->isChecked());
    RK_COMPARE_NEAR(v->ccrpWidget().x(), v->width() / 2.0, 0.5);
    RK_COMPARE_NEAR(v->ccrpWidget().y(), v->height() / 2.0, 0.5);
    // AND the toolbar toggle switches it too
    follow->trigger();
    QVERIFY(!v->overlay().followOwnShip);
    follow->trigger();
    QVERIFY(v->overlay().followOwnShip);
  }

  void theCcrpIsOwnShipsReference() {
    MainWindow w(freshOptions());
    showAndWait(w);
    EcdisView* v = w.chart();
    runUntil(w, 90.0);  // tracks confirmed
    // The default CCRP is the estimated point, the ship's centre
    const geo::GridPoint est = ownEstimate(w);
    RK_COMPARE_NEAR(v->ccrpGrid().xM, est.xM, 1e-9);
    RK_COMPARE_NEAR(v->ccrpGrid().yM, est.yM, 1e-9);
    std::vector<std::pair<int, double>> rangesBefore;
    for (const auto& t : w.history().latest().frame.tracks)
      if (t.status == track::TrackStatus::Confirmed) rangesBefore.push_back({t.trackId, t.kinematics.rangeM});
    QVERIFY(!rangesBefore.empty());
    // WHEN the CCRP is set to the bow (the conning position of some ships)
    w.setCcrp(0.0, 0.0);
    // THEN it is 60 m ahead of the estimate along the heading
    const geo::GridPoint c = v->ccrpGrid();
    const double k = v->frame()->gridInfo(est).scale;
    RK_COMPARE_NEAR(std::hypot(c.xM - est.xM, c.yM - est.yM), 60.0 * k, 1e-6);
    RK_COMPARE_NEAR(radToDeg(angleDiff(bearingOf(c.xM - est.xM, c.yM - est.yM), v->headingGridRad())), 0.0,
                    1e-6);
    // AND the cursor's range is from there
    QVERIFY2(v->cursorText(v->ccrpWidget()).endsWith(QStringLiteral(" 0.00 NM")),
             qPrintable(v->cursorText(v->ccrpWidget())));
    // AND the table's ranges are from there: shorter ahead, longer astern, by 60 m x cos(relative bearing)
    const double headingTrue = v->headingTrueRad();
    for (const auto& [id, before] : rangesBefore) {
      const int row = w.targetModel()->rowOf(id);
      QVERIFY(row >= 0);
      const double after = w.targetModel()->index(row, TargetTableModel::Range).data(Qt::UserRole).toDouble();
      const double bearing =
          w.targetModel()->index(row, TargetTableModel::Bearing).data(Qt::UserRole).toDouble();
      qInfo("track %d: %.1f m from the centre, %.1f m from the bow", id, before, after);
      RK_COMPARE_NEAR(after - before, -60.0 * std::cos(bearing - headingTrue), 2.0);
    }
    // AND it is drawn on the true-scale outline
    v->setView(v->viewport().centre(), 3000.0, v->viewport().rotationRad());
    v->centreOnOwnShip();
    saveWindowShot(w, QStringLiteral("ccrp-at-the-bow"));
    // AND a CCRP outside the hull is refused with a message; the setting is remembered
    w.setCcrp(200.0, 0.0);
    QVERIFY(w.lastError().contains(QStringLiteral("CCRP")));
    QCOMPARE(v->overlay().ccrpFromBowM, 0.0);
    MainWindow again(freshOptions());
    QCOMPARE(again.chart()->overlay().ccrpFromBowM, 0.0);
  }

  void vectorTimeTrueRelativeVectorsPastPositionsAndLabels() {
    MainWindow w(freshOptions());
    showAndWait(w);
    EcdisView* v = w.chart();
    runUntil(w, 240.0);
    // Vector time from the toolbar, shown on the chart
    QComboBox* minutes = combo(w, "vectorMinutes");
    QVERIFY(minutes);
    QCOMPARE(minutes->currentText(), QStringLiteral("6 min"));
    choose(minutes, 3);
    QCOMPARE(v->overlay().vectorMinutes, 12.0);
    QVERIFY(v->modeLines().contains(QStringLiteral("VECT T 12 min")));
    // Relative vectors from the toolbar; the View menu's radio items follow
    choose(combo(w, "vectorMode"), 1);
    QVERIFY(v->overlay().relativeVectors);
    QVERIFY(v->modeLines().contains(QStringLiteral("VECT R 12 min")));
    QVERIFY(action(w, "vectorMode_1")->isChecked());
    action(w, "vectorTime_0")->trigger();
    QCOMPARE(v->overlay().vectorMinutes, 1.0);
    QCOMPARE(minutes->currentIndex(), 0);
    // Past positions: more target-coloured pixels with the dots than without
    const auto targetPixels = [&] {
      paintNow(w);
      const QImage img = v->grab().toImage();
      int n = 0;
      for (const auto& t : w.history().latest().frame.tracks)
        n += pixelsNear(img, v->gridToWidget(t.estimate.x[est::ttkf::kTgtX], t.estimate.x[est::ttkf::kTgtY]),
                        150.0, QColor(0, 130, 0), 30);
      return n;
    };
    const int sixAt30s = targetPixels();
    action(w, "pastPositions_0")->trigger();
    QCOMPARE(v->overlay().targetPastCount, 0);
    const int none = targetPixels();
    action(w, "pastPositions_3")->trigger();
    QCOMPARE(v->overlay().targetPastIntervalS, 120.0);
    qInfo("target pixels: %d with 6 past positions at 30 s, %d with none", sixAt30s, none);
    QVERIFY(sixAt30s > none + 20);
    // Labels off and on
    paintNow(w);
    const auto firstTrack = w.history().latest().frame.tracks.front().trackId;
    QVERIFY(labelStartingWith(*v, QString::number(firstTrack)));
    action(w, "targetLabels")->trigger();
    paintNow(w);
    QVERIFY(!labelStartingWith(*v, QString::number(firstTrack)));
    // All of it remembered
    MainWindow again(freshOptions());
    const OverlaySettings& o = again.chart()->overlay();
    QCOMPARE(o.vectorMinutes, 1.0);
    QVERIFY(o.relativeVectors);
    QCOMPARE(o.targetPastIntervalS, 120.0);
    QVERIFY(!o.showTargetLabels);
    QCOMPARE(combo(again, "vectorMode")->currentIndex(), 1);
  }

  void labelsOfTwoTargetsCloseTogetherAreApart() {
    MainWindow w(freshOptions());
    showAndWait(w);
    EcdisView* v = w.chart();
    runUntil(w, 5.0);
    // GIVEN two vessels 250 m apart, still in the water, 1.5 NM from own ship
    const geo::GridPoint own = ownEstimate(w);
    const double ax = own.xM + 2000.0, ay = own.yM + 1500.0;
    w.controller()->addTarget(ax, ay, 0.0, 0.0);
    w.controller()->addTarget(ax + 250.0, ay + 30.0, 0.0, 0.0);
    std::vector<int> ids;
    const auto near = [&] {
      ids.clear();
      for (const auto& t : w.history().latest().frame.tracks)
        if (t.status == track::TrackStatus::Confirmed &&
            std::hypot(t.estimate.x[est::ttkf::kTgtX] - ax - 125.0, t.estimate.x[est::ttkf::kTgtY] - ay) <
                400.0)
          ids.push_back(t.trackId);
      return ids.size() == 2;
    };
    double t = 5.0;
    while (!near() && t < 300.0) runUntil(w, t += 10.0);
    QVERIFY2(ids.size() == 2, qPrintable(QString("%1 confirmed tracks there").arg(ids.size())));
    // WHEN the scale puts them 9 px apart
    {
      OverlaySettings s = v->overlay();
      s.followOwnShip = false;
      v->setOverlay(s);
    }
    const QPointF mid = v->gridToWidget(ax + 125.0, ay);
    v->setView(v->viewport().toLatLon({mid.x(), mid.y()}), 250.0 / (9.0 * 0.28e-3), 0.0);
    paintNow(w);
    // THEN each number is drawn on its own, their boxes apart and clear of the symbols
    const auto boxA = labelBox(*v, QString::number(ids[0])), boxB = labelBox(*v, QString::number(ids[1]));
    QVERIFY(boxA && boxB);
    qInfo("labels %d at (%.0f,%.0f %.0fx%.0f), %d at (%.0f,%.0f)", ids[0], boxA->x(), boxA->y(),
          boxA->width(), boxA->height(), ids[1], boxB->x(), boxB->y());
    QVERIFY(!boxA->adjusted(-1, -1, 1, 1).intersects(*boxB));
    for (const auto& l : v->placedLabels()) QVERIFY(!l.box.intersects(v->ownSymbolBox()));
    for (const auto& tr : w.history().latest().frame.tracks) {
      const QPointF p = v->gridToWidget(tr.estimate.x[est::ttkf::kTgtX], tr.estimate.x[est::ttkf::kTgtY]);
      QVERIFY(!boxA->contains(p) && !boxB->contains(p));
    }
    saveWindowShot(w, QStringLiteral("labels-two-close-targets"));
  }

  void unitsSwitchEverywhereAndAreRemembered() {
    MainWindow w(freshOptions());
    showAndWait(w);
    EcdisView* v = w.chart();
    runUntil(w, 120.0);
    const sim::TrackSnapshot* tr = nullptr;
    for (const auto& t : w.history().latest().frame.tracks)
      if (t.status == track::TrackStatus::Confirmed && t.kinematics.cpa.defined) tr = &t;
    QVERIFY(tr);
    const int id = tr->trackId;
    const double rangeM = tr->kinematics.rangeM, speedMps = tr->kinematics.speedMps,
                 cpaM = tr->kinematics.cpa.cpaM;
    // In NM and kn first
    RK_COMPARE_NEAR(cellText(w, id, TargetTableModel::Range).toDouble(), metresToNm(rangeM), 0.006);
    RK_COMPARE_NEAR(cellText(w, id, TargetTableModel::Speed).toDouble(), mpsToKnots(speedMps), 0.06);
    // WHEN km and m/s are chosen in View > Units
    action(w, "units_km")->trigger();
    action(w, "units_mps")->trigger();
    // THEN the table, its headers, the cursor, the VRM, the helm order, the own-ship panel, the pick
    // report and the scale say so
    const auto* model = w.targetModel();
    QCOMPARE(model->headerData(TargetTableModel::Range, Qt::Horizontal, Qt::DisplayRole).toString(),
             QStringLiteral("Range km"));
    QCOMPARE(model->headerData(TargetTableModel::Speed, Qt::Horizontal, Qt::DisplayRole).toString(),
             QStringLiteral("Speed m/s"));
    RK_COMPARE_NEAR(cellText(w, id, TargetTableModel::Range).toDouble(), rangeM / 1000.0, 0.006);
    RK_COMPARE_NEAR(cellText(w, id, TargetTableModel::Cpa).toDouble(), cpaM / 1000.0, 0.006);
    RK_COMPARE_NEAR(cellText(w, id, TargetTableModel::Speed).toDouble(), speedMps, 0.06);
    const QPointF somewhere(v->width() / 3.0, v->height() / 3.0);
    QTest::mouseMove(v, somewhere.toPoint());
    auto* readout = w.statusBar()->findChild<QLabel*>(QStringLiteral("cursorReadout"));
    QVERIFY(readout);
    QVERIFY2(readout->text().endsWith(QStringLiteral(" km")), qPrintable(readout->text()));
    QVERIFY(v->buildContextMenu(somewhere)->findChild<QAction*>(QStringLiteral("eblVrm")));
    v->buildContextMenu(somewhere)->findChild<QAction*>(QStringLiteral("eblVrm"))->trigger();
    QVERIFY(v->overlay().vrmRangeM.has_value());
    QVERIFY(w.ownShipPanel()->orderText().endsWith(QStringLiteral(" m/s")));
    paintNow(w);
    const auto order = labelStartingWith(*v, QStringLiteral("Order "));
    QVERIFY(order && order->contains(QStringLiteral(" m/s")));
    v->buildContextMenu(somewhere)->findChild<QAction*>(QStringLiteral("pick"))->trigger();
    const QString pick = w.findChild<QTextBrowser*>(QStringLiteral("pickReport"))->toPlainText();
    QVERIFY2(pick.contains(QStringLiteral(" km from own ship")), qPrintable(pick));
    QVERIFY2(!pick.contains(QStringLiteral(" NM")), qPrintable(pick));
    // (the pick report's position stays in degrees and minutes)
    QVERIFY2(pick.contains(QStringLiteral("°")) && pick.contains(QStringLiteral("'")), qPrintable(pick));
    saveWindowShot(w, QStringLiteral("units-km-mps"));
    // AND a new window keeps them
    MainWindow again(freshOptions());
    QCOMPARE(again.chart()->units().distance, DistanceUnit::Kilometres);
    QCOMPARE(again.chart()->units().speed, SpeedUnit::MetresPerSecond);
    QCOMPARE(
        again.targetModel()->headerData(TargetTableModel::Cpa, Qt::Horizontal, Qt::DisplayRole).toString(),
        QStringLiteral("CPA km"));
    QVERIFY(action(again, "units_km")->isChecked());
  }

  void theHelmOrderIsAlwaysShownOnScreenAndCanBeTyped() {
    MainWindow w(freshOptions());
    showAndWait(w);
    EcdisView* v = w.chart();
    // At the first view the handle is on screen, and its readout with it
    QVERIFY(v->rect().contains(v->handlePosition()->toPoint()));
    paintNow(w);
    auto order = labelStartingWith(*v, QStringLiteral("Order "));
    QVERIFY(order);
    QVERIFY(v->rect().contains(labelBox(*v, *order)->toRect()));
    QVERIFY2(order->startsWith(w.ownShipPanel()->orderText()), qPrintable(*order));
    // WHEN the range is so short that the vector's tip is off the screen THEN the handle is shortened
    // to a time that fits, and says so
    v->setRangeNm(0.25);
    QVERIFY(v->handleMinutes() < v->overlay().vectorMinutes);
    QVERIFY(QRectF(v->rect()).contains(*v->handlePosition()));
    paintNow(w);
    order = labelStartingWith(*v, QStringLiteral("Order "));
    QVERIFY2(order && order->endsWith(QStringLiteral(")")), qPrintable(order.value_or(QString())));
    // AND a drag of the shortened handle orders the speed for its own time base
    const auto [course0, speed0] = v->orderedCourseSpeed();
    const QPointF h = *v->handlePosition(), c = v->ccrpWidget();
    const QPointF half = c + (h - c) * 0.5;
    QTest::mousePress(v, Qt::LeftButton, {}, h.toPoint());
    QTest::mouseMove(v, half.toPoint());
    QTest::mouseRelease(v, Qt::LeftButton, {}, half.toPoint());
    RK_COMPARE_NEAR(v->orderedCourseSpeed().second, 0.5 * speed0, 0.03 * speed0);
    RK_COMPARE_NEAR(radToDeg(angleDiff(v->orderedCourseSpeed().first, course0)), 0.0, 1.0);
    v->setRangeNm(1.5);
    // WHEN the right arrow is pressed (the simulation paused) THEN the order shown turns 5 degrees at once
    const double before = v->orderedCourseSpeed().first;
    v->setFocus();
    QTest::keyClick(v, Qt::Key_Right);
    RK_COMPARE_NEAR(radToDeg(angleDiff(v->orderedCourseSpeed().first, before)), 5.0, 1e-9);
    const QString shown = QStringLiteral("Order ") + formatCourseSpeed(v->orderedCourseSpeed().first,
                                                                       v->orderedCourseSpeed().second, {});
    QCOMPARE(w.ownShipPanel()->orderText(), shown);
    paintNow(w);
    QVERIFY(labelStartingWith(*v, shown));
    // AND the ordered vector shows above the COG vector: order-coloured pixels along it
    runUntil(w, 90.0);
    paintNow(w);
    const QImage img = v->grab().toImage();
    int orange = 0;
    const QPointF from = v->ccrpWidget(), to = *v->handlePosition();
    for (int i = 2; i < 20; ++i)
      orange += pixelsNear(img, from + (to - from) * (i / 20.0), 3.0, QColor(200, 60, 0), 40);
    qInfo("%d order-coloured pixels along the ordered vector", orange);
    QVERIFY(orange >= 30);
    // WHEN an order is typed in the own-ship panel THEN it is shown and given
    OwnShipPanel* panel = w.ownShipPanel();
    panel->courseEdit()->setText(QStringLiteral("45"));
    panel->speedEdit()->setText(QStringLiteral("12,5"));
    QTest::keyClick(panel->speedEdit(), Qt::Key_Return);
    QVERIFY(panel->orderError().isEmpty());
    RK_COMPARE_NEAR(radToDeg(v->orderedCourseSpeed().first), 45.0, 1e-9);
    RK_COMPARE_NEAR(mpsToKnots(v->orderedCourseSpeed().second), 12.5, 1e-9);
    QCOMPARE(panel->orderText(), QStringLiteral("Order 045.0° 12.5 kn"));
    w.controller()->stepOnce();
    const double gamma = v->frame()->gridInfo(ownEstimate(w)).convergenceRad;
    const auto ordered = [&] {
      const auto& o = w.history().latest().frame.order;
      return o && std::abs(angleDiff(o->headingRad + gamma, degToRad(45.0))) < 1e-6 &&
             std::abs(o->speedMps - knotsToMps(12.5)) < 1e-9;
    };
    QTRY_VERIFY_WITH_TIMEOUT(ordered(), kTimeoutMs);
    saveWindowShot(w, QStringLiteral("helm-order-readout"));
    // AND out-of-range values are refused with a message, the order unchanged; in m/s the speed is m/s
    typedOrdersAreCheckedAndInDisplayUnits(w);
  }

  void aStatusMessageStaysVisibleWhileTheMouseMoves() {
    MainWindow w(freshOptions());
    showAndWait(w);
    EcdisView* v = w.chart();
    const QString message = QStringLiteral("Saved /tmp/a-scenario-with-a-long-name.json");
    w.statusBar()->showMessage(message);
    auto* readout = w.statusBar()->findChild<QLabel*>(QStringLiteral("cursorReadout"));
    QVERIFY(readout);
    QString last;
    for (int i = 0; i < 5; ++i) {
      QTest::mouseMove(v, QPoint(100 + 60 * i, 120 + 40 * i));
      // THEN the message stays, the readout follows the mouse, and they do not share any pixels
      QCOMPARE(w.statusBar()->currentMessage(), message);
      QVERIFY(readout->isVisible());
      QVERIFY(readout->text() != last);
      last = readout->text();
    }
    const int messageEnd = 6 + w.statusBar()->fontMetrics().horizontalAdvance(message);
    qInfo("message ends at %d px, the cursor readout starts at %d px", messageEnd,
          readout->geometry().left());
    QVERIFY(readout->geometry().left() >= messageEnd);
    saveShot(*w.statusBar(), QStringLiteral("status-bar-message-and-cursor"));
  }
};

QTEST_MAIN(TestDisplayModes)
#include "tst_display_modes.moc"
