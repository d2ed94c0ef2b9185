// The world background: GSHHG land and water, shorelines, graticule and note (world_layer.h).
#include "charts/render/world_layer.h"

#include <QFont>
#include <QFontMetricsF>
#include <QPainter>
#include <QString>
#include <algorithm>
#include <cmath>
#include <optional>
#include <string_view>
#include <utility>

#include "charts/render/chart_renderer.h"
#include "charts/world/graticule.h"
#include "charts/world/world_data.h"
#include "common/angles.h"
#include "io/text_format.h"

namespace reckoner::charts {

using paint::Ctx;

namespace {

constexpr double kTurn = 2.0 * kPi;
/// At most this many copies of the world side by side (a view wider than the world repeats it).
constexpr int kMaxTurns = 6;

QColor mix(const QColor& a, const QColor& b, double t) {
  const auto m = [t](int x, int y) { return static_cast<int>(std::lround(x + (y - x) * t)); };
  return {m(a.red(), b.red()), m(a.green(), b.green()), m(a.blue(), b.blue())};
}

/// The whole turns k for which the box [lo, hi] shifted by k turns meets the view's Mercator box.
std::pair<int, int> turnsInView(const Ctx& c, double loX, double hiX) {
  const int first = static_cast<int>(std::ceil((c.visLo.x - hiX) / kTurn));
  const int last = static_cast<int>(std::floor((c.visHi.x - loX) / kTurn));
  return {first, std::min(last, first + kMaxTurns - 1)};
}

bool partInView(const Ctx& c, const PreparedWorld::Part& p, double shift) {
  return p.hi.x + shift >= c.visLo.x && p.lo.x + shift <= c.visHi.x && p.hi.y >= c.visLo.y &&
         p.lo.y <= c.visHi.y;
}

/// The part on screen, shifted by `shift` radians east (paint::projectPoints).
const QPolygonF& project(Ctx& c, const PreparedWorld& w, const PreparedWorld::Part& part, double shift) {
  return paint::projectPoints(c, w.points().data() + part.first, part.count, shift);
}

/// Land and water of every bin in view (areas in their painting order), then the shorelines over them.
int drawShoreline(Ctx& c, const PreparedWorld& w, const WorldColours& colours) {
  int binsDrawn = 0;
  c.p.setPen(Qt::NoPen);
  c.p.setRenderHint(QPainter::Antialiasing, false);  // neighbouring bins share their edges
  for (const PreparedWorld::Bin& bin : w.bins()) {
    if (bin.hi.y < c.visLo.y || bin.lo.y > c.visHi.y) continue;
    const auto [first, last] = turnsInView(c, bin.lo.x, bin.hi.x);
    for (int k = first; k <= last; ++k) {
      ++binsDrawn;
      for (const PreparedWorld::Part& a : bin.areas) {
        if (!partInView(c, a, k * kTurn)) continue;
        const QPolygonF& poly = project(c, w, a, k * kTurn);
        if (poly.size() < 3) continue;
        c.p.setBrush(a.level % 2 == 1 ? colours.land : colours.water);
        c.p.drawPolygon(poly, Qt::OddEvenFill);
      }
    }
  }
  c.p.setRenderHint(QPainter::Antialiasing, true);
  c.p.setBrush(Qt::NoBrush);
  c.p.setPen(QPen(colours.shore, 1.0));
  for (const PreparedWorld::Bin& bin : w.bins()) {
    if (bin.hi.y < c.visLo.y || bin.lo.y > c.visHi.y) continue;
    const auto [first, last] = turnsInView(c, bin.lo.x, bin.hi.x);
    for (int k = first; k <= last; ++k)
      for (const PreparedWorld::Part& l : bin.lines)
        if (partInView(c, l, k * kTurn)) c.p.drawPolyline(project(c, w, l, k * kTurn));
  }
  return binsDrawn;
}

/// The part of the segment a-b inside the screen (Liang-Barsky), if any.
std::optional<std::pair<QPointF, QPointF>> clipToScreen(const Ctx& c, QPointF a, QPointF b) {
  double t0 = 0.0, t1 = 1.0;
  const double dx = b.x() - a.x(), dy = b.y() - a.y();
  const double w = c.view.width(), h = c.view.height();
  for (const auto& [p, q] : {std::pair{-dx, a.x()}, {dx, w - a.x()}, {-dy, a.y()}, {dy, h - a.y()}}) {
    if (p == 0.0) {
      if (q < 0.0) return std::nullopt;
      continue;
    }
    const double r = q / p;
    if (p < 0.0)
      t0 = std::max(t0, r);
    else
      t1 = std::min(t1, r);
    if (t0 > t1) return std::nullopt;
  }
  return std::pair{QPointF(a.x() + t0 * dx, a.y() + t0 * dy), QPointF(a.x() + t1 * dx, a.y() + t1 * dy)};
}

void drawLabel(const Ctx& c, const QString& text, QPointF at, const WorldColours& colours) {
  const QFontMetricsF fm(c.p.font());
  const QRectF box(at.x(), at.y() - fm.ascent(), fm.horizontalAdvance(text) + 4, fm.height());
  c.p.setPen(Qt::NoPen);
  c.p.setBrush(colours.water);
  c.p.drawRect(box);
  c.p.setPen(colours.text);
  c.p.drawText(QPointF(at.x() + 2, at.y()), text);
}

/// The width at the bottom right that the window's scale bar may take (a quarter of the width and its
/// margin and label).
double scaleBarBandPx(double width) {
  return 0.25 * width + 40.0;
}

/// Parallels labelled at their left end, meridians at their lower end, at a round interval that keeps
/// them at least 110 px apart.
void drawGraticule(Ctx& c, const WorldColours& colours) {
  const double pxPerDegree = std::hypot(c.t.a, c.t.c) * degToRad(1.0);
  const int step = world::graticuleStepSeconds(pxPerDegree);
  const auto latOf = [](double y) { return radToDeg(2.0 * std::atan(std::exp(y)) - kPi / 2.0); };
  const double latLo = std::max(latOf(c.visLo.y), -85.0), latHi = std::min(latOf(c.visHi.y), 85.0);
  QFont font("DejaVu Sans");
  font.setPixelSize(11);
  c.p.setFont(font);
  const QPen grid(colours.grid, 1.0);
  struct Label {
    QString text;
    QPointF at;
  };
  std::vector<Label> labels;
  for (const double lat : world::graticuleValues(latLo, latHi, step)) {
    const double y = toMercator({lat, 0.0}).y;
    const auto seg = clipToScreen(c, c.pt({c.visLo.x, y}), c.pt({c.visHi.x, y}));
    if (!seg) continue;
    c.p.setPen(grid);
    c.p.drawLine(seg->first, seg->second);
    const QPointF left = seg->first.x() <= seg->second.x() ? seg->first : seg->second;
    if (left.y() > 14 && left.y() < c.view.height() - 22)
      labels.push_back({QString::fromStdString(io::formatLatitudeLabel(lat)), left + QPointF(3, -3)});
  }
  for (const double lon : world::graticuleValues(radToDeg(c.visLo.x), radToDeg(c.visHi.x), step)) {
    const double x = degToRad(lon);
    const auto seg = clipToScreen(c, c.pt({x, c.visLo.y}), c.pt({x, c.visHi.y}));
    if (!seg) continue;
    c.p.setPen(grid);
    c.p.drawLine(seg->first, seg->second);
    const QPointF low = seg->first.y() >= seg->second.y() ? seg->first : seg->second;
    // The bottom right is the window's scale bar's (up to a quarter of the width, 16 px from the edge).
    if (low.x() > 60 && low.x() < c.view.width() - scaleBarBandPx(c.view.width()))
      labels.push_back({QString::fromStdString(io::formatLongitudeLabel(lon)), low + QPointF(3, -5)});
  }
  for (const Label& l : labels) drawLabel(c, l.text, l.at, colours);
}

/// The note at the bottom right, above the window's scale bar: what the background is, or why it has
/// no land.
void drawNoteBox(const Ctx& c, const QString& note, const WorldColours& colours) {
  QFont font("DejaVu Sans");
  font.setPixelSize(11);
  c.p.setFont(font);
  const QFontMetricsF fm(font);
  const double w = fm.horizontalAdvance(note) + 10;
  const QRectF box(c.view.width() - w - 6, c.view.height() - fm.height() - 44, w, fm.height() + 4);
  c.p.setPen(Qt::NoPen);
  c.p.setBrush(colours.water);
  c.p.drawRect(box);
  c.p.setPen(colours.text);
  c.p.drawText(box, Qt::AlignCenter, note);
}

}  // namespace

PreparedWorld::PreparedWorld(std::shared_ptr<const world::Shoreline> shoreline)
    : shoreline_(std::move(shoreline)) {
  points_.reserve(shoreline_->vertexCount());
  bins_.reserve(shoreline_->bins().size());
  const double size = shoreline_->binSizeDeg();
  for (const world::ShoreBin& b : shoreline_->bins()) {
    Bin bin;
    bin.lo = toMercator({b.southDeg, b.westDeg});
    bin.hi = toMercator({b.southDeg + size, b.westDeg + size});
    for (const world::ShoreArea& a : b.areas) bin.areas.push_back(add(a.ring, a.level));
    for (const world::ShoreLine& l : b.lines) bin.lines.push_back(add(l.points, l.level));
    bins_.push_back(std::move(bin));
  }
}

PreparedWorld::Part PreparedWorld::add(const std::vector<LatLon>& pts, int level) {
  const PartSpan span = appendMercator(points_, pts);
  Part p;
  p.first = span.first;
  p.count = span.count;
  p.level = level;
  p.lo = span.lo;
  p.hi = span.hi;
  return p;
}

WorldColours worldColours(const Ctx& c) {
  const QColor nodta = c.colour("NODTA");
  return {mix(c.colour("DEPDW"), nodta, 0.3), mix(c.colour("LANDA"), nodta, 0.4),
          mix(c.colour("CSTLN"), nodta, 0.3), mix(c.colour("CHGRD"), nodta, 0.2), c.colour("CHBLK")};
}

const PreparedWorld& WorldLayer::preparedOf(const std::shared_ptr<const world::Shoreline>& s) {
  auto it = prepared_.find(s.get());
  if (it == prepared_.end()) it = prepared_.emplace(s.get(), std::make_unique<PreparedWorld>(s)).first;
  return *it->second;
}

void WorldLayer::drawNote(const Ctx& c, const QString& note) {
  drawNoteBox(c, note, worldColours(c));
}

QString WorldLayer::draw(Ctx& c, RenderStats& stats) {
  const WorldColours colours = worldColours(c);
  c.p.fillRect(QRect(0, 0, c.view.width(), c.view.height()), colours.water);
  const world::WorldData data = world::worldShoreline(world::resolutionFor(c.view.metresPerPixel()));
  stats.worldProblem = data.problem;
  QString note;
  if (data.shoreline) {
    stats.worldResolution = world::resolutionLetter(data.shoreline->resolution());
    stats.worldBinsDrawn = drawShoreline(c, preparedOf(data.shoreline), colours);
    const std::string_view name = world::resolutionName(data.shoreline->resolution());
    note = QString("World background: GSHHG %1 shoreline, not an ENC")
               .arg(QString::fromLatin1(name.data(), static_cast<qsizetype>(name.size())));
  } else {
    note = QString("No world shoreline: %1").arg(QString::fromStdString(data.problem));
  }
  drawGraticule(c, colours);
  return note;
}

}  // namespace reckoner::charts
