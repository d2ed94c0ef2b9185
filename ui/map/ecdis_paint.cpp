// EcdisView's painting: the navigation overlays drawn over the chart at every repaint, from the latest
// LiveFrame and the run's history (SimHistory). Input handling and the view's state are in
// ecdis_view.cpp, the radar overlay in ecdis_radar.cpp.
#include <QDateTime>
#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>
#include <cstring>

#include "common/angles.h"
#include "common/units.h"
#include "estimation/chi_square.h"
#include "ui/map/ecdis_view.h"
#include "ui/map/label_placer.h"
#include "ui/map/range_scale.h"

namespace reckoner::ui {
namespace {
constexpr double kSymbolMm = 6.0;        // own-ship and target symbols, as S-52 draws them
constexpr double kPxPerMm = 1.0 / 0.28;  // pixels per millimetre at the S-52 reference pitch

double chi2Scale95() {
  static const double k = std::sqrt(est::chiSquareQuantile(0.95, 2.0));
  return k;
}

/// A track's symbol by status (IEC 62388): tentative a broken circle, confirmed a full circle, lost a
/// diamond crossed out.
void paintTrackSymbol(QPainter& p, track::TrackStatus status, QPointF at, double r, const QPen& pen) {
  p.setPen(pen);
  switch (status) {
    case track::TrackStatus::Tentative:
      for (int q = 0; q < 4; ++q)
        p.drawArc(QRectF(at.x() - r, at.y() - r, 2 * r, 2 * r), (q * 90 + 20) * 16, 50 * 16);
      break;
    case track::TrackStatus::Confirmed:
      p.drawEllipse(at, r, r);
      break;
    case track::TrackStatus::Lost: {
      QPolygonF diamond{
          {at.x(), at.y() - r}, {at.x() + r, at.y()}, {at.x(), at.y() + r}, {at.x() - r, at.y()}};
      p.drawPolygon(diamond);
      p.drawLine(at + QPointF(-r, -r), at + QPointF(r, r));
      p.drawLine(at + QPointF(-r, r), at + QPointF(r, -r));
      break;
    }
  }
}

/// The selected target: square corner brackets at `half` pixels from its centre.
void paintSelectionBrackets(QPainter& p, QPointF at, double half, const QPen& pen) {
  const double k = 5.0;
  p.setPen(pen);
  for (int sx : {-1, 1})
    for (int sy : {-1, 1}) {
      const QPointF c0 = at + QPointF(sx * half, sy * half);
      p.drawLine(c0, c0 - QPointF(sx * k, 0));
      p.drawLine(c0, c0 - QPointF(0, sy * k));
    }
}
}  // namespace

QPolygonF EcdisView::ellipse95(const Local& at, double pxx, double pxy, double pyy, int points) {
  est::Mat<2> P;
  P << pxx, pxy, pxy, pyy;
  const Eigen::SelfAdjointEigenSolver<est::Mat<2>> eig(P);
  const double k = chi2Scale95();
  const double a = k * std::sqrt(std::max(0.0, eig.eigenvalues()[0]));
  const double b = k * std::sqrt(std::max(0.0, eig.eigenvalues()[1]));
  QPolygonF poly;
  for (int i = 0; i <= points; ++i) {
    const double th = kTwoPi * i / points;
    const est::Vec<2> u = eig.eigenvectors() * est::Vec<2>(a * std::cos(th), b * std::sin(th));
    poly << at.offset(u[0], u[1]);
  }
  return poly;
}

QColor EcdisView::colour(const char* role) const {
  const charts::Palette pal = settings().palette;
  const int i = pal == charts::Palette::Day ? 0 : pal == charts::Palette::Dusk ? 1 : 2;
  struct Entry {
    const char* role;
    QRgb c[3];
  };
  static const Entry kTable[] = {
      {"own", {qRgb(0, 0, 0), qRgb(230, 230, 230), qRgb(160, 160, 120)}},
      {"order", {qRgb(200, 60, 0), qRgb(255, 140, 60), qRgb(170, 90, 30)}},
      {"truth", {qRgb(120, 120, 120), qRgb(150, 150, 150), qRgb(80, 80, 80)}},
      {"ellipse", {qRgb(0, 90, 200), qRgb(90, 160, 255), qRgb(50, 90, 150)}},
      {"target", {qRgb(0, 130, 0), qRgb(80, 220, 80), qRgb(40, 130, 40)}},
      {"ais", {qRgb(20, 20, 20), qRgb(210, 210, 210), qRgb(150, 150, 150)}},
      {"danger", {qRgb(220, 0, 0), qRgb(255, 60, 60), qRgb(170, 30, 30)}},
      {"plot", {qRgb(200, 120, 0), qRgb(255, 190, 60), qRgb(150, 100, 30)}},
      {"tool", {qRgb(120, 0, 140), qRgb(220, 120, 230), qRgb(130, 70, 140)}},
      {"zone", {qRgb(190, 110, 0), qRgb(240, 170, 60), qRgb(150, 100, 40)}},
      {"text", {qRgb(0, 0, 0), qRgb(230, 230, 230), qRgb(150, 150, 130)}},
      {"panel", {qRgb(255, 255, 255), qRgb(30, 30, 40), qRgb(10, 10, 12)}},
      {"gps", {qRgb(0, 120, 120), qRgb(60, 220, 220), qRgb(40, 120, 120)}},
      {"loran", {qRgb(150, 0, 150), qRgb(230, 110, 230), qRgb(120, 60, 120)}},
      {"seed002", {qRgb(200, 0, 90), qRgb(255, 110, 170), qRgb(150, 50, 90)}},
      // Routes: S-52's planned route (PLRTE, red-orange) for the active one, the alternate planned
      // route's orange (APLRT) for one being planned or edited.
      {"routeActive", {qRgb(225, 60, 20), qRgb(255, 110, 70), qRgb(170, 60, 30)}},
      {"route", {qRgb(240, 130, 0), qRgb(255, 170, 60), qRgb(160, 100, 30)}},
  };
  for (const Entry& e : kTable)
    if (std::strcmp(e.role, role) == 0) return QColor::fromRgb(e.c[i]);
  return Qt::magenta;
}

void EcdisView::paintOverlay(QPainter& p, const charts::Viewport& view) {
  p.setRenderHint(QPainter::Antialiasing, true);
  labelObstacles_.clear();
  pendingLabels_.clear();
  if (haveOwnShip() && overlay_.showRadarPicture) paintRadarPicture(p);
  paintRoute(p);  // over the radar picture, under own ship and the targets
  if (haveOwnShip()) {
    const geo::GridPoint c = ccrpGrid();
    const Local ccrp = localAt(c.xM, c.yM);
    paintLookAhead(p);
    paintZones(p);
    paintRings(p, ccrp);
    if (overlay_.showRadarEchoes) paintRadarEchoes(p);
    if (overlay_.showPlots) paintPlots(p);
    paintTargets(p);
    paintAis(p);  // with the AIS layer off, the search and rescue devices in distress alone
    paintTrial(p);
    paintOwnShip(p);
  }
  // The boxes first (labels keep out of them), the labels last.
  paintScaleBar(p, view);
  labelObstacles_.push_back(paintModes(p));
  if (const QRectF box = paintReadouts(p); !box.isEmpty()) labelObstacles_.push_back(box);
  paintLabels(p);
}

void EcdisView::paintRings(QPainter& p, const Local& own) {
  // Range rings, the VRM and the EBL from the CCRP.
  const double pxm = own.pxPerMetre();
  QPen pen(colour("tool"), 1.0, Qt::DotLine);
  p.setPen(pen);
  p.setBrush(Qt::NoBrush);
  if (overlay_.showRings) {
    const double range = displayedRangeNm(viewport()), interval = ringIntervalNm(range);
    const int rings = static_cast<int>(std::floor(range / interval + 1e-6));
    for (int i = 1; i <= rings; ++i) {
      const double r = nmToMetres(interval * i) * pxm;
      p.drawEllipse(own.p, r, r);
    }
  }
  const double gamma = frame_->gridInfo(ccrpGrid()).convergenceRad;
  p.setPen(QPen(colour("tool"), 1.5, Qt::DashLine));
  if (overlay_.vrmRangeM) {
    const double r = *overlay_.vrmRangeM * pxm;
    p.drawEllipse(own.p, r, r);
  }
  if (overlay_.eblBearingRad) {
    const double g = *overlay_.eblBearingRad - gamma;
    const double len = 2.0 * std::hypot(width(), height()) / std::max(pxm, 1e-9);
    p.drawLine(own.p, own.offset(len * std::sin(g), len * std::cos(g)));
  }
}

void EcdisView::paintOwnShip(QPainter& p) {
  // The estimate (the ship's centre) carries the ellipse and the truth line; the CCRP the vectors and
  // the symbol's reference.
  const auto& x = history_->latest().frame.estimate.x;
  const Local est = localAt(x[est::drkf::kPosX], x[est::drkf::kPosY]);
  const geo::GridPoint c = ccrpGrid();
  const Local ccrp = localAt(c.xM, c.yM);
  if (overlay_.showPastTrack) paintPastTrack(p);
  if (overlay_.showTruth && history_->latest().frame.hasTruth) paintTruth(p, est);
  paintFixes(p);
  if (overlay_.showEllipses) paintOwnEllipse(p, est);
  if (overlay_.seed002Shown > 0 && history_->latest().seed002) paintSeed002(p);
  paintCourseVector(p, ccrp);
  paintOwnSymbol(p, est, ccrp);
  // above the COG vector and the symbol; a live ship takes no orders from the chart
  if (!history_->latest().live) paintOrderedVector(p, ccrp);
  if (!ownOutline(est).isEmpty()) {
    // The CCRP on the true-scale outline, above the vectors that start there: a circle with a cross,
    // on a disc of the panel colour.
    p.setPen(QPen(colour("own"), 1.5));
    p.setBrush(colour("panel"));
    p.drawEllipse(ccrp.p, 4.0, 4.0);
    p.drawLine(ccrp.p + QPointF(-7, 0), ccrp.p + QPointF(7, 0));
    p.drawLine(ccrp.p + QPointF(0, -7), ccrp.p + QPointF(0, 7));
  }
}

void EcdisView::paintPastTrack(QPainter& p) {
  // Past track: estimated positions, a dot every minute, the last pastTrackMinutes.
  const QColor ownColour = colour("own");
  const auto& ownHistory = history_->own();
  const double t0 = toSeconds(history_->latest().frame.timeUs) - overlay_.pastTrackMinutes * 60.0;
  QPainterPath path;
  bool started = false;
  std::vector<QPointF> marks;
  double nextMark = std::ceil(std::max(0.0, t0) / 60.0) * 60.0;
  for (auto it = std::lower_bound(ownHistory.begin(), ownHistory.end(), t0,
                                  [](const OwnSample&s, double t) { return s.tS < t; });
       it != ownHistory.end(); ++it) {
    const QPointF q = gridToWidget(it->estPos[0], it->estPos[1]);
    if (!started)
      path.moveTo(q);
    else
      path.lineTo(q);
    started = true;
    if (it->tS >= nextMark) {
      marks.push_back(q);
      nextMark += 60.0;
    }
  }
  p.setPen(QPen(ownColour, 1.2));
  p.setBrush(Qt::NoBrush);
  p.drawPath(path);
  p.setBrush(ownColour);
  for (const QPointF& q : marks) p.drawEllipse(q, 2.0, 2.0);
}

void EcdisView::paintTruth(QPainter& p, const Local& own) {
  // Truth: a small grey diamond and a thin line to the estimate (the error).
  const sim::SimFrame& f = history_->latest().frame;
  const QPointF t = gridToWidget(f.truth.position.xM, f.truth.position.yM);
  p.setPen(QPen(colour("truth"), 1.0));
  p.setBrush(Qt::NoBrush);
  p.drawLine(t, own.p);
  QPolygonF d{{t.x(), t.y() - 4}, {t.x() + 4, t.y()}, {t.x(), t.y() + 4}, {t.x() - 4, t.y()}};
  p.drawPolygon(d);
}

void EcdisView::paintFixes(QPainter& p) {
  // Latest position fixes: GPS a small cross, Loran-C a small triangle (hollow when rejected).
  const LiveFrame& live = history_->latest();
  const double now = toSeconds(live.frame.timeUs);
  for (int i = 0; i < 2; ++i) {
    const LastFix& fx = live.lastFix[static_cast<std::size_t>(i)];
    if (!fx.valid || now - fx.tS > 10.0) continue;
    const QPointF q = gridToWidget(fx.xM, fx.yM);
    p.setPen(QPen(colour(i == 0 ? "gps" : "loran"), fx.accepted ? 1.6 : 0.8));
    p.setBrush(Qt::NoBrush);
    if (i == 0) {
      p.drawLine(q + QPointF(-4, 0), q + QPointF(4, 0));
      p.drawLine(q + QPointF(0, -4), q + QPointF(0, 4));
    } else {
      p.drawPolygon(QPolygonF{{q.x(), q.y() - 4.5}, {q.x() + 4, q.y() + 3}, {q.x() - 4, q.y() + 3}});
    }
  }
}

void EcdisView::paintOwnEllipse(QPainter& p, const Local& own) {
  // 95% position ellipse of the DRKF, filled, bolder in dead reckoning.
  namespace dk = est::drkf;
  const LiveFrame& live = history_->latest();
  const auto& P = live.frame.estimate.P;
  const QPolygonF poly =
      ellipse95(own, P(dk::kPosX, dk::kPosX), P(dk::kPosX, dk::kPosY), P(dk::kPosY, dk::kPosY), 48);
  QColor fill = colour("ellipse");
  fill.setAlpha(live.positionFixUsed ? 40 : 70);
  p.setPen(QPen(colour("ellipse"), live.positionFixUsed ? 1.2 : 2.0));
  p.setBrush(fill);
  p.drawPolygon(poly);
}

void EcdisView::paintSeed002(QPainter& p) {
  // Seed 002's estimate beside the DRKF's: a ring with its 95% ellipse, labelled G or L.
  const LiveFrame& live = history_->latest();
  const est::Gaussian<4>& g = (*live.seed002)[static_cast<std::size_t>(overlay_.seed002Shown - 1)];
  const Local at = localAt(g.x[0], g.x[1]);
  p.setPen(QPen(colour("seed002"), 1.4, Qt::DashLine));
  p.setBrush(Qt::NoBrush);
  if (overlay_.showEllipses) p.drawPolygon(ellipse95(at, g.P(0, 0), g.P(0, 1), g.P(1, 1), 48));
  p.setPen(QPen(colour("seed002"), 1.8));
  p.drawEllipse(at.p, 4.0, 4.0);
  p.drawText(at.p + QPointF(6, -6), overlay_.seed002Shown == 1 ? QStringLiteral("G") : QStringLiteral("L"));
}

void EcdisView::paintCourseVector(QPainter& p, const Local& own) {
  // Course over ground for vectorMinutes, with minute marks and a double arrowhead.
  namespace dk = est::drkf;
  const auto& x = history_->latest().frame.estimate.x;
  const double gvx = x[dk::kVelX] + x[dk::kCurX], gvy = x[dk::kVelY] + x[dk::kCurY];
  const double minutes = overlay_.vectorMinutes;
  const QPointF tip = own.offset(gvx * minutes * 60.0, gvy * minutes * 60.0);
  p.setPen(QPen(colour("own"), 2.0));
  p.drawLine(own.p, tip);
  for (int m = 1; m < static_cast<int>(minutes); ++m) {
    const QPointF q = own.offset(gvx * m * 60.0, gvy * m * 60.0);
    const QPointF dir = tip - own.p;
    const double len = std::hypot(dir.x(), dir.y());
    if (len < 1.0) break;
    const QPointF n(-dir.y() / len * 4.0, dir.x() / len * 4.0);
    p.drawLine(q - n, q + n);
  }
  const QPointF dir = tip - own.p;
  const double len = std::hypot(dir.x(), dir.y());
  if (len > 8.0) {
    const QPointF u = dir / len, n(-u.y(), u.x());
    for (double back : {0.0, 6.0}) {
      const QPointF t = tip - u * back;
      p.drawLine(t, t - u * 8.0 + n * 4.0);
      p.drawLine(t, t - u * 8.0 - n * 4.0);
    }
  }
}

void EcdisView::paintOrderedVector(QPainter& p, const Local& own) {
  // The ordered vector: long dashes in the order colour on a casing of the panel colour, drawn above
  // the COG vector so that it shows where the two lie together, and the round handle at its tip with
  // a cross. Its readout ("Order 045.0° 12.0 kn") is always shown beside the handle: while dragged,
  // what the drag would order.
  const double minutes = handleDrag_ ? dragMinutes_ : handleMinutes();
  const auto h = handleAt(minutes);
  if (!h) return;
  const QPointF hp = handleDrag_.value_or(*h);
  QColor casing = colour("panel");
  casing.setAlpha(220);
  p.setBrush(Qt::NoBrush);
  p.setPen(QPen(casing, 5.0, Qt::SolidLine, Qt::RoundCap));
  p.drawLine(own.p, hp);
  QPen dashes(colour("order"), 2.5, Qt::CustomDashLine, Qt::FlatCap);
  dashes.setDashPattern({4.0, 2.0});
  p.setPen(dashes);
  p.drawLine(own.p, hp);
  p.setPen(QPen(colour("order"), 2.0));
  p.setBrush(colour("panel"));
  p.drawEllipse(hp, kHandleRadiusPx, kHandleRadiusPx);
  const double k = kHandleRadiusPx * 0.6;
  p.drawLine(hp + QPointF(-k, 0), hp + QPointF(k, 0));
  p.drawLine(hp + QPointF(0, -k), hp + QPointF(0, k));
  const auto [course, speed] = handleDrag_ ? orderAt(hp, minutes) : orderedCourseSpeed();
  QString text = QStringLiteral("Order ") + formatCourseSpeed(course, speed, units_);
  if (std::abs(minutes - overlay_.vectorMinutes) > 1e-9)  // the handle's shortened time base
    text += minutes >= 1.0 ? QStringLiteral(" (%1 min)").arg(minutes)
                           : QStringLiteral(" (%1 s)").arg(minutes * 60.0);
  labelObstacles_.push_back(QRectF(hp - QPointF(kHandleRadiusPx, kHandleRadiusPx),
                                   QSizeF(2 * kHandleRadiusPx, 2 * kHandleRadiusPx)));
  // First in line: the order's readout gets the best place, the target labels keep out of it.
  pendingLabels_.insert(pendingLabels_.begin(),
                        PendingLabel{text, hp, kHandleRadiusPx + 2.0, colour("order"), 9.0, true});
}

QPolygonF EcdisView::ownOutline(const Local& est) const {
  // The true-scale outline around the estimated point (the ship's centre), when it is larger than the
  // 6 mm symbol; else none.
  if (overlay_.ownLengthM * est.pxPerMetre() <= kSymbolMm * kPxPerMm) return {};
  const double hdg = headingGridRad();
  const double L = overlay_.ownLengthM, B = overlay_.ownBeamM;
  const double s = std::sin(hdg), c = std::cos(hdg);
  const auto pt = [&](double along, double across) {
    return est.offset(along * s + across * c, along * c - across * s);
  };
  return {pt(L * 0.5, 0), pt(L * 0.3, B * 0.5), pt(-L * 0.5, B * 0.5), pt(-L * 0.5, -B * 0.5),
          pt(L * 0.3, -B * 0.5)};
}

QRectF EcdisView::ownSymbolBox() const {
  if (!haveOwnShip()) return {};
  const auto& x = history_->latest().frame.estimate.x;
  const QPolygonF hull = ownOutline(localAt(x[est::drkf::kPosX], x[est::drkf::kPosY]));
  if (!hull.isEmpty()) return hull.boundingRect();
  const double r = kSymbolMm * kPxPerMm / 2.0;
  return {ccrpWidget() - QPointF(r, r), QSizeF(2 * r, 2 * r)};
}

void EcdisView::paintOwnSymbol(QPainter& p, const Local& est, const Local& ccrp) {
  // Own-ship symbol: true-scale outline (around the estimate) with the CCRP marked, when it is larger
  // than 6 mm, else two concentric circles at the CCRP; the heading line runs from the CCRP to the
  // edge of the screen. The heading is the filter's: the direction of its velocity through the water
  // (what the gyro measures), held from the last time the ship was moving clearly enough to have one.
  const LiveFrame& live = history_->latest();
  const double pxm = ccrp.pxPerMetre();
  const double hdg = headingGridRad();
  p.setPen(QPen(colour("own"), 2.0));
  p.setBrush(Qt::NoBrush);
  const double far = 2.0 * std::hypot(width(), height()) / std::max(pxm, 1e-9);
  p.drawLine(ccrp.p, ccrp.offset(far * std::sin(hdg), far * std::cos(hdg)));
  const QPolygonF hull = ownOutline(est);
  if (!hull.isEmpty()) {
    p.drawPolygon(hull);
  } else {
    const double r = kSymbolMm * kPxPerMm / 2.0;
    p.drawEllipse(ccrp.p, r, r);
    p.drawEllipse(ccrp.p, r / 2.0, r / 2.0);
  }
  labelObstacles_.push_back(ownSymbolBox());
  // Positioning mode beside the symbol: DR when no position fix is being used.
  if (!live.positionFixUsed) {
    QFont font = p.font();
    font.setPointSizeF(10.0);
    font.setBold(true);
    p.setFont(font);
    p.setPen(colour("danger"));
    const QPointF at = ccrp.p + QPointF(-kSymbolMm * kPxPerMm - 22.0, -kSymbolMm * kPxPerMm / 2.0);
    p.drawText(at, QStringLiteral("DR"));
    labelObstacles_.push_back(QRectF(at - QPointF(0, 12), QSizeF(22, 14)));
  }
}

void EcdisView::paintTargets(QPainter& p) {
  const sim::SimFrame& f = history_->latest().frame;
  const auto& ox = f.estimate.x;
  TargetPaint k;
  k.ownVx = ox[est::drkf::kVelX] + ox[est::drkf::kCurX];
  k.ownVy = ox[est::drkf::kVelY] + ox[est::drkf::kCurY];
  k.radiusPx = kSymbolMm * kPxPerMm / 2.0 * 0.8;
  k.flashOn = (QDateTime::currentMSecsSinceEpoch() / 500) % 2 == 0;
  k.nowS = toSeconds(f.timeUs);
  QFont font = p.font();
  font.setPointSizeF(8.0);
  p.setFont(font);
  for (const auto& t : f.tracks) paintTarget(p, t, k);
}

void EcdisView::paintTarget(QPainter& p, const sim::TrackSnapshot& t, const TargetPaint& k) {
  namespace tk = est::ttkf;
  // Associated with an AIS station shown by its AIS symbol: the radar symbol only when selected.
  if (t.aisMmsi != 0 && !overlay_.associatedAsRadar && selected_ != t.trackId && overlay_.showAis) return;
  const auto& x = t.estimate.x;
  const Local at = localAt(x[tk::kTgtX], x[tk::kTgtY]);
  // Dangerous while the tracker says so or its CPA/TCPA alarm stands (the alarm's hysteresis keeps it a
  // little longer); flashing while that alarm waits for acknowledgement.
  const alerts::AlertId cpaAlert{alerts::AlertKind::CpaTcpa, t.trackId};
  const bool alarm = history_->unacknowledged(cpaAlert);
  const bool danger = (t.dangerous || history_->alert(cpaAlert)) && t.status != track::TrackStatus::Lost;
  const QColor c = danger ? colour("danger") : colour("target");
  const double width = danger ? 2.5 : 1.6;
  const double r = k.radiusPx;

  // Past positions: the sweep-end estimates nearest before every interval back from now, as many as
  // set (View > Target past positions).
  const auto& hist = history_->track(t.trackId);
  p.setPen(Qt::NoPen);
  p.setBrush(c);
  const double interval = std::max(1.0, overlay_.targetPastIntervalS);
  double next = k.nowS - interval;
  int dots = 0;
  for (auto it = hist.rbegin(); it != hist.rend() && dots < overlay_.targetPastCount; ++it) {
    if (it->tS > next) continue;
    p.drawEllipse(gridToWidget(it->estPos[0], it->estPos[1]), 1.8, 1.8);
    next = it->tS - interval;
    ++dots;
  }

  // 95% position ellipse.
  if (overlay_.showEllipses && t.status != track::TrackStatus::Lost) {
    const auto& P = t.estimate.P;
    const QPolygonF poly =
        ellipse95(at, P(tk::kTgtX, tk::kTgtX), P(tk::kTgtX, tk::kTgtY), P(tk::kTgtY, tk::kTgtY), 36);
    QColor fill = c;
    fill.setAlpha(30);
    p.setPen(QPen(c, 0.8));
    p.setBrush(fill);
    p.drawPolygon(poly);
  }

  // Vector: true (over ground) or relative to own ship, for vectorMinutes.
  if (t.status == track::TrackStatus::Confirmed) {
    double vx = x[tk::kTgtVx], vy = x[tk::kTgtVy];
    if (overlay_.relativeVectors) {
      vx -= k.ownVx;
      vy -= k.ownVy;
    }
    const double s = overlay_.vectorMinutes * 60.0;
    p.setPen(QPen(c, width, overlay_.relativeVectors ? Qt::DashLine : Qt::SolidLine));
    p.drawLine(at.p, at.offset(vx * s, vy * s));
  }

  // Symbol by status; dangerous in red and bold, flashing until acknowledged.
  p.setBrush(Qt::NoBrush);
  if (!(danger && alarm && !k.flashOn)) paintTrackSymbol(p, t.status, at.p, r, QPen(c, width));
  if (selected_ == t.trackId) paintSelectionBrackets(p, at.p, r + 5.0, QPen(colour("text"), 1.5));
  const double box = selected_ == t.trackId ? r + 5.0 : r;
  labelObstacles_.push_back(QRectF(at.p - QPointF(box, box), QSizeF(2 * box, 2 * box)));
  // Label: the track number, and M while input estimation flags a manoeuvre (placed in paintLabels).
  if (overlay_.showTargetLabels)
    pendingLabels_.push_back(
        PendingLabel{t.manoeuvring ? QStringLiteral("%1 M").arg(t.trackId) : QString::number(t.trackId), at.p,
                     box, c, 8.0, false});
}

void EcdisView::paintLabels(QPainter& p) {
  // Every label in a place of its own (label_placer.h): none covers another, a symbol or a box.
  std::vector<LabelRequest> requests;
  requests.reserve(pendingLabels_.size());
  QFont font = p.font();
  for (const PendingLabel& l : pendingLabels_) {
    font.setPointSizeF(l.pointSize);
    const QFontMetricsF fm(font);
    const double pad = l.boxed ? 3.0 : 0.0;
    requests.push_back(
        {l.anchor, l.clearancePx, QSizeF(fm.horizontalAdvance(l.text) + 2 * pad, fm.height())});
  }
  const std::vector<QRectF> boxes = placeLabels(requests, labelObstacles_, QRectF(rect()));
  placedLabels_.clear();
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const PendingLabel& l = pendingLabels_[i];
    font.setPointSizeF(l.pointSize);
    p.setFont(font);
    if (l.boxed) {
      QColor bg = colour("panel");
      bg.setAlpha(210);
      p.setPen(QPen(l.colour, 1.0));
      p.setBrush(bg);
      p.drawRect(boxes[i]);
    }
    p.setPen(l.boxed ? colour("text") : l.colour);
    p.drawText(boxes[i], Qt::AlignCenter, l.text);
    placedLabels_.push_back({l.text, boxes[i]});
  }
}

void EcdisView::paintPlots(QPainter& p) {
  const LiveFrame& live = history_->latest();
  if (live.recentPlots.empty()) return;
  const int newest = live.recentPlots.back().sweep;
  p.setPen(Qt::NoPen);
  for (const ShownPlot& s : live.recentPlots) {
    QColor c = colour("plot");
    c.setAlpha(std::max(40, 255 - 40 * (newest - s.sweep)));
    p.setBrush(c);
    p.drawEllipse(gridToWidget(s.xM, s.yM), 2.5, 2.5);
  }
}

}  // namespace reckoner::ui
