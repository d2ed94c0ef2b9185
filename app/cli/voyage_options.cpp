#include "cli/voyage_options.h"

#include <cstdio>

#include "charts/route/chart_safety.h"
#include "charts/s57/s57_loader.h"
#include "cli/cli_options.h"
#include "io/route_files.h"

namespace reckoner::cli {

void addVoyageOptions(CLI::App& app, VoyageArgs& a) {
  addText(app, "route", a.route, "FILE",
          "monitor own ship against this route (RTZ or GPX): XTE, RMB and APB to --nmea-out, route alerts");
  addText(
      app, "enc", a.enc, "PATH",
      "the anti-grounding look-ahead on these S-57 cells (a cell or a folder), against the safety contour "
      "and dangers");
  addReal(app, "safety-contour", a.safetyContourM, 0.0, 1000.0, "M",
          "the look-ahead's safety contour, metres (default: the settings' voyage, 10)");
  addReal(app, "draught", a.draughtM, 0.1, 30.0, "M",
          "own ship's draught, metres (default: the settings' voyage, 5)");
}

void applyVoyageArgs(const VoyageArgs& a, sim::VoyageSpec& v) {
  if (a.route) {
    v.route = io::readRouteFile(*a.route);
    if (const auto p = v.route->problems(); !p.empty())
      throw UsageError("--route " + *a.route + ": " + p.front());
    v.followRoute = false;
  }
  if (a.safetyContourM) v.safetyContourM = *a.safetyContourM;
  if (a.draughtM) v.draughtM = *a.draughtM;
  if (const auto p = v.problems(); !p.empty()) throw UsageError("voyage: " + p.front());
}

std::shared_ptr<const sim::ChartGuard> chartGuardFor(const sim::VoyageSpec& v,
                                                     const std::optional<std::string>& enc) {
  if (!enc) return nullptr;
  const charts::LoadResult loaded = charts::loadCharts({*enc});
  for (const auto& f : loaded.failures)
    std::fprintf(stderr, "reckoner-cli: error: %s: %s\n", f.file.c_str(), f.reason.c_str());
  if (loaded.cells.empty()) throw UsageError("--enc: no cell loaded from " + *enc);
  return std::make_shared<const charts::ChartSafety>(loaded.cells, charts::antiGroundingSettingsOf(v));
}

}  // namespace reckoner::cli
