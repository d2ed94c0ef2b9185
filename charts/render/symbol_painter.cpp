// Point symbols: buoys, beacons, topmarks, lights, dangers, centre and point symbols (painting.h).
// Our own vector shapes, sized in millimetres at S-52's 0.28 mm pixel.
#include <QPainterPath>
#include <QPolygonF>
#include <QRectF>
#include <algorithm>
#include <cmath>

#include "charts/render/painting.h"
#include "common/angles.h"

namespace reckoner::charts::paint {
namespace {

QColor s57Colour(const Ctx& c, std::int64_t code) {
  switch (code) {
    case 1:
      return c.colour("CHWHT");
    case 2:
      return c.colour("CHBLK");
    case 3:
      return c.colour("CHRED");
    case 4:
      return c.colour("CHGRN");
    case 6:
      return c.colour("CHYLW");
    default:
      return c.colour("CHGRD");
  }
}

}  // namespace

/// Buoys by shape (BOYSHP) and beacons by shape (BCNSHP), filled with their colours in horizontal
/// bands (several colours: COLPAT horizontal, the usual case for cardinal, isolated-danger and
/// bifurcation marks) or vertical stripes (COLPAT 2, safe-water marks). Our own vector shapes.
void drawBuoy(const Ctx& c, const ChartFeature& f, QPointF at, bool beacon) {
  const auto cols = f.list("COLOUR");
  const auto colpat = f.list("COLPAT");
  const bool vertical = !colpat.empty() && colpat.front() == 2;
  const double h = Ctx::mm(beacon ? 4.0 : 3.5), w = Ctx::mm(2.4);
  QPainterPath shape;
  if (beacon) {
    const int bcnshp = static_cast<int>(f.number("BCNSHP").value_or(1));
    if (bcnshp == 3 || bcnshp == 4 || bcnshp == 5) {  // tower, lattice, pile: a broad tapering tower
      shape.moveTo(at.x() - w * 0.45, at.y());
      shape.lineTo(at.x() - w * 0.2, at.y() - h);
      shape.lineTo(at.x() + w * 0.2, at.y() - h);
      shape.lineTo(at.x() + w * 0.45, at.y());
      shape.closeSubpath();
    } else {  // stake, withy, cairn and others: a stake
      shape.addRect(QRectF(at.x() - w * 0.15, at.y() - h, w * 0.3, h));
    }
  } else {
    const int boyshp = static_cast<int>(f.number("BOYSHP").value_or(4));
    if (boyshp == 1) {  // conical
      shape.moveTo(at.x() - w / 2, at.y());
      shape.lineTo(at.x(), at.y() - h);
      shape.lineTo(at.x() + w / 2, at.y());
      shape.closeSubpath();
    } else if (boyshp == 2) {  // can
      shape.addRect(QRectF(at.x() - w / 2, at.y() - h * 0.8, w, h * 0.8));
    } else if (boyshp == 3) {  // spherical
      shape.addEllipse(QPointF(at.x(), at.y() - w / 2), w / 2, w / 2);
    } else if (boyshp == 5) {  // spar
      shape.addRect(QRectF(at.x() - w / 8, at.y() - h, w / 4, h));
    } else if (boyshp == 6 || boyshp == 7) {  // barrel, super-buoy: a low wide body
      shape.addRoundedRect(QRectF(at.x() - w * 0.6, at.y() - h * 0.5, w * 1.2, h * 0.5), 3, 3);
    } else {  // pillar and others: a tall narrow shape
      shape.moveTo(at.x() - w / 2, at.y());
      shape.lineTo(at.x() - w / 6, at.y() - h);
      shape.lineTo(at.x() + w / 6, at.y() - h);
      shape.lineTo(at.x() + w / 2, at.y());
      shape.closeSubpath();
    }
  }
  const QRectF box = shape.boundingRect();
  c.p.save();
  c.p.setClipPath(shape);
  const std::size_t n = std::max<std::size_t>(cols.size(), 1);
  for (std::size_t i = 0; i < n; ++i) {
    const QColor fill = cols.empty() ? c.colour("CHGRD") : s57Colour(c, cols[i]);
    const double k = static_cast<double>(i) / static_cast<double>(n), dk = 1.0 / static_cast<double>(n);
    const QRectF band =
        vertical ? QRectF(box.left() + box.width() * k, box.top(), box.width() * dk + 0.5, box.height())
                 : QRectF(box.left(), box.top() + box.height() * k, box.width(), box.height() * dk + 0.5);
    c.p.fillRect(band, fill);
  }
  c.p.restore();
  c.p.setPen(QPen(c.colour("OUTLW"), 1.0));
  c.p.setBrush(Qt::NoBrush);
  c.p.drawPath(shape);
  c.p.drawEllipse(at, 1.5, 1.5);  // position circle
}

/// Topmarks (TOPMAR, at the position of the buoy or beacon they top) by TOPSHP, drawn above the mark.
void drawTopmark(const Ctx& c, const ChartFeature& f, QPointF at) {
  const int shp = static_cast<int>(f.number("TOPSHP").value_or(0));
  const auto cols = f.list("COLOUR");
  const QColor fill = cols.empty() ? c.colour("CHBLK") : s57Colour(c, cols.front());
  const double s = Ctx::mm(1.1);                      // half size of one element
  const QPointF base(at.x(), at.y() - Ctx::mm(4.2));  // just above a buoy or beacon body
  auto cone = [&](double cy, bool up) {
    QPolygonF t;
    t << QPointF(base.x() - s, cy + (up ? s : -s)) << QPointF(base.x() + s, cy + (up ? s : -s))
      << QPointF(base.x(), cy + (up ? -s : s));
    c.p.drawPolygon(t);
  };
  c.p.setPen(QPen(c.colour("OUTLW"), 0.8));
  c.p.setBrush(fill);
  c.p.drawLine(base, QPointF(base.x(), base.y() - s * 0.6));  // the staff
  const double y1 = base.y() - s * 1.6, y2 = base.y() - s * 3.8;
  switch (shp) {
    case 1:  // cone, point up
      cone(y1, true);
      break;
    case 2:  // cone, point down
      cone(y1, false);
      break;
    case 3:  // sphere
      c.p.drawEllipse(QPointF(base.x(), y1), s * 0.9, s * 0.9);
      break;
    case 4:  // two spheres (isolated danger)
      c.p.drawEllipse(QPointF(base.x(), y1), s * 0.8, s * 0.8);
      c.p.drawEllipse(QPointF(base.x(), y2 + s * 0.6), s * 0.8, s * 0.8);
      break;
    case 5:  // cylinder (can)
      c.p.drawRect(QRectF(base.x() - s * 0.8, y1 - s, s * 1.6, s * 2));
      break;
    case 7:  // x-shape (special mark)
    case 8:  // upright cross
    {
      QPen pen(fill, 2.0);
      c.p.setPen(pen);
      if (shp == 7) {
        c.p.drawLine(QPointF(base.x() - s, y1 - s), QPointF(base.x() + s, y1 + s));
        c.p.drawLine(QPointF(base.x() - s, y1 + s), QPointF(base.x() + s, y1 - s));
      } else {
        c.p.drawLine(QPointF(base.x(), y1 - s), QPointF(base.x(), y1 + s));
        c.p.drawLine(QPointF(base.x() - s, y1), QPointF(base.x() + s, y1));
      }
      break;
    }
    case 10:  // two cones point to point (west cardinal)
      cone(y1, true);
      cone(y2, false);
      break;
    case 11:  // two cones base to base (east cardinal)
      cone(y1, false);
      cone(y2, true);
      break;
    case 12: {  // rhombus
      QPolygonF r;
      r << QPointF(base.x(), y1 - s) << QPointF(base.x() + s, y1) << QPointF(base.x(), y1 + s)
        << QPointF(base.x() - s, y1);
      c.p.drawPolygon(r);
      break;
    }
    case 13:  // two cones, points upward (north cardinal)
      cone(y1, true);
      cone(y2, true);
      break;
    case 14:  // two cones, points downward (south cardinal)
      cone(y1, false);
      cone(y2, false);
      break;
    default:  // board, cube, flag and the rest: a small square
      c.p.drawRect(QRectF(base.x() - s * 0.8, y1 - s * 0.8, s * 1.6, s * 1.6));
      break;
  }
}

void drawLight(const Ctx& c, const ChartFeature& f, QPointF at) {
  const auto cols = f.list("COLOUR");
  QColor lc = c.colour("LITYW");
  for (auto code : cols) {
    if (code == 3) lc = c.colour("LITRD");
    if (code == 4) lc = c.colour("LITGN");
  }
  const auto s1 = f.number("SECTR1"), s2 = f.number("SECTR2");
  if (s1 && s2) {
    // Sector arcs at 20 mm, legs dashed: bearings are from seaward towards the light.
    const double r = Ctx::mm(20.0);
    const double a1 = std::fmod(*s1 + 180.0, 360.0), a2 = std::fmod(*s2 + 180.0, 360.0);
    double span = a2 - a1;
    if (span <= 0) span += 360.0;
    const QRectF box(at.x() - r, at.y() - r, 2 * r, 2 * r);
    c.p.setPen(QPen(c.colour("OUTLW"), 5.0, Qt::SolidLine, Qt::FlatCap));
    c.p.setBrush(Qt::NoBrush);
    // Qt: 0 deg at 3 o'clock, counter-clockwise positive, 1/16 deg units.
    c.p.drawArc(box, static_cast<int>((90.0 - a1) * 16.0), static_cast<int>(-span * 16.0));
    c.p.setPen(QPen(lc, 3.0, Qt::SolidLine, Qt::FlatCap));
    c.p.drawArc(box, static_cast<int>((90.0 - a1) * 16.0), static_cast<int>(-span * 16.0));
    QPen leg(c.colour("CHBLK"), 1.0);
    leg.setDashPattern({4, 4});
    c.p.setPen(leg);
    for (double a : {a1, a2}) {
      const double rad = a * kPi / 180.0;
      c.p.drawLine(at, QPointF(at.x() + r * 1.2 * std::sin(rad), at.y() - r * 1.2 * std::cos(rad)));
    }
    return;
  }
  // Flare: a teardrop pointing from the light at 135 degrees.
  QPainterPath flare;
  const double len = Ctx::mm(4.5), wid = Ctx::mm(1.2);
  flare.moveTo(0, 0);
  flare.cubicTo(wid, len * 0.4, wid, len, 0, len);
  flare.cubicTo(-wid, len, -wid, len * 0.4, 0, 0);
  c.p.save();
  c.p.translate(at);
  c.p.rotate(-45.0);  // the teardrop hangs down-right, towards 135 degrees
  c.p.setPen(QPen(c.colour("OUTLW"), 0.8));
  c.p.setBrush(lc);
  c.p.drawPath(flare);
  c.p.restore();
}

void drawDanger(const Ctx& c, const ChartFeature& f, QPointF at) {
  if (isIsolatedDanger(f.number("VALSOU"), c.safetyContourM)) {
    const double r = Ctx::mm(2.0);
    c.p.setPen(QPen(c.colour("ISDNG"), 1.5));
    c.p.setBrush(Qt::NoBrush);
    c.p.drawEllipse(at, r, r);
    c.p.drawLine(QPointF(at.x() - r * 0.7, at.y() - r * 0.7), QPointF(at.x() + r * 0.7, at.y() + r * 0.7));
    c.p.drawLine(QPointF(at.x() - r * 0.7, at.y() + r * 0.7), QPointF(at.x() + r * 0.7, at.y() - r * 0.7));
    return;
  }
  c.p.setPen(QPen(c.colour("CHBLK"), 1.0));
  c.p.setBrush(Qt::NoBrush);
  if (f.objectClass == "WRECKS") {
    c.p.drawLine(QPointF(at.x() - Ctx::mm(2), at.y()), QPointF(at.x() + Ctx::mm(2), at.y()));
    for (int k = -1; k <= 1; ++k)
      c.p.drawLine(QPointF(at.x() + k * Ctx::mm(1), at.y() - Ctx::mm(1)),
                   QPointF(at.x() + k * Ctx::mm(1), at.y() + Ctx::mm(1)));
  } else if (f.objectClass == "UWTROC") {  // a cross with dots: rock awash or underwater
    const double r = Ctx::mm(1.2);
    c.p.drawLine(QPointF(at.x() - r, at.y()), QPointF(at.x() + r, at.y()));
    c.p.drawLine(QPointF(at.x(), at.y() - r), QPointF(at.x(), at.y() + r));
  } else {
    QPen dotted(c.colour("CHBLK"), 1.0);
    dotted.setDashPattern({1, 2});
    c.p.setPen(dotted);
    c.p.drawEllipse(at, Ctx::mm(1.5), Ctx::mm(1.5));
  }
}

void drawCentreSymbol(const Ctx& c, const ChartFeature& f, const std::string& name, QPointF at,
                      const QColor& colour) {
  c.p.setPen(QPen(colour, 1.5));
  c.p.setBrush(Qt::NoBrush);
  const double r = Ctx::mm(2.0);
  if (name == "anchor") {
    c.p.drawLine(QPointF(at.x(), at.y() - r), QPointF(at.x(), at.y() + r));
    c.p.drawArc(QRectF(at.x() - r, at.y() - r * 0.2, 2 * r, 1.2 * r), 180 * 16, 180 * 16);
    c.p.drawLine(QPointF(at.x() - r * 0.5, at.y() - r * 0.6), QPointF(at.x() + r * 0.5, at.y() - r * 0.6));
  } else if (name == "restricted") {
    c.p.drawRect(QRectF(at.x() - r, at.y() - r, 2 * r, 2 * r));
    c.p.drawLine(QPointF(at.x() - r, at.y() + r), QPointF(at.x() + r, at.y() - r));
  } else if (name == "tss_arrow") {
    // Direction of traffic flow (ORIENT, degrees true): an open arrow 10 mm long.
    const double orient = f.number("ORIENT").value_or(0.0);
    const double screenAngle = orient * kPi / 180.0 - c.view.rotationRad();
    const double L = Ctx::mm(5.0), hw = Ctx::mm(1.5);
    c.p.save();
    c.p.translate(at);
    c.p.rotate(screenAngle * 180.0 / kPi);  // rotate "up" to the flow direction
    QPolygonF arrow;
    arrow << QPointF(-hw * 0.4, L) << QPointF(-hw * 0.4, -L * 0.3) << QPointF(-hw, -L * 0.3) << QPointF(0, -L)
          << QPointF(hw, -L * 0.3) << QPointF(hw * 0.4, -L * 0.3) << QPointF(hw * 0.4, L);
    c.p.setPen(QPen(colour, 1.2));
    c.p.drawPolygon(arrow);
    c.p.restore();
  } else {  // caution: a triangle with a bar
    QPolygonF tri;
    tri << QPointF(at.x(), at.y() - r) << QPointF(at.x() - r, at.y() + r) << QPointF(at.x() + r, at.y() + r);
    c.p.drawPolygon(tri);
    c.p.drawLine(QPointF(at.x(), at.y() - r * 0.4), QPointF(at.x(), at.y() + r * 0.4));
  }
}

void drawPointSymbol(const Ctx& c, const std::string& name, QPointF at, const QColor& colour) {
  c.p.setPen(QPen(colour, 1.2));
  c.p.setBrush(Qt::NoBrush);
  if (name == "square") {
    c.p.drawRect(QRectF(at.x() - Ctx::mm(0.8), at.y() - Ctx::mm(0.8), Ctx::mm(1.6), Ctx::mm(1.6)));
  } else if (name == "landmark") {  // a circle with a dot: a conspicuous point
    c.p.drawEllipse(at, Ctx::mm(1.2), Ctx::mm(1.2));
    c.p.setBrush(colour);
    c.p.drawEllipse(at, 1.5, 1.5);
  } else {
    c.p.drawEllipse(at, Ctx::mm(1.0), Ctx::mm(1.0));
  }
}

}  // namespace reckoner::charts::paint
