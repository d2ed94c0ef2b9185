// EcdisView's state and input: the view's geometry, following own ship, the helm handle, the mouse,
// the keys and the context menu. The painting is in ecdis_paint.cpp.
#include "ui/map/ecdis_view.h"

#include <QContextMenuEvent>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QWheelEvent>
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

EcdisView::EcdisView(QWidget* parent) : ChartView(parent), routeOverlay_(new RouteOverlay(this)) {
  setFocusPolicy(Qt::StrongFocus);
  setMouseTracking(true);
  connect(routeOverlay_, &RouteOverlay::changed, this, qOverload<>(&QWidget::update));
}

void EcdisView::setHistory(const SimHistory* history, const geo::LocalFrame& frame) {
  history_ = history;
  frame_ = frame;
  pendingZones_.reset();
  update();
}

void EcdisView::setOverlay(const OverlaySettings& s) {
  const OverlaySettings before = overlay_;
  overlay_ = s;
  if (s.orientation != before.orientation) rotationStale_ = true;
  // A new place for own ship (or following again) moves the view now; other changes wait for own ship
  // to leave the middle (true motion).
  const bool place = s.motion != before.motion || s.offCentred != before.offCentred ||
                     (s.followOwnShip && !before.followOwnShip) || s.ccrpFromBowM != before.ccrpFromBowM ||
                     s.ccrpToStarboardM != before.ccrpToStarboardM;
  emit overlayChanged(overlay_);
  if (haveOwnShip()) {
    applyMotion(wantedRotation(), place);
    emitCcrpOffset();
  } else if (s.orientation == Orientation::NorthUp && viewport().rotationRad() != 0.0) {
    const charts::Viewport v = viewport();
    setView(v.centre(), v.scaleDenominator(), 0.0);
  }
  emitOrderShown();
  update();
}

void EcdisView::setUnits(const DisplayUnits& units) {
  units_ = units;
  update();
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
  if (!haveOwnShip()) return {0.0, 0.0};
  const sim::SimFrame& f = history_->latest().frame;
  const double gamma = frame_->gridInfo(f.truth.position).convergenceRad;
  if (f.order) return {wrapTwoPi(f.order->headingRad + gamma), f.order->speedMps};
  const auto& x = f.estimate.x;
  const double vx = x[est::drkf::kVelX], vy = x[est::drkf::kVelY];
  return {wrapTwoPi(bearingOf(vx, vy) + gamma), std::hypot(vx, vy)};
}

void EcdisView::requestOrder(double trueCourseRad, double speedMps) {
  if (history_ && history_->latest().live) return;  // Live mode: the real ship is steered on the bridge
  if (!std::isfinite(trueCourseRad) || !std::isfinite(speedMps)) return;
  pendingOrder_ = PendingOrder{wrapTwoPi(trueCourseRad), std::max(0.0, speedMps),
                               history_ && !history_->empty() ? history_->latest().sequence : 0};
  emit orderRequested(pendingOrder_->course, pendingOrder_->speed);
  emitOrderShown();
  update();
}

void EcdisView::emitOrderShown() {
  const auto shown = orderedCourseSpeed();
  if (lastOrderShown_ && std::abs(angleDiff(lastOrderShown_->first, shown.first)) < 1e-9 &&
      std::abs(lastOrderShown_->second - shown.second) < 1e-9)
    return;
  lastOrderShown_ = shown;
  emit orderShown(shown.first, shown.second);
}

std::optional<QPointF> EcdisView::handleAt(double minutes) const {
  if (!haveOwnShip() || history_->latest().live) return std::nullopt;  // a live ship takes no helm orders
  const geo::GridPoint c = ccrpGrid();
  const Local own = localAt(c.xM, c.yM);
  const auto [course, speed] = orderedCourseSpeed();
  const geo::GridInfo gi = frame_->gridInfo(c);
  const double len = speed * minutes * 60.0 * gi.scale;  // grid metres
  const double g = course - gi.convergenceRad;
  return own.offset(len * std::sin(g), len * std::cos(g));
}

double EcdisView::handleMinutes() const {
  double minutes = overlay_.vectorMinutes;
  if (!haveOwnShip()) return minutes;
  // Shortened only while own ship is on screen: a handle off screen with own ship is of no use either.
  const QRectF inside = QRectF(rect()).adjusted(24.0, 24.0, -24.0, -24.0);
  if (!inside.contains(ccrpWidget())) return minutes;
  while (minutes > 0.5) {
    const auto h = handleAt(minutes);
    if (!h || inside.contains(*h)) break;
    minutes = std::max(0.5, minutes / 2.0);
  }
  return minutes;
}

