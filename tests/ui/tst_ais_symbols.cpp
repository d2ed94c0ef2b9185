// AIS target symbols (ui/map/ecdis_ais.h), the AIS table model and the pick report, offscreen: targets
// of every state painted into a QImage (saved as a PNG for a look when RECKONER_AIS_PNG names a file),
// with painted pixels asserted: red only where a target is dangerous, the vector only on activated
// targets, the scaled hull only when the ship is large on screen, nothing of a dangerous target in the
// flash's off phase.
#include <QBrush>
#include <QImage>
#include <QPainter>
#include <QTest>

#include <cmath>

#include "common/angles.h"
#include "common/units.h"
#include "support/compare_near.h"
#include "ui/map/ecdis_ais.h"
#include "ui/panels/ais_table_model.h"

using namespace reckoner;
using namespace reckoner::ui;

namespace {

constexpr int kSize = 400;

/// 1 pixel per metre, grid origin at the image centre, north up.
AisPaintGeometry geometry(double ppm = 1.0) {
  AisPaintGeometry g;
  g.toWidget = [ppm](double x, double y) { return QPointF(kSize / 2.0 + x * ppm, kSize / 2.0 - y * ppm); };
  g.pixelsPerMetre = ppm;
  return g;
}

AisSymbol symbol(double x, double y, double headingDeg, double sogKn) {
  AisSymbol s;
  s.mmsi = 1;
  s.xM = x;
  s.yM = y;
  s.headingGridRad = degToRad(headingDeg);
  s.cogGridRad = degToRad(headingDeg);
  s.sogMps = knotsToMps(sogKn);
  return s;
}

QImage render(const std::vector<AisSymbol>& symbols, const AisPaintGeometry& g,
              const AisPaintStyle& st = {}) {
  QImage img(kSize, kSize, QImage::Format_ARGB32);
  img.fill(Qt::white);
  QPainter p(&img);
  paintAisTargets(p, symbols, g, st);
  p.end();
  return img;
}

/// Pixels in the box that are not white; red ones.
struct Ink {
  int dark = 0, red = 0;
};
Ink inkIn(const QImage& img, QRect box) {
  Ink ink;
  box = box.intersected(img.rect());
  for (int y = box.top(); y <= box.bottom(); ++y)
    for (int x = box.left(); x <= box.right(); ++x) {
      const QColor c = img.pixelColor(x, y);
      if (c.red() > 180 && c.green() < 90 && c.blue() < 90)
        ++ink.red;
      else if (c.lightness() < 160)
        ++ink.dark;
    }
  return ink;
}

}  // namespace

