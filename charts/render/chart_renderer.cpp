#include "charts/render/chart_renderer.h"

#include <QFont>
#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>
#include <QTransform>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "common/angles.h"

namespace reckoner::charts {

// ---- prepared cells: geometry in Mercator, features in drawing order

struct PartSpan {
  std::uint32_t first = 0, count = 0;
  MercatorPoint lo, hi;  // Mercator box of the part
};

struct PreparedItem {
  const ChartFeature* f = nullptr;
  const PortrayalRule* rule = nullptr;
  std::uint32_t firstPart = 0, partCount = 0;
  MercatorPoint lo, hi;  // box of the feature
  double scamin = std::numeric_limits<double>::infinity();
};

class PreparedCell {
 public:
  PreparedCell(CellPtr cell, const PortrayalTable& table) : cell_(std::move(cell)) {
    const auto& features = cell_->features();
    std::vector<std::pair<int, PreparedItem>> ordered;
    ordered.reserve(features.size());
    for (const auto& f : features) {
      if (f.objectClass == "M_COVR") {
        const auto catcov = f.number("CATCOV");
        if (f.geometry.primitive == Primitive::Area && (!catcov || *catcov == 1)) {
          PreparedItem cov;
          addGeometry(f.geometry, cov);
          cov.f = &f;
          coverage_.push_back(cov);
        }
      }
      if (f.objectClass == "DEPCNT")
        if (const auto v = f.number("VALDCO")) contourValues_.push_back(*v);
      const PortrayalRule* r = table.find(f.objectClass, f.geometry.primitive);
      if (!r || f.geometry.parts.empty()) continue;
      PreparedItem it;
      it.f = &f;
      it.rule = r;
      if (const auto s = f.number("SCAMIN"); s && *s > 0) it.scamin = *s;
      addGeometry(f.geometry, it);
      const int layer = f.geometry.primitive == Primitive::Area   ? 0
                        : f.geometry.primitive == Primitive::Line ? 1
                                                                  : 2;
      ordered.emplace_back(r->priority * 3 + layer, it);
    }
    std::stable_sort(ordered.begin(), ordered.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    items_.reserve(ordered.size());
    for (auto& [order, it] : ordered) items_.push_back(it);
  }

  [[nodiscard]] const ChartCell& cell() const { return *cell_; }
  [[nodiscard]] const std::vector<PreparedItem>& items() const { return items_; }
  [[nodiscard]] const std::vector<PreparedItem>& coverage() const { return coverage_; }
  [[nodiscard]] const std::vector<PartSpan>& parts() const { return parts_; }
  [[nodiscard]] const std::vector<MercatorPoint>& points() const { return points_; }
  [[nodiscard]] const std::vector<double>& contourValues() const { return contourValues_; }

 private:
  void addGeometry(const Geometry& g, PreparedItem& it) {
    it.firstPart = static_cast<std::uint32_t>(parts_.size());
    it.lo = {1e9, 1e9};
    it.hi = {-1e9, -1e9};
    for (const auto& part : g.parts) {
      PartSpan span;
      span.first = static_cast<std::uint32_t>(points_.size());
      span.count = static_cast<std::uint32_t>(part.size());
      span.lo = {1e9, 1e9};
      span.hi = {-1e9, -1e9};
      for (const auto& ll : part) {
        const MercatorPoint m = toMercator(ll);
        points_.push_back(m);
        span.lo = {std::min(span.lo.x, m.x), std::min(span.lo.y, m.y)};
        span.hi = {std::max(span.hi.x, m.x), std::max(span.hi.y, m.y)};
      }
      it.lo = {std::min(it.lo.x, span.lo.x), std::min(it.lo.y, span.lo.y)};
      it.hi = {std::max(it.hi.x, span.hi.x), std::max(it.hi.y, span.hi.y)};
      parts_.push_back(span);
    }
    it.partCount = static_cast<std::uint32_t>(g.parts.size());
  }

  CellPtr cell_;
  std::vector<PreparedItem> items_;
  std::vector<PreparedItem> coverage_;
  std::vector<PartSpan> parts_;
  std::vector<MercatorPoint> points_;
  std::vector<double> contourValues_;
};

namespace {

struct Fonts {
  QFont sounding, soundingBold, soundingSmall, soundingSmallBold, text, contour;
  double soundingAscent = 0;
};

/// Everything one render needs: painter, view, transform, settings, colours, scratch buffers.
struct Ctx {
  QPainter& p;
  const Viewport& view;
  MercatorToScreen t;
  MercatorPoint visLo, visHi;
  const MarinerSettings& s;
  const ColourTable& colours;
  double safetyContourM;
  Fonts fonts;
  QPolygonF scratch;
  struct Label {
    QString text;
    QPointF at;
    QColor colour;
  };
  std::vector<Label> labels;  // names and light descriptions: drawn after everything else, S-52's text layer

