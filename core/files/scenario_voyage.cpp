// The scenario format's voyage (docs/scenarios.md, "voyage"): the active route written out waypoint by
// waypoint, whether own ship's autopilot follows it, the draught, the safety contour and depth, and the
// anti-grounding look-ahead and its alert.
#include "files/scenario_fields.h"
#include "files/scenario_json.h"

namespace reckoner::files::scenario_detail {

using io::JsonValue;
using io::JsonWriter;

namespace {

inline constexpr std::array<NamedValue<geo::LegGeometry>, 2> kLegGeometries{{
    {geo::LegGeometry::RhumbLine, "rhumb_line", "constant course, RTZ Loxodrome"},
    {geo::LegGeometry::GreatCircle, "great_circle", "the geodesic, RTZ Orthodrome"},
}};

std::optional<double> optionalNumber(Fields& f, std::string_view key, Fields::Check check) {
  if (!f.get(key)) return std::nullopt;
  return f.number(key, check);
}

geo::Waypoint readWaypoint(Fields& w, int index) {
  using C = Fields::Check;
  geo::Waypoint p;
  p.id = index + 1;
  p.name = w.stringOr("name", "");
  p.position = {w.number("lat_deg"), w.number("lon_deg")};
  p.turnRadiusNm = optionalNumber(w, "radius_nm", C::NonNegative);
  p.leg.portXtlNm = w.numberOr("xtl_port_nm", p.leg.portXtlNm, C::NonNegative);
  p.leg.starboardXtlNm = w.numberOr("xtl_starboard_nm", p.leg.starboardXtlNm, C::NonNegative);
  p.leg.plannedSpeedKn = optionalNumber(w, "speed_kn", C::NonNegative);
  if (const JsonValue* g = w.get("geometry"))
    p.leg.geometry = valueOf(kLegGeometries, w, *g, w.pathOf("geometry"));
  w.finish();
  return p;
}

geo::Route readRoute(Fields& voyage) {
  Fields r(voyage.file(), voyage.require("route"), voyage.pathOf("route"));
  geo::Route route;
  route.name = r.stringOr("name", "");
  route.defaultTurnRadiusNm =
      r.numberOr("default_radius_nm", route.defaultTurnRadiusNm, Fields::Check::NonNegative);
  const JsonValue& wps = r.require("waypoints");
  if (!wps.isArray() || wps.array.size() < 2 || wps.array.size() > 10000)
    r.fail(wps, r.pathOf("waypoints"), "must be an array of 2 to 10000 waypoints");
  for (std::size_t i = 0; i < wps.array.size(); ++i) {
    Fields w(voyage.file(), wps.array[i], r.pathOf("waypoints") + "[" + std::to_string(i) + "]");
    route.waypoints.push_back(readWaypoint(w, static_cast<int>(i)));
  }
  r.finish();
  return route;
}

}  // namespace

void readVoyage(Fields& top, sim::Scenario& s) {
  const JsonValue* v = top.get("voyage");
  if (!v) return;
  Fields f(top.file(), *v, "voyage");
  using C = Fields::Check;
  sim::VoyageSpec& y = s.voyage;
  if (f.get("route")) y.route = readRoute(f);
  if (const JsonValue* b = f.get("follow_route")) y.followRoute = f.boolean(*b, "voyage.follow_route");
  y.draughtM = f.numberOr("draught_m", y.draughtM, C::Positive);
  y.safetyContourM = f.numberOr("safety_contour_m", y.safetyContourM);
  y.safetyDepthM = optionalNumber(f, "safety_depth_m", C::Any);
  y.dangerClearanceM = f.numberOr("danger_clearance_m", y.dangerClearanceM, C::NonNegative);
  y.halfBeamM = f.numberOr("half_beam_m", y.halfBeamM, C::NonNegative);
  y.lookAhead.horizonS = 60.0 * f.numberOr("look_ahead_min", y.lookAhead.horizonS / 60.0, C::Positive);
  y.lookAheadPeriodS = f.numberOr("look_ahead_period_s", y.lookAheadPeriodS, C::Positive);
  y.alertProbability = f.numberOr("alert_probability", y.alertProbability, C::Positive);
  y.alertConfirmationS = f.numberOr("alert_confirmation_s", y.alertConfirmationS, C::NonNegative);
  y.monitor.arrivalCircleNm = f.numberOr("arrival_circle_nm", y.monitor.arrivalCircleNm, C::Positive);
  y.monitor.approachWarningS = f.numberOr("approach_warning_s", y.monitor.approachWarningS, C::NonNegative);
  f.finish();
}

void writeVoyage(JsonWriter& w, const sim::VoyageSpec& y) {
  const sim::VoyageSpec d;
  if (!y.route && y.draughtM == d.draughtM && y.safetyContourM == d.safetyContourM && !y.safetyDepthM &&
      y.lookAhead.horizonS == d.lookAhead.horizonS && y.alertProbability == d.alertProbability)
    return;
  w.key("voyage").beginObject();
  if (y.route) {
    w.key("route").beginObject();
    w.key("name").value(y.route->name);
    w.key("default_radius_nm").value(y.route->defaultTurnRadiusNm, 17);
    w.key("waypoints").beginArray();
    for (const geo::Waypoint& p : y.route->waypoints) {
      w.beginObject();
      w.key("name").value(p.name);
      w.key("lat_deg").value(p.position.latDeg, 17).key("lon_deg").value(p.position.lonDeg, 17);
      if (p.turnRadiusNm) w.key("radius_nm").value(*p.turnRadiusNm, 17);
      w.key("xtl_port_nm").value(p.leg.portXtlNm, 17).key("xtl_starboard_nm").value(p.leg.starboardXtlNm, 17);
      if (p.leg.plannedSpeedKn) w.key("speed_kn").value(*p.leg.plannedSpeedKn, 17);
      w.key("geometry").value(nameOf(kLegGeometries, p.leg.geometry));
      w.endObject();
    }
    w.endArray();
    w.endObject();
    w.key("follow_route").value(y.followRoute);
  }
  w.key("draught_m").value(y.draughtM, 17);
  w.key("safety_contour_m").value(y.safetyContourM, 17);
  if (y.safetyDepthM) w.key("safety_depth_m").value(*y.safetyDepthM, 17);
  w.key("danger_clearance_m").value(y.dangerClearanceM, 17);
  w.key("half_beam_m").value(y.halfBeamM, 17);
  w.key("look_ahead_min").value(y.lookAhead.horizonS / 60.0, 17);
  w.key("look_ahead_period_s").value(y.lookAheadPeriodS, 17);
  w.key("alert_probability").value(y.alertProbability, 17);
  w.key("alert_confirmation_s").value(y.alertConfirmationS, 17);
  w.key("arrival_circle_nm").value(y.monitor.arrivalCircleNm, 17);
  w.key("approach_warning_s").value(y.monitor.approachWarningS, 17);
  w.endObject();
}

}  // namespace reckoner::files::scenario_detail
