// EcdisView's indications: the scale bar (bottom right), the display modes and the north arrow (top
// right) and the readouts (top left: cursor, EBL, VRM, what a mouse mode expects). Each returns the box
// it took, which the labels keep out of. Own ship and targets are painted in ecdis_paint.cpp.
#include <QPainter>
#include <algorithm>
#include <cmath>

#include "common/angles.h"
#include "common/units.h"
#include "ui/map/ecdis_view.h"

namespace reckoner::ui {
namespace {
/// Nice scale-bar length (1, 2 or 5 times a power of ten) not longer than maxM.
double niceLength(double maxM) {
  const double p = std::pow(10.0, std::floor(std::log10(maxM)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * p <= maxM) return m * p;
  return p;
}

/// Lines of text in a box of the panel colour at `topLeft` (or, rightAligned, with its top right there).
/// The box paintBox draws for `lines` from `base` (the painter's font) without drawing it.
QRectF boxRect(const QStringList& lines, QPointF corner, bool rightAligned, QFont font, double pointSize,
               bool bold) {
  if (lines.isEmpty()) return {};
  font.setPointSizeF(pointSize);
  font.setBold(bold);
  const QFontMetrics fm(font);
  int w = 0;
  for (const QString& l : lines) w = std::max(w, fm.horizontalAdvance(l));
  const QSizeF size(w + 12, static_cast<double>(lines.size()) * fm.height() + 8);
  return {rightAligned ? corner - QPointF(size.width(), 0) : corner, size};
}

QRectF paintBox(QPainter& p, const QStringList& lines, QPointF corner, bool rightAligned, const QColor& panel,
                const QColor& text, double pointSize, bool bold) {
  if (lines.isEmpty()) return {};
  const QRectF box = boxRect(lines, corner, rightAligned, p.font(), pointSize, bold);
  QFont font = p.font();
  font.setPointSizeF(pointSize);
  font.setBold(bold);
  p.setFont(font);
  const QFontMetrics fm(font);
  QColor bg = panel;
  bg.setAlpha(200);
  p.setPen(Qt::NoPen);
  p.setBrush(bg);
  p.drawRect(box);
  p.setPen(text);
  for (int i = 0; i < lines.size(); ++i)
    p.drawText(QPointF(box.left() + 6, box.top() + 4 + fm.ascent() + i * fm.height()), lines[i]);
  return box;
}
}  // namespace

void EcdisView::paintScaleBar(QPainter& p, const charts::Viewport& view) {
  const double mpp = view.metresPerPixel();
  if (!(mpp > 0.0)) return;
  const double maxM = mpp * width() * 0.25;
  // In the distance unit (NM or km) from a fifth of a mile or a kilometre, in metres below.
  const DistanceUnit u = units_.distance;
  const bool big = u == DistanceUnit::NauticalMiles ? maxM >= nmToMetres(0.2) : maxM >= metresFrom(1.0, u);
  const double len = big ? metresFrom(niceLength(distanceIn(maxM, u)), u) : niceLength(maxM);
  const double px = len / mpp;
  // Bottom right (the not-for-navigation notice takes the bottom left).
  const QPointF a(width() - 16 - px, height() - 14), b(width() - 16, height() - 14);
  p.setPen(QPen(colour("text"), 2.0));
  p.drawLine(a, b);
  p.drawLine(a, a - QPointF(0, 6));
  p.drawLine(b, b - QPointF(0, 6));
  const QString label = big ? QStringLiteral("%1 %2").arg(distanceIn(len, u), 0, 'g', 3).arg(unitName(u))
                            : QStringLiteral("%1 m").arg(len, 0, 'f', 0);
  QFont font = p.font();
  font.setPointSizeF(9.0);
  font.setBold(false);
  p.setFont(font);
  p.drawText(a + QPointF(2, -8), label);
  labelObstacles_.push_back(QRectF(a.x() - 2, a.y() - 24, px + 4, 28));
}

void EcdisView::paintNorthArrow(QPainter& p, const charts::Viewport& view, QPointF c) {
  // A disc of the panel colour with a bold arrow to true north and an N at its tip, in the text
  // colour (black by day, light at dusk and night): readable on any chart colour.
  constexpr double kRadius = 24.0;
  QColor bg = colour("panel");
  bg.setAlpha(230);
  p.setPen(QPen(colour("text"), 1.5));
  p.setBrush(bg);
  p.drawEllipse(c, kRadius, kRadius);
  const double r = view.rotationRad();
  const QPointF up(-std::sin(r), -std::cos(r)), side(-up.y(), up.x());
  const QPointF tip = c + up * 13.0, tail = c - up * 13.0;
  p.setBrush(colour("text"));
  p.drawPolygon(QPolygonF{tip, c + side * 6.0, c - side * 6.0});
  p.setBrush(Qt::NoBrush);
  p.drawPolygon(QPolygonF{tail, c + side * 6.0, c - side * 6.0});
  QFont font = p.font();
  font.setPointSizeF(9.0);
  font.setBold(true);
  p.setFont(font);
  const QPointF n = c + up * 19.5;
  p.drawText(QRectF(n - QPointF(7, 7), QSizeF(14, 14)), Qt::AlignCenter, QStringLiteral("N"));
}

QStringList EcdisView::modeLines() const {
  static const char* const kOrientation[] = {"N UP", "C UP", "H UP"};
  QString motion = overlay_.motion == Motion::Relative ? QStringLiteral("RM") : QStringLiteral("TM");
  if (overlay_.offCentred) motion += QStringLiteral(" off-centred");
  QStringList lines{QStringLiteral("%1   %2").arg(
                        QString::fromLatin1(kOrientation[static_cast<int>(overlay_.orientation)]), motion),
                    QStringLiteral("VECT %1 %2 min")
                        .arg(overlay_.relativeVectors ? QStringLiteral("R") : QStringLiteral("T"))
                        .arg(overlay_.vectorMinutes, 0, 'g', 3)};
  if (!overlay_.followOwnShip) lines << QStringLiteral("NOT FOLLOWING (C: own ship)");
  return lines;
}

QRectF EcdisView::paintModes(QPainter& p) {
  const QRectF box =
      paintBox(p, modeLines(), QPointF(width() - 6.0, 6.0), true, colour("panel"), colour("text"), 9.0, true);
  northArrowAt_.reset();
  if (overlay_.orientation == Orientation::NorthUp) return box;
  const QPointF c(box.right() - 30.0, box.bottom() + 34.0);
  northArrowAt_ = c;
  paintNorthArrow(p, viewport(), c);
  return box.united(QRectF(c - QPointF(26, 26), QSizeF(52, 52)));
}

QStringList EcdisView::readoutLines() const {
  QStringList lines;
  if (cursor_) lines << QStringLiteral("Cursor ") + cursorText(*cursor_);
  if (overlay_.eblBearingRad) lines << QStringLiteral("EBL ") + formatBearing(*overlay_.eblBearingRad);
  if (overlay_.vrmRangeM) lines << QStringLiteral("VRM ") + formatDistance(*overlay_.vrmRangeM, units_);
  if (addTargetFrom_ && steerTarget_)
    lines << QStringLiteral(
                 "Steer track %1: move to set its new vector (%2 min), click to order, Esc to cancel")
                 .arg(steerTrack_)
                 .arg(overlay_.vectorMinutes);
  else if (addTargetFrom_)
    lines << QStringLiteral("New target: move to set its vector (%1 min), click to place, Esc to cancel")
                 .arg(overlay_.vectorMinutes);
  if (routeOverlay_->editing())
    lines << QStringLiteral(
        "ROUTE EDIT: click adds a waypoint, drag moves one, right button inserts, deletes, renames; Esc "
        "ends");
  return lines;
}

QRect EcdisView::readoutRect() const {
  return boxRect(readoutLines(), QPointF(6.0, 6.0), false, font(), 9.0, false).toAlignedRect();
}

QRectF EcdisView::paintReadouts(QPainter& p) {
  p.setFont(font());  // readoutRect's font
  const QRectF box =
      paintBox(p, readoutLines(), QPointF(6.0, 6.0), false, colour("panel"), colour("text"), 9.0, false);
  if (addTargetFrom_ && addTargetTo_) {
    const QPointF from = gridToWidget(addTargetFrom_->xM, addTargetFrom_->yM);
    p.setPen(QPen(colour("target"), 2.0, Qt::DashLine));
    p.setBrush(Qt::NoBrush);
    p.drawEllipse(from, 8.0, 8.0);
    p.drawLine(from, *addTargetTo_);
  }
  return box;
}

}  // namespace reckoner::ui
