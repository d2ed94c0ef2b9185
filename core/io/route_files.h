#pragma once
// Route exchange files (docs/routes.md, "Route files"): RTZ (IEC 61174 route plan exchange, XML) 1.0,
// 1.1 and 1.2 read, RTZ 1.1 written; GPX 1.0 / 1.1 routes (<rte>) read. What is read goes into the
// route model of geo/route.h in its own units (NM, kn, m, UTC), and is valid by Route::problems() or
// not returned at all: every problem throws one io::InputError naming the source, the line, the
// element and attribute, and what is wrong. Hostile input is bounded (kMaxRouteFileBytes,
// kMaxRouteWaypoints, kMaxRouteSchedules) and never crashes the reader. XML by pugixml (Debian's
// libpugixml-dev), which only rtz.cpp and gpx.cpp see.
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "geo/route.h"

namespace pugi {
class xml_document;
class xml_node;
}  // namespace pugi

namespace reckoner::io {

/// Largest route file read (16 MiB; a route of 10,000 waypoints in RTZ is about 3 MB).
inline constexpr std::size_t kMaxRouteFileBytes = std::size_t{16} << 20;
/// Most waypoints of a route read, and most entries of one schedule list.
inline constexpr std::size_t kMaxRouteWaypoints = 10000;
/// Most schedules of an RTZ route read.
inline constexpr std::size_t kMaxRouteSchedules = 100;

/// An RTZ document (UTF-8, or ISO-8859-1 where it declares so) -> route. `source` names the input in
/// errors (a file name). Throws InputError: not XML, root not an RTZ <route> of version 1.0 / 1.1 /
/// 1.2, a missing or malformed field, a number out of its range, a duplicate waypoint id, a schedule
/// naming no waypoint of the route, a limit exceeded, or any of the route's problems().
geo::Route readRtz(std::string_view xml, const std::string& source);

/// A route -> an RTZ 1.1 document (UTF-8, namespace http://www.cirm.org/RTZ/1/1) with every field
/// of the model; numbers are the shortest decimal that reads back to the same double; control
/// characters are left out of text. Throws std::invalid_argument for what readRtz would refuse: the
/// route's problems(), a first leg or schedule that is not valid, a limit exceeded.
std::string writeRtz(const geo::Route& route);

/// The routeIndex-th (from 0) <rte> of a GPX 1.0 / 1.1 document -> route: the <rte>'s <name>, the
/// <rtept>s' lat, lon and <name>; waypoint ids are 1, 2, ...; legs rhumb lines with the model's
/// default limits. Throws InputError as readRtz does; a GPX without <rte> (tracks, waypoints only)
/// is an error, never thinned into a route.
geo::Route readGpxRoute(std::string_view xml, const std::string& source, int routeIndex = 0);

/// A route file, RTZ or GPX by its root element (<route> or <gpx>), else by its extension (.rtz, .gpx).
/// Throws InputError naming the path: missing, not a regular file, over kMaxRouteFileBytes, zipped
/// (RTZP), or what readRtz / readGpxRoute (its first route) throw.
geo::Route readRouteFile(const std::string& path);

/// Writes the route as RTZ 1.1 (writeRtz) to path. Throws InputError naming the path when it cannot
/// be written, std::invalid_argument as writeRtz does.
void writeRouteFile(const std::string& path, const geo::Route& route);

/// What rtz.cpp and gpx.cpp share (defined in gpx.cpp); not for other callers.
namespace route_xml {

/// The input as UTF-8 text: size limit, UTF-8 byte-order mark dropped, ISO-8859-1 (as declared)
/// converted, UTF-16 and zip archives refused, UTF-8 checked. Throws InputError naming the source.
std::string utf8Text(std::string_view xml, const std::string& source);

/// One parsed document, its text (for line numbers) and its source name.
class Reader {
 public:
  Reader(std::string text, std::string source);
  ~Reader();
  Reader(const Reader&) = delete;
  Reader& operator=(const Reader&) = delete;

  /// The one root element. Throws InputError: not well-formed XML (with the line), no root, two roots.
  [[nodiscard]] pugi::xml_node root() const;
  [[nodiscard]] const std::string& source() const { return source_; }
  /// 1-based line of an element's name in the text.
  [[nodiscard]] int line(const pugi::xml_node& element) const;
  [[noreturn]] void fail(const pugi::xml_node& at, const std::string& field,
                         const std::string& problem) const;

  /// A text field (an attribute's value or an element's text, as is): UTF-8 without control
  /// characters but tab, line feed and carriage return, else fail().
  [[nodiscard]] std::string text(const pugi::xml_node& at, std::string_view value,
                                 const std::string& field) const;
  /// A decimal number (xs:decimal, or with an exponent; white space around it) in [lo, hi], else
  /// fail() naming the field and quoting the value.
  [[nodiscard]] double number(const pugi::xml_node& at, std::string_view value, const std::string& field,
                              double lo, double hi) const;
  /// The route's problems() as InputError, at the line of the waypoint they name (waypointElements
  /// holds the element of each waypoint, in order) or of `routeElement`.
  void validate(const geo::Route& route, const std::vector<pugi::xml_node>& waypointElements,
                const pugi::xml_node& routeElement) const;

 private:
  std::string text_;
  std::string source_;
  std::unique_ptr<pugi::xml_document> doc_;
};

/// The value of an unprefixed attribute, "" when it is absent.
std::string_view attribute(const pugi::xml_node& element, const char* name);
/// The child elements of `parent` named `local` whose namespace begins with nsPrefix, or that have
/// none; in document order. Elements of other namespaces (extensions) are not among them.
std::vector<pugi::xml_node> children(const pugi::xml_node& parent, std::string_view local,
                                     std::string_view nsPrefix);
/// An element's name without its namespace prefix.
std::string_view localName(const pugi::xml_node& element);
/// The namespace URI of an element (from the xmlns declarations in scope), "" when it has none, and
/// "?" for a prefix that is not declared.
std::string_view namespaceUri(const pugi::xml_node& element);

}  // namespace route_xml
}  // namespace reckoner::io
