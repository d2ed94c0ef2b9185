#pragma once
// The widgets' palette for each display palette (docs/gui.md), like the chart's colour tables.
#include <QPalette>

#include "charts/portrayal/portrayal.h"

namespace reckoner::ui {

/// The widgets' palette for a display palette: the system's by day; at dusk and night every role a
/// widget paints with (selection, tooltips, links, frames, disabled text) dark and dim, so that no
/// bright area is left on a dark bridge.
QPalette widgetPalette(charts::Palette palette);

}  // namespace reckoner::ui
