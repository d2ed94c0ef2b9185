// RTZ, the route plan exchange format of IEC 61174 (docs/routes.md, "Route files"): 1.0, 1.1 and 1.2
// read, 1.1 written. Elements are matched by local name in the RTZ namespaces (or in none), so prefixes
// are welcome and other namespaces (extensions, STM's) are passed over, as are <extensions> themselves.
#include <charconv>
#include <cmath>
#include <limits>
#include <pugixml.hpp>
#include <sstream>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

#include "io/error_line.h"
#include "io/input_error.h"
#include "io/iso8601.h"
#include "io/route_files.h"
#include "io/utf8.h"

namespace reckoner::io {
namespace {

using route_xml::Reader;

constexpr std::string_view kRtzNamespace = "http://www.cirm.org/RTZ/";
constexpr const char* kWrittenNamespace = "http://www.cirm.org/RTZ/1/1";
constexpr double kMax = std::numeric_limits<double>::max();

bool inRtzNamespace(const pugi::xml_node& element) {
  const std::string_view ns = route_xml::namespaceUri(element);
  return ns.empty() || ns.substr(0, kRtzNamespace.size()) == kRtzNamespace;
}

std::string join(const std::string& where, std::string_view what) {
  return where.empty() ? std::string(what) : where + " " + std::string(what);
}

bool blank(std::string_view v) {
  return v.find_first_not_of(" \t\r\n") == std::string_view::npos;
}

/// The one RTZ child element `local` of `parent`, or an empty node; two are an error.
pugi::xml_node single(const Reader& r, const pugi::xml_node& parent, std::string_view local,
                      const std::string& where) {
  const std::vector<pugi::xml_node> found = route_xml::children(parent, local, kRtzNamespace);
  if (found.size() > 1) r.fail(found[1], join(where, local), "given twice");
  return found.empty() ? pugi::xml_node() : found.front();
}

int integer(const Reader& r, const pugi::xml_node& at, std::string_view text, const std::string& field) {
  std::string_view v = text;
  while (!v.empty() && v.front() == ' ') v.remove_prefix(1);
  while (!v.empty() && v.back() == ' ') v.remove_suffix(1);
  if (v.size() > 1 && v.front() == '+' && v[1] != '-') v.remove_prefix(1);
  int x = 0;
  const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), x);
  if (v.empty() || ec != std::errc() || end != v.data() + v.size())
    r.fail(at, field, "must be an integer, got " + quoted(text, 40));
  return x;
}

/// A required integer attribute.
int requiredInteger(const Reader& r, const pugi::xml_node& el, const char* name, const std::string& where) {
  const std::string_view v = route_xml::attribute(el, name);
  if (blank(v)) r.fail(el, join(where, name), "missing");
  return integer(r, el, v, join(where, name));
}

std::optional<double> optionalNumber(const Reader& r, const pugi::xml_node& el, const char* name,
                                     const std::string& where, double lo, double hi) {
  const std::string_view v = route_xml::attribute(el, name);
  if (blank(v)) return std::nullopt;
  return r.number(el, v, join(where, name), lo, hi);
}

/// The times read and written: the years 0001 to 9999 (xs:dateTime's four-digit years).
bool timeInRange(UtcUs t) {
  return t >= daysFromCivil(1, 1, 1) * kUsPerDay && t < daysFromCivil(10000, 1, 1) * kUsPerDay;
}

/// xs:dateTime -> UTC: "Z", an offset "+hh:mm" / "-hh:mm", or no zone (taken as UTC, as IEC 61174
/// keeps route times in UTC).
std::optional<UtcUs> dateTime(std::string_view s) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  if (s.empty() || s.size() > 64) return std::nullopt;
  if (s.front() < '0' || s.front() > '9') return std::nullopt;  // no negative years
  if (s.back() == 'Z') {
    const std::optional<UtcUs> t = parseIso8601(s);
    return t && timeInRange(*t) ? t : std::nullopt;
  }
  std::int64_t offsetUs = 0;
  if (s.size() > 6 && (s[s.size() - 6] == '+' || s[s.size() - 6] == '-') && s[s.size() - 3] == ':') {
    int hh = 0, mm = 0;
    const char* zone = s.data() + s.size() - 5;
    if (std::from_chars(zone, zone + 2, hh).ptr != zone + 2 ||
        std::from_chars(zone + 3, zone + 5, mm).ptr != zone + 5 || hh < 0 || hh > 14 || mm < 0 || mm > 59)
      return std::nullopt;
    offsetUs = (s[s.size() - 6] == '-' ? -1 : 1) * (hh * 60LL + mm) * 60LL * kMicrosPerSecond;
    s.remove_suffix(6);
  }
  const std::optional<UtcUs> local = parseIso8601(std::string(s) + "Z");
  if (!local || !timeInRange(*local - offsetUs)) return std::nullopt;
  return *local - offsetUs;
}

