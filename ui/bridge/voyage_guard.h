#pragma once
// The charts' answers to a voyage (charts::ChartSafety: the anti-grounding look-ahead and grounding) for
// a worker of the window: made from the cells the window shows, the mariner's safety contour and depth
// and the voyage's draught and clearances, and made again only when one of them changed (in the
// worker's thread: some milliseconds on a harbour cell, more on many).
#include <memory>
#include <optional>
#include <vector>

#include "charts/route/chart_safety.h"
#include "sim/voyage_spec.h"

namespace reckoner::ui {

class VoyageGuard {
 public:
  void setCells(std::vector<charts::CellPtr> cells);
  /// The mariner's settings from now (before the first call: the voyage's own contour and depth).
  void setSafety(const charts::SafetySettings& safety);
  /// The guard for the voyage's draught and clearances; null without cells. Throws
  /// std::invalid_argument for settings with problems.
  std::shared_ptr<const charts::ChartSafety> guardFor(const sim::VoyageSpec& voyage);

 private:
  std::vector<charts::CellPtr> cells_;
  std::optional<charts::SafetySettings> safety_;
  std::shared_ptr<const charts::ChartSafety> guard_;
};

}  // namespace reckoner::ui
