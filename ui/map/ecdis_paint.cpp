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
#include "ui/map/range_scale.h"

namespace reckoner::ui {
namespace {
constexpr double kSymbolMm = 6.0;        // own-ship and target symbols, as S-52 draws them
constexpr double kPxPerMm = 1.0 / 0.28;  // pixels per millimetre at the S-52 reference pitch

double chi2Scale95() {
  static const double k = std::sqrt(est::chiSquareQuantile(0.95, 2.0));
  return k;
}

/// Nice scale-bar length (1, 2 or 5 times a power of ten) not longer than maxM.
double niceLength(double maxM) {
  const double p = std::pow(10.0, std::floor(std::log10(maxM)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * p <= maxM) return m * p;
  return p;
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
      {"danger", {qRgb(220, 0, 0), qRgb(255, 60, 60), qRgb(170, 30, 30)}},
      {"plot", {qRgb(200, 120, 0), qRgb(255, 190, 60), qRgb(150, 100, 30)}},
      {"tool", {qRgb(120, 0, 140), qRgb(220, 120, 230), qRgb(130, 70, 140)}},
      {"text", {qRgb(0, 0, 0), qRgb(230, 230, 230), qRgb(150, 150, 130)}},
      {"panel", {qRgb(255, 255, 255), qRgb(30, 30, 40), qRgb(10, 10, 12)}},
      {"gps", {qRgb(0, 120, 120), qRgb(60, 220, 220), qRgb(40, 120, 120)}},
      {"loran", {qRgb(150, 0, 150), qRgb(230, 110, 230), qRgb(120, 60, 120)}},
      {"seed002", {qRgb(200, 0, 90), qRgb(255, 110, 170), qRgb(150, 50, 90)}},
  };
  for (const Entry& e : kTable)
    if (std::strcmp(e.role, role) == 0) return QColor::fromRgb(e.c[i]);
  return Qt::magenta;
}

void EcdisView::paintOverlay(QPainter& p, const charts::Viewport& view) {
  p.setRenderHint(QPainter::Antialiasing, true);
  if (history_ && !history_->empty() && frame_) {
    const auto& x = history_->latest().frame.estimate.x;
    const Local own = localAt(x[est::drkf::kPosX], x[est::drkf::kPosY]);
    if (overlay_.showRadarPicture) paintRadarPicture(p);
    paintRings(p, own);
    if (overlay_.showRadarEchoes) paintRadarEchoes(p);
    if (overlay_.showPlots) paintPlots(p);
    paintTargets(p);
    paintOwnShip(p);
  }
  paintScaleBar(p, view);
  paintReadouts(p);
}

void EcdisView::paintRings(QPainter& p, const Local& own) {
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
  const auto& x = history_->latest().frame.estimate.x;
  const double gamma = frame_->gridInfo({x[est::drkf::kPosX], x[est::drkf::kPosY]}).convergenceRad;
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
  const auto& x = history_->latest().frame.estimate.x;
  const Local own = localAt(x[est::drkf::kPosX], x[est::drkf::kPosY]);
  if (overlay_.showPastTrack) paintPastTrack(p);
  if (overlay_.showTruth) paintTruth(p, own);
  paintFixes(p);
  if (overlay_.showEllipses) paintOwnEllipse(p, own);
  if (overlay_.seed002Shown > 0 && history_->latest().seed002) paintSeed002(p);
  paintCourseVector(p, own);
  paintOrderedVector(p, own);
  paintOwnSymbol(p, own);
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
  // The ordered vector (dashed) and its handle; while dragged, the course and speed it orders.
  const auto h = handlePosition();
  if (!h) return;
  const QPointF hp = handleDrag_.value_or(*h);
  p.setPen(QPen(colour("order"), 1.5, Qt::DashLine));
  p.drawLine(own.p, hp);
  p.setPen(QPen(colour("order"), 2.0));
  p.setBrush(colour("panel"));
  p.drawEllipse(hp, kHandleRadiusPx, kHandleRadiusPx);
  if (!handleDrag_) return;
  const auto& x = history_->latest().frame.estimate.x;
  const double ox = x[est::drkf::kPosX], oy = x[est::drkf::kPosY];
  const double gamma = frame_->gridInfo({ox, oy}).convergenceRad;
  const geo::GridPoint g = widgetToGrid(hp);
  const double course = wrapTwoPi(bearingOf(g.xM - ox, g.yM - oy) + gamma);
  const double speed = std::hypot(g.xM - ox, g.yM - oy) / (overlay_.vectorMinutes * 60.0);
  p.setPen(colour("text"));
  p.drawText(hp + QPointF(10, -10), QStringLiteral("%1° %2 kn")
                                        .arg(radToDeg(course), 5, 'f', 1, QChar('0'))
                                        .arg(speed / kMpsPerKnot, 0, 'f', 1));
}

void EcdisView::paintOwnSymbol(QPainter& p, const Local& own) {
  // Own-ship symbol: true-scale outline when it is larger than 6 mm, else two concentric circles;
  // the heading line runs to the edge of the screen.
  // The heading is the filter's: the direction of its velocity through the water (what the gyro
  // measures), kept from the last time the ship was moving clearly enough to have one.
  const LiveFrame& live = history_->latest();
  const auto& x = live.frame.estimate.x;
  const double pxm = own.pxPerMetre();
  const double hx = x[est::drkf::kVelX], hy = x[est::drkf::kVelY];
  if (std::hypot(hx, hy) > 0.3) lastHeadingRad_ = bearingOf(hx, hy);
  const double hdg = lastHeadingRad_;
  const double lengthPx = overlay_.ownLengthM * pxm;
  p.setPen(QPen(colour("own"), 2.0));
  p.setBrush(Qt::NoBrush);
  const double far = 2.0 * std::hypot(width(), height()) / std::max(pxm, 1e-9);
  p.drawLine(own.p, own.offset(far * std::sin(hdg), far * std::cos(hdg)));
  if (lengthPx > kSymbolMm * kPxPerMm) {
    const double L = overlay_.ownLengthM, B = overlay_.ownBeamM;
    const double s = std::sin(hdg), c = std::cos(hdg);
    const auto pt = [&](double along, double across) {
      return own.offset(along * s + across * c, along * c - across * s);
    };
    QPolygonF hull{pt(L * 0.5, 0), pt(L * 0.3, B * 0.5), pt(-L * 0.5, B * 0.5), pt(-L * 0.5, -B * 0.5),
                   pt(L * 0.3, -B * 0.5)};
    p.drawPolygon(hull);
  } else {
    const double r = kSymbolMm * kPxPerMm / 2.0;
    p.drawEllipse(own.p, r, r);
    p.drawEllipse(own.p, r / 2.0, r / 2.0);
  }
  // Positioning mode beside the symbol: DR when no position fix is being used.
  if (!live.positionFixUsed) {
    QFont font = p.font();
    font.setPointSizeF(10.0);
    font.setBold(true);
    p.setFont(font);
    p.setPen(colour("danger"));
    p.drawText(own.p + QPointF(-kSymbolMm * kPxPerMm - 22.0, -kSymbolMm * kPxPerMm / 2.0),
               QStringLiteral("DR"));
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

  // Past positions: sweep-end estimates every 30 s over the last 3 minutes.
  const auto& hist = history_->track(t.trackId);
  p.setPen(Qt::NoPen);
  p.setBrush(c);
  double next = k.nowS - 30.0;
  int dots = 0;
  for (auto it = hist.rbegin(); it != hist.rend() && dots < 6; ++it) {
    if (it->tS > next) continue;
    p.drawEllipse(gridToWidget(it->estPos[0], it->estPos[1]), 1.8, 1.8);
    next = it->tS - 30.0;
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
  p.setPen(c);
  // Label: the track number, and M while input estimation flags a manoeuvre.
  p.drawText(at.p + QPointF(r + 3, -r - 2),
             t.manoeuvring ? QStringLiteral("%1 M").arg(t.trackId) : QString::number(t.trackId));
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

void EcdisView::paintScaleBar(QPainter& p, const charts::Viewport& view) {
  const double mpp = view.metresPerPixel();
  if (!(mpp > 0.0)) return;
  const double maxM = mpp * width() * 0.25;
  const bool nm = maxM >= 1852.0 * 0.2;
  const double len = nm ? nmToMetres(niceLength(metresToNm(maxM))) : niceLength(maxM);
  const double px = len / mpp;
  // Bottom right (the not-for-navigation notice takes the bottom left).
  const QPointF a(width() - 16 - px, height() - 14), b(width() - 16, height() - 14);
  p.setPen(QPen(colour("text"), 2.0));
  p.drawLine(a, b);
  p.drawLine(a, a - QPointF(0, 6));
  p.drawLine(b, b - QPointF(0, 6));
  const QString label = nm ? QStringLiteral("%1 NM").arg(metresToNm(len), 0, 'g', 3)
                           : QStringLiteral("%1 m").arg(len, 0, 'f', 0);
  p.drawText(a + QPointF(2, -8), label);
  if (std::abs(view.rotationRad()) > 1e-9) {
    // North arrow when the chart is not north-up.
    const QPointF c(width() - 24.0, 70.0);
    const double r = view.rotationRad();
    const QPointF tip = c + QPointF(-14 * std::sin(r), -14 * std::cos(r));
    p.drawLine(c, tip);
    p.drawText(tip + QPointF(-4, -4), QStringLiteral("N"));
  }
}

QStringList EcdisView::readoutLines() const {
  QStringList lines;
  if (cursor_) lines << QStringLiteral("Cursor ") + cursorText(*cursor_);
  if (overlay_.eblBearingRad)
    lines << QStringLiteral("EBL %1°").arg(radToDeg(*overlay_.eblBearingRad), 5, 'f', 1, QChar('0'));
  if (overlay_.vrmRangeM)
    lines << QStringLiteral("VRM %1 NM").arg(metresToNm(*overlay_.vrmRangeM), 0, 'f', 2);
  if (addTargetFrom_ && steerTarget_)
    lines << QStringLiteral(
                 "Steer track %1: move to set its new vector (%2 min), click to order, Esc to cancel")
                 .arg(steerTrack_)
                 .arg(overlay_.vectorMinutes);
  else if (addTargetFrom_)
    lines << QStringLiteral("New target: move to set its vector (%1 min), click to place, Esc to cancel")
                 .arg(overlay_.vectorMinutes);
  return lines;
}

QFont EcdisView::readoutFont() const {
  QFont f = font();
  f.setPointSizeF(9.0);
  return f;
}

QRect EcdisView::readoutRect() const {
  const QStringList lines = readoutLines();
  if (lines.isEmpty()) return {};
  const QFontMetrics fm(readoutFont());
  int w = 0;
  for (const QString& l : lines) w = std::max(w, fm.horizontalAdvance(l));
  return {6, 6, w + 12, static_cast<int>(lines.size()) * fm.height() + 8};
}

void EcdisView::paintReadouts(QPainter& p) {
  const QStringList lines = readoutLines();
  if (lines.isEmpty()) return;
  p.setFont(readoutFont());
  const QFontMetrics fm(p.font());
  const QRect box = readoutRect();
  QColor bg = colour("panel");
  bg.setAlpha(200);
  p.setPen(Qt::NoPen);
  p.setBrush(bg);
  p.drawRect(box);
  p.setPen(colour("text"));
  for (int i = 0; i < lines.size(); ++i)
    p.drawText(box.left() + 6, box.top() + 4 + fm.ascent() + i * fm.height(), lines[i]);
  if (addTargetFrom_ && addTargetTo_) {
    const QPointF from = gridToWidget(addTargetFrom_->xM, addTargetFrom_->yM);
    p.setPen(QPen(colour("target"), 2.0, Qt::DashLine));
    p.setBrush(Qt::NoBrush);
    p.drawEllipse(from, 8.0, 8.0);
    p.drawLine(from, *addTargetTo_);
  }
}

}  // namespace reckoner::ui
