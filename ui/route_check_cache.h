#pragma once
// The route check in the window (docs/gui.md "Routes"): the hazards of the open charts for the
// mariner's safety contour and depth (charts::ChartHazards, some 30 ms to build for a harbour cell) are
// built once and kept while the cells and those settings stay the same; each check of a route then
// only runs charts::checkRoute on them. Plain C++, GUI thread.
#include <optional>
#include <vector>

#include "charts/portrayal/portrayal.h"
#include "charts/route/route_check.h"

namespace reckoner::ui {

/// The route check's settings from the mariner's: the safety contour and the safety depth; the areas
/// for which special conditions exist are reported.
[[nodiscard]] charts::SafetySettings safetySettingsOf(const charts::MarinerSettings& mariner);

class RouteCheckCache {
 public:
  /// The hazards of `cells` under `settings`: built at the first call and again only when the cells
  /// (the same cell objects, in order) or the settings differ from the last build.
  const charts::ChartHazards& hazards(const std::vector<charts::CellPtr>& cells,
                                      const charts::SafetySettings& settings);
  /// The findings of `route` (no legs: none).
  std::vector<charts::RouteFinding> check(const geo::Route& route, const std::vector<charts::CellPtr>& cells,
                                          const charts::SafetySettings& settings);
  /// The hazards of the last build (nullptr before the first): what findings' reports are read from.
  [[nodiscard]] const charts::ChartHazards* lastHazards() const { return hazards_ ? &*hazards_ : nullptr; }
  /// How many times the hazards were built, and how long the last build took.
  [[nodiscard]] int builds() const { return builds_; }
  [[nodiscard]] double lastBuildMs() const { return lastBuildMs_; }

 private:
  std::optional<charts::ChartHazards> hazards_;
  std::vector<const charts::ChartCell*> cells_;
  charts::SafetySettings settings_;
  int builds_ = 0;
  double lastBuildMs_ = 0.0;
};

}  // namespace reckoner::ui