std::optional<UtcUs> optionalTime(const Reader& r, const pugi::xml_node& el, const char* name,
                                  const std::string& where) {
  const std::string_view v = route_xml::attribute(el, name);
  if (blank(v)) return std::nullopt;
  const std::optional<UtcUs> t = dateTime(v);
  if (!t)
    r.fail(el, join(where, name),
           "must be a date and time such as 2024-05-01T12:00:00Z, got " + quoted(v, 40));
  return t;
}

void readLeg(const Reader& r, const pugi::xml_node& el, geo::LegPlan& leg, const std::string& owner) {
  const std::string where = join(owner, "leg");
  if (const auto v = optionalNumber(r, el, "portsideXTD", where, 0.0, kMax)) leg.portXtlNm = *v;
  if (const auto v = optionalNumber(r, el, "starboardXTD", where, 0.0, kMax)) leg.starboardXtlNm = *v;
  if (const auto v = optionalNumber(r, el, "speedMax", where, 0.0, kMax)) leg.plannedSpeedKn = v;
  if (const auto v = optionalNumber(r, el, "speedMin", where, 0.0, kMax)) leg.minSpeedKn = v;
  if (const auto v = optionalNumber(r, el, "safetyContour", where, -kMax, kMax)) leg.safetyContourM = v;
  if (const auto v = optionalNumber(r, el, "safetyDepth", where, 0.0, kMax)) leg.safetyDepthM = v;
  const std::string_view geometry = route_xml::attribute(el, "geometryType");
  if (!blank(geometry)) {
    std::string g(geometry);
    for (char& c : g) c = (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
    if (g == "loxodrome") {
      leg.geometry = geo::LegGeometry::RhumbLine;
    } else if (g == "orthodrome") {
      leg.geometry = geo::LegGeometry::GreatCircle;
    } else {
      r.fail(el, join(where, "geometryType"), "must be Loxodrome or Orthodrome, got " + quoted(geometry, 40));
    }
  }
  if (const pugi::xml_attribute info = el.attribute("legInfo"))
    leg.note = r.text(el, info.value(), join(where, "legInfo"));
}

geo::GeoPoint readPosition(const Reader& r, const pugi::xml_node& waypoint, const std::string& where) {
  const pugi::xml_node el = single(r, waypoint, "position", where);
  if (!el) r.fail(waypoint, join(where, "position"), "missing (a waypoint needs <position lat=... lon=...>)");
  geo::GeoPoint p;
  for (const char* name : {"lat", "lon"}) {
    const bool lat = name[1] == 'a';
    const std::string field = join(where, std::string("position ") + name);
    const std::string_view v = route_xml::attribute(el, name);
    if (blank(v)) r.fail(el, field, "missing");
    (lat ? p.latDeg : p.lonDeg) = r.number(el, v, field, lat ? -90.0 : -180.0, lat ? 90.0 : 180.0);
  }
  return p;
}

geo::Waypoint readWaypoint(const Reader& r, const pugi::xml_node& el, std::size_t k,
                           const geo::LegPlan& defaultLeg) {
  geo::Waypoint w;
  w.id = requiredInteger(r, el, "id", "waypoint " + std::to_string(k + 1));
  const std::string where = "waypoint id=\"" + std::to_string(w.id) + "\"";
  if (const pugi::xml_attribute name = el.attribute("name"))
    w.name = r.text(el, name.value(), join(where, "name"));
  w.turnRadiusNm = optionalNumber(r, el, "radius", where, 0.0, kMax);
  w.position = readPosition(r, el, where);
  w.leg = defaultLeg;
  if (const pugi::xml_node leg = single(r, el, "leg", where)) readLeg(r, leg, w.leg, where);
  return w;
}

/// <waypoints>: the defaults of <defaultWaypoint> (its radius the route's, its leg every waypoint's
/// unless the waypoint's own leg says otherwise), then the waypoints; `elements` gets their elements.
void readWaypoints(const Reader& r, const pugi::xml_node& list, geo::Route& route,
                   std::vector<pugi::xml_node>& elements) {
  geo::LegPlan defaultLeg;
  if (const pugi::xml_node d = single(r, list, "defaultWaypoint", "")) {
    if (const auto radius = optionalNumber(r, d, "radius", "defaultWaypoint", 0.0, kMax))
      route.defaultTurnRadiusNm = *radius;
    if (const pugi::xml_node leg = single(r, d, "leg", "defaultWaypoint"))
      readLeg(r, leg, defaultLeg, "defaultWaypoint");
  }
  elements = route_xml::children(list, "waypoint", kRtzNamespace);
  if (elements.size() > kMaxRouteWaypoints)
    r.fail(elements[kMaxRouteWaypoints], "waypoint",
           "more than " + std::to_string(kMaxRouteWaypoints) + " waypoints; the limit is " +
               std::to_string(kMaxRouteWaypoints));
  std::unordered_map<int, std::size_t> seen;  // id -> index
  for (std::size_t k = 0; k < elements.size(); ++k) {
    geo::Waypoint w = readWaypoint(r, elements[k], k, defaultLeg);
    if (const auto [it, fresh] = seen.emplace(w.id, k); !fresh)
      r.fail(
          elements[k], "waypoint id=\"" + std::to_string(w.id) + "\" id",
          "used twice: the waypoint at line " + std::to_string(r.line(elements[it->second])) + " has it too");
    route.waypoints.push_back(std::move(w));
  }
}

/// <manual> or <calculated>: scheduleElement (RTZ 1.0's schema spells it sheduleElement) in order.
std::vector<geo::ScheduleEntry> readScheduleList(const Reader& r, const pugi::xml_node& list,
                                                 const std::string& where,
                                                 const std::unordered_set<int>& ids) {
  std::vector<geo::ScheduleEntry> out;
  for (const pugi::xml_node el : list.children()) {
    const std::string_view name = route_xml::localName(el);
    if (el.type() != pugi::node_element || (name != "scheduleElement" && name != "sheduleElement") ||
        !inRtzNamespace(el))
      continue;
    if (out.size() == kMaxRouteWaypoints)
      r.fail(el, where, "more than " + std::to_string(kMaxRouteWaypoints) + " schedule elements");
    geo::ScheduleEntry e;
    const std::string element = join(where, name);
    e.waypointId = requiredInteger(r, el, "waypointId", element);
    if (ids.count(e.waypointId) == 0)
      r.fail(el, join(element, "waypointId"),
             "no waypoint of the route has id " + std::to_string(e.waypointId));
    const std::string at = element + " waypointId=\"" + std::to_string(e.waypointId) + "\"";
    e.etd = optionalTime(r, el, "etd", at);
    e.eta = optionalTime(r, el, "eta", at);
    e.speedKn = optionalNumber(r, el, "speed", at, 0.0, kMax);
    out.push_back(e);
  }
  return out;
}

void readSchedules(const Reader& r, const pugi::xml_node& list, geo::Route& route) {
  std::unordered_set<int> ids;
  for (const geo::Waypoint& w : route.waypoints) ids.insert(w.id);
  const std::vector<pugi::xml_node> elements = route_xml::children(list, "schedule", kRtzNamespace);
  if (elements.size() > kMaxRouteSchedules)
    r.fail(elements[kMaxRouteSchedules], "schedule",
           "more than " + std::to_string(kMaxRouteSchedules) + " schedules; the limit is " +
               std::to_string(kMaxRouteSchedules));
  std::unordered_map<int, std::size_t> seen;
  for (std::size_t k = 0; k < elements.size(); ++k) {
    const pugi::xml_node el = elements[k];
    geo::Schedule s;
    s.id = requiredInteger(r, el, "id", "schedule " + std::to_string(k + 1));
    const std::string where = "schedule id=\"" + std::to_string(s.id) + "\"";
    if (const auto [it, fresh] = seen.emplace(s.id, k); !fresh)
      r.fail(
          el, join(where, "id"),
          "used twice: the schedule at line " + std::to_string(r.line(elements[it->second])) + " has it too");
    if (const pugi::xml_attribute name = el.attribute("name"))
      s.name = r.text(el, name.value(), join(where, "name"));
    if (const pugi::xml_node manual = single(r, el, "manual", where))
      s.manual = readScheduleList(r, manual, join(where, "manual"), ids);
    if (const pugi::xml_node calculated = single(r, el, "calculated", where))
      s.calculated = readScheduleList(r, calculated, join(where, "calculated"), ids);
    route.schedules.push_back(std::move(s));
  }
}

void checkRoot(const Reader& r, const pugi::xml_node& root) {
  if (route_xml::localName(root) != "route" || !inRtzNamespace(root))
    r.fail(root, "", "the root element is " + quoted(root.name(), 80) + ", not RTZ's <route>");
  const std::string_view version = route_xml::attribute(root, "version");
  if (!version.empty() && version != "1.0" && version != "1.1" && version != "1.2")
    r.fail(root, "route version", "RTZ 1.0, 1.1 and 1.2 are read, not " + quoted(version, 40));
}

}  // namespace

