#pragma once
// The voyage of a live run or a replay (docs/routes.md, "Live"): the route monitored on the estimate,
// the charts of the anti-grounding look-ahead and its safety settings, as options shared by
// `reckoner-cli live` and `replay --recording`, and the charts' answers (charts::ChartSafety) that
// `run --enc` uses too.
#include <memory>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "sim/chart_guard.h"
#include "sim/voyage_spec.h"

namespace reckoner::cli {

struct VoyageArgs {
  std::optional<std::string> route;  ///< RTZ or GPX
  std::optional<std::string> enc;    ///< a cell or a folder of cells
  std::optional<double> safetyContourM, draughtM;
};

/// --route FILE, --enc PATH, --safety-contour M, --draught M.
void addVoyageOptions(CLI::App& app, VoyageArgs& a);
/// The route and the settings given into a voyage (the others as they were). Throws io::InputError
/// naming the route file when it cannot be read, UsageError for a route with problems.
void applyVoyageArgs(const VoyageArgs& a, sim::VoyageSpec& v);
/// The charts' answers under the voyage's settings, from the cells at `enc` (one cell or a folder);
/// null without it. Failures to load are reported on stderr; none loaded: UsageError.
std::shared_ptr<const sim::ChartGuard> chartGuardFor(const sim::VoyageSpec& v,
                                                     const std::optional<std::string>& enc);

}  // namespace reckoner::cli