class TestAisSymbols : public QObject {
  Q_OBJECT
 private slots:
  void everyStateIsDrawnAsItShould() {
    // GIVEN one target of each state, 100 m apart, all steering 045 at 10 kn, a 1-minute vector (308 m)
    AisSymbol sleeping = symbol(-150, 150, 45, 10);
    AisSymbol activated = symbol(-150, -50, 45, 10);
    activated.activated = true;
    activated.turn = 1;
    AisSymbol selected = symbol(50, 150, 45, 10);
    selected.activated = selected.selected = true;
    AisSymbol dangerous = symbol(50, -50, 45, 10);
    dangerous.activated = dangerous.dangerous = true;
    AisSymbol lost = symbol(150, -150, 45, 10);
    lost.activated = lost.lost = true;
    AisPaintStyle st;
    st.vectorMinutes = 1.0;
    // WHEN they are painted
    const QImage img = render({sleeping, activated, selected, dangerous, lost}, geometry(), st);
    if (qEnvironmentVariableIsSet("RECKONER_AIS_PNG")) {  // and the same 4 times larger, to look at
      const QString path = qEnvironmentVariable("RECKONER_AIS_PNG");
      img.save(path);
      img.scaled(4 * kSize, 4 * kSize, Qt::IgnoreAspectRatio, Qt::FastTransformation)
          .save(QString(path).replace(QStringLiteral(".png"), QStringLiteral("_x4.png")));
    }
    auto at = [](const AisSymbol& s, int r) {
      const QPointF c = geometry().toWidget(s.xM, s.yM);
      return QRect(static_cast<int>(c.x()) - r, static_cast<int>(c.y()) - r, 2 * r, 2 * r);
    };
    // THEN the dangerous one alone is red, and bold
    QVERIFY(inkIn(img, at(dangerous, 12)).red > 40);
    for (const AisSymbol* s : {&sleeping, &activated, &selected, &lost}) {
      QCOMPARE(inkIn(img, at(*s, 12)).red, 0);
      QVERIFY(inkIn(img, at(*s, 10)).dark > 10);  // every state draws its symbol
    }
    // AND activated targets have a vector along 045 (60 m out), the sleeping and the lost one none
    auto vectorInk = [&](const AisSymbol& s) {
      const QPointF c = geometry().toWidget(s.xM, s.yM) + QPointF(42.0, -42.0);
      return inkIn(img, QRect(static_cast<int>(c.x()) - 4, static_cast<int>(c.y()) - 4, 8, 8));
    };
    QVERIFY(vectorInk(activated).dark > 0);
    QVERIFY(vectorInk(dangerous).red > 0);
    QCOMPARE(vectorInk(sleeping).dark, 0);
    QCOMPARE(vectorInk(lost).dark, 0);
    // AND the selected one has its corner brackets (the top-left one at 1.2 x 14 px out), no other
    const QPointF sc = geometry().toWidget(selected.xM, selected.yM);
    QVERIFY(inkIn(img, QRect(static_cast<int>(sc.x()) - 18, static_cast<int>(sc.y()) - 18, 4, 4)).dark > 0);
    const QPointF ac = geometry().toWidget(activated.xM, activated.yM);
    QCOMPARE(inkIn(img, QRect(static_cast<int>(ac.x()) - 18, static_cast<int>(ac.y()) - 18, 4, 4)).dark, 0);
    // AND the lost one is crossed out: ink at the ends of the cross, beyond the triangle
    const QPointF lc = geometry().toWidget(lost.xM, lost.yM);
    QVERIFY(inkIn(img, QRect(static_cast<int>(lc.x()) - 12, static_cast<int>(lc.y()) + 8, 4, 4)).dark > 0);
    // AND in the flash's off phase the dangerous one is not drawn
    st.flashOn = false;
    const QImage off = render({dangerous}, geometry(), st);
    QCOMPARE(inkIn(off, off.rect()).red, 0);
  }

