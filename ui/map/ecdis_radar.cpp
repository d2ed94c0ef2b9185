// EcdisView's radar overlay (seed 004): the simulated picture, coloured and drawn through the chart's
// local linearisation over the chart or clipped to its water, and the echoes of the latest match with
// the chart points they were matched to. The other overlays are painted in ecdis_paint.cpp.
#include <QPainter>
#include <QPainterPath>
#include <algorithm>

#include "ui/map/ecdis_view.h"

namespace reckoner::ui {

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
  if (radarImageOf_ != live.radarRaster || radarImageColour_ != c.rgb()) {
    radarImage_ = QImage(r.mask.size(), QImage::Format_ARGB32_Premultiplied);
    for (int y = 0; y < r.mask.height(); ++y) {
      const uchar* in = r.mask.constScanLine(y);
      auto* out = reinterpret_cast<QRgb*>(radarImage_.scanLine(y));
      for (int x = 0; x < r.mask.width(); ++x)
        out[x] = in[x] ? qPremultiply(qRgba(c.red(), c.green(), c.blue(), in[x])) : 0;
    }
    radarImageOf_ = live.radarRaster;
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
    if (waterOf_ != live.land) {
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
      waterOf_ = live.land;
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

}  // namespace reckoner::ui
