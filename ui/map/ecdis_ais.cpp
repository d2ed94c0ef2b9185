#include "ui/map/ecdis_ais.h"

#include <QDateTime>
#include <QLineF>
#include <QPainterPath>
#include <QPolygonF>
#include <QStringList>
#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <unordered_map>
#include <vector>

#include "common/angles.h"
#include "common/units.h"
#include "ui/map/ecdis_view.h"

namespace reckoner::ui {

namespace {

constexpr double kActivatedUnits = 14.0;  // triangle height, logical units
constexpr double kSleepingUnits = 10.0;

/// Screen point at `forward` along screen angle a and `right` across it from c (y down).
QPointF along(QPointF c, double a, double forward, double right) {
  const double s = std::sin(a), k = std::cos(a);
  return {c.x() + forward * s + right * k, c.y() - forward * k + right * s};
}

/// Drawn with the bold red pen: a dangerous target, a distress, while not lost.
bool alarmed(const AisSymbol& s) {
  return (s.dangerous || s.distress) && !s.lost;
}

int paintOrder(const AisSymbol& s) {
  return alarmed(s) ? 3 : s.selected ? 2 : s.activated ? 1 : 0;
}

/// The shapes of the symbols of one layer and pen, drawn together: one drawLines call per pen instead
/// of a pen change and a call per line (QPainter's cost with 2000 targets is in the calls and the
/// dash stroking, not in the pixels).
struct Batch {
  std::vector<QPolygonF> polygons;
  std::vector<QLineF> lines, dashed;
  /// Search and rescue devices: circles and the crosses in them (dashed in the alarm pen's batch).
  std::vector<QRectF> rings;
  std::vector<QLineF> ringCrosses;
};

/// The device symbol: a circle 1.4 h across (5 mm on a 96 dpi screen; IEC 62288 asks 5 mm) with a
/// cross inside, not turned with the heading.
void collectDevice(Batch& b, QPointF c, double h) {
  const double r = 0.7 * h, d = r * std::sqrt(0.5);
  b.rings.emplace_back(c.x() - r, c.y() - r, 2.0 * r, 2.0 * r);
  b.ringCrosses.emplace_back(QPointF(c.x() - d, c.y() - d), QPointF(c.x() + d, c.y() + d));
  b.ringCrosses.emplace_back(QPointF(c.x() - d, c.y() + d), QPointF(c.x() + d, c.y() - d));
}

void collect(Batch& b, const AisSymbol& s, const AisPaintGeometry& g, const AisPaintStyle& st) {
  const QPointF c = g.toWidget(s.xM, s.yM);
  const bool oriented = s.headingGridRad || s.cogGridRad;
  const double a = s.headingGridRad.value_or(s.cogGridRad.value_or(0.0)) + g.gridNorthScreenRad;
  const double h = (s.activated ? kActivatedUnits : kSleepingUnits) * st.scale;

  // The hull to scale when it is larger on screen than the triangle (the position is the reference
  // point: A to the bow, B to the stern, C to port, D to starboard).
  QPointF bow = along(c, a, h / 2.0, 0.0);
  if (s.device) collectDevice(b, c, h);
  const bool scaled = !s.device && oriented && s.toBowM && s.toSternM && s.toPortM && s.toStarboardM &&
                      (*s.toBowM + *s.toSternM) * g.pixelsPerMetre > h;
  if (scaled) {
    const double ppm = g.pixelsPerMetre;
    const double A = *s.toBowM * ppm, B = *s.toSternM * ppm, C = *s.toPortM * ppm, D = *s.toStarboardM * ppm;
    const double shoulder = A - 0.2 * (A + B);
    bow = along(c, a, A, (D - C) / 2.0);
    b.polygons.push_back(QPolygonF(
        {along(c, a, -B, -C), along(c, a, shoulder, -C), bow, along(c, a, shoulder, D), along(c, a, -B, D)}));
  } else if (!s.device) {
    b.polygons.push_back(QPolygonF({bow, along(c, a, -h / 2.0, -0.3 * h), along(c, a, -h / 2.0, 0.3 * h)}));
  }

  if (s.lost) {  // crossed out, no vector
    // A screen-aligned X over the symbol, whatever its heading (past the device's circle).
    const double r = (s.device ? 1.1 : 0.75) * h;
    b.lines.emplace_back(QPointF(c.x() - r, c.y() - r), QPointF(c.x() + r, c.y() + r));
    b.lines.emplace_back(QPointF(c.x() - r, c.y() + r), QPointF(c.x() + r, c.y() - r));
    return;
  }
  if (s.activated) {
    if (s.headingGridRad && !s.device) {
      const double lineLen = 2.0 * h;
      const double ha = *s.headingGridRad + g.gridNorthScreenRad;
      const QPointF end = along(bow, ha, lineLen, 0.0);
      b.lines.emplace_back(bow, end);
      if (s.turn != 0) b.lines.emplace_back(end, along(end, ha, 0.0, s.turn * 0.4 * h));
    }
    if (s.cogGridRad && s.sogMps > 0.0) {
      const double len = s.sogMps * st.vectorMinutes * 60.0 * g.pixelsPerMetre;
      b.dashed.emplace_back(c, along(c, *s.cogGridRad + g.gridNorthScreenRad, len, 0.0));
    }
  }
  if (s.selected) {  // four corner brackets of a square 2.4 h wide
    const double r = 1.2 * h, arm = 0.4 * h;
    for (const int sx : {-1, 1})
      for (const int sy : {-1, 1}) {
        const QPointF corner(c.x() + sx * r, c.y() + sy * r);
        b.lines.emplace_back(corner, QPointF(corner.x() - sx * arm, corner.y()));
        b.lines.emplace_back(corner, QPointF(corner.x(), corner.y() - sy * arm));
      }
  }
}

void draw(QPainter& p, const Batch& b, const QColor& colour, double width, bool dashedRings) {
  QPen pen(colour, width);
  pen.setJoinStyle(Qt::MiterJoin);
  p.setPen(pen);
  p.setBrush(Qt::NoBrush);
  for (const QPolygonF& poly : b.polygons) p.drawPolygon(poly);
  if (!b.lines.empty()) p.drawLines(b.lines.data(), static_cast<int>(b.lines.size()));
  if (!b.rings.empty()) {
    QPen ring = pen;
    if (dashedRings) ring.setDashPattern({2.0, 1.5});  // in pen widths: at 3 px, 6 px dashes, 4.5 px gaps
    p.setPen(ring);
    for (const QRectF& r : b.rings) p.drawEllipse(r);
    p.drawLines(b.ringCrosses.data(), static_cast<int>(b.ringCrosses.size()));
    p.setPen(pen);
  }
  if (!b.dashed.empty()) {
    pen.setStyle(Qt::DashLine);
    p.setPen(pen);
    p.drawLines(b.dashed.data(), static_cast<int>(b.dashed.size()));
  }
}

QString optText(const std::optional<double>& v, const char* fmt) {
  return v ? QString::asprintf(fmt, *v) : QStringLiteral("n/a");
}

}  // namespace

std::optional<AisSymbol> aisSymbolOf(const track::AisTarget& t, const geo::LocalFrame& frame, TimeUs now,
                                     double turningRotDegMin) {
  if (!t.hasPosition()) return std::nullopt;
  geo::GridPoint p = frame.toLocal({*t.latDeg, *t.lonDeg});
  if (!std::isfinite(p.xM) || !std::isfinite(p.yM)) return std::nullopt;
  const double conv = frame.gridInfo(p).convergenceRad;
  AisSymbol s;
  s.mmsi = t.mmsi;
  if (t.headingDeg) s.headingGridRad = degToRad(*t.headingDeg) - conv;
  if (t.cogDeg) s.cogGridRad = degToRad(*t.cogDeg) - conv;
  s.sogMps = t.sogKn ? knotsToMps(*t.sogKn) : 0.0;
  if (s.cogGridRad && !t.lost) {  // where the reported motion has taken it by now
    const double dtS = toSeconds(now - t.lastPositionUs);
    p.xM += s.sogMps * std::sin(*s.cogGridRad) * dtS;
    p.yM += s.sogMps * std::cos(*s.cogGridRad) * dtS;
  }
  s.xM = p.xM;
  s.yM = p.yM;
  if (t.rotFast != 0)
    s.turn = t.rotFast;
  else if (t.rotDegMin && std::abs(*t.rotDegMin) >= turningRotDegMin)
    s.turn = *t.rotDegMin > 0.0 ? 1 : -1;
  auto dim = [](const std::optional<int>& v) { return v ? std::optional<double>(*v) : std::nullopt; };
  s.toBowM = dim(t.info.toBowM);
  s.toSternM = dim(t.info.toSternM);
  s.toPortM = dim(t.info.toPortM);
  s.toStarboardM = dim(t.info.toStarboardM);
  s.activated = t.activated;
  s.selected = t.selected;
  s.dangerous = t.dangerous;
  s.lost = t.lost;
  s.device = t.device != track::AisDevice::None;
  s.distress = t.distress();
  return s;
}

void paintAisTargets(QPainter& p, const std::vector<AisSymbol>& symbols, const AisPaintGeometry& g,
                     const AisPaintStyle& style) {
  p.save();
  p.setRenderHint(QPainter::Antialiasing, true);
  // Layers bottom to top (sleeping, activated, selected, dangerous); in each, the symbols of the plain
  // pen and those of the dangerous (bold red) pen.
  std::array<std::array<Batch, 2>, 4> layers;
  for (const AisSymbol& s : symbols) {
    // A dangerous target flashes; a distress until its alarm is acknowledged (then it is steady).
    const bool flashes = !s.lost && (s.dangerous || (s.distress && s.unacknowledged));
    if (flashes && !style.flashOn) continue;
    collect(layers[static_cast<std::size_t>(paintOrder(s))][alarmed(s) ? 1 : 0], s, g, style);
  }
  for (const auto& layer : layers) {
    draw(p, layer[0], style.colour, 1.0 * style.scale, false);
    draw(p, layer[1], style.dangerous, 3.0 * style.scale, true);
  }
  p.restore();
}

QString aisPickReport(const track::AisTarget& t) {
  QStringList l;
  if (t.device != track::AisDevice::None)
    l << QStringLiteral("%1 %2  %3")
             .arg(QString::fromLatin1(track::aisDeviceName(t.device)))
             .arg(t.mmsi)
             .arg(t.deviceTest ? QStringLiteral("TEST") : QStringLiteral("ACTIVE: DISTRESS"));
  else
    l << QStringLiteral("AIS %1  class %2").arg(t.mmsi).arg(QString::fromLatin1(track::aisClassName(t.cls)));
  const auto& s = t.info;
  if (!s.name.empty()) l << QStringLiteral("Name %1").arg(QString::fromStdString(s.name));
  if (!s.callsign.empty()) l << QStringLiteral("Call sign %1").arg(QString::fromStdString(s.callsign));
  if (s.imo) l << QStringLiteral("IMO %1").arg(*s.imo);
  if (s.shipType) l << QStringLiteral("Ship type %1").arg(*s.shipType);
  if (s.lengthM() && s.beamM())
    l << QStringLiteral("Length %1 m, beam %2 m").arg(*s.lengthM()).arg(*s.beamM());
  if (s.draughtM) l << QStringLiteral("Draught %1 m").arg(*s.draughtM, 0, 'f', 1);
  if (!s.destination.empty())
    l << QStringLiteral("Destination %1").arg(QString::fromStdString(s.destination));
  if (s.etaMonth || s.etaDay || s.etaHour || s.etaMinute) {
    auto part = [](const std::optional<int>& v) {
      return v ? QStringLiteral("%1").arg(*v, 2, 10, QLatin1Char('0')) : QStringLiteral("--");
    };
    l << QStringLiteral("ETA %1-%2 %3:%4 UTC")
             .arg(part(s.etaMonth), part(s.etaDay), part(s.etaHour), part(s.etaMinute));
  }
  if (t.navStatus) l << QStringLiteral("Navigational status %1").arg(*t.navStatus);
  if (!t.safetyText.empty())
    l << QStringLiteral("Safety message: %1").arg(QString::fromStdString(t.safetyText));
  if (t.positionNotFix)
    l << QStringLiteral("Position NOT A FIX: %1 (time stamp %2)")
             .arg(*t.positionNotFix == 61   ? QStringLiteral("manual input")
                  : *t.positionNotFix == 62 ? QStringLiteral("dead reckoning")
                                            : QStringLiteral("positioning system inoperative"))
             .arg(*t.positionNotFix);
  l << QStringLiteral("SOG %1 kn  COG %2°  HDG %3")
           .arg(optText(t.sogKn, "%.1f"), optText(t.cogDeg, "%.1f"),
                t.headingDeg ? QStringLiteral("%1°").arg(*t.headingDeg) : QStringLiteral("n/a"));
  if (t.rotDegMin) l << QStringLiteral("ROT %1°/min").arg(*t.rotDegMin, 0, 'f', 1);
  if (t.cpaValid)
    l << QStringLiteral("CPA %1 NM  TCPA %2 min")
             .arg(metresToNm(t.cpa.cpaM), 0, 'f', 2)
             .arg(t.cpa.tcpaS / 60.0, 0, 'f', 1);
  QStringList state;
  state << (t.activated ? QStringLiteral("activated") : QStringLiteral("sleeping"));
  if (t.dangerous) state << QStringLiteral("DANGEROUS");
  if (t.lost) state << QStringLiteral("LOST");
  l << state.join(QStringLiteral(", "));
  return l.join(QLatin1Char('\n'));
}

void EcdisView::paintAis(QPainter& p) {
  const LiveFrame& live = history_->latest();
  if (!live.aisTargets || live.aisTargets->empty()) return;
  if (aisSymbolsOf_ != live.aisTargets) {
    aisSymbols_.clear();
    aisSymbols_.reserve(live.aisTargets->size());
    for (const track::AisTarget& t : *live.aisTargets)
      if (auto s = aisSymbolOf(t, *frame_, live.aisUtc)) aisSymbols_.push_back(*s);
    aisSymbolsOf_ = live.aisTargets;
  }
  const geo::GridPoint c = ccrpGrid();
  const Local at = localAt(c.xM, c.yM);
  AisPaintGeometry g;
  g.toWidget = [this](double xM, double yM) { return gridToWidget(xM, yM); };
  g.pixelsPerMetre = at.pxPerMetre();
  g.gridNorthScreenRad = std::atan2(at.b, -at.d);  // grid north (0, 1) on screen, clockwise from up
  AisPaintStyle style;
  style.colour = colour("ais");
  style.dangerous = colour("danger");
  style.vectorMinutes = overlay_.vectorMinutes;
  style.flashOn = (QDateTime::currentMSecsSinceEpoch() / 500) % 2 == 0;
  // A station associated with a radar track is one target: drawn activated (with its vector) in place
  // of the radar symbol, or left out when the radar symbol stands for it (unless its track is selected,
  // or it is a search and rescue device).
  std::unordered_map<std::uint32_t, int> trackOf;
  for (const auto& t : live.frame.tracks)
    if (t.aisMmsi != 0) trackOf[t.aisMmsi] = t.trackId;
  // The distresses whose alarm is not acknowledged yet flash (silenced is not acknowledged).
  std::set<std::uint32_t> unacknowledged;
  for (const alerts::Alert& a : live.alerts)
    if (a.id.kind == alerts::AlertKind::AisDistress && a.state != alerts::AlertState::Acknowledged)
      unacknowledged.insert(static_cast<std::uint32_t>(a.id.source));
  if (trackOf.empty() && unacknowledged.empty() && overlay_.showAis) {
    paintAisTargets(p, aisSymbols_, g, style);
    return;
  }
  std::vector<AisSymbol> shown;
  shown.reserve(aisSymbols_.size());
  for (const AisSymbol& s : aisSymbols_) {
    // The AIS layer switched off hides every target but a distress (IEC 62388: never filtered out).
    if (!overlay_.showAis && !s.distress) continue;
    const auto it = trackOf.find(s.mmsi);
    if (it == trackOf.end()) {
      shown.push_back(s);
    } else if (!overlay_.associatedAsRadar || selected_ == it->second || s.device) {
      // (a search and rescue device's symbol is never left out for its radar track's)
      shown.push_back(s);
      shown.back().activated = true;
    } else {
      continue;
    }
    shown.back().unacknowledged = unacknowledged.contains(s.mmsi);
  }
  paintAisTargets(p, shown, g, style);
}

}  // namespace reckoner::ui