  /// GIVEN an AIS-SART in distress (its alarm unacknowledged), the same acknowledged, and a MOB in test
  /// WHEN painted THEN each is a circle with a cross, not a triangle: the distresses bold red, the test
  /// one thin in the AIS colour; in the flash's off phase only the acknowledged distress and the test
  /// one are drawn. Saved as a PNG for a look when RECKONER_SART_PNG names a file.
  void searchAndRescueDevicesAreACircleWithACross() {
    AisSymbol active = symbol(-100, 0, 0, 0);
    active.headingGridRad.reset();
    active.cogGridRad.reset();
    active.activated = active.device = active.distress = active.unacknowledged = true;
    AisSymbol acknowledged = active;
    acknowledged.xM = 0;
    acknowledged.unacknowledged = false;
    AisSymbol test = active;
    test.xM = 100;
    test.distress = test.unacknowledged = false;
    const QImage on = render({active, acknowledged, test}, geometry());
    if (qEnvironmentVariableIsSet("RECKONER_SART_PNG")) {
      const QString path = qEnvironmentVariable("RECKONER_SART_PNG");
      on.scaled(4 * kSize, 4 * kSize, Qt::IgnoreAspectRatio, Qt::FastTransformation).save(path);
    }
    // The ring 0.7 x 14 = 9.8 px out: ink to the right of the centre, where a triangle (4.2 px) has none;
    // the cross: ink at the centre and on the diagonal at 5 px.
    auto ring = [](const QImage& img, const AisSymbol& s) {
      const QPointF c = geometry().toWidget(s.xM, s.yM);
      return inkIn(img, QRect(static_cast<int>(c.x()) + 8, static_cast<int>(c.y()) - 3, 4, 6));
    };
    auto cross = [](const QImage& img, const AisSymbol& s) {
      const QPointF c = geometry().toWidget(s.xM, s.yM);
      const Ink centre = inkIn(img, QRect(static_cast<int>(c.x()) - 1, static_cast<int>(c.y()) - 1, 3, 3));
      const Ink diagonal = inkIn(img, QRect(static_cast<int>(c.x()) + 4, static_cast<int>(c.y()) + 4, 3, 3));
      return Ink{centre.dark + diagonal.dark, centre.red + diagonal.red};
    };
    for (const AisSymbol* s : {&active, &acknowledged}) {
      QVERIFY(ring(on, *s).red > 0);
      QVERIFY(cross(on, *s).red > 0);
      QCOMPARE(ring(on, *s).dark + cross(on, *s).dark, 0);
    }
    QVERIFY(ring(on, test).dark > 0 && cross(on, test).dark > 0);
    QCOMPARE(ring(on, test).red + cross(on, test).red, 0);
    // The ring is dashed: along the circle, some of its points are not inked
    const QPointF c = geometry().toWidget(active.xM, active.yM);
    int inked = 0;
    for (int i = 0; i < 72; ++i) {
      const double a = i * 5.0 * kPi / 180.0;
      const QColor px = on.pixelColor(static_cast<int>(std::lround(c.x() + 9.8 * std::cos(a))),
                                      static_cast<int>(std::lround(c.y() + 9.8 * std::sin(a))));
      if (px.red() > 180 && px.green() < 90) ++inked;
    }
    QVERIFY2(inked > 20 && inked < 68, qPrintable(QString::number(inked)));
    AisPaintStyle st;
    st.flashOn = false;
    const QImage off = render({active, acknowledged, test}, geometry(), st);
    QCOMPARE(ring(off, active).red + cross(off, active).red, 0);
    QVERIFY(ring(off, acknowledged).red > 0);
    QVERIFY(ring(off, test).dark > 0);
  }

  void largeShipsAreDrawnToScale() {
    // GIVEN a 200 m ship heading north, antenna 150 m from the bow
    AisSymbol s = symbol(0, 0, 0, 0);
    s.toBowM = 150;
    s.toSternM = 50;
    s.toPortM = 15;
    s.toStarboardM = 15;
    // WHEN drawn at 1 px/m THEN its hull reaches 150 px ahead of the position and 50 px astern
    QImage img = render({s}, geometry(1.0));
    QVERIFY(inkIn(img, QRect(kSize / 2 - 3, kSize / 2 - 152, 6, 6)).dark > 0);
    QVERIFY(inkIn(img, QRect(kSize / 2 - 16, kSize / 2 + 47, 4, 6)).dark > 0);
    // WHEN drawn at 0.02 px/m (4 px long) THEN the minimal triangle is drawn instead, nothing far out
    img = render({s}, geometry(0.02));
    QCOMPARE(inkIn(img, QRect(0, 0, kSize, kSize / 2 - 12)).dark, 0);
    QVERIFY(inkIn(img, QRect(kSize / 2 - 8, kSize / 2 - 8, 16, 16)).dark > 5);
  }