  [[nodiscard]] QColor colour(std::string_view token) const {
    const Rgb c = colours.colour(s.palette, token);
    return {c.r, c.g, c.b};
  }
  [[nodiscard]] QPointF pt(const MercatorPoint& m) const {
    const ScreenPoint sp = t(m.x, m.y);
    return {sp.x, sp.y};
  }
  [[nodiscard]] static double mm(double v) { return v / 0.28; }  // millimetres to pixels at 0.28 mm
  [[nodiscard]] bool onScreen(const MercatorPoint& lo, const MercatorPoint& hi) const {
    return hi.x >= visLo.x && lo.x <= visHi.x && hi.y >= visLo.y && lo.y <= visHi.y;
  }
};

/// Screen polygon of one part, dropping vertices within half a pixel of the last one kept (the last
/// vertex always kept, so rings stay closed and lines end where they should).
const QPolygonF& project(Ctx& c, const PreparedCell& pc, const PartSpan& part) {
  QPolygonF& poly = c.scratch;
  poly.clear();
  const MercatorPoint* pts = pc.points().data() + part.first;
  double lx = 0, ly = 0;
  for (std::uint32_t i = 0; i < part.count; ++i) {
    const ScreenPoint sp = c.t(pts[i].x, pts[i].y);
    if (i == 0 || i + 1 == part.count || std::abs(sp.x - lx) >= 0.5 || std::abs(sp.y - ly) >= 0.5) {
      poly.append(QPointF(sp.x, sp.y));
      lx = sp.x;
      ly = sp.y;
    }
  }
  return poly;
}

QPainterPath areaPath(Ctx& c, const PreparedCell& pc, const PreparedItem& it) {
  QPainterPath path;
  path.setFillRule(Qt::OddEvenFill);
  for (std::uint32_t k = 0; k < it.partCount; ++k) {
    const PartSpan& part = pc.parts()[it.firstPart + k];
    if (part.count < 3) continue;
    const QPolygonF& poly = project(c, pc, part);
    if (poly.size() < 3) continue;
    path.addPolygon(poly);
    path.closeSubpath();
  }
  return path;
}

/// Fills an area: one ring goes straight to drawPolygon (no path object).
void fillArea(Ctx& c, const PreparedCell& pc, const PreparedItem& it, const QBrush& brush) {
  c.p.setBrush(brush);
  c.p.setPen(Qt::NoPen);
  if (it.partCount == 1) {
    const PartSpan& part = pc.parts()[it.firstPart];
    if (part.count < 3) return;
    const QPolygonF& poly = project(c, pc, part);
    if (poly.size() >= 3) c.p.drawPolygon(poly, Qt::OddEvenFill);
    return;
  }
  c.p.drawPath(areaPath(c, pc, it));
}

/// Offsets at which a one-pixel line is drawn to make a line `width` pixels wide: Qt's raster engine
/// strokes lines up to one pixel wide with its fast cosmetic stroker, but wider ones through the
/// general path stroker (joins, caps, then a polygon fill), several times slower. Copies shifted by
/// at most a pixel along x and along y widen a line of any direction by at least 0.7 of the shift.
/// Used for widths up to 3 px, so at most two steps: five offsets, no allocation per line.
struct WidthOffsets {
  std::array<QPointF, 5> at{};
  int n = 1;  // at[0] = (0, 0)
};

WidthOffsets widthOffsets(double width) {
  WidthOffsets o;
  const int steps = std::clamp(static_cast<int>(std::ceil(width - 1.0 - 1e-9)), 0, 2);
  for (int k = 1; k <= steps; ++k) {
    const double d = (width - 1.0) * k / steps;
    o.at[static_cast<std::size_t>(o.n++)] = QPointF(d, 0);
    o.at[static_cast<std::size_t>(o.n++)] = QPointF(0, d);
  }
  return o;
}

/// Strokes parts [first, first + count) as polylines (rings come closed from the loader).
void strokeParts(Ctx& c, const PreparedCell& pc, std::uint32_t first, std::uint32_t count, const QPen& pen) {
  c.p.setBrush(Qt::NoBrush);
  const double width = pen.widthF();
  const bool thin = width <= 1.0 || width > 3.0;  // beyond 3 px: the path stroker, for looks
  QPen p1 = pen;
  if (!thin) p1.setWidthF(1.0);
  c.p.setPen(p1);
  const WidthOffsets offsets = thin ? WidthOffsets{} : widthOffsets(width);
  for (std::uint32_t k = 0; k < count; ++k) {
    const PartSpan& part = pc.parts()[first + k];
    if (part.count < 2 || !c.onScreen(part.lo, part.hi)) continue;
    const QPolygonF& poly = project(c, pc, part);
    if (poly.size() < 2) continue;
    c.p.drawPolyline(poly);
    for (int i = 1; i < offsets.n; ++i) {
      const QPointF& o = offsets.at[static_cast<std::size_t>(i)];
      c.p.translate(o);
      c.p.drawPolyline(poly);
      c.p.translate(-o);
    }
  }
}

void drawLines(Ctx& c, const PreparedCell& pc, const PreparedItem& it, const QPen& pen) {
  strokeParts(c, pc, it.firstPart, it.partCount, pen);
}

QPen penOf(const Ctx& c, const LineStyle& l) {
  QPen pen(c.colour(l.colour));
  pen.setWidthF(l.widthPx);
  switch (l.dash) {
    case LineDash::Dash:
      pen.setDashPattern({6, 3});
      break;
    case LineDash::Dot:
      pen.setDashPattern({1, 3});
      break;
    case LineDash::DashDot:
      pen.setDashPattern({6, 3, 1, 3});
      break;
    case LineDash::Solid:
      break;
  }
  return pen;
}

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

void drawSoundings(Ctx& c, const PreparedCell& pc, const PreparedItem& it) {
  const PartSpan& part = pc.parts()[it.firstPart];
  const auto& depths = it.f->geometry.depthsM;
  const QFontMetricsF fm(c.fonts.sounding), fmBold(c.fonts.soundingBold);
  const QColor deep = c.colour("SNDG1"), shallowColour = c.colour("SNDG2");
  const double w = c.view.width(), h = c.view.height();
  for (std::uint32_t i = 0; i < part.count && i < depths.size(); ++i) {
    const QPointF at = c.pt(pc.points()[part.first + i]);
    if (at.x() < -20 || at.y() < -20 || at.x() > w + 20 || at.y() > h + 20) continue;
    const double d = depths[i];
    const auto [whole, tenth] = soundingText(d);
    const bool shallow = d <= c.s.safetyDepthM;
    c.p.setPen(shallow ? shallowColour : deep);
    c.p.setFont(shallow ? c.fonts.soundingBold : c.fonts.sounding);
    const QString w1 = QString::fromStdString(whole);
    const double wWhole = (shallow ? fmBold : fm).horizontalAdvance(w1);
    const double base = at.y() + c.fonts.soundingAscent / 2;
    c.p.drawText(QPointF(at.x() - wWhole / 2, base), w1);
    if (!tenth.empty()) {
      c.p.setFont(shallow ? c.fonts.soundingSmallBold : c.fonts.soundingSmall);
      c.p.drawText(QPointF(at.x() + wWhole / 2, base + Ctx::mm(0.6)), QString::fromStdString(tenth));
    }
    if (d < 0)  // drying height: underlined
      c.p.drawLine(QPointF(at.x() - wWhole / 2, base + 2), QPointF(at.x() + wWhole / 2, base + 2));
  }
}

void drawText(Ctx& c, const QString& text, QPointF at, const QColor& colour) {
  c.labels.push_back({text, QPointF(at.x() + Ctx::mm(2.5), at.y() + Ctx::mm(1.0)), colour});
}

void drawLabels(Ctx& c) {
  c.p.setFont(c.fonts.text);
  const double line = QFontMetricsF(c.fonts.text).height();
  // Labels anchored at the same point (the sectors of one light, a buoy and its light) are stacked.
  std::vector<std::pair<QPointF, int>> anchors;
  for (const auto& l : c.labels) {
    int stacked = 0;
    for (auto& [at, n] : anchors)
      if (std::abs(at.x() - l.at.x()) < 1.0 && std::abs(at.y() - l.at.y()) < 1.0) stacked = n++;
    if (stacked == 0) anchors.emplace_back(l.at, 1);
    c.p.setPen(l.colour);
    c.p.drawText(QPointF(l.at.x(), l.at.y() + stacked * line), l.text);
  }
  c.labels.clear();
}

/// Depth contour value labels: one per line part long enough on screen, at its middle vertex.
void drawContourLabel(Ctx& c, const PreparedCell& pc, const PreparedItem& it, double value) {
  const QString label = QString::number(value, 'g', 4);
  c.p.setFont(c.fonts.contour);
  c.p.setPen(c.colour("DEPCN"));
  for (std::uint32_t k = 0; k < it.partCount; ++k) {
    const PartSpan& part = pc.parts()[it.firstPart + k];
    if (part.count < 2 || !c.onScreen(part.lo, part.hi)) continue;
    const QPointF a = c.pt(pc.points()[part.first]), b = c.pt(pc.points()[part.first + part.count - 1]);
    const QPointF lo = c.pt(part.lo), hi = c.pt(part.hi);
    if (std::abs(hi.x() - lo.x()) + std::abs(hi.y() - lo.y()) < 150 && QLineF(a, b).length() < 150) continue;
    const QPointF mid = c.pt(pc.points()[part.first + part.count / 2]);
    if (mid.x() < 0 || mid.y() < 0 || mid.x() > c.view.width() || mid.y() > c.view.height()) continue;
    c.p.drawText(QPointF(mid.x() + 2, mid.y() - 2), label);
  }
}

QPointF centreOf(const Ctx& c, const PreparedItem& it) {
  return c.pt({(it.lo.x + it.hi.x) / 2, (it.lo.y + it.hi.y) / 2});
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

Fonts makeFonts() {
  Fonts f;
  f.sounding = QFont("DejaVu Sans");
  f.sounding.setPixelSize(static_cast<int>(Ctx::mm(2.6)));
  f.soundingBold = f.sounding;
  f.soundingBold.setBold(true);
  f.soundingSmall = f.sounding;
  f.soundingSmall.setPixelSize(static_cast<int>(Ctx::mm(1.9)));
  f.soundingSmallBold = f.soundingSmall;
  f.soundingSmallBold.setBold(true);
  f.text = f.sounding;
  f.text.setPixelSize(static_cast<int>(Ctx::mm(2.4)));
  f.contour = f.sounding;
  f.contour.setPixelSize(static_cast<int>(Ctx::mm(2.0)));
  f.soundingAscent = QFontMetricsF(f.sounding).ascent();
  return f;
}

bool visible(const PreparedItem& it, const Ctx& c) {
  if (static_cast<int>(it.rule->category) > static_cast<int>(c.s.category)) return false;
  if (c.s.honourScamin && c.view.scaleDenominator() > it.scamin) return false;
  return c.onScreen(it.lo, it.hi);
}

void drawItem(Ctx& c, const PreparedCell& pc, const PreparedItem& it, const MarinerSettings& shades) {
  const ChartFeature& f = *it.f;
  const PortrayalRule& r = *it.rule;
  const std::string& proc = r.procedure ? *r.procedure : std::string();
  QPainter& p = c.p;
  if (f.geometry.primitive == Primitive::Area) {
    std::optional<std::string> fill = r.fill;
    if (proc == "depth_area") fill = depthShade(f.number("DRVAL1"), shades);
    if (fill || r.line) {
      // Fills need no antialiasing (neighbouring areas share their edges); outlines get it.
      if (fill) {
        p.setRenderHint(QPainter::Antialiasing, false);
        fillArea(c, pc, it, QBrush(c.colour(*fill)));
        p.setRenderHint(QPainter::Antialiasing, true);
      }
      if (r.line) strokeParts(c, pc, it.firstPart, it.partCount, penOf(c, *r.line));
    }
    if (proc == "danger") drawDanger(c, f, centreOf(c, it));
    if (r.centreSymbol && r.colour)
      drawCentreSymbol(c, f, *r.centreSymbol, centreOf(c, it), c.colour(*r.colour));
    if (c.s.showText && r.textAttribute)
      if (const auto t = f.text(*r.textAttribute))
        drawText(c, QString::fromStdString(*t), centreOf(c, it), c.colour("CHBLK"));
    return;
  }
  if (f.geometry.primitive == Primitive::Line) {
    if (proc == "depth_contour") {
      const auto v = f.number(f.objectClass == "DEPCNT" ? "VALDCO" : "DRVAL1");
      const bool isSafety = v && std::abs(*v - c.safetyContourM) < 1e-6;
      if (!isSafety && c.s.category == DisplayCategory::Base) return;  // only the safety contour is base
      drawLines(c, pc, it, isSafety ? QPen(c.colour("DEPSC"), 2.5) : QPen(c.colour("DEPCN"), 0.8));
      if (v && c.s.showText && c.s.contourLabels && f.objectClass == "DEPCNT" &&
          c.s.category != DisplayCategory::Base)
        drawContourLabel(c, pc, it, *v);
    } else if (proc == "danger") {
      QPen pen(c.colour("CHBLK"), 1.0);
      pen.setDashPattern({1, 2});
      drawLines(c, pc, it, pen);
    } else if (r.line) {
      drawLines(c, pc, it, penOf(c, *r.line));
    }
    return;
  }
  const PartSpan& part = pc.parts()[it.firstPart];
  if (part.count == 0) return;
  const QPointF at = c.pt(pc.points()[part.first]);
  if (proc == "soundings") {
    drawSoundings(c, pc, it);
  } else if (proc == "buoy" || proc == "beacon") {
    drawBuoy(c, f, at, proc == "beacon");
  } else if (proc == "topmark") {
    drawTopmark(c, f, at);
  } else if (proc == "light") {
    drawLight(c, f, at);
    if (c.s.showText && c.s.category == DisplayCategory::Other)
      if (const std::string d = lightDescription(f); !d.empty())
        drawText(c, QString::fromStdString(d), QPointF(at.x(), at.y() + Ctx::mm(3.5)), c.colour("CHBLK"));
  } else if (proc == "danger") {
    drawDanger(c, f, at);
  } else if (r.symbol) {
    drawPointSymbol(c, *r.symbol, at, c.colour(r.colour.value_or("CHBLK")));
  }
  if (c.s.showText && r.textAttribute)
    if (const auto t = f.text(*r.textAttribute))
      drawText(c, QString::fromStdString(*t), at, c.colour("CHBLK"));
}

}  // namespace

ChartRenderer::ChartRenderer(const PortrayalTable& table, const ColourTable& colours)
    : table_(table), colours_(colours) {}

ChartRenderer::~ChartRenderer() = default;

const PreparedCell& ChartRenderer::preparedOf(const CellPtr& cell) {
  auto it = prepared_.find(cell.get());
  if (it == prepared_.end())
    it = prepared_.emplace(cell.get(), std::make_unique<PreparedCell>(cell, table_)).first;
  return *it->second;
}

void ChartRenderer::prepare(const CellPtr& cell) {
  if (cell) preparedOf(cell);
}

void ChartRenderer::retainOnly(const std::vector<CellPtr>& keep) {
  for (auto it = prepared_.begin(); it != prepared_.end();) {
    const bool kept =
        std::any_of(keep.begin(), keep.end(), [&](const CellPtr& c) { return c.get() == it->first; });
    it = kept ? std::next(it) : prepared_.erase(it);
  }
}

RenderStats ChartRenderer::render(QImage& image, const std::vector<CellPtr>& cells, const Viewport& view,
                                  const MarinerSettings& s, const std::atomic<bool>* cancel) {
  RenderStats stats;
  QPainter p(&image);
  p.setRenderHint(QPainter::Antialiasing, true);
  p.setRenderHint(QPainter::TextAntialiasing, true);
  const Rgb nodta = colours_.colour(s.palette, "NODTA");
  image.fill(QColor(nodta.r, nodta.g, nodta.b));
  const Bounds vb = view.visibleBounds();

  // Coarse cells first, finer ones on top; each finer cell first blanks its own coverage.
  std::vector<const PreparedCell*> order;
  for (const auto& cell : cells)
    if (cell && cell->bounds().intersects(vb)) order.push_back(&preparedOf(cell));
  std::stable_sort(order.begin(), order.end(), [](const PreparedCell* a, const PreparedCell* b) {
    return a->cell().info().compilationScale > b->cell().info().compilationScale;
  });
  // The safety contour drawn: from the contours present in the visible cells.
  std::vector<double> contours;
  for (const PreparedCell* pc : order)
    contours.insert(contours.end(), pc->contourValues().begin(), pc->contourValues().end());
  const double safety = chooseSafetyContour(contours, s.safetyContourM).value_or(s.safetyContourM);
  const auto [visLo, visHi] = view.visibleMercator();
  Ctx c{p, view, view.mercatorToScreen(), visLo, visHi, s, colours_, safety, makeFonts(), {}, {}};
  MarinerSettings shades = s;
  shades.safetyContourM = safety;

  for (const PreparedCell* pc : order) {
    ++stats.cellsDrawn;
    if (pc->cell().info().compilationScale > 0)
      stats.overscale = static_cast<double>(pc->cell().info().compilationScale) / view.scaleDenominator();
    p.setRenderHint(QPainter::Antialiasing, false);
    for (const PreparedItem& cov : pc->coverage()) fillArea(c, *pc, cov, QBrush(c.colour("NODTA")));
    p.setRenderHint(QPainter::Antialiasing, true);
    int sinceCheck = 0;
    for (const PreparedItem& it : pc->items()) {
      if (cancel && ++sinceCheck == 64) {
        sinceCheck = 0;
        if (cancel->load(std::memory_order_relaxed)) {
          stats.cancelled = true;
          return stats;
        }
      }
      if (!visible(it, c)) continue;
      ++stats.featuresDrawn;
      drawItem(c, *pc, it, shades);
    }
    drawLabels(c);
    // Cell boundary.
    QPen boundary(c.colour("CHGRD"), 1.0);
    boundary.setDashPattern({2, 4});
    for (const PreparedItem& cov : pc->coverage())
      strokeParts(c, *pc, cov.firstPart, cov.partCount, boundary);
  }
  // A chart that says it is not for navigation (the fictional default chart) says so on screen too.
  for (const PreparedCell* pc : order)
    if (pc->cell().info().comment.find("NOT FOR NAVIGATION") != std::string::npos) {
      QFont font("DejaVu Sans");
      font.setPixelSize(15);
      font.setBold(true);
      p.setFont(font);
      const QString note = QString("FICTIONAL CHART %1 - NOT FOR NAVIGATION")
                               .arg(QString::fromStdString(pc->cell().info().name));
      const QRectF box(8, view.height() - 30, QFontMetricsF(font).horizontalAdvance(note) + 16, 24);
      p.setPen(Qt::NoPen);
      p.setBrush(c.colour("BKGND"));
      p.drawRect(box);
      p.setPen(c.colour("DNGHL"));
      p.drawText(box, Qt::AlignCenter, note);
      stats.notForNavigation = true;
      break;
    }
  if (stats.overscale > 1.0 + 1e-9) {
    QFont font("DejaVu Sans");
    font.setPixelSize(14);
    p.setFont(font);
    p.setPen(c.colour("CHBLK"));
    p.drawText(QPointF(10, 20), QString("OVERSCALE x%1").arg(stats.overscale, 0, 'f', 1));
  }
  return stats;
}

RenderStats renderChart(QImage& image, const std::vector<CellPtr>& cells, const Viewport& view,
                        const MarinerSettings& settings, const PortrayalTable& table,
                        const ColourTable& colours) {
  ChartRenderer renderer(table, colours);
  return renderer.render(image, cells, view, settings);
}

void drawFromCache(QPainter& painter, const QImage& cachedImage, const Viewport& cachedView,
                   const Viewport& now, const QColor& background) {
  // screen_now = T_now(T_cached^-1(screen_cached)): both maps are affine, so is their composition.
  const MercatorToScreen a = cachedView.mercatorToScreen(), b = now.mercatorToScreen();
  const QTransform cachedToMercator =
      QTransform(a.a, a.c, a.b, a.d, a.e, a.f).inverted();  // QTransform(m11, m12, m21, m22, dx, dy)
  const QTransform mercatorToNow(b.a, b.c, b.b, b.d, b.e, b.f);
  painter.save();
  painter.setCompositionMode(QPainter::CompositionMode_Source);
  painter.fillRect(QRect(0, 0, now.width(), now.height()), background);
  const QTransform map = cachedToMercator * mercatorToNow;
  const bool pureShift =
      std::abs(cachedView.scaleDenominator() - now.scaleDenominator()) < 1e-9 * now.scaleDenominator() &&
      cachedView.rotationRad() == now.rotationRad();
  if (pureShift) {
    // A pan: the map is a translation (to well under a pixel over the screen: the scale's change
    // with the centre latitude is negligible), so a plain blit at the rounded offset.
    const QPointF origin = map.map(QPointF(0, 0));
    painter.drawImage(
        QPoint(static_cast<int>(std::lround(origin.x())), static_cast<int>(std::lround(origin.y()))),
        cachedImage);
  } else {
    painter.setTransform(map);
    painter.setRenderHint(QPainter::SmoothPixmapTransform, true);
    painter.drawImage(QPointF(0, 0), cachedImage);
  }
  painter.restore();
}

}  // namespace reckoner::charts
