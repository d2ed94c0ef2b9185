// The render loop: the world background, then cells from coarse to fine, each one's coverage blanked, its
// features culled and handed to the painters (painting.h) in drawing order, then its labels and
// boundary; the notices.
#include "charts/render/chart_renderer.h"

#include <QBrush>
#include <QFont>
#include <QFontMetricsF>
#include <QPainter>
#include <QTransform>
#include <algorithm>
#include <cmath>

#include "charts/render/painting.h"
#include "charts/render/prepared_cell.h"
#include "charts/render/world_layer.h"

namespace reckoner::charts {

using paint::Ctx;

namespace {

bool visible(const PreparedItem& it, const Ctx& c) {
  if (static_cast<int>(it.rule->category) > static_cast<int>(c.s.category)) return false;
  if (c.s.honourScamin && c.view.scaleDenominator() > it.scamin) return false;
  return c.onScreen(it.lo, it.hi);
}

QPointF centreOf(const Ctx& c, const PreparedItem& it) {
  return c.pt({(it.lo.x + it.hi.x) / 2, (it.lo.y + it.hi.y) / 2});
}

void drawArea(Ctx& c, const PreparedCell& pc, const PreparedItem& it, const MarinerSettings& shades) {
  const ChartFeature& f = *it.f;
  const PortrayalRule& r = *it.rule;
  const std::string& proc = r.procedure ? *r.procedure : std::string();
  QPainter& p = c.p;
  std::optional<std::string> fill = r.fill;
  if (proc == "depth_area") fill = depthShade(f.number("DRVAL1"), shades);
  if (fill || r.line) {
    // Fills need no antialiasing (neighbouring areas share their edges); outlines get it.
    if (fill) {
      p.setRenderHint(QPainter::Antialiasing, false);
      paint::fillArea(c, pc, it, QBrush(c.colour(*fill)));
      p.setRenderHint(QPainter::Antialiasing, true);
    }
    if (r.line) paint::strokeParts(c, pc, it.firstPart, it.partCount, paint::penOf(c, *r.line));
  }
  if (proc == "danger") paint::drawDanger(c, f, centreOf(c, it));
  if (r.centreSymbol && r.colour)
    paint::drawCentreSymbol(c, f, *r.centreSymbol, centreOf(c, it), c.colour(*r.colour));
  if (c.s.showText && r.textAttribute)
    if (const auto t = f.text(*r.textAttribute))
      paint::drawText(c, QString::fromStdString(*t), centreOf(c, it), c.colour("CHBLK"));
}

void drawLine(Ctx& c, const PreparedCell& pc, const PreparedItem& it) {
  const ChartFeature& f = *it.f;
  const PortrayalRule& r = *it.rule;
  const std::string& proc = r.procedure ? *r.procedure : std::string();
  if (proc == "depth_contour") {
    const auto v = f.number(f.objectClass == "DEPCNT" ? "VALDCO" : "DRVAL1");
    const bool isSafety = v && std::abs(*v - c.safetyContourM) < 1e-6;
    if (!isSafety && c.s.category == DisplayCategory::Base) return;  // only the safety contour is base
    paint::drawLines(c, pc, it, isSafety ? QPen(c.colour("DEPSC"), 2.5) : QPen(c.colour("DEPCN"), 0.8));
    if (v && c.s.showText && c.s.contourLabels && f.objectClass == "DEPCNT" &&
        c.s.category != DisplayCategory::Base)
      paint::drawContourLabel(c, pc, it, *v);
  } else if (proc == "danger") {
    QPen pen(c.colour("CHBLK"), 1.0);
    pen.setDashPattern({1, 2});
    paint::drawLines(c, pc, it, pen);
  } else if (r.line) {
    paint::drawLines(c, pc, it, paint::penOf(c, *r.line));
  }
}

void drawPoint(Ctx& c, const PreparedCell& pc, const PreparedItem& it) {
  const ChartFeature& f = *it.f;
  const PortrayalRule& r = *it.rule;
  const std::string& proc = r.procedure ? *r.procedure : std::string();
  const PartSpan& part = pc.parts()[it.firstPart];
  if (part.count == 0) return;
  const QPointF at = c.pt(pc.points()[part.first]);
  if (proc == "soundings") {
    paint::drawSoundings(c, pc, it);
  } else if (proc == "buoy" || proc == "beacon") {
    paint::drawBuoy(c, f, at, proc == "beacon");
  } else if (proc == "topmark") {
    paint::drawTopmark(c, f, at);
  } else if (proc == "light") {
    paint::drawLight(c, f, at);
    if (c.s.showText && c.s.category == DisplayCategory::Other)
      if (const std::string d = lightDescription(f); !d.empty())
        paint::drawText(c, QString::fromStdString(d), QPointF(at.x(), at.y() + Ctx::mm(3.5)),
                        c.colour("CHBLK"));
  } else if (proc == "danger") {
    paint::drawDanger(c, f, at);
  } else if (r.symbol) {
    paint::drawPointSymbol(c, *r.symbol, at, c.colour(r.colour.value_or("CHBLK")));
  }
  if (c.s.showText && r.textAttribute)
    if (const auto t = f.text(*r.textAttribute))
      paint::drawText(c, QString::fromStdString(*t), at, c.colour("CHBLK"));
}

void drawItem(Ctx& c, const PreparedCell& pc, const PreparedItem& it, const MarinerSettings& shades) {
  switch (it.f->geometry.primitive) {
    case Primitive::Area:
      drawArea(c, pc, it, shades);
      return;
    case Primitive::Line:
      drawLine(c, pc, it);
      return;
    case Primitive::Point:
    case Primitive::None:
      drawPoint(c, pc, it);
      return;
  }
}

/// Draws one cell: its coverage blanked, its visible features, its labels, its boundary. False when
/// `cancel` was raised on the way (the image is then incomplete).
bool drawCell(Ctx& c, const PreparedCell& pc, const MarinerSettings& shades, const std::atomic<bool>* cancel,
              RenderStats& stats) {
  c.p.setRenderHint(QPainter::Antialiasing, false);
  for (const PreparedItem& cov : pc.coverage()) paint::fillArea(c, pc, cov, QBrush(c.colour("NODTA")));
  c.p.setRenderHint(QPainter::Antialiasing, true);
  int sinceCheck = 0;
  for (const PreparedItem& it : pc.items()) {
    if (cancel && ++sinceCheck == 64) {
      sinceCheck = 0;
      if (cancel->load(std::memory_order_relaxed)) return false;
    }
    if (!visible(it, c)) continue;
    ++stats.featuresDrawn;
    drawItem(c, pc, it, shades);
  }
  paint::drawLabels(c);
  // Cell boundary.
  QPen boundary(c.colour("CHGRD"), 1.0);
  boundary.setDashPattern({2, 4});
  for (const PreparedItem& cov : pc.coverage())
    paint::strokeParts(c, pc, cov.firstPart, cov.partCount, boundary);
  return true;
}

/// A chart that says it is not for navigation (the fictional default chart) says so on screen too:
/// the first such cell of `order` names itself at the bottom left. The box it took, empty if none did.
QRectF drawNotForNavigation(const Ctx& c, const std::vector<const PreparedCell*>& order) {
  for (const PreparedCell* pc : order)
    if (pc->cell().info().comment.find("NOT FOR NAVIGATION") != std::string::npos) {
      QFont font("DejaVu Sans");
      font.setPixelSize(15);
      font.setBold(true);
      c.p.setFont(font);
      const QString note = QString("FICTIONAL CHART %1 - NOT FOR NAVIGATION")
                               .arg(QString::fromStdString(pc->cell().info().name));
      const QRectF box(8, c.view.height() - 30, QFontMetricsF(font).horizontalAdvance(note) + 16, 24);
      c.p.setPen(Qt::NoPen);
      c.p.setBrush(c.colour("BKGND"));
      c.p.drawRect(box);
      c.p.setPen(c.colour("DNGHL"));
      c.p.drawText(box, Qt::AlignCenter, note);
      return box;
    }
  return {};
}

/// "OVERSCALE xk" at the bottom centre, clear of the view's readouts (top left), scale bar (bottom
/// right) and north arrow (top right); above the not-for-navigation notice where the two would meet.
/// The box it took.
QRectF drawOverscale(const Ctx& c, double overscale, const QRectF& notice) {
  QFont font("DejaVu Sans");
  font.setPixelSize(14);
  font.setBold(true);
  c.p.setFont(font);
  const QString note = QString("OVERSCALE x%1").arg(overscale, 0, 'f', 1);
  const QFontMetricsF fm(font);
  const double w = fm.horizontalAdvance(note) + 12, h = fm.height() + 4;
  QRectF box(0.5 * (c.view.width() - w), c.view.height() - 8 - h, w, h);
  if (box.intersects(notice)) box.moveBottom(notice.top() - 4);
  QColor back = c.colour("BKGND");
  back.setAlpha(210);
  c.p.setPen(Qt::NoPen);
  c.p.setBrush(back);
  c.p.drawRect(box);
  c.p.setPen(c.colour("CHBLK"));
  c.p.drawText(box, Qt::AlignCenter, note);
  return box;
}

/// The overscale the view shows: of the best drawn cell whose coverage holds the view's centre, else
/// of the finest cell drawn (order: coarse to fine), 1 without a compilation scale.
double overscaleOf(const std::vector<const PreparedCell*>& order, const Viewport& view) {
  const PreparedCell* chosen = nullptr;
  for (const PreparedCell* pc : order)
    if (pc->cell().covers(view.centre())) chosen = pc;
  if (!chosen && !order.empty()) chosen = order.back();
  if (!chosen || chosen->cell().info().compilationScale <= 0) return 1.0;
  return static_cast<double>(chosen->cell().info().compilationScale) / view.scaleDenominator();
}

/// Whether the drawn cells cover the whole view (its corners, edge middles and centre each in some
/// cell's coverage): then no world background shows and its note would only clutter the chart.
bool coversView(const std::vector<const PreparedCell*>& order, const Viewport& view) {
  const double w = view.width(), h = view.height();
  for (const double fx : {0.0, 0.5, 1.0})
    for (const double fy : {0.0, 0.5, 1.0}) {
      const LatLon p = view.toLatLon({fx * w, fy * h});
      if (std::none_of(order.begin(), order.end(),
                       [&](const PreparedCell* pc) { return pc->cell().covers(p); }))
        return false;
    }
  return true;
}

}  // namespace

ChartRenderer::ChartRenderer(const PortrayalTable& table, const ColourTable& colours)
    : table_(table), colours_(colours), world_(std::make_unique<WorldLayer>()) {}

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
  if (!worldBackground_) {  // the world background fills the image itself
    const Rgb nodta = colours_.colour(s.palette, "NODTA");
    image.fill(QColor(nodta.r, nodta.g, nodta.b));
  }
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
  Ctx c{p,        view,   view.mercatorToScreen(), visLo, visHi, s,
        colours_, safety, paint::makeFonts(),      {},    {},    &stats.texts};
  MarinerSettings shades = s;
  shades.safetyContourM = safety;
  // Under the cells, the world background: wherever no cell's coverage reaches, the view still shows
  // land, water and a graticule.
  const QString worldNote = worldBackground_ ? world_->draw(c, stats) : QString();

  for (const PreparedCell* pc : order) {
    ++stats.cellsDrawn;
    if (!drawCell(c, *pc, shades, cancel, stats)) {
      stats.cancelled = true;
      return stats;
    }
  }
  // The world note over the cells, unless cells cover the whole view (the background is not seen).
  if (!worldNote.isEmpty() && !coversView(order, view)) WorldLayer::drawNote(c, worldNote);
  const QRectF notice = drawNotForNavigation(c, order);
  stats.notForNavigation = !notice.isEmpty();
  stats.overscale = overscaleOf(order, view);
  if (stats.overscale > 1.0 + 1e-9) stats.overscaleNote = drawOverscale(c, stats.overscale, notice);
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
