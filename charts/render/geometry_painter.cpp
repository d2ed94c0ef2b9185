// Areas and lines on screen: polygons from prepared parts, fills, strokes and pens (painting.h).
#include <QBrush>
#include <QPainterPath>
#include <algorithm>
#include <array>
#include <cmath>

#include "charts/render/painting.h"

namespace reckoner::charts::paint {
namespace {

const QPolygonF& project(Ctx& c, const PreparedCell& pc, const PartSpan& part) {
  return projectPoints(c, pc.points().data() + part.first, part.count);
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

}  // namespace

const QPolygonF& projectPoints(Ctx& c, const MercatorPoint* pts, std::uint32_t count, double shiftX) {
  QPolygonF& poly = c.scratch;
  poly.clear();
  double lx = 0, ly = 0;
  for (std::uint32_t i = 0; i < count; ++i) {
    const ScreenPoint sp = c.t(pts[i].x + shiftX, pts[i].y);
    if (i == 0 || i + 1 == count || std::abs(sp.x - lx) >= 0.5 || std::abs(sp.y - ly) >= 0.5) {
      poly.append(QPointF(sp.x, sp.y));
      lx = sp.x;
      ly = sp.y;
    }
  }
  return poly;
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

}  // namespace reckoner::charts::paint