std::optional<QPointF> EcdisView::handlePosition() const {
  return handleAt(handleMinutes());
}

std::pair<double, double> EcdisView::bearingRangeFromCcrp(const geo::GridPoint& g) const {
  const geo::GridPoint c = ccrpGrid();
  const geo::GridInfo gi = frame_->gridInfo(c);
  return {wrapTwoPi(bearingOf(g.xM - c.xM, g.yM - c.yM) + gi.convergenceRad),
          std::hypot(g.xM - c.xM, g.yM - c.yM) / gi.scale};
}

std::pair<double, double> EcdisView::orderAt(QPointF p, double minutes) const {
  const auto [course, rangeM] = bearingRangeFromCcrp(widgetToGrid(p));
  return {course, rangeM / (minutes * 60.0)};
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
  if (pendingZones_ && history_ && !history_->empty() && history_->latest().frame.zones == *pendingZones_)
    pendingZones_.reset();
  if (pendingOrder_ && haveOwnShip()) {
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
  if (haveOwnShip()) {
    lastHeadingRad_ = headingGridRad();
    applyMotion(wantedRotation(), false);
    emitCcrpOffset();
    if (cursor_) emit cursorReadout(cursorText(*cursor_));  // own ship moved: the readout with it
  }
  emitOrderShown();
  update();
}

void EcdisView::emitCcrpOffset() {
  const geo::GridPoint off = ccrpOffsetGrid();
  if (lastCcrpOffset_ && lastCcrpOffset_->xM == off.xM && lastCcrpOffset_->yM == off.yM) return;
  lastCcrpOffset_ = off;
  emit ccrpOffsetChanged(off.xM, off.yM, frame_->gridInfo(ccrpGrid()).convergenceRad);
}

void EcdisView::centreOnOwnShip() {
  if (!overlay_.followOwnShip) {
    OverlaySettings s = overlay_;
    s.followOwnShip = true;
    setOverlay(s);  // places own ship
    return;
  }
  if (haveOwnShip()) applyMotion(wantedRotation(), true);
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
  const charts::Viewport v = viewport();
  setView(v.centre(), scaleForRange(rangeNm, width(), height()), v.rotationRad());
  // From own ship: at its place while following, else at the centre.
  if (haveOwnShip())
    placeAt(ccrpGrid(), overlay_.followOwnShip ? ownShipPlace() : QPointF(width() / 2.0, height() / 2.0),
            v.rotationRad());
}

void EcdisView::stepRange(int step) {
  setRangeNm(kRangeScales[steppedRangeIndex(displayedRangeNm(viewport()), step)].rangeNm);
}

QString EcdisView::fromOwnShipText(charts::LatLon where) const {
  if (!haveOwnShip()) return {};
  // From own ship's CCRP along the geodesic: the grid is only valid near its zone, and the point may be
  // anywhere on the chart.
  const geo::GeoPoint own = frame_->toGeodetic(ccrpGrid());
  const geo::RangeBearing rb = geo::rangeBearing(own, {where.latDeg, where.lonDeg});
  if (!std::isfinite(rb.rangeM) || !std::isfinite(rb.trueBearingRad)) return {};
  return formatBearing(rb.trueBearingRad) + QLatin1Char(' ') + formatDistance(rb.rangeM, units_);
}

QString EcdisView::cursorText(QPointF at) const {
  const charts::LatLon ll = viewport().toLatLon({at.x(), at.y()});
  QString s = latLonText(ll.latDeg, ll.lonDeg);
  if (const QString from = fromOwnShipText(ll); !from.isEmpty()) s += QStringLiteral("   ") + from;
  return s;
}

void EcdisView::setTrialMode(bool on) {
  trialMode_ = on;
  update();
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
  if (e->button() == Qt::LeftButton && routeOverlay_->press(e->position(), viewport())) return;
  if (e->button() == Qt::LeftButton && routeOverlay_->editing()) {  // a click adds a waypoint, a drag pans
    ChartView::mousePressEvent(e);
    return;
  }
  if (e->button() == Qt::LeftButton) {
    if (const auto h = handlePosition(); h && QLineF(*h, e->position()).length() <= kHandleRadiusPx + 3.0) {
      draggingHandle_ = true;
      dragMinutes_ = handleMinutes();
      handleDrag_ = e->position();
      update();
      return;
    }
    if (e->modifiers() & Qt::ControlModifier) {
      // Steer towards the point at the ordered speed.
      if (haveOwnShip())
        requestOrder(bearingRangeFromCcrp(widgetToGrid(e->position())).first, orderedCourseSpeed().second);
      return;
    }
    if (const auto t = trackNear(e->position())) {
      setSelectedTrack(t);
    } else if (const auto m = polarMap()) {
      // A guard zone's edge is dragged; its middle only with Shift (a plain drag there pans).
      const ZoneHit hit = hitZone(shownZones(), e->position(), *m);
      if (hit.zone >= 0 && (hit.edge != ZoneEdge::Inside || (e->modifiers() & Qt::ShiftModifier)) &&
          zoneEditor_.press(shownZones(), e->position(), *m)) {
        update();
        return;
      }
    }
  }
  ChartView::mousePressEvent(e);
}

void EcdisView::mouseMoveEvent(QMouseEvent* e) {
  cursor_ = e->position();
  emit cursorReadout(cursorText(e->position()));
  if (addTargetFrom_) addTargetTo_ = e->position();
  if (routeOverlay_->move(e->position(), viewport())) return;
  if (draggingHandle_) {
    handleDrag_ = e->position();
    if (trialMode_ && haveOwnShip()) {  // the trial follows the drag
      const auto [course, speed] = orderAt(e->position(), dragMinutes_);
      emit trialRequested(course, speed);
    }
    update();
    return;
  }
  if (const auto m = polarMap(); m && zoneEditor_.move(e->position(), *m)) {
    update();
    return;
  }
  const charts::LatLon before = viewport().centre();
  ChartView::mouseMoveEvent(e);
  const charts::LatLon after = viewport().centre();
  if ((e->buttons() & Qt::LeftButton) && overlay_.followOwnShip &&
      (after.latDeg != before.latDeg || after.lonDeg != before.lonDeg)) {
    // The operator pans: the view stops following own ship (it would snap back at the next frame).
    OverlaySettings s = overlay_;
    s.followOwnShip = false;
    setOverlay(s);
  }
  update();
}

void EcdisView::mouseReleaseEvent(QMouseEvent* e) {
  if (e->button() == Qt::LeftButton && routeOverlay_->release(e->position(), viewport())) return;
  if (draggingHandle_ && e->button() == Qt::LeftButton) {
    draggingHandle_ = false;
    handleDrag_.reset();
    if (haveOwnShip()) {
      const auto [course, speed] = orderAt(e->position(), dragMinutes_);
      if (trialMode_)
        emit trialRequested(course, speed);
      else
        requestOrder(course, speed);
    }
    update();
    return;
  }
  if (zoneEditor_.dragging() && e->button() == Qt::LeftButton) {
    if (const auto m = polarMap())
      if (auto zones = zoneEditor_.release(e->position(), *m)) editZones(*zones);
    update();
    return;
  }
  ChartView::mouseReleaseEvent(e);
}

bool EcdisView::chartClicked(QPointF at) {
  return routeOverlay_->click(at, viewport());
}

void EcdisView::wheelEvent(QWheelEvent* e) {
  // In relative motion the zoom keeps own ship where it is (it is put back there at every frame).
  const double steps = e->angleDelta().y() / 120.0;
  if (steps != 0 && overlay_.followOwnShip && overlay_.motion == Motion::Relative && haveOwnShip()) {
    zoomAbout(std::pow(1.25, steps), ccrpWidget());
    e->accept();
    return;
  }
  ChartView::wheelEvent(e);
}

QMenu* EcdisView::buildContextMenu(QPointF at) {
  auto* menu = new QMenu(this);
  menu->setAttribute(Qt::WA_DeleteOnClose);
  routeOverlay_->addContextActions(menu, at, viewport());  // in route edit mode: the route's first
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
  addZoneActions(menu, at);
  menu->addSeparator();
  // (The grid point, not the widget point: in relative motion the chart moves under the menu.)
  menu->addAction(tr("Steer towards here"), this, [this, g] {
    if (haveOwnShip()) requestOrder(bearingRangeFromCcrp(g).first, orderedCourseSpeed().second);
  });
  menu->addAction(tr("EBL and VRM to here"), this,
                  [this, g] {
                    if (!haveOwnShip()) return;
                    // From the CCRP: the EBL's bearing and the VRM's radius are the cursor readout's.
                    const auto [bearing, rangeM] = bearingRangeFromCcrp(g);
                    OverlaySettings s = overlay_;
                    s.eblBearingRad = bearing;
                    s.vrmRangeM = rangeM;
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
  if (routeOverlay_->key(e->key())) return;  // route edit mode: Esc leaves it, Delete a waypoint
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
