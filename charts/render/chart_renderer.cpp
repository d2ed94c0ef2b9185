#include "charts/render/chart_renderer.h"

#include <QFont>
#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>

namespace reckoner::charts {
namespace {

struct Ctx {
  QPainter& p;
  const Viewport& view;
  const MarinerSettings& s;
  const ColourTable& colours;
  double safetyContourM;
  QColor colour(std::string_view token) const {
    const Rgb c = colours.colour(s.palette, token);
    return QColor(c.r, c.g, c.b);
  }
  QPointF pt(const LatLon& ll) const {
    const ScreenPoint sp = view.toScreen(ll);
    return {sp.x, sp.y};
  }
  double mm(double v) const { return v / 0.28; }  // millimetres to pixels at the reference pitch
};

QPainterPath areaPath(const Ctx& c, const Geometry& g) {
  QPainterPath path;
  path.setFillRule(Qt::OddEvenFill);
  for (const auto& ring : g.parts) {
    if (ring.empty()) continue;
    path.moveTo(c.pt(ring[0]));
    for (std::size_t i = 1; i < ring.size(); ++i) path.lineTo(c.pt(ring[i]));
    path.closeSubpath();
  }
  return path;
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

void drawLines(const Ctx& c, const Geometry& g, const QPen& pen) {
  c.p.setPen(pen);
  c.p.setBrush(Qt::NoBrush);
  for (const auto& part : g.parts) {
    if (part.size() < 2) continue;
    QPolygonF poly;
    poly.reserve(static_cast<qsizetype>(part.size()));
    for (const auto& ll : part) poly << c.pt(ll);
    c.p.drawPolyline(poly);
  }
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

/// Buoys by shape (BOYSHP) filled with their colours (stacked when several), our own vector shapes.
void drawBuoy(const Ctx& c, const ChartFeature& f, QPointF at, bool beacon) {
  const auto cols = f.list("COLOUR");
  const double h = c.mm(beacon ? 4.0 : 3.5), w = c.mm(2.4);
  QPainterPath shape;
  const int boyshp = static_cast<int>(f.number(beacon ? "BCNSHP" : "BOYSHP").value_or(beacon ? 1 : 4));
  if (beacon) {
    shape.addRect(QRectF(at.x() - w * 0.2, at.y() - h, w * 0.4, h));
  } else if (boyshp == 1) {  // conical
    shape.moveTo(at.x() - w / 2, at.y());
    shape.lineTo(at.x(), at.y() - h);
    shape.lineTo(at.x() + w / 2, at.y());
    shape.closeSubpath();
  } else if (boyshp == 2) {  // can
    shape.addRect(QRectF(at.x() - w / 2, at.y() - h * 0.8, w, h * 0.8));
  } else if (boyshp == 3) {  // spherical
    shape.addEllipse(QPointF(at.x(), at.y() - w / 2), w / 2, w / 2);
  } else {  // pillar, spar and others: a tall narrow shape
    shape.moveTo(at.x() - w / 2, at.y());
    shape.lineTo(at.x() - w / 6, at.y() - h);
    shape.lineTo(at.x() + w / 6, at.y() - h);
    shape.lineTo(at.x() + w / 2, at.y());
    shape.closeSubpath();
  }
  const QRectF box = shape.boundingRect();
  c.p.save();
  c.p.setClipPath(shape);
  const std::size_t n = std::max<std::size_t>(cols.size(), 1);
  for (std::size_t i = 0; i < n; ++i) {
    const QColor fill = cols.empty() ? c.colour("CHGRD") : s57Colour(c, cols[i]);
    c.p.fillRect(
        QRectF(box.left(), box.top() + box.height() * static_cast<double>(i) / static_cast<double>(n),
               box.width(), box.height() / static_cast<double>(n) + 0.5),
        fill);
  }
  c.p.restore();
  c.p.setPen(QPen(c.colour("OUTLW"), 1.0));
  c.p.setBrush(Qt::NoBrush);
  c.p.drawPath(shape);
  c.p.drawEllipse(at, 1.5, 1.5);  // position circle
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
    const double r = c.mm(20.0);
    const double a1 = std::fmod(*s1 + 180.0, 360.0), a2 = std::fmod(*s2 + 180.0, 360.0);
    double span = a2 - a1;
    if (span <= 0) span += 360.0;
    const QRectF box(at.x() - r, at.y() - r, 2 * r, 2 * r);
    QPen arc(lc, 3.0);
    c.p.setPen(arc);
    c.p.setBrush(Qt::NoBrush);
    // Qt: 0 deg at 3 o'clock, counter-clockwise positive, 1/16 deg units.
    c.p.drawArc(box, static_cast<int>((90.0 - a1) * 16.0), static_cast<int>(-span * 16.0));
    QPen leg(c.colour("CHBLK"), 1.0);
    leg.setDashPattern({4, 4});
    c.p.setPen(leg);
    for (double a : {a1, a2}) {
      const double rad = a * M_PI / 180.0;
      c.p.drawLine(at, QPointF(at.x() + r * 1.2 * std::sin(rad), at.y() - r * 1.2 * std::cos(rad)));
    }
    return;
  }
  // Flare: a teardrop pointing from the light at 135 degrees.
  QPainterPath flare;
  const double len = c.mm(4.5), wid = c.mm(1.2);
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
    const double r = c.mm(2.0);
    c.p.setPen(QPen(c.colour("ISDNG"), 1.5));
    c.p.setBrush(Qt::NoBrush);
    c.p.drawEllipse(at, r, r);
    c.p.drawLine(QPointF(at.x() - r * 0.7, at.y() - r * 0.7), QPointF(at.x() + r * 0.7, at.y() + r * 0.7));
    c.p.drawLine(QPointF(at.x() - r * 0.7, at.y() + r * 0.7), QPointF(at.x() + r * 0.7, at.y() - r * 0.7));
    return;
  }
  c.p.setPen(QPen(c.colour("CHBLK"), 1.0));
  if (f.objectClass == "WRECKS") {
    c.p.drawLine(QPointF(at.x() - c.mm(2), at.y()), QPointF(at.x() + c.mm(2), at.y()));
    for (int k = -1; k <= 1; ++k)
      c.p.drawLine(QPointF(at.x() + k * c.mm(1), at.y() - c.mm(1)),
                   QPointF(at.x() + k * c.mm(1), at.y() + c.mm(1)));
  } else {
    QPen dotted(c.colour("CHBLK"), 1.0);
    dotted.setDashPattern({1, 2});
    c.p.setPen(dotted);
    c.p.setBrush(Qt::NoBrush);
    c.p.drawEllipse(at, c.mm(1.5), c.mm(1.5));
  }
}

void drawSoundings(const Ctx& c, const ChartFeature& f) {
  QFont big("DejaVu Sans");
  big.setPixelSize(static_cast<int>(c.mm(2.6)));
  QFont small = big;
  small.setPixelSize(static_cast<int>(c.mm(1.9)));
  const auto& pts = f.geometry.parts.empty() ? std::vector<LatLon>{} : f.geometry.parts[0];
  for (std::size_t i = 0; i < pts.size() && i < f.geometry.depthsM.size(); ++i) {
    const QPointF at = c.pt(pts[i]);
    if (at.x() < -20 || at.y() < -20 || at.x() > c.view.width() + 20 || at.y() > c.view.height() + 20)
      continue;
    const double d = f.geometry.depthsM[i];
    const auto [whole, tenth] = soundingText(d);
    const bool shallow = d <= c.s.safetyDepthM;
    c.p.setPen(c.colour(shallow ? "SNDG2" : "SNDG1"));
    big.setBold(shallow);
    c.p.setFont(big);
    const QFontMetricsF fm(big);
    const double wWhole = fm.horizontalAdvance(QString::fromStdString(whole));
    c.p.drawText(QPointF(at.x() - wWhole / 2, at.y() + fm.ascent() / 2), QString::fromStdString(whole));
    if (!tenth.empty()) {
      c.p.setFont(small);
      c.p.drawText(QPointF(at.x() + wWhole / 2, at.y() + fm.ascent() / 2 + c.mm(0.6)),
                   QString::fromStdString(tenth));
    }
    if (d < 0)
      c.p.drawLine(QPointF(at.x() - wWhole / 2, at.y() + fm.ascent() / 2 + 2),
                   QPointF(at.x() + wWhole / 2, at.y() + fm.ascent() / 2 + 2));
  }
}

void drawText(const Ctx& c, const std::string& text, QPointF at, const QColor& colour) {
  QFont font("DejaVu Sans");
  font.setPixelSize(static_cast<int>(c.mm(2.4)));
  c.p.setFont(font);
  c.p.setPen(colour);
  c.p.drawText(QPointF(at.x() + c.mm(2.5), at.y() + c.mm(1.0)), QString::fromStdString(text));
}

QPointF centreOf(const Ctx& c, const Geometry& g) {
  const LatLon mid{(g.bounds.minLatDeg + g.bounds.maxLatDeg) / 2,
                   (g.bounds.minLonDeg + g.bounds.maxLonDeg) / 2};
  return c.pt(mid);
}

void drawCentreSymbol(const Ctx& c, const std::string& name, QPointF at, const QColor& colour) {
  c.p.setPen(QPen(colour, 1.5));
  c.p.setBrush(Qt::NoBrush);
  const double r = c.mm(2.0);
  if (name == "anchor") {
    c.p.drawLine(QPointF(at.x(), at.y() - r), QPointF(at.x(), at.y() + r));
    c.p.drawArc(QRectF(at.x() - r, at.y() - r * 0.2, 2 * r, 1.2 * r * 1.0), 180 * 16, 180 * 16);
    c.p.drawLine(QPointF(at.x() - r * 0.5, at.y() - r * 0.6), QPointF(at.x() + r * 0.5, at.y() - r * 0.6));
  } else if (name == "restricted") {
    c.p.drawRect(QRectF(at.x() - r, at.y() - r, 2 * r, 2 * r));
    c.p.drawLine(QPointF(at.x() - r, at.y() + r), QPointF(at.x() + r, at.y() - r));
  } else {  // caution: a triangle with a bar
    QPolygonF tri;
    tri << QPointF(at.x(), at.y() - r) << QPointF(at.x() - r, at.y() + r) << QPointF(at.x() + r, at.y() + r);
    c.p.drawPolygon(tri);
    c.p.drawLine(QPointF(at.x(), at.y() - r * 0.4), QPointF(at.x(), at.y() + r * 0.4));
  }
}

struct Item {
  const ChartFeature* f;
  const PortrayalRule* rule;
  int order;  // priority * 3 + primitive layer (areas, lines, points)
};

bool visible(const ChartFeature& f, const PortrayalRule& r, const Viewport& view, const MarinerSettings& s,
             const Bounds& vb) {
  if (static_cast<int>(r.category) > static_cast<int>(s.category)) return false;
  if (s.honourScamin)
    if (const auto scamin = f.number("SCAMIN"); scamin && view.scaleDenominator() > *scamin) return false;
  return f.geometry.bounds.intersects(vb);
}
}  // namespace

RenderStats renderChart(QImage& image, const std::vector<CellPtr>& cells, const Viewport& view,
                        const MarinerSettings& s, const PortrayalTable& table, const ColourTable& colours) {
  RenderStats stats;
  QPainter p(&image);
  p.setRenderHint(QPainter::Antialiasing, true);
  p.setRenderHint(QPainter::TextAntialiasing, true);
  const Rgb nodta = colours.colour(s.palette, "NODTA");
  image.fill(QColor(nodta.r, nodta.g, nodta.b));
  const Bounds vb = view.visibleBounds();

  // Coarse cells first, finer ones on top; each finer cell first blanks its own coverage.
  std::vector<CellPtr> order;
  for (const auto& c : cells)
    if (c && c->bounds().intersects(vb)) order.push_back(c);
  std::sort(order.begin(), order.end(), [](const CellPtr& a, const CellPtr& b) {
    return a->info().compilationScale > b->info().compilationScale;
  });
  // The safety contour drawn: from the contours present in the visible cells.
  std::vector<double> contours;
  for (const auto& cell : order)
    for (const auto& f : cell->features())
      if (f.objectClass == "DEPCNT")
        if (const auto v = f.number("VALDCO")) contours.push_back(*v);
  const double safety = chooseSafetyContour(contours, s.safetyContourM).value_or(s.safetyContourM);
  const Ctx c{p, view, s, colours, safety};
  MarinerSettings shades = s;
  shades.safetyContourM = safety;

  for (const auto& cell : order) {
    ++stats.cellsDrawn;
    if (cell->info().compilationScale > 0)
      stats.overscale = static_cast<double>(cell->info().compilationScale) / view.scaleDenominator();
    for (const ChartFeature* cov : cell->coverage()) {
      p.setPen(Qt::NoPen);
      p.setBrush(c.colour("NODTA"));
      p.drawPath(areaPath(c, cov->geometry));
    }
    std::vector<Item> items;
    items.reserve(cell->features().size());
    for (const auto& f : cell->features()) {
      const PortrayalRule* r = table.find(f.objectClass, f.geometry.primitive);
      if (!r || !visible(f, *r, view, s, vb)) continue;
      const int layer = f.geometry.primitive == Primitive::Area   ? 0
                        : f.geometry.primitive == Primitive::Line ? 1
                                                                  : 2;
      items.push_back({&f, r, r->priority * 3 + layer});
    }
    std::stable_sort(items.begin(), items.end(),
                     [](const Item& a, const Item& b) { return a.order < b.order; });
    for (const Item& it : items) {
      const ChartFeature& f = *it.f;
      const PortrayalRule& r = *it.rule;
      ++stats.featuresDrawn;
      const std::string proc = r.procedure.value_or("");
      if (f.geometry.primitive == Primitive::Area) {
        const QPainterPath path = areaPath(c, f.geometry);
        std::optional<std::string> fill = r.fill;
        if (proc == "depth_area") fill = depthShade(f.number("DRVAL1"), shades);
        if (fill) {
          p.setPen(Qt::NoPen);
          p.setBrush(c.colour(*fill));
          p.drawPath(path);
        }
        if (r.line) {
          p.setPen(penOf(c, *r.line));
          p.setBrush(Qt::NoBrush);
          p.drawPath(path);
        }
        if (proc == "danger") drawDanger(c, f, centreOf(c, f.geometry));
        if (r.centreSymbol && r.colour)
          drawCentreSymbol(c, *r.centreSymbol, centreOf(c, f.geometry), c.colour(*r.colour));
        if (s.showText && r.textAttribute)
          if (const auto t = f.text(*r.textAttribute))
            drawText(c, *t, centreOf(c, f.geometry), c.colour("CHBLK"));
      } else if (f.geometry.primitive == Primitive::Line) {
        if (proc == "depth_contour") {
          const auto v = f.number(f.objectClass == "DEPCNT" ? "VALDCO" : "DRVAL1");
          const bool isSafety = v && std::abs(*v - safety) < 1e-6;
          if (!isSafety && s.category == DisplayCategory::Base) continue;  // only the safety contour is base
          drawLines(c, f.geometry, isSafety ? QPen(c.colour("DEPSC"), 2.5) : QPen(c.colour("DEPCN"), 0.8));
        } else if (proc == "danger") {
          QPen pen(c.colour("CHBLK"), 1.0);
          pen.setDashPattern({1, 2});
          drawLines(c, f.geometry, pen);
        } else if (r.line) {
          drawLines(c, f.geometry, penOf(c, *r.line));
        }
      } else if (f.geometry.primitive == Primitive::Point && !f.geometry.parts.empty() &&
                 !f.geometry.parts[0].empty()) {
        const QPointF at = c.pt(f.geometry.parts[0][0]);
        if (proc == "soundings") {
          drawSoundings(c, f);
        } else if (proc == "buoy" || proc == "beacon") {
          drawBuoy(c, f, at, proc == "beacon");
        } else if (proc == "light") {
          drawLight(c, f, at);
        } else if (proc == "danger") {
          drawDanger(c, f, at);
        } else if (r.symbol) {
          p.setPen(QPen(c.colour(r.colour.value_or("CHBLK")), 1.2));
          p.setBrush(Qt::NoBrush);
          p.drawEllipse(at, c.mm(1.0), c.mm(1.0));
        }
        if (s.showText && r.textAttribute)
          if (const auto t = f.text(*r.textAttribute)) drawText(c, *t, at, c.colour("CHBLK"));
      }
    }
    // Cell boundary.
    QPen boundary(c.colour("CHGRD"), 1.0);
    boundary.setDashPattern({2, 4});
    p.setPen(boundary);
    p.setBrush(Qt::NoBrush);
    for (const ChartFeature* cov : cell->coverage()) p.drawPath(areaPath(c, cov->geometry));
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

}  // namespace reckoner::charts