geo::Route readRtz(std::string_view xml, const std::string& source) {
  const Reader r(route_xml::utf8Text(xml, source), source);
  const pugi::xml_node root = r.root();
  checkRoot(r, root);
  geo::Route route;
  if (const pugi::xml_node info = single(r, root, "routeInfo", "")) {
    if (const pugi::xml_attribute a = info.attribute("routeName"))
      route.name = r.text(info, a.value(), "routeInfo routeName");
    if (const pugi::xml_attribute a = info.attribute("routeAuthor"))
      route.author = r.text(info, a.value(), "routeInfo routeAuthor");
    if (const pugi::xml_attribute a = info.attribute("routeStatus"))
      route.status = r.text(info, a.value(), "routeInfo routeStatus");
  }
  const pugi::xml_node list = single(r, root, "waypoints", "");
  if (!list) r.fail(root, "waypoints", "missing (an RTZ route has <waypoints>)");
  std::vector<pugi::xml_node> elements;
  readWaypoints(r, list, route, elements);
  if (const pugi::xml_node schedules = single(r, root, "schedules", "")) readSchedules(r, schedules, route);
  r.validate(route, elements, list);
  return route;
}

// ---- writing ----

namespace {

/// The shortest decimal (no exponent: xs:decimal) that reads back as v.
std::string decimal(double v) {
  char buf[512];  // the longest fixed form of a double (a subnormal) is under 400 characters
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed);
  return ec == std::errc() ? std::string(buf, end) : std::string("0");
}

