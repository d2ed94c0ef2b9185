#include "ui/map/chart_view.h"

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

namespace reckoner::ui {

ChartView::ChartView(QWidget* parent) : QWidget(parent) {
  qRegisterMetaType<charts::Viewport>();
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
  requestRender();
}

void ChartView::setSettings(const charts::MarinerSettings& settings) {
  settings_ = settings;
  requestRender();
}

void ChartView::setView(charts::LatLon centre, double scaleDenominator, double rotationRad) {
  centre_ = {std::clamp(centre.latDeg, -84.0, 84.0), std::remainder(centre.lonDeg, 360.0)};
  scale_ = std::clamp(scaleDenominator, 500.0, 2.0e7);
  rotation_ = std::isfinite(rotationRad) ? rotationRad : 0.0;
  requestRender();
  emit viewChanged(viewport());
}

charts::Viewport ChartView::viewport() const {
  return charts::Viewport(centre_, scale_, std::max(width(), 16), std::max(height(), 16), 0.28, rotation_);
}

void ChartView::zoomAbout(double factor, QPointF anchor) {
  if (!(factor > 0) || !std::isfinite(factor)) return;
  const charts::Viewport before = viewport();
  const charts::LatLon fixed = before.toLatLon({anchor.x(), anchor.y()});
  const double newScale = std::clamp(scale_ / factor, 500.0, 2.0e7);
  // Put `fixed` back under the anchor: the centre moves along the anchor-centre line by the zoom.
  const charts::Viewport trial(centre_, newScale, before.width(), before.height(), 0.28, rotation_);
  const charts::ScreenPoint now = trial.toScreen(fixed);
  const charts::LatLon newCentre = trial.toLatLon(
      {0.5 * before.width() + (now.x - anchor.x()), 0.5 * before.height() + (now.y - anchor.y())});
  setView(newCentre, newScale, rotation_);
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

void ChartView::onRendered(const QImage& image, const charts::Viewport& view, quint64 generation, double ms) {
  // The worker answers in request order and skips superseded requests, so each image is newer than
  // the one shown (not necessarily the latest requested: a finished render is shown until the next).
  image_ = image;
  imageView_ = view;
  imageGeneration_ = generation;
  lastRenderMs_ = ms;
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
  paintOverlay(p, now);
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
  emit cursorMoved(v.toLatLon({e->position().x(), e->position().y()}));
  if (!pressAt_ || !(e->buttons() & Qt::LeftButton)) return;
  if (!dragged_ && QLineF(*pressAt_, e->position()).length() < 4.0) return;  // a click, not yet a drag
  dragged_ = true;
  panBy(e->position() - *lastMouse_);
  lastMouse_ = e->position();
}

void ChartView::mouseReleaseEvent(QMouseEvent* e) {
  if (e->button() != Qt::LeftButton || !pressAt_) return;
  if (!dragged_) {
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

void ChartView::wheelEvent(QWheelEvent* e) {
  const double steps = e->angleDelta().y() / 120.0;
  if (steps == 0) return;
  zoomAbout(std::pow(1.25, steps), e->position());
  e->accept();
}

}  // namespace reckoner::ui
