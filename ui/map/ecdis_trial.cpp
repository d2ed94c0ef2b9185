// The trial manoeuvre on the chart (docs/trial.md, docs/gui.md "Trial manoeuvre"): the collision-danger
// sectors around own ship (courses and speeds that would bring a target inside the CPA limit), own
// ship's trial path, each target's predicted closest approach (own and target at the CPA, joined) with
// CPA, sd and P(CPA < limit), and the "T" that IEC 62388 asks for while a trial is shown. Everything
// drawn is the frame's sim::TrialResult, converted to pixels.
#include <QPainterPath>
#include <QPolygonF>

#include <cmath>

#include "common/angles.h"
#include "common/units.h"
#include "ui/map/ecdis_view.h"

namespace reckoner::ui {

void EcdisView::paintDangerSectors(QPainter& p, const sim::TrialResult& r, const Local& own) {
  const auto& d = r.sectors;
  if (d.courses <= 0 || d.speedsMps.empty()) return;
  // A speed ring's radius is the distance that speed covers in the vector time (the vectors' scale).
  const double vectorS = overlay_.vectorMinutes * 60.0;
  const double gamma = frame_->gridInfo(ccrpGrid()).convergenceRad;
  const double cell = kTwoPi / d.courses;
  QPainterPath path;
  for (std::size_t i = 0; i < d.speedsMps.size(); ++i) {
    const double inner = i == 0 ? 0.0 : d.speedsMps[i - 1] * vectorS, outer = d.speedsMps[i] * vectorS;
    for (const auto& [j, k] : d.dangerousRuns(i)) {
      // Cells j..k: from half a cell before j to half a cell after k, true courses.
      const double a0 = (j - 0.5) * cell - gamma, a1 = (k + 0.5) * cell - gamma;
      QPolygonF poly;
      const int steps = std::max(2, (k - j + 1) * 2);
      for (int s = 0; s <= steps; ++s) {
        const double a = a0 + (a1 - a0) * s / steps;
        poly << own.offset(outer * std::sin(a), outer * std::cos(a));
      }
      for (int s = steps; s >= 0; --s) {
        const double a = a0 + (a1 - a0) * s / steps;
        poly << own.offset(inner * std::sin(a), inner * std::cos(a));
      }
      path.addPolygon(poly);
      path.closeSubpath();
    }
  }
  QColor fill = colour("danger");
  fill.setAlpha(55);
  p.setPen(Qt::NoPen);
  p.setBrush(fill);
  p.drawPath(path);
}

void EcdisView::paintTrial(QPainter& p) {
  const LiveFrame& live = history_->latest();
  if (!live.trial || !frame_) return;
  const sim::TrialResult& r = *live.trial;
  const geo::GridPoint c = ccrpGrid();
  const Local own = localAt(c.xM, c.yM);
  p.save();
  paintDangerSectors(p, r, own);

  // Own ship's trial path and the trial vector.
  const QColor trialColour = colour("tool");
  p.setBrush(Qt::NoBrush);
  p.setPen(QPen(trialColour, 2.0, Qt::DashLine));
  QPolygonF path;
  for (const auto& g : r.ownPath) path << gridToWidget(g.xM, g.yM);
  p.drawPolyline(path);

  // Each target's closest approach under the trial.
  QFont small = p.font();
  small.setPointSizeF(8.0);
  p.setFont(small);
  for (const auto& t : r.targets) {
    if (t.tcpaS <= 0.0 || t.tcpaS > 3.0 * 3600.0) continue;  // opening now, or hours away
    const QPointF tp = gridToWidget(t.targetAtCpa.xM, t.targetAtCpa.yM);
    const QPointF op = gridToWidget(t.ownAtCpa.xM, t.ownAtCpa.yM);
    const QColor col = t.dangerous ? colour("danger") : trialColour;
    p.setPen(QPen(col, t.dangerous ? 2.0 : 1.2, Qt::DotLine));
    p.drawLine(op, tp);
    p.setPen(QPen(col, 1.5));
    p.drawEllipse(tp, 4.0, 4.0);
    if (!t.dangerous && t.probabilityBelowLimit < 0.01) continue;  // label the ones that matter
    p.drawText(tp + QPointF(6.0, -4.0), QStringLiteral("CPA %1±%2  %3 min  P %4%")
                                            .arg(metresToNm(t.cpaM), 0, 'f', 2)
                                            .arg(metresToNm(t.sdCpaM), 0, 'f', 2)
                                            .arg(t.tcpaS / 60.0, 0, 'f', 1)
                                            .arg(100.0 * t.probabilityBelowLimit, 0, 'f', 0));
  }

  // "T" (IEC 62388): prominent while the trial is shown, with the order.
  QFont big = p.font();
  big.setPointSizeF(26.0);
  big.setBold(true);
  p.setFont(big);
  const QRectF box(width() / 2.0 - 24.0, 8.0, 48.0, 44.0);
  p.setPen(QPen(colour("danger"), 2.0));
  p.setBrush(colour("panel"));
  p.drawRect(box);
  p.drawText(box, Qt::AlignCenter, QStringLiteral("T"));
  QFont note = p.font();
  note.setPointSizeF(8.5);
  note.setBold(false);
  p.setFont(note);
  p.setPen(colour("text"));
  p.drawText(QRectF(box.left() - 80.0, box.bottom() + 2.0, box.width() + 160.0, 16.0), Qt::AlignCenter,
             QStringLiteral("TRIAL %1° %2 kn after %3 s")
                 .arg(radToDeg(r.order.courseRad), 0, 'f', 0)
                 .arg(mpsToKnots(r.order.speedMps), 0, 'f', 1)
                 .arg(r.order.delayS, 0, 'f', 0));
  p.restore();
}

}  // namespace reckoner::ui
