#include "ui/map/chart_view.h"

#include <QFontMetricsF>
#include <QMenu>
#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

#include "charts/render/chart_extent.h"

namespace reckoner::ui {

namespace {
/// The outlines' colour: the chart's magenta, as S-52 draws the limits of things to note.
QColor outlineColour(const charts::MarinerSettings& s) {
  const charts::Rgb c = charts::defaultColours().colour(s.palette, "CHMGD");
  return {c.r, c.g, c.b};
}
constexpr double kMinOutlinePx = 14.0;  // a cell smaller than this on screen gets a box of this size

/// A ring in screen pixels, vertices closer than a pixel to the last one kept dropped.
QPolygonF screenRing(const std::vector<charts::MercatorPoint>& ring, const charts::MercatorToScreen& t) {
  QPolygonF poly;
  poly.reserve(static_cast<qsizetype>(ring.size()));
  for (const charts::MercatorPoint& m : ring) {
    const charts::ScreenPoint s = t(m.x, m.y);
    if (poly.isEmpty() || std::abs(poly.back().x() - s.x) + std::abs(poly.back().y() - s.y) >= 1.0)
      poly.append(QPointF(s.x, s.y));
  }
  if (!ring.empty() && poly.size() > 1) {  // the closing vertex, even when near the last kept
    const charts::ScreenPoint s = t(ring.back().x, ring.back().y);
    poly.back() = QPointF(s.x, s.y);
  }
  return poly;
}
}  // namespace

ChartView::ChartView(QWidget* parent) : QWidget(parent) {
  qRegisterMetaType<charts::Viewport>();
  qRegisterMetaType<charts::RenderStats>();
  setMouseTracking(true);
  setAttribute(Qt::WA_OpaquePaintEvent);
  setMinimumSize(64, 64);
  connect(render_.worker(), &ChartRenderWorker::rendered, this, &ChartView::onRendered, Qt::QueuedConnection);
}

ChartView::~ChartView() {
  render_.worker()->requests().issue();  // stops a render in progress; render_ then stops the thread
}

void ChartView::setCells(std::vector<charts::CellPtr> cells) {
  cells_ = std::move(cells);
  outlines_.clear();
  for (const charts::CellPtr& c : cells_) {
    if (!c) continue;
    Outline o{c, {}, {1e9, 1e9}, {-1e9, -1e9}};
    const auto add = [&o](const std::vector<charts::LatLon>& ring) {
      auto& r = o.rings.emplace_back();
      for (const charts::LatLon& q : ring) {
        const charts::MercatorPoint m = charts::toMercator(q);
        r.push_back(m);
        o.lo = {std::min(o.lo.x, m.x), std::min(o.lo.y, m.y)};
        o.hi = {std::max(o.hi.x, m.x), std::max(o.hi.y, m.y)};
      }
    };
    for (const charts::ChartFeature* f : c->coverage())
      for (const auto& ring : f->geometry.parts) add(ring);
    if (o.rings.empty()) {  // no coverage areas: the cell's extent
      const charts::Bounds& b = c->bounds();
      add({{b.minLatDeg, b.minLonDeg},
           {b.minLatDeg, b.maxLonDeg},
           {b.maxLatDeg, b.maxLonDeg},
           {b.maxLatDeg, b.minLonDeg},
           {b.minLatDeg, b.minLonDeg}});
    }
    outlines_.push_back(std::move(o));
  }
  setUnderCursor(cursorAt_ ? cellsAt(*cursorAt_) : std::vector<charts::CellPtr>{});
  requestRender();
  emit cellsChanged();
}

void ChartView::setSettings(const charts::MarinerSettings& settings) {
  settings_ = settings;
  requestRender();
  emit settingsChanged(settings_);
}

void ChartView::setView(charts::LatLon centre, double scaleDenominator, double rotationRad) {
  centre_ = {std::clamp(centre.latDeg, -84.0, 84.0), std::remainder(centre.lonDeg, 360.0)};
  scale_ = allowedScale(centre_, scaleDenominator);
  rotation_ = std::isfinite(rotationRad) ? rotationRad : 0.0;
  requestRender();
  if (cursorAt_) setUnderCursor(cellsAt(*cursorAt_));  // the chart moved under a still cursor
  emit viewChanged(viewport());
}

double ChartView::largestScale(charts::LatLon centre) const {
  return charts::largestScaleAt(cells_, centre);
}

double ChartView::smallestScale(charts::LatLon centre) const {
  return charts::smallestScale(centre.latDeg, std::max(width(), 16));
}

double ChartView::allowedScale(charts::LatLon centre, double requested) const {
  double s = std::isfinite(requested) && requested > 0.0 ? requested : scale_;
  // Zooming stops at a limit; a view already past it (moved onto a coarser chart or off the charts,
  // or the widget narrowed) keeps its scale rather than jump, and may only zoom back.
  if (const double in = largestScale(centre); s < in) s = std::max(s, std::min(in, scale_));
  if (const double out = smallestScale(centre); s > out) s = std::min(s, std::max(out, scale_));
  return std::max(s, charts::kLargestScale);
}

charts::Viewport ChartView::viewport() const {
  return charts::Viewport(centre_, scale_, std::max(width(), 16), std::max(height(), 16), 0.28, rotation_);
}

void ChartView::zoomAbout(double factor, QPointF anchor) {
  if (!(factor > 0) || !std::isfinite(factor)) return;
  const charts::Viewport before = viewport();
  const charts::LatLon fixed = before.toLatLon({anchor.x(), anchor.y()});
  const double newScale = allowedScale(centre_, scale_ / factor);
  // Put `fixed` back under the anchor: the centre moves along the anchor-centre line by the zoom.
  const charts::Viewport trial(centre_, newScale, before.width(), before.height(), 0.28, rotation_);
  const charts::ScreenPoint now = trial.toScreen(fixed);
  const charts::LatLon newCentre = trial.toLatLon(
      {0.5 * before.width() + (now.x - anchor.x()), 0.5 * before.height() + (now.y - anchor.y())});
  setView(newCentre, newScale, rotation_);
}

bool ChartView::zoomToCells(const std::vector<charts::CellPtr>& cells) {
  const charts::Bounds box = charts::coverageOf(cells);
  if (box.empty()) return false;
  const charts::Viewport fit =
      charts::fitView(box, std::max(width(), 16), std::max(height(), 16), rotation_, 24.0);
  setView(fit.centre(), fit.scaleDenominator(), rotation_);
  return true;
}

std::vector<charts::CellPtr> ChartView::cellsAt(QPointF p) const {
  return charts::cellsAt(cells_, viewport().toLatLon({p.x(), p.y()}));
}

void ChartView::setShowOutlines(bool on) {
  showOutlines_ = on;
  update();
}

void ChartView::setUnderCursor(std::vector<charts::CellPtr> cells) {
  if (cells == underCursor_) return;
  underCursor_ = std::move(cells);
  if (showOutlines_) update();
  emit cellsUnderCursorChanged(underCursor_);
}

void ChartView::addChartActions(QMenu* menu, QPointF at) {
  for (const charts::CellPtr& c : cellsAt(at)) {
    const QString name = QString::fromStdString(c->info().name);
    QAction* a = menu->addAction(tr("Zoom to chart %1").arg(name), this, [this, c] { zoomToCells({c}); });
    a->setObjectName(QStringLiteral("zoomToChart_") + name);
    a->setToolTip(tr("Show all of %1 (1:%2)").arg(name).arg(c->info().compilationScale));
  }
  if (!cells_.empty())
    menu->addAction(tr("Show all charts"), this, [this] { zoomToCells(cells_); })
        ->setObjectName(QStringLiteral("showAllCharts"));
}

void ChartView::panBy(QPointF deltaPx) {
  const charts::Viewport v = viewport();
  setView(v.toLatLon({0.5 * v.width() - deltaPx.x(), 0.5 * v.height() - deltaPx.y()}), scale_, rotation_);
}

void ChartView::requestRender() {
  if (width() < 16 || height() < 16) return;
  render_.post(&ChartRenderWorker::render,
               ChartRenderRequest{cells_, viewport(), settings_, render_.worker()->requests().issue()});
  update();
}

void ChartView::onRendered(const QImage& image, const charts::Viewport& view, quint64 generation, double ms,
                           const charts::RenderStats& stats) {
  // The worker answers in request order and skips superseded requests, so each image is newer than
  // the one shown (not necessarily the latest requested: a finished render is shown until the next).
  image_ = image;
  imageView_ = view;
  imageGeneration_ = generation;
  lastRenderMs_ = ms;
  lastStats_ = stats;
  update();
  emit renderFinished(ms);
}

void ChartView::paintEvent(QPaintEvent*) {
  QPainter p(this);
  const charts::Viewport now = viewport();
  const charts::Rgb bg = charts::defaultColours().colour(settings_.palette, "NODTA");
  if (imageView_ && !image_.isNull())
    charts::drawFromCache(p, image_, *imageView_, now, QColor(bg.r, bg.g, bg.b));
  else
    p.fillRect(rect(), QColor(bg.r, bg.g, bg.b));
  if (showOutlines_) paintOutlines(p, now);
  paintOverlay(p, now);
}

void ChartView::paintOutlines(QPainter& p, const charts::Viewport& view) {
  p.save();
  p.setRenderHint(QPainter::Antialiasing, true);
  const charts::MercatorToScreen t = view.mercatorToScreen();
  const QColor colour = outlineColour(settings_);
  const charts::Rgb bk = charts::defaultColours().colour(settings_.palette, "BKGND");
  const QColor back(bk.r, bk.g, bk.b, 180);
  QFont font = p.font();
  font.setPixelSize(11);
  font.setBold(true);
  p.setFont(font);
  const QFontMetricsF fm(font);
  const QRectF screen = rect();
  std::vector<QRectF> names;  // placed so far: a name never covers another
  for (const Outline& o : outlines_) {
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;  // the outline's screen box
    for (const charts::MercatorPoint m :
         {o.lo, o.hi, charts::MercatorPoint{o.lo.x, o.hi.y}, charts::MercatorPoint{o.hi.x, o.lo.y}}) {
      const charts::ScreenPoint s = t(m.x, m.y);
      x0 = std::min(x0, s.x);
      x1 = std::max(x1, s.x);
      y0 = std::min(y0, s.y);
      y1 = std::max(y1, s.y);
    }
    QRectF box(QPointF(x0, y0), QPointF(x1, y1));
    const double pad = kMinOutlinePx;
    if (!box.adjusted(-pad, -pad, pad, pad).intersects(screen)) continue;
    const bool under = std::find(underCursor_.begin(), underCursor_.end(), o.cell) != underCursor_.end();
    p.setPen(QPen(colour, under ? 2.5 : 1.0));
    p.setBrush(Qt::NoBrush);
    const bool tiny = box.width() < kMinOutlinePx && box.height() < kMinOutlinePx;
    if (tiny) {  // too small to see at this scale: a box of its own, so that the chart can be found
      box = QRectF(box.center() - QPointF(pad / 2, pad / 2), QSizeF(pad, pad));
      p.drawRect(box);
    } else {
      for (const auto& ring : o.rings) p.drawPolyline(screenRing(ring, t));
    }
    // The name at the first place where it fits on the screen clear of the names placed before:
    // inside a corner of a large box (top left, top right, bottom left, bottom right); beside a small
    // one (right, left), moved down a line at a time past the names of its neighbours.
    const QString name = QString::fromStdString(o.cell->info().name);
    const QSizeF size(fm.horizontalAdvance(name) + 6, fm.height() + 2);
    std::vector<QPointF> places;
    if (box.width() < 2 * size.width() || box.height() < 2 * size.height()) {
      for (int down = 0; down < 6; ++down)
        for (const QPointF& beside :
             {box.topRight() + QPointF(3, 0), box.topLeft() - QPointF(3 + size.width(), 0)})
          places.push_back(beside + QPointF(0, (down - 0.5) * size.height()));
    } else {
      places = {box.topLeft() + QPointF(3, 3), box.topRight() + QPointF(-3 - size.width(), 3),
                box.bottomLeft() + QPointF(3, -3 - size.height()),
                box.bottomRight() + QPointF(-3 - size.width(), -3 - size.height())};
    }
    for (const QPointF& c : places) {
      const QRectF label(c, size);
      if (!screen.contains(label) ||
          std::any_of(names.begin(), names.end(), [&label](const QRectF& n) { return n.intersects(label); }))
        continue;
      names.push_back(label);
      p.fillRect(label, back);
      p.setPen(colour);
      p.drawText(label, Qt::AlignCenter, name);
      break;
    }
  }
  p.restore();
}

void ChartView::paintOverlay(QPainter&, const charts::Viewport&) {}

void ChartView::resizeEvent(QResizeEvent*) {
  requestRender();
}

void ChartView::mousePressEvent(QMouseEvent* e) {
  if (e->button() != Qt::LeftButton) return;
  pressAt_ = lastMouse_ = e->position();
  dragged_ = false;
}

void ChartView::mouseMoveEvent(QMouseEvent* e) {
  const charts::Viewport v = viewport();
  const charts::LatLon at = v.toLatLon({e->position().x(), e->position().y()});
  emit cursorMoved(at);
  cursorAt_ = e->position();
  setUnderCursor(charts::cellsAt(cells_, at));
  if (!pressAt_ || !(e->buttons() & Qt::LeftButton)) return;
  if (!dragged_ && QLineF(*pressAt_, e->position()).length() < 4.0) return;  // a click, not yet a drag
  dragged_ = true;
  panBy(e->position() - *lastMouse_);
  lastMouse_ = e->position();
}

void ChartView::mouseReleaseEvent(QMouseEvent* e) {
  if (e->button() != Qt::LeftButton || !pressAt_) return;
  if (!dragged_ && !chartClicked(e->position())) {
    const charts::Viewport v = viewport();
    const charts::ScreenPoint at{e->position().x(), e->position().y()};
    try {
      emit picked(charts::pickFeatures(cells_, v, at), v.toLatLon(at));
    } catch (const std::exception&) {
      emit picked({}, v.toLatLon(at));  // no catalogue: an empty report rather than a crash
    }
  }
  pressAt_.reset();
  lastMouse_.reset();
  dragged_ = false;
}

void ChartView::leaveEvent(QEvent*) {
  cursorAt_.reset();
  setUnderCursor({});
}

void ChartView::wheelEvent(QWheelEvent* e) {
  const double steps = e->angleDelta().y() / 120.0;
  if (steps == 0) return;
  zoomAbout(std::pow(1.25, steps), e->position());
  e->accept();
}

}  // namespace reckoner::ui
