#pragma once
// AIS target symbols as IEC 62288 (edition 2, annex on AIS symbols) draws them, painted with our own
// QPainter code (docs/ais.md, "Symbols"): an isosceles triangle pointing along the heading (COG when no
// heading), drawn to the ship's dimensions when that outline is larger on screen than the triangle;
// sleeping targets a smaller triangle without vector; activated targets with the heading line, the
// COG/SOG vector (dashed, the display's vector time long) and the turn indicator (a flag at the end of
// the heading line towards the turn); a selected target inside four corner brackets; a dangerous one
// bold red (and flashing, which the caller drives with AisPaintStyle::flashOn); a lost one crossed out,
// without vector; an AIS-SART, MOB or EPIRB-AIS as a circle with a cross (IEC 62288; SN.1/Circ.243/Add.1),
// bold red and dashed when active, flashing until its alarm is acknowledged, thin in the AIS colour in test.
// The GUI converts the table's rows (track::AisTarget) into symbols; it computes nothing the core computes.
#include <QColor>
#include <QPainter>
#include <QPointF>
#include <functional>
#include <optional>
#include <vector>

#include "common/time.h"
#include "geo/local_frame.h"
#include "tracking/ais_targets.h"

namespace reckoner::ui {

/// One AIS target as the chart draws it (grid frame, SI).
struct AisSymbol {
  std::uint32_t mmsi = 0;
  double xM = 0.0, yM = 0.0;             ///< grid position now (dead reckoned from the report)
  std::optional<double> headingGridRad;  ///< the reported heading, grid
  std::optional<double> cogGridRad;      ///< course over ground, grid
  double sogMps = 0.0;
  int turn = 0;  ///< +1 turning right, -1 left, 0 not turning (or not known)
  std::optional<double> toBowM, toSternM, toPortM, toStarboardM;
  bool activated = false, selected = false, dangerous = false, lost = false;
  /// A search and rescue device (AIS-SART, MOB, EPIRB-AIS): a circle with a cross (IEC 62288), drawn
  /// bold, red and dashed when it is a distress (not in test), flashing while its alarm is unacknowledged.
  bool device = false, distress = false, unacknowledged = false;
};

/// The symbol of a table row at `now` in `frame`; empty when the target has no position.
std::optional<AisSymbol> aisSymbolOf(const track::AisTarget& t, const geo::LocalFrame& frame, TimeUs now,
                                     double turningRotDegMin = 5.0);

struct AisPaintStyle {
  QColor colour = QColor(20, 20, 20);
  QColor dangerous = QColor(220, 0, 0);
  double vectorMinutes = 6.0;
  double scale = 1.0;  ///< device pixels per logical symbol unit (the triangle is 14 units activated)
  /// false: dangerous targets and unacknowledged distresses are not drawn (the off phase of the flash)
  bool flashOn = true;
};

/// Where grid metres go on screen: the widget point of a grid point, and the screen angle of grid
/// north (radians, clockwise; 0 north-up).
struct AisPaintGeometry {
  std::function<QPointF(double xM, double yM)> toWidget;
  double pixelsPerMetre = 1.0;
  double gridNorthScreenRad = 0.0;
};

/// Paints the symbols: sleeping first, then activated, selected and dangerous on top.
void paintAisTargets(QPainter& p, const std::vector<AisSymbol>& symbols, const AisPaintGeometry& g,
                     const AisPaintStyle& style = {});

/// The pick report of a target: identity, class, static and voyage data, dynamic data, CPA/TCPA.
QString aisPickReport(const track::AisTarget& t);

}  // namespace reckoner::ui