/// Text as XML 1.0 may carry it: valid UTF-8, no control characters but tab, line feed and return.
std::string xmlText(std::string_view s) {
  std::string out = validUtf8(s);
  std::erase_if(out, [](char c) {
    const auto b = static_cast<unsigned char>(c);
    return (b < 0x20 && c != '\t' && c != '\n' && c != '\r') || b == 0x7F;
  });
  return out;
}

void set(pugi::xml_node& el, const char* name, const std::string& value) {
  el.append_attribute(name).set_value(value.c_str());
}

void setNumber(pugi::xml_node& el, const char* name, const std::optional<double>& v) {
  if (v) set(el, name, decimal(*v));
}

void writeLeg(pugi::xml_node& waypoint, const geo::LegPlan& leg) {
  pugi::xml_node el = waypoint.append_child("leg");
  set(el, "starboardXTD", decimal(leg.starboardXtlNm));
  set(el, "portsideXTD", decimal(leg.portXtlNm));
  setNumber(el, "safetyContour", leg.safetyContourM);
  setNumber(el, "safetyDepth", leg.safetyDepthM);
  set(el, "geometryType", leg.geometry == geo::LegGeometry::GreatCircle ? "Orthodrome" : "Loxodrome");
  setNumber(el, "speedMin", leg.minSpeedKn);
  setNumber(el, "speedMax", leg.plannedSpeedKn);
  if (!leg.note.empty()) set(el, "legInfo", xmlText(leg.note));
}

void writeWaypoints(pugi::xml_node& root, const geo::Route& route) {
  pugi::xml_node list = root.append_child("waypoints");
  pugi::xml_node defaults = list.append_child("defaultWaypoint");
  set(defaults, "radius", decimal(route.defaultTurnRadiusNm));
  for (std::size_t k = 0; k < route.waypoints.size(); ++k) {
    const geo::Waypoint& w = route.waypoints[k];
    pugi::xml_node el = list.append_child("waypoint");
    set(el, "id", std::to_string(w.id));
    if (!w.name.empty()) set(el, "name", xmlText(w.name));
    setNumber(el, "radius", w.turnRadiusNm);
    pugi::xml_node position = el.append_child("position");
    set(position, "lat", decimal(w.position.latDeg));
    set(position, "lon", decimal(w.position.lonDeg));
    // The first waypoint's leg arrives nowhere: written only when it holds something.
    if (k > 0 || w.leg != geo::LegPlan{}) writeLeg(el, w.leg);
  }
}

