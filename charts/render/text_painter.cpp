// Text on the chart: fonts, soundings, names and light descriptions, contour labels (painting.h).
#include <QFontMetricsF>
#include <QLineF>
#include <algorithm>
#include <cmath>
#include <utility>

#include "charts/render/painting.h"

namespace reckoner::charts::paint {

Fonts makeFonts() {
  Fonts f;
  f.sounding = QFont("DejaVu Sans");
  f.sounding.setPixelSize(static_cast<int>(Ctx::mm(2.6)));
  f.soundingBold = f.sounding;
  f.soundingBold.setBold(true);
  f.soundingSmall = f.sounding;
  f.soundingSmall.setPixelSize(static_cast<int>(Ctx::mm(1.9)));
  f.soundingSmallBold = f.soundingSmall;
  f.soundingSmallBold.setBold(true);
  f.text = f.sounding;
  f.text.setPixelSize(static_cast<int>(Ctx::mm(2.4)));
  f.contour = f.sounding;
  f.contour.setPixelSize(static_cast<int>(Ctx::mm(2.0)));
  f.soundingAscent = QFontMetricsF(f.sounding).ascent();
  return f;
}

void drawSoundings(Ctx& c, const PreparedCell& pc, const PreparedItem& it) {
  const PartSpan& part = pc.parts()[it.firstPart];
  const auto& depths = it.f->geometry.depthsM;
  const QFontMetricsF fm(c.fonts.sounding), fmBold(c.fonts.soundingBold);
  const QColor deep = c.colour("SNDG1"), shallowColour = c.colour("SNDG2");
  const double w = c.view.width(), h = c.view.height();
  for (std::uint32_t i = 0; i < part.count && i < depths.size(); ++i) {
    const QPointF at = c.pt(pc.points()[part.first + i]);
    if (at.x() < -20 || at.y() < -20 || at.x() > w + 20 || at.y() > h + 20) continue;
    const double d = depths[i];
    const auto [whole, tenth] = soundingText(d);
    const bool shallow = d <= c.s.safetyDepthM;
    c.p.setPen(shallow ? shallowColour : deep);
    c.p.setFont(shallow ? c.fonts.soundingBold : c.fonts.sounding);
    const QString w1 = QString::fromStdString(whole);
    const double wWhole = (shallow ? fmBold : fm).horizontalAdvance(w1);
    const double base = at.y() + c.fonts.soundingAscent / 2;
    c.p.drawText(QPointF(at.x() - wWhole / 2, base), w1);
    if (!tenth.empty()) {
      c.p.setFont(shallow ? c.fonts.soundingSmallBold : c.fonts.soundingSmall);
      c.p.drawText(QPointF(at.x() + wWhole / 2, base + Ctx::mm(0.6)), QString::fromStdString(tenth));
    }
    if (d < 0)  // drying height: underlined
      c.p.drawLine(QPointF(at.x() - wWhole / 2, base + 2), QPointF(at.x() + wWhole / 2, base + 2));
  }
}

void drawText(Ctx& c, const QString& text, QPointF at, const QColor& colour) {
  c.labels.push_back({text, QPointF(at.x() + Ctx::mm(2.5), at.y() + Ctx::mm(1.0)), colour});
}

void drawLabels(Ctx& c) {
  c.p.setFont(c.fonts.text);
  const QFontMetricsF fm(c.fonts.text);
  const double line = fm.height();
  // Labels anchored at the same point (the sectors of one light, a buoy and its light) are stacked.
  // The same text where it would overlap its copy is written once: NOAA encodes an anchorage as an
  // ACHARE and a SEAARE with the same ring and OBJNAM, and both rules write the name.
  std::vector<std::pair<QPointF, int>> anchors;
  std::vector<std::pair<const QString*, QRectF>> written;  // text and box at its anchor
  for (const auto& l : c.labels) {
    const QRectF atAnchor(l.at.x(), l.at.y() - fm.ascent(), fm.horizontalAdvance(l.text), line);
    const bool copy = std::any_of(written.begin(), written.end(), [&](const auto& w) {
      return *w.first == l.text && w.second.intersects(atAnchor);
    });
    if (copy) continue;
    written.emplace_back(&l.text, atAnchor);
    int stacked = 0;
    for (auto& [at, n] : anchors)
      if (std::abs(at.x() - l.at.x()) < 1.0 && std::abs(at.y() - l.at.y()) < 1.0) stacked = n++;
    if (stacked == 0) anchors.emplace_back(l.at, 1);
    c.p.setPen(l.colour);
    c.p.drawText(QPointF(l.at.x(), l.at.y() + stacked * line), l.text);
    if (c.written) c.written->push_back({l.text, atAnchor.translated(0, stacked * line)});
  }
  c.labels.clear();
}

/// Depth contour value labels: one per line part long enough on screen, at its middle vertex.
void drawContourLabel(Ctx& c, const PreparedCell& pc, const PreparedItem& it, double value) {
  const QString label = QString::number(value, 'g', 4);
  c.p.setFont(c.fonts.contour);
  c.p.setPen(c.colour("DEPCN"));
  for (std::uint32_t k = 0; k < it.partCount; ++k) {
    const PartSpan& part = pc.parts()[it.firstPart + k];
    if (part.count < 2 || !c.onScreen(part.lo, part.hi)) continue;
    const QPointF a = c.pt(pc.points()[part.first]), b = c.pt(pc.points()[part.first + part.count - 1]);
    const QPointF lo = c.pt(part.lo), hi = c.pt(part.hi);
    if (std::abs(hi.x() - lo.x()) + std::abs(hi.y() - lo.y()) < 150 && QLineF(a, b).length() < 150) continue;
    const QPointF mid = c.pt(pc.points()[part.first + part.count / 2]);
    if (mid.x() < 0 || mid.y() < 0 || mid.x() > c.view.width() || mid.y() > c.view.height()) continue;
    c.p.drawText(QPointF(mid.x() + 2, mid.y() - 2), label);
  }
}

}  // namespace reckoner::charts::paint
