// route check ROUTE --enc PATH: a route file (RTZ or GPX) checked against S-57 cells, leg by leg inside
// each leg's cross-track corridor (charts/route/route_check.h, docs/routes.md). A table on stdout, or
// with --json one JSON object per finding and line. Then the turns whose radius does not fit between
// their legs (geo/route_turns.h), which the route monitor sails on a smaller radius. Findings are the
// result, not a failure: exit 0.
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "charts/route/route_check.h"
#include "charts/s57/s57_loader.h"
#include "cli/cli_options.h"
#include "cli/commands.h"
#include "common/angles.h"
#include "common/units.h"
#include "geo/route_turns.h"
#include "io/json.h"
#include "io/route_files.h"
#include "io/text_format.h"

namespace reckoner::cli {
namespace {

struct CheckArgs {
  std::string route;
  std::optional<std::string> enc;
  double safetyContourM = 10.0;
  std::optional<double> safetyDepthM;
  bool noSpecialAreas = false;
  bool json = false;
};

std::string findingJson(const charts::RouteFinding& f, const charts::PickedFeature& report) {
  io::JsonWriter w(true);
  w.beginObject();
  w.key("leg").value(static_cast<std::int64_t>(f.leg));
  w.key("lat_deg").value(f.position.latDeg, 10);
  w.key("lon_deg").value(f.position.lonDeg, 10);
  w.key("kind").value(charts::hazardKindName(f.kind));
  w.key("dangerous").value(charts::isDangerous(f.kind));
  w.key("class").value(f.objectClass);
  w.key("class_name").value(report.className);
  if (f.depthM) {
    w.key("depth_m").value(*f.depthM, 6);
  } else {
    w.key("depth_m").null();
  }
  w.key("cell").value(f.cell);
  w.key("lnam").value(f.lnam);
  w.key("attributes").beginObject();
  for (const auto& a : report.attributes) w.key(a.acronym).value(a.value);
  w.endObject();
  w.endObject();
  return w.str();
}

/// A turn that does not fit, as one JSON object: kind "turn", at its waypoint.
std::string turnJson(const geo::Route& route, const geo::TurnFit& t) {
  const geo::Waypoint& w = route.waypoints[t.waypoint];
  io::JsonWriter j(true);
  j.beginObject();
  j.key("leg").value(static_cast<std::int64_t>(t.waypoint));  // the leg arriving at the turn
  j.key("kind").value("turn");
  j.key("dangerous").value(false);
  j.key("waypoint").value(static_cast<std::int64_t>(t.waypoint));
  j.key("waypoint_id").value(static_cast<std::int64_t>(w.id));
  j.key("name").value(w.name);
  j.key("lat_deg").value(w.position.latDeg, 10);
  j.key("lon_deg").value(w.position.lonDeg, 10);
  j.key("change_deg").value(radToDeg(t.changeRad), 6);
  j.key("radius_nm").value(metresToNm(t.plannedRadiusM), 6);
  j.key("wheel_over_nm").value(metresToNm(t.plannedWheelOverM), 6);
  j.key("leg_before_nm").value(metresToNm(t.legBeforeM), 6);
  j.key("leg_after_nm").value(metresToNm(t.legAfterM), 6);
  j.key("sailed_radius_nm").value(metresToNm(t.radiusM), 6);
  j.endObject();
  return j.str();
}

std::string objectName(const charts::PickedFeature& report) {
  for (const auto& a : report.attributes)
    if (a.acronym == "OBJNAM") return a.value;
  return {};
}

void printTurns(const geo::Route& route, const std::vector<geo::TurnFit>& turns) {
  if (turns.empty()) return;
  std::printf("turns that do not fit between their legs (sailed on the largest radius that does):\n");
  std::printf("%-6s %-16s %10s %9s %13s %13s %12s %9s\n", "wp", "name", "change_deg", "radius_nm",
              "wheel_over_nm", "leg_before_nm", "leg_after_nm", "sailed_nm");
  for (const geo::TurnFit& t : turns) {
    const geo::Waypoint& w = route.waypoints[t.waypoint];
    std::printf("%-6d %-16.16s %10.1f %9.2f %13.2f %13.2f %12.2f %9.2f\n", w.id, w.name.c_str(),
                radToDeg(t.changeRad), metresToNm(t.plannedRadiusM), metresToNm(t.plannedWheelOverM),
                metresToNm(t.legBeforeM), metresToNm(t.legAfterM), metresToNm(t.radiusM));
  }
}

void printTable(const geo::Route& route, const std::vector<charts::RouteFinding>& findings,
                const std::vector<geo::TurnFit>& turns, const charts::ChartHazards& hazards) {
  std::printf("%-4s %-24s %-16s %-7s %8s  %-26s %s\n", "leg", "from - to", "kind", "class", "depth_m",
              "position", "name");
  for (const auto& f : findings) {
    const charts::PickedFeature report = charts::findingReport(hazards, f);
    const std::string legName = route.waypoints[f.leg - 1].name + " - " + route.waypoints[f.leg].name;
    const std::string depth = f.depthM ? numberText(*f.depthM) : "-";
    const std::string pos =
        io::formatLatitude(f.position.latDeg) + " " + io::formatLongitude(f.position.lonDeg);
    std::printf("%-4zu %-24.24s %-16s %-7s %8s  %-26s %s\n", f.leg, legName.c_str(),
                charts::hazardKindName(f.kind), f.objectClass.c_str(), depth.c_str(), pos.c_str(),
                objectName(report).c_str());
  }
  std::size_t dangerous = 0;
  for (const auto& f : findings) dangerous += charts::isDangerous(f.kind) ? 1 : 0;
  printTurns(route, turns);
  std::printf(
      "%zu finding(s) on %zu leg(s): %zu dangerous, %zu caution(s) (restricted and special areas); %zu "
      "turn(s) that do not fit\n",
      findings.size(), route.legCount(), dangerous, findings.size() - dangerous, turns.size());
}

int routeCheck(const CheckArgs& a) {
  if (a.route.empty()) throw UsageError("route check needs a ROUTE file (RTZ or GPX)");
  if (!a.enc) throw UsageError("route check: --enc is required (S-57 cells: a .000 file or a folder)");
  if (a.safetyDepthM && *a.safetyDepthM < a.safetyContourM) {
    // S-52 lets the safety depth be shallower than the contour; say what is checked
    std::fprintf(stderr, "reckoner-cli: note: safety depth %g m is shallower than the safety contour %g m\n",
                 *a.safetyDepthM, a.safetyContourM);
  }
  const geo::Route route = io::readRouteFile(a.route);
  const charts::LoadResult charts = charts::loadCharts({*a.enc});
  for (const auto& f : charts.failures)
    std::fprintf(stderr, "reckoner-cli: error: %s: %s\n", f.file.c_str(), f.reason.c_str());
  if (charts.cells.empty()) throw UsageError("route check: no cell loaded from " + *a.enc);
  charts::SafetySettings settings;
  settings.safetyContourM = a.safetyContourM;
  settings.safetyDepthM = a.safetyDepthM;
  settings.specialAreas = !a.noSpecialAreas;
  const charts::ChartHazards hazards(charts.cells, settings);
  const std::vector<charts::RouteFinding> findings = charts::checkRoute(route, hazards);
  const std::vector<geo::TurnFit> turns = geo::turnsThatDoNotFit(route);
  if (a.json) {
    for (const auto& f : findings)
      std::printf("%s\n", findingJson(f, charts::findingReport(hazards, f)).c_str());
    for (const auto& t : turns) std::printf("%s\n", turnJson(route, t).c_str());
  } else {
    printTable(route, findings, turns, hazards);
  }
  return 0;
}

}  // namespace

void addRouteCommands(CLI::App& root, Commands& out) {
  CLI::App* route = root.add_subcommand("route", "routes (RTZ, GPX): check against the charts");
  route->require_subcommand(1);

  auto c = std::make_shared<CheckArgs>();
  CLI::App* check = route->add_subcommand(
      "check",
      "each leg against S-57 cells inside its cross-track corridor, and the turns that do not fit between "
      "their legs: one line (or JSON) per finding");
  check->add_option("ROUTE", c->route, "the route: RTZ (.rtz) or GPX (.gpx)")->type_name("")->expected(1);
  addText(*check, "enc", c->enc, "PATH", "S-57 cells: a .000 file or a folder of them; required");
  addReal(*check, "safety-contour", c->safetyContourM, -20.0, 1000.0, "M",
          "safety contour: areas with DRVAL1 below it are unsafe, metres");
  addReal(*check, "safety-depth", c->safetyDepthM, -20.0, 1000.0, "M",
          "safety depth: dangers with VALSOU below it are reported, metres", "the safety contour");
  addFlag(*check, "no-special-areas", c->noSpecialAreas,
          "leave out the areas for which special conditions exist");
  addFlag(*check, "json", c->json, "one JSON object per finding and line");
  addIgnoredQuiet(*check);
  out.push_back({check, [c] { return routeCheck(*c); }, ""});
}

}  // namespace reckoner::cli
