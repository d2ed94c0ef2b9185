#pragma once
// What the painters of one render share (internal to charts/render): the render context and the
// drawing functions, by file:
//  - geometry_painter.cpp: areas and lines (screen polygons, fills, strokes, pens);
//  - symbol_painter.cpp: point symbols (buoys, beacons, topmarks, lights, dangers, centre symbols);
//  - text_painter.cpp: fonts, soundings, names and light descriptions, contour labels.
// chart_renderer.cpp runs the loop over cells and features and picks the painter for each feature.
#include <QColor>
#include <QFont>
#include <QPainter>
#include <QPen>
#include <QPointF>
#include <QPolygonF>
#include <QString>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "charts/render/chart_renderer.h"
#include "charts/render/prepared_cell.h"

namespace reckoner::charts::paint {

struct Fonts {
  QFont sounding, soundingBold, soundingSmall, soundingSmallBold, text, contour;
  double soundingAscent = 0;
};

/// Everything one render needs: painter, view, transform, settings, colours, scratch buffers.
struct Ctx {
  QPainter& p;
  const Viewport& view;
  MercatorToScreen t;
  MercatorPoint visLo, visHi;
  const MarinerSettings& s;
  const ColourTable& colours;
  double safetyContourM;
  Fonts fonts;
  QPolygonF scratch;
  struct Label {
    QString text;
    QPointF at;
    QColor colour;
  };
  std::vector<Label> labels;  // names and light descriptions: drawn after everything else, S-52's text layer
  std::vector<DrawnText>* written = nullptr;  // where drawLabels() records what it wrote (RenderStats)

  [[nodiscard]] QColor colour(std::string_view token) const {
    const Rgb c = colours.colour(s.palette, token);
    return {c.r, c.g, c.b};
  }
  [[nodiscard]] QPointF pt(const MercatorPoint& m) const {
    const ScreenPoint sp = t(m.x, m.y);
    return {sp.x, sp.y};
  }
  [[nodiscard]] static double mm(double v) { return v / 0.28; }  // millimetres to pixels at 0.28 mm
  [[nodiscard]] bool onScreen(const MercatorPoint& lo, const MercatorPoint& hi) const {
    return hi.x >= visLo.x && lo.x <= visHi.x && hi.y >= visLo.y && lo.y <= visHi.y;
  }
};

// ---- geometry_painter.cpp: areas and lines

/// Fills an area (odd-even over its rings) with `brush`, no outline.
/// The screen polygon of `count` Mercator points shifted `shiftX` radians east, into c.scratch:
/// vertices within half a pixel of the last one kept are dropped (the last vertex always kept, so rings
/// stay closed and lines end where they should). Cells and the world background share it.
const QPolygonF& projectPoints(Ctx& c, const MercatorPoint* pts, std::uint32_t count, double shiftX = 0.0);
void fillArea(Ctx& c, const PreparedCell& pc, const PreparedItem& it, const QBrush& brush);
/// Strokes parts [first, first + count) as polylines (rings come closed from the loader).
void strokeParts(Ctx& c, const PreparedCell& pc, std::uint32_t first, std::uint32_t count, const QPen& pen);
/// Strokes every part of a feature.
void drawLines(Ctx& c, const PreparedCell& pc, const PreparedItem& it, const QPen& pen);
/// The pen of a portrayal line style: colour, width in pixels, dash pattern.
QPen penOf(const Ctx& c, const LineStyle& l);

// ---- symbol_painter.cpp: point symbols at `at` (screen pixels)

/// A buoy (BOYSHP) or beacon (BCNSHP) body in the bands of its COLOUR and COLPAT.
void drawBuoy(const Ctx& c, const ChartFeature& f, QPointF at, bool beacon);
/// A topmark (TOPSHP) above the mark it tops.
void drawTopmark(const Ctx& c, const ChartFeature& f, QPointF at);
/// A light: sector arcs and legs (SECTR1, SECTR2), or a flare.
void drawLight(const Ctx& c, const ChartFeature& f, QPointF at);
/// A wreck, obstruction or rock: the isolated-danger symbol when it is one, else its own symbol.
void drawDanger(const Ctx& c, const ChartFeature& f, QPointF at);
/// An area's centre symbol by name: anchor, restricted, tss_arrow (along ORIENT) or caution.
void drawCentreSymbol(const Ctx& c, const ChartFeature& f, const std::string& name, QPointF at,
                      const QColor& colour);
/// A point symbol by name: square, landmark or a circle.
void drawPointSymbol(const Ctx& c, const std::string& name, QPointF at, const QColor& colour);

// ---- text_painter.cpp: fonts and text

Fonts makeFonts();
/// The soundings of a SOUNDG feature, shallow ones (at or above the safety depth) bold.
void drawSoundings(Ctx& c, const PreparedCell& pc, const PreparedItem& it);
/// Queues a label beside `at`; drawLabels() writes the queue.
void drawText(Ctx& c, const QString& text, QPointF at, const QColor& colour);
/// Writes the queued labels (those at one anchor stacked; a text already written where it would overlap
/// its copy, written once) and empties the queue.
void drawLabels(Ctx& c);
/// Depth contour value labels: one per line part long enough on screen, at its middle vertex.
void drawContourLabel(Ctx& c, const PreparedCell& pc, const PreparedItem& it, double value);

}  // namespace reckoner::charts::paint
