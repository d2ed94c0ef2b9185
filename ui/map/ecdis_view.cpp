#include "ui/map/ecdis_view.h"

#include <QContextMenuEvent>
#include <QDateTime>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QtMath>
#include <algorithm>
#include <cmath>

#include "common/angles.h"
#include "common/units.h"
#include "estimation/chi_square.h"
#include "io/text_format.h"

namespace reckoner::ui {
namespace {
constexpr double kHandleRadiusPx = 7.0;
constexpr double kSymbolMm = 6.0;  // own-ship and target symbols, as S-52 draws them

double chi2Scale95() {
  static const double k = std::sqrt(est::chiSquareQuantile(0.95, 2.0));
  return k;
}

QString latLonText(double latDeg, double lonDeg) {
  return QString::fromStdString(io::formatLatitude(latDeg) + ' ' + io::formatLongitude(lonDeg));
}

/// Nice scale-bar length (1, 2 or 5 times a power of ten) not longer than maxM.
double niceLength(double maxM) {
  const double p = std::pow(10.0, std::floor(std::log10(maxM)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * p <= maxM) return m * p;
  return p;
}
}  // namespace

struct EcdisView::Local {
  QPointF p;
  double a = 1, b = 0, c = 0, d = 1;  // widget px per grid metre
  [[nodiscard]] QPointF offset(double dxM, double dyM) const {
    return {p.x() + a * dxM + b * dyM, p.y() + c * dxM + d * dyM};
  }
  [[nodiscard]] double pxPerMetre() const { return std::sqrt(std::abs(a * d - b * c)); }
};

QPolygonF EcdisView::ellipse95(const Local& at, double pxx, double pxy, double pyy, int points) {
  est::Mat<2> P;
  P << pxx, pxy, pxy, pyy;
  const Eigen::SelfAdjointEigenSolver<est::Mat<2>> eig(P);
  const double k = chi2Scale95();
  const double a = k * std::sqrt(std::max(0.0, eig.eigenvalues()[0]));
  const double b = k * std::sqrt(std::max(0.0, eig.eigenvalues()[1]));
  QPolygonF poly;
  for (int i = 0; i <= points; ++i) {
    const double th = 2.0 * M_PI * i / points;
    const est::Vec<2> u = eig.eigenvectors() * est::Vec<2>(a * std::cos(th), b * std::sin(th));
    poly << at.offset(u[0], u[1]);
  }
  return poly;
}

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
  if (overlay_.ringSpacingNm > 0.0) {
    for (int i = 1; i <= overlay_.ringCount; ++i) {
      const double r = nmToMetres(overlay_.ringSpacingNm * i) * pxm;
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
  namespace dk = est::drkf;
  const LiveFrame& live = history_->latest();
  const sim::SimFrame& f = live.frame;
  const auto& x = f.estimate.x;
  const double ox = x[dk::kPosX], oy = x[dk::kPosY];
  const Local own = localAt(ox, oy);
  const double pxm = own.pxPerMetre();
  const double mmPx = 1.0 / 0.28;  // pixels per millimetre at the S-52 reference pitch
  const QColor ownColour = colour("own");

  // Past track: estimated positions, a dot every minute, the last pastTrackMinutes.
  if (overlay_.showPastTrack) {
    const auto& ownHistory = history_->own();
    const double t0 = toSeconds(f.timeUs) - overlay_.pastTrackMinutes * 60.0;
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

  // Truth: a small grey diamond and a thin line to the estimate (the error).
  if (overlay_.showTruth) {
    const QPointF t = gridToWidget(f.truth.position.xM, f.truth.position.yM);
    p.setPen(QPen(colour("truth"), 1.0));
    p.setBrush(Qt::NoBrush);
    p.drawLine(t, own.p);
    QPolygonF d{{t.x(), t.y() - 4}, {t.x() + 4, t.y()}, {t.x(), t.y() + 4}, {t.x() - 4, t.y()}};
    p.drawPolygon(d);
  }

  // Latest position fixes: GPS a small cross, Loran-C a small triangle (hollow when rejected).
  const double now = toSeconds(f.timeUs);
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

  // 95% position ellipse of the DRKF.
  if (overlay_.showEllipses) {
    const auto& P = f.estimate.P;
    const QPolygonF poly =
        ellipse95(own, P(dk::kPosX, dk::kPosX), P(dk::kPosX, dk::kPosY), P(dk::kPosY, dk::kPosY), 48);
    QColor fill = colour("ellipse");
    fill.setAlpha(live.positionFixUsed ? 40 : 70);
    p.setPen(QPen(colour("ellipse"), live.positionFixUsed ? 1.2 : 2.0));
    p.setBrush(fill);
    p.drawPolygon(poly);
  }

  // Seed 002's estimate beside the DRKF's: a ring with its 95% ellipse, labelled G or L.
  if (overlay_.seed002Shown > 0 && live.seed002) {
    const est::Gaussian<4>& g = (*live.seed002)[static_cast<std::size_t>(overlay_.seed002Shown - 1)];
    const Local at = localAt(g.x[0], g.x[1]);
    p.setPen(QPen(colour("seed002"), 1.4, Qt::DashLine));
    p.setBrush(Qt::NoBrush);
    if (overlay_.showEllipses) p.drawPolygon(ellipse95(at, g.P(0, 0), g.P(0, 1), g.P(1, 1), 48));
    p.setPen(QPen(colour("seed002"), 1.8));
    p.drawEllipse(at.p, 4.0, 4.0);
    p.drawText(at.p + QPointF(6, -6), overlay_.seed002Shown == 1 ? QStringLiteral("G") : QStringLiteral("L"));
  }

  // Vectors: course over ground with minute marks and a double arrowhead.
  const double gamma = frame_->gridInfo({ox, oy}).convergenceRad;
  const double gvx = x[dk::kVelX] + x[dk::kCurX], gvy = x[dk::kVelY] + x[dk::kCurY];
  const double minutes = overlay_.vectorMinutes;
  const QPointF tip = own.offset(gvx * minutes * 60.0, gvy * minutes * 60.0);
  p.setPen(QPen(ownColour, 2.0));
  p.drawLine(own.p, tip);
  for (int m = 1; m < static_cast<int>(minutes); ++m) {
    const QPointF q = own.offset(gvx * m * 60.0, gvy * m * 60.0);
    const QPointF dir = tip - own.p;
    const double len = std::hypot(dir.x(), dir.y());
    if (len < 1.0) break;
    const QPointF n(-dir.y() / len * 4.0, dir.x() / len * 4.0);
    p.drawLine(q - n, q + n);
  }
  {
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

  // The ordered vector (dashed) and its handle.
  if (const auto h = handlePosition()) {
    const QPointF hp = handleDrag_.value_or(*h);
    p.setPen(QPen(colour("order"), 1.5, Qt::DashLine));
    p.drawLine(own.p, hp);
    p.setPen(QPen(colour("order"), 2.0));
    p.setBrush(colour("panel"));
    p.drawEllipse(hp, kHandleRadiusPx, kHandleRadiusPx);
    if (handleDrag_) {
      const geo::GridPoint g = widgetToGrid(hp);
      const double course = wrapTwoPi(bearingOf(g.xM - ox, g.yM - oy) + gamma);
      const double speed = std::hypot(g.xM - ox, g.yM - oy) / (minutes * 60.0);
      p.setPen(colour("text"));
      p.drawText(hp + QPointF(10, -10), QStringLiteral("%1° %2 kn")
                                            .arg(radToDeg(course), 5, 'f', 1, QChar('0'))
                                            .arg(speed / kMpsPerKnot, 0, 'f', 1));
    }
  }

  // Own-ship symbol: true-scale outline when it is larger than 6 mm, else two concentric circles;
  // the heading line runs to the edge of the screen.
  // The heading is the filter's: the direction of its velocity through the water (what the gyro
  // measures), kept from the last time the ship was moving clearly enough to have one.
  const double hx = x[dk::kVelX], hy = x[dk::kVelY];
  if (std::hypot(hx, hy) > 0.3) lastHeadingRad_ = bearingOf(hx, hy);
  const double hdg = lastHeadingRad_;
  const double lengthPx = overlay_.ownLengthM * pxm;
  p.setPen(QPen(ownColour, 2.0));
  p.setBrush(Qt::NoBrush);
  const double far = 2.0 * std::hypot(width(), height()) / std::max(pxm, 1e-9);
  p.drawLine(own.p, own.offset(far * std::sin(hdg), far * std::cos(hdg)));
  if (lengthPx > kSymbolMm * mmPx) {
    const double L = overlay_.ownLengthM, B = overlay_.ownBeamM;
    const double s = std::sin(hdg), c = std::cos(hdg);
    const auto pt = [&](double along, double across) {
      return own.offset(along * s + across * c, along * c - across * s);
    };
    QPolygonF hull{pt(L * 0.5, 0), pt(L * 0.3, B * 0.5), pt(-L * 0.5, B * 0.5), pt(-L * 0.5, -B * 0.5),
                   pt(L * 0.3, -B * 0.5)};
    p.drawPolygon(hull);
  } else {
    const double r = kSymbolMm * mmPx / 2.0;
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
    p.drawText(own.p + QPointF(-kSymbolMm * mmPx - 22.0, -kSymbolMm * mmPx / 2.0), QStringLiteral("DR"));
  }
}

void EcdisView::paintTargets(QPainter& p) {
  namespace tk = est::ttkf;
  const sim::SimFrame& f = history_->latest().frame;
  const auto& ox = f.estimate.x;
  const double ownVx = ox[est::drkf::kVelX] + ox[est::drkf::kCurX],
               ownVy = ox[est::drkf::kVelY] + ox[est::drkf::kCurY];
  const double mmPx = 1.0 / 0.28;
  const double r = kSymbolMm * mmPx / 2.0 * 0.8;
  const bool flashOn = (QDateTime::currentMSecsSinceEpoch() / 500) % 2 == 0;
  QFont font = p.font();
  font.setPointSizeF(8.0);
  p.setFont(font);
  for (const auto& t : f.tracks) {
    const auto& x = t.estimate.x;
    const Local at = localAt(x[tk::kTgtX], x[tk::kTgtY]);
    const bool alarm = history_->unacknowledged(Alarm::Kind::Dangerous, t.trackId);
    const bool danger = t.dangerous && t.status != track::TrackStatus::Lost;
    QColor c = danger ? colour("danger") : colour("target");
    const double width = danger ? 2.5 : 1.6;

    // Past positions: sweep-end estimates every 30 s over the last 3 minutes.
    const auto& hist = history_->track(t.trackId);
    p.setPen(Qt::NoPen);
    p.setBrush(c);
    double next = toSeconds(f.timeUs) - 30.0;
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
        vx -= ownVx;
        vy -= ownVy;
      }
      const double s = overlay_.vectorMinutes * 60.0;
      p.setPen(QPen(c, width, overlay_.relativeVectors ? Qt::DashLine : Qt::SolidLine));
      p.drawLine(at.p, at.offset(vx * s, vy * s));
    }

    // Symbol by status (IEC 62388): tentative a broken circle, confirmed a full circle, lost a circle
    // crossed out; dangerous in red and bold, flashing until acknowledged.
    p.setBrush(Qt::NoBrush);
    if (!(danger && alarm && !flashOn)) {
      switch (t.status) {
        case track::TrackStatus::Tentative: {
          p.setPen(QPen(c, width));
          for (int q = 0; q < 4; ++q)
            p.drawArc(QRectF(at.p.x() - r, at.p.y() - r, 2 * r, 2 * r), (q * 90 + 20) * 16, 50 * 16);
          break;
        }
        case track::TrackStatus::Confirmed:
          p.setPen(QPen(c, width));
          p.drawEllipse(at.p, r, r);
          break;
        case track::TrackStatus::Lost: {
          p.setPen(QPen(c, width));
          QPolygonF diamond{{at.p.x(), at.p.y() - r},
                            {at.p.x() + r, at.p.y()},
                            {at.p.x(), at.p.y() + r},
                            {at.p.x() - r, at.p.y()}};
          p.drawPolygon(diamond);
          p.drawLine(at.p + QPointF(-r, -r), at.p + QPointF(r, r));
          p.drawLine(at.p + QPointF(-r, r), at.p + QPointF(r, -r));
          break;
        }
      }
    }
    if (selected_ == t.trackId) {
      // Selected target: square corner brackets.
      const double s = r + 5.0, k = 5.0;
      p.setPen(QPen(colour("text"), 1.5));
      for (int sx : {-1, 1})
        for (int sy : {-1, 1}) {
          const QPointF c0 = at.p + QPointF(sx * s, sy * s);
          p.drawLine(c0, c0 - QPointF(sx * k, 0));
          p.drawLine(c0, c0 - QPointF(0, sy * k));
        }
    }
    p.setPen(c);
    // Label: the track number, and M while input estimation flags a manoeuvre.
    p.drawText(at.p + QPointF(r + 3, -r - 2),
               t.manoeuvring ? QStringLiteral("%1 M").arg(t.trackId) : QString::number(t.trackId));
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

QColor EcdisView::radarColour() const {
  const int n = static_cast<int>(std::size(kRadarColours));
  const QColor day = QColor::fromRgb(kRadarColours[std::clamp(overlay_.radarColour, 0, n - 1)].day);
  const charts::Palette pal = settings().palette;
  const double k = pal == charts::Palette::Day ? 1.0 : pal == charts::Palette::Dusk ? 0.8 : 0.45;
  return QColor::fromRgbF(static_cast<float>(day.redF() * k), static_cast<float>(day.greenF() * k),
                          static_cast<float>(day.blueF() * k));
}

void EcdisView::paintRadarPicture(QPainter& p) {
  const LiveFrame& live = history_->latest();
  if (!live.radarRaster || live.radarRaster->isNull()) return;
  const RadarRaster& r = *live.radarRaster;
  const QColor c = radarColour();
  if (radarImageOf_ != live.radarRaster.get() || radarImageColour_ != c.rgb()) {
    radarImage_ = QImage(r.mask.size(), QImage::Format_ARGB32_Premultiplied);
    for (int y = 0; y < r.mask.height(); ++y) {
      const uchar* in = r.mask.constScanLine(y);
      auto* out = reinterpret_cast<QRgb*>(radarImage_.scanLine(y));
      for (int x = 0; x < r.mask.width(); ++x)
        out[x] = in[x] ? qPremultiply(qRgba(c.red(), c.green(), c.blue(), in[x])) : 0;
    }
    radarImageOf_ = live.radarRaster.get();
    radarImageColour_ = c.rgb();
  }
  // Grid metres to widget pixels, linearised at the picture's centre (the chart's projection is
  // conformal; over a few miles the difference is under a pixel at radar scales).
  const QPointF o = gridToWidget(r.centreX, r.centreY);
  const QPointF ax = (gridToWidget(r.centreX + 1000.0, r.centreY) - o) / 1000.0;
  const QPointF ay = (gridToWidget(r.centreX, r.centreY + 1000.0) - o) / 1000.0;
  const QTransform gridT(ax.x(), ax.y(), ay.x(), ay.y(), o.x() - ax.x() * r.centreX - ay.x() * r.centreY,
                         o.y() - ax.y() * r.centreX - ay.y() * r.centreY);
  // Image pixel (u, v) to grid: x = cx + (u - n/2) m, y = cy - (v - n/2) m.
  const double m = r.metresPerPixel, h = 0.5 * r.mask.width() * m;
  const QTransform imageToGrid(m, 0.0, 0.0, -m, r.centreX - h, r.centreY + h);
  p.save();
  if (!overlay_.radarOverChart && live.land && !live.land->empty()) {
    if (waterOf_ != live.land.get()) {
      water_ = QPainterPath();
      water_.setFillRule(Qt::OddEvenFill);
      double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
      for (const auto& ring : live.land->rings()) {
        QPolygonF poly;
        poly.reserve(static_cast<qsizetype>(ring.size()));
        for (const auto& q : ring) {
          poly << QPointF(q[0], q[1]);
          x0 = std::min(x0, q[0]);
          y0 = std::min(y0, q[1]);
          x1 = std::max(x1, q[0]);
          y1 = std::max(y1, q[1]);
        }
        water_.addPolygon(poly);
        water_.closeSubpath();
      }
      const double pad = 50000.0;
      water_.addRect(QRectF(QPointF(x0 - pad, y0 - pad), QPointF(x1 + pad, y1 + pad)));
      waterOf_ = live.land.get();
    }
    p.setTransform(gridT);
    p.setClipPath(water_);
  }
  p.setTransform(imageToGrid * gridT);
  p.setOpacity(std::clamp(overlay_.radarOpacity, 0.05, 1.0));
  p.drawImage(QPointF(0.0, 0.0), radarImage_);
  p.restore();
}

void EcdisView::paintRadarEchoes(QPainter& p) {
  const LiveFrame& live = history_->latest();
  if (!live.radarMatch) return;
  const RadarMatchShown& m = *live.radarMatch;
  const QColor echo = radarColour().darker(130), chart = colour("tool");
  p.save();
  p.setPen(QPen(chart, 1.0));
  for (std::size_t i = 0; i < m.raw.size() && i < m.chart.size(); ++i)
    p.drawLine(gridToWidget(m.raw[i][0], m.raw[i][1]), gridToWidget(m.chart[i][0], m.chart[i][1]));
  p.setPen(QPen(echo, 1.5));
  p.setBrush(Qt::NoBrush);
  for (const auto& e : m.raw) p.drawRect(QRectF(gridToWidget(e[0], e[1]) - QPointF(2.5, 2.5), QSizeF(5, 5)));
  p.setPen(Qt::NoPen);
  p.setBrush(chart);
  for (const auto& c : m.chart) p.drawEllipse(gridToWidget(c[0], c[1]), 2.0, 2.0);
  p.restore();
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

QString EcdisView::cursorText(QPointF at) const {
  const charts::LatLon ll = viewport().toLatLon({at.x(), at.y()});
  QString s = latLonText(ll.latDeg, ll.lonDeg);
  if (history_ && !history_->empty() && frame_) {
    const auto& x = history_->latest().frame.estimate.x;
    const geo::GridPoint g = widgetToGrid(at);
    const double ox = x[est::drkf::kPosX], oy = x[est::drkf::kPosY];
    const double gamma = frame_->gridInfo({ox, oy}).convergenceRad;
    const double brg = wrapTwoPi(bearingOf(g.xM - ox, g.yM - oy) + gamma);
    const double range = std::hypot(g.xM - ox, g.yM - oy) / frame_->gridInfo({ox, oy}).scale;
    s += QStringLiteral("   %1° %2 NM")
             .arg(radToDeg(brg), 5, 'f', 1, QChar('0'))
             .arg(metresToNm(range), 0, 'f', 2);
  }
  return s;
}

void EcdisView::paintReadouts(QPainter& p) {
  QStringList lines;
  if (cursor_) lines << QStringLiteral("Cursor ") + cursorText(*cursor_);
  if (overlay_.eblBearingRad)
    lines << QStringLiteral("EBL %1°").arg(radToDeg(*overlay_.eblBearingRad), 5, 'f', 1, QChar('0'));
  if (overlay_.vrmRangeM)
    lines << QStringLiteral("VRM %1 NM").arg(metresToNm(*overlay_.vrmRangeM), 0, 'f', 2);
  if (addTargetFrom_ && steerTarget_)
    lines << QStringLiteral(
                 "Steer target %1: move to set its new vector (%2 min), click to order, Esc to cancel")
                 .arg(*steerTarget_)
                 .arg(overlay_.vectorMinutes);
  else if (addTargetFrom_)
    lines << QStringLiteral("New target: move to set its vector (%1 min), click to place, Esc to cancel")
                 .arg(overlay_.vectorMinutes);
  if (lines.isEmpty()) return;
  QFont font = p.font();
  font.setPointSizeF(9.0);
  p.setFont(font);
  const QFontMetrics fm(font);
  int w = 0;
  for (const QString& l : lines) w = std::max(w, fm.horizontalAdvance(l));
  const QRect box(6, 6, w + 12, static_cast<int>(lines.size()) * fm.height() + 8);
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
      menu->addAction(tr("Steer target %1 (simulation)…").arg(target), this,
                      [this, target, from] {
                        steerTarget_ = target;
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
