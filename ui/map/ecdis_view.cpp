// EcdisView's state and input: the view's geometry, following own ship, the helm handle, the mouse,
// the keys and the context menu. The painting is in ecdis_paint.cpp.
#include "ui/map/ecdis_view.h"

#include <QContextMenuEvent>
#include <QKeyEvent>
#include <QMouseEvent>
#include <algorithm>
#include <cmath>

#include "common/angles.h"
#include "common/units.h"
#include "geo/geodesic.h"
#include "io/text_format.h"
#include "ui/map/range_scale.h"

namespace reckoner::ui {
namespace {
QString latLonText(double latDeg, double lonDeg) {
  return QString::fromStdString(io::formatLatitude(latDeg) + ' ' + io::formatLongitude(lonDeg));
}
}  // namespace

EcdisView::EcdisView(QWidget* parent) : ChartView(parent) {
  setFocusPolicy(Qt::StrongFocus);
  setMouseTracking(true);
}

void EcdisView::setHistory(const SimHistory* history, const geo::LocalFrame& frame) {
  history_ = history;
  frame_ = frame;
  update();
}

void EcdisView::setOverlay(const OverlaySettings& s) {
  const bool rotate = s.courseUp != overlay_.courseUp;
  overlay_ = s;
  if (rotate && !s.courseUp) {
    const charts::Viewport v = viewport();
    setView(v.centre(), v.scaleDenominator(), 0.0);
    appliedRotation_ = 0.0;
  }
  if (rotate && s.courseUp) appliedRotation_ = 1e9;  // force the next frame to rotate
  emit overlayChanged(overlay_);
  frameUpdated();
}

void EcdisView::setSelectedTrack(std::optional<int> trackId) {
  if (selected_ == trackId) return;
  selected_ = trackId;
  emit trackSelected(selected_);
  update();
}

QPointF EcdisView::gridToWidget(double xM, double yM) const {
  if (!frame_) return {};
  const geo::GeoPoint g = frame_->toGeodetic({xM, yM});
  const charts::ScreenPoint s = viewport().toScreen({g.latDeg, g.lonDeg});
  return {s.x, s.y};
}

geo::GridPoint EcdisView::widgetToGrid(QPointF p) const {
  if (!frame_) return {};
  const charts::LatLon ll = viewport().toLatLon({p.x(), p.y()});
  return frame_->toLocal({ll.latDeg, ll.lonDeg});
}

EcdisView::Local EcdisView::localAt(double xM, double yM) const {
  constexpr double h = 50.0;
  Local l;
  l.p = gridToWidget(xM, yM);
  const QPointF px = gridToWidget(xM + h, yM), py = gridToWidget(xM, yM + h);
  l.a = (px.x() - l.p.x()) / h;
  l.c = (px.y() - l.p.y()) / h;
  l.b = (py.x() - l.p.x()) / h;
  l.d = (py.y() - l.p.y()) / h;
  return l;
}

std::pair<double, double> EcdisView::orderedCourseSpeed() const {
  if (pendingOrder_) return {pendingOrder_->course, pendingOrder_->speed};
  if (!history_ || history_->empty() || !frame_) return {0.0, 0.0};
  const sim::SimFrame& f = history_->latest().frame;
  const double gamma = frame_->gridInfo(f.truth.position).convergenceRad;
  if (f.order) return {wrapTwoPi(f.order->headingRad + gamma), f.order->speedMps};
  const auto& x = f.estimate.x;
  const double vx = x[est::drkf::kVelX], vy = x[est::drkf::kVelY];
  return {wrapTwoPi(bearingOf(vx, vy) + gamma), std::hypot(vx, vy)};
}

void EcdisView::requestOrder(double trueCourseRad, double speedMps) {
  pendingOrder_ = PendingOrder{wrapTwoPi(trueCourseRad), std::max(0.0, speedMps),
                               history_ && !history_->empty() ? history_->latest().sequence : 0};
  emit orderRequested(pendingOrder_->course, pendingOrder_->speed);
  update();
}

std::optional<QPointF> EcdisView::handlePosition() const {
  if (!history_ || history_->empty() || !frame_) return std::nullopt;
  const auto& x = history_->latest().frame.estimate.x;
  const Local own = localAt(x[est::drkf::kPosX], x[est::drkf::kPosY]);
  const auto [course, speed] = orderedCourseSpeed();
  const double gamma = frame_->gridInfo({x[est::drkf::kPosX], x[est::drkf::kPosY]}).convergenceRad;
  const double len = speed * overlay_.vectorMinutes * 60.0;
  const double g = course - gamma;
  return own.offset(len * std::sin(g), len * std::cos(g));
}

std::optional<int> EcdisView::trackNear(QPointF p, double tolPx) const {
  if (!history_ || history_->empty()) return std::nullopt;
  std::optional<int> best;
  double bestD = tolPx;
  for (const auto& t : history_->latest().frame.tracks) {
    const auto& x = t.estimate.x;
    const double d = QLineF(p, gridToWidget(x[est::ttkf::kTgtX], x[est::ttkf::kTgtY])).length();
    if (d <= bestD) {
      bestD = d;
      best = t.trackId;
    }
  }
  return best;
}

void EcdisView::frameUpdated() {
  if (pendingOrder_ && history_ && !history_->empty() && frame_) {
    // An order given here shows at once; the frames take over once one carries it (commands reach
    // the worker before its next step), or a few frames later in any case.
    const LiveFrame& live = history_->latest();
    const sim::SimFrame& f = live.frame;
    const double gamma = frame_->gridInfo(f.truth.position).convergenceRad;
    const bool carried = f.order &&
                         std::abs(angleDiff(f.order->headingRad + gamma, pendingOrder_->course)) < 1e-3 &&
                         std::abs(f.order->speedMps - pendingOrder_->speed) < 1e-6;
    if (carried || live.sequence > pendingOrder_->sequence + 5) pendingOrder_.reset();
  }
  if (history_ && !history_->empty() && frame_) {
    const auto& x = history_->latest().frame.estimate.x;
    const double ox = x[est::drkf::kPosX], oy = x[est::drkf::kPosY];
    const charts::Viewport v = viewport();
    double rotation = v.rotationRad();
    if (overlay_.courseUp) {
      // Course-up, stabilised: the chart turns when the course has moved more than 5 degrees.
      const double gamma = frame_->gridInfo({ox, oy}).convergenceRad;
      const double cog = wrapTwoPi(
          bearingOf(x[est::drkf::kVelX] + x[est::drkf::kCurX], x[est::drkf::kVelY] + x[est::drkf::kCurY]) +
          gamma);
      if (std::abs(angleDiff(cog, appliedRotation_)) > degToRad(5.0) || appliedRotation_ > 100.0) {
        rotation = cog;
        appliedRotation_ = cog;
      }
    }
    if (overlay_.followOwnShip) {
      // True motion with reset: recentre when own ship leaves the middle 60% of the screen.
      const QPointF p = gridToWidget(ox, oy);
      const bool outside = std::abs(p.x() - width() / 2.0) > 0.3 * width() ||
                           std::abs(p.y() - height() / 2.0) > 0.3 * height();
      if (outside || rotation != v.rotationRad()) {
        const geo::GeoPoint g = frame_->toGeodetic({ox, oy});
        setView({g.latDeg, g.lonDeg}, v.scaleDenominator(), rotation);
      }
    } else if (rotation != v.rotationRad()) {
      setView(v.centre(), v.scaleDenominator(), rotation);
    }
  }
  update();
}

void EcdisView::centreOnOwnShip() {
  if (!history_ || history_->empty() || !frame_) return;
  const auto& x = history_->latest().frame.estimate.x;
  const geo::GeoPoint g = frame_->toGeodetic({x[est::drkf::kPosX], x[est::drkf::kPosY]});
  const charts::Viewport v = viewport();
  setView({g.latDeg, g.lonDeg}, v.scaleDenominator(), v.rotationRad());
}

void EcdisView::fitOwnShipAndTargets() {
  if (!history_ || history_->empty() || !frame_) return;
  const sim::SimFrame& f = history_->latest().frame;
  const auto& x = f.estimate.x;
  const geo::GeoPoint own = frame_->toGeodetic({x[est::drkf::kPosX], x[est::drkf::kPosY]});
  std::vector<charts::LatLon> points{{own.latDeg, own.lonDeg}};
  for (std::size_t i = 0; i < f.targets.size(); ++i) {
    if (i < f.targetPresent.size() && !f.targetPresent[i]) continue;
    const geo::GeoPoint g = frame_->toGeodetic(f.targets[i].position);
    points.push_back({g.latDeg, g.lonDeg});
  }
  // Centred on the middle of them all, so the scale is as large as it can be.
  double lat0 = own.latDeg, lat1 = own.latDeg, lon0 = own.lonDeg, lon1 = own.lonDeg;
  for (const auto& p : points) {
    lat0 = std::min(lat0, p.latDeg);
    lat1 = std::max(lat1, p.latDeg);
    lon0 = std::min(lon0, p.lonDeg);
    lon1 = std::max(lon1, p.lonDeg);
  }
  const charts::LatLon centre{0.5 * (lat0 + lat1), 0.5 * (lon0 + lon1)};
  const double marginPx = 40.0;
  double chosen = 0.0;
  for (const double scale : {25000.0, 50000.0, 90000.0, 180000.0, 350000.0, 700000.0}) {
    chosen = scale;
    const charts::Viewport v(centre, scale, std::max(width(), 16), std::max(height(), 16), 0.28,
                             viewport().rotationRad());
    const bool all = std::all_of(points.begin(), points.end(), [&](const charts::LatLon& p) {
      const charts::ScreenPoint s = v.toScreen(p);
      return s.x >= marginPx && s.y >= marginPx && s.x <= v.width() - marginPx &&
             s.y <= v.height() - marginPx;
    });
    if (all) break;
  }
  setView(centre, chosen, viewport().rotationRad());
}

void EcdisView::setRangeNm(double rangeNm) {
  if (!(rangeNm > 0.0) || !std::isfinite(rangeNm)) return;
  charts::LatLon centre = viewport().centre();
  if (history_ && !history_->empty() && frame_) {
    const auto& x = history_->latest().frame.estimate.x;
    const geo::GeoPoint own = frame_->toGeodetic({x[est::drkf::kPosX], x[est::drkf::kPosY]});
    centre = {own.latDeg, own.lonDeg};
  }
  setView(centre, scaleForRange(rangeNm, width(), height()), viewport().rotationRad());
}

void EcdisView::stepRange(int step) {
  setRangeNm(kRangeScales[steppedRangeIndex(displayedRangeNm(viewport()), step)].rangeNm);
}

QString EcdisView::cursorText(QPointF at) const {
  const charts::LatLon ll = viewport().toLatLon({at.x(), at.y()});
  QString s = latLonText(ll.latDeg, ll.lonDeg);
  if (history_ && !history_->empty() && frame_) {
    // From own ship along the geodesic: the grid is only valid near its zone, and the cursor may be
    // anywhere on the chart.
    const auto& x = history_->latest().frame.estimate.x;
    const geo::GeoPoint own = frame_->toGeodetic({x[est::drkf::kPosX], x[est::drkf::kPosY]});
    const geo::RangeBearing rb = geo::rangeBearing(own, {ll.latDeg, ll.lonDeg});
    if (std::isfinite(rb.rangeM))
      s += QStringLiteral("   %1° %2 NM")
               .arg(radToDeg(rb.trueBearingRad), 5, 'f', 1, QChar('0'))
               .arg(metresToNm(rb.rangeM), 0, 'f', 2);
  }
  return s;
}

void EcdisView::mousePressEvent(QMouseEvent* e) {
  setFocus();
  if (e->button() == Qt::LeftButton && addTargetFrom_) {
    const geo::GridPoint to = widgetToGrid(e->position());
    const double s = overlay_.vectorMinutes * 60.0;
    const double vx = (to.xM - addTargetFrom_->xM) / s, vy = (to.yM - addTargetFrom_->yM) / s;
    if (steerTarget_ && frame_) {
      const double gamma = frame_->gridInfo(*addTargetFrom_).convergenceRad;
      emit steerTargetRequested(*steerTarget_, wrapTwoPi(bearingOf(vx, vy) + gamma), std::hypot(vx, vy));
    } else {
      emit addTargetRequested(addTargetFrom_->xM, addTargetFrom_->yM, vx, vy);
    }
    steerTarget_.reset();
    addTargetFrom_.reset();
    addTargetTo_.reset();
    update();
    return;
  }
  if (e->button() == Qt::LeftButton) {
    if (const auto h = handlePosition(); h && QLineF(*h, e->position()).length() <= kHandleRadiusPx + 3.0) {
      draggingHandle_ = true;
      handleDrag_ = e->position();
      update();
      return;
    }
    if (e->modifiers() & Qt::ControlModifier) {
      // Steer towards the point at the ordered speed.
      if (history_ && !history_->empty() && frame_) {
        const auto& x = history_->latest().frame.estimate.x;
        const geo::GridPoint g = widgetToGrid(e->position());
        const double ox = x[est::drkf::kPosX], oy = x[est::drkf::kPosY];
        const double gamma = frame_->gridInfo({ox, oy}).convergenceRad;
        requestOrder(wrapTwoPi(bearingOf(g.xM - ox, g.yM - oy) + gamma), orderedCourseSpeed().second);
      }
      return;
    }
    if (const auto t = trackNear(e->position())) setSelectedTrack(t);
  }
  ChartView::mousePressEvent(e);
}

void EcdisView::mouseMoveEvent(QMouseEvent* e) {
  cursor_ = e->position();
  emit cursorReadout(cursorText(e->position()));
  if (addTargetFrom_) addTargetTo_ = e->position();
  if (draggingHandle_) {
    handleDrag_ = e->position();
    update();
    return;
  }
  ChartView::mouseMoveEvent(e);
  update();
}

void EcdisView::mouseReleaseEvent(QMouseEvent* e) {
  if (draggingHandle_ && e->button() == Qt::LeftButton) {
    draggingHandle_ = false;
    handleDrag_.reset();
    if (history_ && !history_->empty() && frame_) {
      const auto& x = history_->latest().frame.estimate.x;
      const double ox = x[est::drkf::kPosX], oy = x[est::drkf::kPosY];
      const geo::GridPoint g = widgetToGrid(e->position());
      const geo::GridInfo gi = frame_->gridInfo({ox, oy});
      const double course = wrapTwoPi(bearingOf(g.xM - ox, g.yM - oy) + gi.convergenceRad);
      const double speed = std::hypot(g.xM - ox, g.yM - oy) / gi.scale / (overlay_.vectorMinutes * 60.0);
      requestOrder(course, speed);
    }
    update();
    return;
  }
  ChartView::mouseReleaseEvent(e);
}

QMenu* EcdisView::buildContextMenu(QPointF at) {
  auto* menu = new QMenu(this);
  menu->setAttribute(Qt::WA_DeleteOnClose);
  const geo::GridPoint g = widgetToGrid(at);
  menu->addAction(tr("Add target here…"), this,
                  [this, g] {
                    addTargetFrom_ = g;
                    addTargetTo_.reset();
                    update();
                  })
      ->setObjectName(QStringLiteral("addTarget"));
  menu->addAction(tr("Acquire plot here"), this, [this, g] { emit acquireRequested(g.xM, g.yM); })
      ->setObjectName(QStringLiteral("acquire"));
  if (const auto t = trackNear(at, 20.0)) {
    const int id = *t;
    menu->addAction(tr("Cancel track %1").arg(id), this, [this, id] { emit cancelTrackRequested(id); })
        ->setObjectName(QStringLiteral("cancelTrack"));
    menu->addAction(tr("Select track %1").arg(id), this, [this, id] { setSelectedTrack(id); })
        ->setObjectName(QStringLiteral("selectTrack"));
    // Simulation control: give the target this track follows a new course and speed (drag its vector).
    const auto& tracks = history_->latest().frame.tracks;
    const auto it =
        std::find_if(tracks.begin(), tracks.end(), [id](const auto& tr) { return tr.trackId == id; });
    if (it != tracks.end() && it->targetId >= 0) {
      const int target = it->targetId;
      const geo::GridPoint from{it->estimate.x[est::ttkf::kTgtX], it->estimate.x[est::ttkf::kTgtY]};
      // One numbering on screen: the track's. The simulated vessel behind it has its own id, which the
      // operator never sees elsewhere.
      menu->addAction(tr("Steer the vessel of track %1 (simulation)…").arg(id), this,
                      [this, target, from, id] {
                        steerTarget_ = target;
                        steerTrack_ = id;
                        addTargetFrom_ = from;
                        addTargetTo_.reset();
                        update();
                      })
          ->setObjectName(QStringLiteral("steerTarget"));
    }
  }
  menu->addSeparator();
  menu->addAction(tr("Steer towards here"), this, [this, g] {
    if (!history_ || history_->empty() || !frame_) return;
    const auto& x = history_->latest().frame.estimate.x;
    const double ox = x[est::drkf::kPosX], oy = x[est::drkf::kPosY];
    const double gamma = frame_->gridInfo({ox, oy}).convergenceRad;
    requestOrder(wrapTwoPi(bearingOf(g.xM - ox, g.yM - oy) + gamma), orderedCourseSpeed().second);
  });
  menu->addAction(tr("EBL and VRM to here"), this,
                  [this, g] {
                    if (!history_ || history_->empty() || !frame_) return;
                    const auto& x = history_->latest().frame.estimate.x;
                    const double ox = x[est::drkf::kPosX], oy = x[est::drkf::kPosY];
                    const geo::GridInfo gi = frame_->gridInfo({ox, oy});
                    OverlaySettings s = overlay_;
                    s.eblBearingRad = wrapTwoPi(bearingOf(g.xM - ox, g.yM - oy) + gi.convergenceRad);
                    s.vrmRangeM = std::hypot(g.xM - ox, g.yM - oy) / gi.scale;
                    setOverlay(s);
                  })
      ->setObjectName(QStringLiteral("eblVrm"));
  if (overlay_.eblBearingRad || overlay_.vrmRangeM)
    menu->addAction(tr("Clear EBL and VRM"), this, [this] {
      OverlaySettings s = overlay_;
      s.eblBearingRad.reset();
      s.vrmRangeM.reset();
      setOverlay(s);
    });
  menu->addSeparator();
  addChartActions(menu, at);  // Zoom to chart NAME (the cells here), Show all charts
  menu->addAction(tr("Pick report"), this, [this, at] { emit pickRequested(at); })
      ->setObjectName(QStringLiteral("pick"));
  return menu;
}

void EcdisView::contextMenuEvent(QContextMenuEvent* e) {
  buildContextMenu(e->pos())->popup(e->globalPos());
}

void EcdisView::keyPressEvent(QKeyEvent* e) {
  if (e->key() == Qt::Key_Escape && addTargetFrom_) {
    steerTarget_.reset();
    addTargetFrom_.reset();
    addTargetTo_.reset();
    update();
    return;
  }
  if (e->key() == Qt::Key_Plus || e->key() == Qt::Key_Equal || e->key() == Qt::Key_Minus) {
    stepRange(e->key() == Qt::Key_Minus ? 1 : -1);  // '+' zooms in to a shorter range
    return;
  }
  if (!history_ || history_->empty()) {
    ChartView::keyPressEvent(e);
    return;
  }
  auto [course, speed] = orderedCourseSpeed();
  const double step = (e->modifiers() & Qt::ShiftModifier) ? 1.0 : 5.0;
  switch (e->key()) {
    case Qt::Key_Left:
      course = wrapTwoPi(course - degToRad(step));
      break;
    case Qt::Key_Right:
      course = wrapTwoPi(course + degToRad(step));
      break;
    case Qt::Key_Up:
      speed += 0.5 * kMpsPerKnot;
      break;
    case Qt::Key_Down:
      speed = std::max(0.0, speed - 0.5 * kMpsPerKnot);
      break;
    default:
      ChartView::keyPressEvent(e);
      return;
  }
  requestOrder(course, speed);
}

}  // namespace reckoner::ui