void writeScheduleList(pugi::xml_node& schedule, const char* name,
                       const std::vector<geo::ScheduleEntry>& entries) {
  if (entries.empty()) return;
  pugi::xml_node list = schedule.append_child(name);
  for (const geo::ScheduleEntry& e : entries) {
    pugi::xml_node el = list.append_child("scheduleElement");
    set(el, "waypointId", std::to_string(e.waypointId));
    if (e.etd) set(el, "etd", formatIso8601(*e.etd));
    if (e.eta) set(el, "eta", formatIso8601(*e.eta));
    setNumber(el, "speed", e.speedKn);
  }
}

[[noreturn]] void refuse(const std::string& what) {
  throw std::invalid_argument("writeRtz: " + what);
}

/// What readRtz would refuse and Route::problems() does not look at: the first waypoint's leg (unused,
/// but read as any other) and the schedules.
void checkWritable(const geo::Route& route) {
  if (!route.waypoints.empty()) {
    const geo::LegPlan& leg = route.waypoints.front().leg;
    const auto bad = [](const std::optional<double>& v) { return v && !(std::isfinite(*v) && *v >= 0.0); };
    if (bad(leg.portXtlNm) || bad(leg.starboardXtlNm) || bad(leg.plannedSpeedKn) || bad(leg.minSpeedKn) ||
        bad(leg.safetyDepthM) || (leg.safetyContourM && !std::isfinite(*leg.safetyContourM)))
      refuse("waypoint 1: its leg's limits, speeds and depths must be finite numbers >= 0");
  }
  if (route.schedules.size() > kMaxRouteSchedules)
    refuse("more than " + std::to_string(kMaxRouteSchedules) + " schedules");
  std::unordered_set<int> ids, scheduleIds;
  for (const geo::Waypoint& w : route.waypoints) ids.insert(w.id);
  for (const geo::Schedule& s : route.schedules) {
    const std::string where = "schedule " + std::to_string(s.id);
    if (!scheduleIds.insert(s.id).second) refuse(where + ": id used twice");
    for (const auto* list : {&s.manual, &s.calculated}) {
      if (list->size() > kMaxRouteWaypoints)
        refuse(where + ": more than " + std::to_string(kMaxRouteWaypoints) + " entries");
      for (const geo::ScheduleEntry& e : *list) {
        if (ids.count(e.waypointId) == 0)
          refuse(where + ": no waypoint has id " + std::to_string(e.waypointId));
        if (e.speedKn && !(std::isfinite(*e.speedKn) && *e.speedKn >= 0.0))
          refuse(where + ": speed must be a finite number >= 0");
        for (const auto& t : {e.etd, e.eta})
          if (t && !timeInRange(*t)) refuse(where + ": a time outside the years 0001 to 9999");
      }
    }
  }
}

}  // namespace

std::string writeRtz(const geo::Route& route) {
  if (const std::vector<std::string> problems = route.problems(); !problems.empty()) refuse(problems.front());
  if (route.waypoints.size() > kMaxRouteWaypoints)
    refuse("more than " + std::to_string(kMaxRouteWaypoints) + " waypoints");
  checkWritable(route);
  pugi::xml_document doc;
  pugi::xml_node declaration = doc.append_child(pugi::node_declaration);
  set(declaration, "version", "1.0");
  set(declaration, "encoding", "UTF-8");
  pugi::xml_node root = doc.append_child("route");
  set(root, "xmlns", kWrittenNamespace);
  set(root, "version", "1.1");
  pugi::xml_node info = root.append_child("routeInfo");
  set(info, "routeName", xmlText(route.name));
  if (!route.author.empty()) set(info, "routeAuthor", xmlText(route.author));
  if (!route.status.empty()) set(info, "routeStatus", xmlText(route.status));
  writeWaypoints(root, route);
  if (!route.schedules.empty()) {
    pugi::xml_node schedules = root.append_child("schedules");
    for (const geo::Schedule& s : route.schedules) {
      pugi::xml_node el = schedules.append_child("schedule");
      set(el, "id", std::to_string(s.id));
      if (!s.name.empty()) set(el, "name", xmlText(s.name));
      writeScheduleList(el, "manual", s.manual);
      writeScheduleList(el, "calculated", s.calculated);
    }
  }
  std::ostringstream out;
  doc.save(out, "  ", pugi::format_default, pugi::encoding_utf8);
  return out.str();
}

}  // namespace reckoner::io