  void tableRowsAndPickReport() {
    const geo::LocalFrame f(50.0, -3.0);
    track::AisTargetTable table;
    io::AisMessage m;
    m.type = 1;
    m.mmsi = 244000001;
    m.latDeg = 50.01;
    m.lonDeg = -3.0;
    m.sogKn = 10.0;
    m.cogDeg = 180.0;
    m.headingDeg = 181;
    m.navStatus = 0;
    table.feed(m, 0);
    io::AisMessage s;
    s.type = 5;
    s.mmsi = 244000001;
    s.name = "ZEEHOND";
    s.toBowM = 80;
    s.toSternM = 20;
    s.toPortM = 6;
    s.toStarboardM = 6;
    table.feed(s, 1);
    table.update(1, f, {f.origin(), 0.0, 0.0});
    AisTableModel model;
    model.setTargets(table.targets());
    QCOMPARE(model.rowCount(), 1);
    QCOMPARE(model.columnCount(), int{AisTableModel::ColumnCount});
    QCOMPARE(model.data(model.index(0, AisTableModel::Mmsi), Qt::DisplayRole).toString(),
             QString("244000001"));
    QCOMPARE(model.data(model.index(0, AisTableModel::Name), Qt::DisplayRole).toString(), QString("ZEEHOND"));
    QVERIFY(
        model.data(model.index(0, AisTableModel::Status), Qt::DisplayRole).toString().contains("dangerous"));
    QCOMPARE(model.data(model.index(0, AisTableModel::Cpa), Qt::UserRole).toDouble() < 1.0, true);
    const QString report = aisPickReport(*table.find(244000001));
    QVERIFY2(report.contains("ZEEHOND") && report.contains("Length 100 m, beam 12 m") &&
                 report.contains("HDG 181") && !report.contains("NOT A FIX"),
             qPrintable(report));
    // A position the transponder dead reckons (time stamp 62) says so in the pick report
    track::AisTarget dr = *table.find(244000001);
    dr.positionNotFix = 62;
    QVERIFY2(aisPickReport(dr).contains("Position NOT A FIX: dead reckoning (time stamp 62)"),
             qPrintable(aisPickReport(dr)));
    // AND its symbol sits 0.01 deg (about 1112 m) north of own ship, heading 181 true
    const auto sym = aisSymbolOf(*table.find(244000001), f, 1);
    QVERIFY(sym);
    RK_COMPARE_NEAR(sym->yM, 1112.0, 5.0);
    RK_COMPARE_NEAR(radToDeg(*sym->headingGridRad), 181.0, 0.01);
    QVERIFY(sym->dangerous && sym->activated);
  }

  void searchAndRescueDeviceRowsAndPickReport() {
    const geo::LocalFrame f(50.0, -3.0);
    track::AisTargetTable table;
    io::AisMessage m;
    m.type = 1;
    m.mmsi = 970012345;
    m.latDeg = 50.005;
    m.lonDeg = -3.0;
    m.sogKn = 0.4;
    m.cogDeg = 90.0;
    m.navStatus = 14;
    m.positionNotFix = 61;
    table.feed(m, 0);
    io::AisMessage t;
    t.type = 14;
    t.mmsi = 970012345;
    t.text = "SART ACTIVE";
    table.feed(t, 1);
    table.update(1, f, {f.origin(), 0.0, 0.0});
    AisTableModel model;
    model.setTargets(table.targets());
    QCOMPARE(model.data(model.index(0, AisTableModel::Class), Qt::DisplayRole).toString(),
             QString("AIS-SART"));
    QVERIFY(model.data(model.index(0, AisTableModel::Status), Qt::DisplayRole)
                .toString()
                .startsWith("AIS-SART ACTIVE"));
    QCOMPARE(model.data(model.index(0, AisTableModel::Mmsi), Qt::ForegroundRole).value<QBrush>().color(),
             QColor(200, 0, 0));
    const QString report = aisPickReport(*table.find(970012345));
    QVERIFY2(report.startsWith("AIS-SART 970012345  ACTIVE: DISTRESS") &&
                 report.contains("Safety message: SART ACTIVE") &&
                 report.contains("Position NOT A FIX: manual input (time stamp 61)"),
             qPrintable(report));
    const auto sym = aisSymbolOf(*table.find(970012345), f, 1);
    QVERIFY(sym && sym->device && sym->distress && sym->activated && !sym->dangerous);
  }
};

QTEST_MAIN(TestAisSymbols)
#include "tst_ais_symbols.moc"
