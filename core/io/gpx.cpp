// GPX routes (docs/routes.md, "Route files"), the choice between RTZ and GPX for a file, and the XML
// handling both readers share (route_xml in io/route_files.h): text encoding, parsing with line numbers,
// namespaces, numbers and text fields, the route's problems() as errors.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <limits>
#include <pugixml.hpp>

#include "io/error_line.h"
#include "io/input_error.h"
#include "io/route_files.h"
#include "io/text_file.h"
#include "io/text_format.h"
#include "io/utf8.h"

namespace reckoner::io {
namespace {

int lineAtOffset(std::string_view text, std::size_t offset) {
  offset = std::min(offset, text.size());
  return 1 +
         static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
}

std::string lowerAscii(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return out;
}

/// The encoding named in the XML declaration, lower case; "" when there is none.
std::string declaredEncoding(std::string_view text) {
  if (text.substr(0, 5) != "<?xml") return "";
  const std::string_view decl = text.substr(0, text.find("?>"));
  const std::size_t at = decl.find("encoding");
  if (at == std::string_view::npos) return "";
  const std::size_t open = decl.find_first_of("\"'", at);
  if (open == std::string_view::npos) return "";
  const std::size_t close = decl.find(decl[open], open + 1);
  if (close == std::string_view::npos) return "";
  return lowerAscii(decl.substr(open + 1, close - open - 1));
}

std::string latin1ToUtf8(std::string_view s) {
  std::string out;
  out.reserve(s.size() + s.size() / 8);
  for (const char c : s) {
    const auto b = static_cast<unsigned char>(c);
    if (b < 0x80) {
      out.push_back(c);
    } else {
      out.push_back(static_cast<char>(0xC0 | (b >> 6)));
      out.push_back(static_cast<char>(0x80 | (b & 0x3F)));
    }
  }
  return out;
}

std::string formatBound(double v) {
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc() ? std::string(buf, end) : std::string("?");
}

}  // namespace

namespace route_xml {

std::string utf8Text(std::string_view xml, const std::string& source) {
  if (xml.size() > kMaxRouteFileBytes)
    throw InputError(source, 0, "",
                     "is " + std::to_string(xml.size()) + " bytes; the limit for a route file is " +
                         std::to_string(kMaxRouteFileBytes) + " bytes");
  if (xml.substr(0, 4) == std::string_view("PK\x03\x04", 4))
    throw InputError(source, 0, "",
                     "is a zip archive (an RTZP route package?); unzip it and read the .rtz in it");
  if (xml.substr(0, 2) == "\xFE\xFF" || xml.substr(0, 2) == "\xFF\xFE" ||
      (xml.size() >= 2 && (xml[0] == '\0' || xml[1] == '\0')))
    throw InputError(source, 1, "", "is UTF-16 or UTF-32; route files are read as UTF-8 (or ISO-8859-1)");
  stripByteOrderMark(xml);
  const std::string encoding = declaredEncoding(xml);
  std::string text;
  if (encoding.empty() || encoding == "utf-8" || encoding == "utf8" || encoding == "us-ascii" ||
      encoding == "ascii") {
    text.assign(xml);
  } else if (encoding == "iso-8859-1" || encoding == "latin1" || encoding == "latin-1" ||
             encoding == "iso_8859-1") {
    text = latin1ToUtf8(xml);
  } else {
    throw InputError(
        source, 1, "encoding",
        "the file declares " + quoted(encoding, 40) + "; route files are read as UTF-8 or ISO-8859-1");
  }
  if (const std::size_t bad = firstInvalidUtf8(text); bad != std::string::npos)
    throw InputError(source, lineAtOffset(text, bad), "",
                     "not UTF-8 (byte " + quoted(std::string_view(text).substr(bad, 1)) +
                         "); save the file as UTF-8 or declare its encoding");
  if (const std::size_t nul = text.find('\0'); nul != std::string::npos)
    throw InputError(source, lineAtOffset(text, nul), "", "a NUL byte: not a text file");
  return text;
}

Reader::Reader(std::string text, std::string source)
    : text_(std::move(text)), source_(std::move(source)), doc_(std::make_unique<pugi::xml_document>()) {
  // No DOCTYPE processing, no entities beyond XML's five: nothing external is ever read.
  const pugi::xml_parse_result r =
      doc_->load_buffer(text_.data(), text_.size(), pugi::parse_default, pugi::encoding_utf8);
  if (r.status == pugi::status_no_document_element)
    throw InputError(source_, 0, "", "no XML element in it (not an XML file?)");
  if (!r)
    throw InputError(source_,
                     lineAtOffset(text_, static_cast<std::size_t>(std::max<std::ptrdiff_t>(r.offset, 0))), "",
                     std::string("not well-formed XML: ") + r.description());
}

Reader::~Reader() = default;

pugi::xml_node Reader::root() const {
  pugi::xml_node root;
  for (const pugi::xml_node n : doc_->children()) {
    if (n.type() != pugi::node_element) continue;
    if (root) fail(n, "", "a second root element " + quoted(n.name(), 80) + ": not well-formed XML");
    root = n;
  }
  if (!root) throw InputError(source_, 0, "", "no XML element in it (not an XML file?)");
  return root;
}

int Reader::line(const pugi::xml_node& element) const {
  const std::ptrdiff_t offset = element.offset_debug();
  return offset < 0 ? 0 : lineAtOffset(text_, static_cast<std::size_t>(offset));
}

void Reader::fail(const pugi::xml_node& at, const std::string& field, const std::string& problem) const {
  throw InputError(source_, line(at), field, problem);
}

std::string Reader::text(const pugi::xml_node& at, std::string_view value, const std::string& field) const {
  // Character references may have made what the UTF-8 check of the whole text could not see.
  if (firstInvalidUtf8(value) != std::string_view::npos) fail(at, field, "not UTF-8: " + quoted(value, 80));
  for (const char c : value) {
    const auto b = static_cast<unsigned char>(c);
    if ((b < 0x20 && c != '\t' && c != '\n' && c != '\r') || b == 0x7F)
      fail(at, field, "a control character in " + quoted(value, 80));
  }
  return std::string(value);
}

double Reader::number(const pugi::xml_node& at, std::string_view value, const std::string& field, double lo,
                      double hi) const {
  std::string_view v = value;
  while (!v.empty() && (v.front() == ' ' || v.front() == '\t')) v.remove_prefix(1);
  if (v.size() > 1 && v.front() == '+' && v[1] != '-') v.remove_prefix(1);  // xs:decimal allows "+1.5"
  const std::optional<double> x = parseFiniteNumber(v);
  if (!x || *x < lo || *x > hi) {
    constexpr double kMax = std::numeric_limits<double>::max();
    const std::string range = hi != kMax    ? " in [" + formatBound(lo) + ", " + formatBound(hi) + "]"
                              : lo != -kMax ? " >= " + formatBound(lo)
                                            : "";
    fail(at, field, "must be a number" + range + ", got " + quoted(value, 40));
  }
  return *x;
}

void Reader::validate(const geo::Route& route, const std::vector<pugi::xml_node>& waypointElements,
                      const pugi::xml_node& routeElement) const {
  const std::vector<std::string> problems = route.problems();
  if (problems.empty()) return;
  // problems() names a waypoint as "waypoint K (id N...)": K, from 1, is the element's place.
  const std::string& p = problems.front();
  const std::string_view prefix = "waypoint ";
  int k = 0;
  if (std::string_view(p).substr(0, prefix.size()) == prefix &&
      std::from_chars(p.data() + prefix.size(), p.data() + p.size(), k).ec != std::errc())
    k = 0;
  const bool named = k >= 1 && static_cast<std::size_t>(k) <= waypointElements.size();
  throw InputError(source_, line(named ? waypointElements[static_cast<std::size_t>(k) - 1] : routeElement),
                   "", p);
}

std::string_view attribute(const pugi::xml_node& element, const char* name) {
  return element.attribute(name).value();
}

std::string_view localName(const pugi::xml_node& element) {
  const std::string_view name = element.name();
  const std::size_t colon = name.find(':');
  return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

std::string_view namespaceUri(const pugi::xml_node& element) {
  const std::string_view name = element.name();
  const std::size_t colon = name.find(':');
  const std::string declaration =
      colon == std::string_view::npos ? std::string("xmlns") : "xmlns:" + std::string(name.substr(0, colon));
  for (pugi::xml_node n = element; n && n.type() == pugi::node_element; n = n.parent())
    if (const pugi::xml_attribute a = n.attribute(declaration.c_str())) return a.value();
  return colon == std::string_view::npos ? "" : "?";
}

std::vector<pugi::xml_node> children(const pugi::xml_node& parent, std::string_view local,
                                     std::string_view nsPrefix) {
  std::vector<pugi::xml_node> out;
  for (const pugi::xml_node n : parent.children()) {
    if (n.type() != pugi::node_element || localName(n) != local) continue;
    const std::string_view ns = namespaceUri(n);
    if (ns.empty() || ns.substr(0, nsPrefix.size()) == nsPrefix) out.push_back(n);
  }
  return out;
}

}  // namespace route_xml

namespace {

using route_xml::Reader;

constexpr std::string_view kGpxNamespace = "http://www.topografix.com/GPX/";

/// The text of the first child element `local` of `parent` (GPX namespace), trimmed; "" when none.
std::string childText(const Reader& r, const pugi::xml_node& parent, std::string_view local,
                      const std::string& field) {
  const std::vector<pugi::xml_node> found = route_xml::children(parent, local, kGpxNamespace);
  if (found.empty()) return "";
  std::string_view v = found.front().text().get();
  while (!v.empty() && std::isspace(static_cast<unsigned char>(v.front()))) v.remove_prefix(1);
  while (!v.empty() && std::isspace(static_cast<unsigned char>(v.back()))) v.remove_suffix(1);
  return r.text(found.front(), v, field);
}

pugi::xml_node chooseRoute(const Reader& r, const pugi::xml_node& gpx, int routeIndex) {
  const std::vector<pugi::xml_node> routes = route_xml::children(gpx, "rte", kGpxNamespace);
  if (routes.empty())
    r.fail(gpx, "rte",
           "no route (<rte>) in the file; tracks (<trk>) and waypoints (<wpt>) are not read as routes");
  if (routeIndex < 0 || static_cast<std::size_t>(routeIndex) >= routes.size())
    r.fail(gpx, "rte",
           "route " + std::to_string(routeIndex) + " asked for; the file has " +
               std::to_string(routes.size()) + " route(s), numbered from 0");
  return routes[static_cast<std::size_t>(routeIndex)];
}

std::string author(const Reader& r, const pugi::xml_node& gpx) {
  // GPX 1.1: <metadata><author><name>; GPX 1.0: <author> as text.
  for (const pugi::xml_node metadata : route_xml::children(gpx, "metadata", kGpxNamespace))
    for (const pugi::xml_node a : route_xml::children(metadata, "author", kGpxNamespace))
      return childText(r, a, "name", "metadata author name");
  return childText(r, gpx, "author", "author");
}

geo::Waypoint routePoint(const Reader& r, const pugi::xml_node& pt, std::size_t k) {
  const std::string where = "rtept " + std::to_string(k + 1);
  geo::Waypoint w;
  w.id = static_cast<int>(k + 1);
  for (const char* coordinate : {"lat", "lon"}) {
    const std::string_view v = route_xml::attribute(pt, coordinate);
    const bool lat = coordinate[1] == 'a';
    if (v.find_first_not_of(" \t\r\n") == std::string_view::npos)
      r.fail(pt, where + " " + coordinate, "missing (a route point needs lat and lon)");
    (lat ? w.position.latDeg : w.position.lonDeg) =
        r.number(pt, v, where + " " + coordinate, lat ? -90.0 : -180.0, lat ? 90.0 : 180.0);
  }
  w.name = childText(r, pt, "name", where + " name");
  return w;
}

}  // namespace

geo::Route readGpxRoute(std::string_view xml, const std::string& source, int routeIndex) {
  const Reader r(route_xml::utf8Text(xml, source), source);
  const pugi::xml_node gpx = r.root();
  const std::string_view ns = route_xml::namespaceUri(gpx);
  if (route_xml::localName(gpx) != "gpx" ||
      !(ns.empty() || ns.substr(0, kGpxNamespace.size()) == kGpxNamespace))
    r.fail(gpx, "", "the root element is " + quoted(gpx.name(), 80) + ", not GPX's <gpx>");
  const std::string_view version = route_xml::attribute(gpx, "version");
  if (!version.empty() && version != "1.0" && version != "1.1")
    r.fail(gpx, "gpx version", "must be \"1.0\" or \"1.1\", got " + quoted(version, 40));
  const pugi::xml_node rte = chooseRoute(r, gpx, routeIndex);
  geo::Route route;
  route.name = childText(r, rte, "name", "rte name");
  route.author = author(r, gpx);
  const std::vector<pugi::xml_node> points = route_xml::children(rte, "rtept", kGpxNamespace);
  if (points.size() > kMaxRouteWaypoints)
    r.fail(points[kMaxRouteWaypoints], "rtept",
           "more than " + std::to_string(kMaxRouteWaypoints) + " route points; the limit is " +
               std::to_string(kMaxRouteWaypoints));
  for (std::size_t k = 0; k < points.size(); ++k) route.waypoints.push_back(routePoint(r, points[k], k));
  r.validate(route, points, rte);
  return route;
}

namespace {

/// The root element's local name, "" when the text does not start like XML. Skips a byte-order mark,
/// the XML declaration, comments, processing instructions and a DOCTYPE.
std::string_view rootName(std::string_view s) {
  stripByteOrderMark(s);
  while (true) {
    const std::size_t lt = s.find('<');
    if (lt == std::string_view::npos ||
        s.substr(0, lt).find_first_not_of(" \t\r\n") != std::string_view::npos)
      return "";
    s.remove_prefix(lt);
    std::size_t end = std::string_view::npos;  // of the construct's last character, '>'
    if (s.substr(0, 4) == "<!--") {
      end = s.find("-->", 4);
      if (end != std::string_view::npos) end += 2;
    } else if (s.substr(0, 2) == "<?" || s.substr(0, 2) == "<!") {
      const std::size_t bracket = s.find('['), close = s.find('>');
      end = bracket < close && s.substr(0, 9) == "<!DOCTYPE" ? s.find("]>") : close;
      if (end != close && end != std::string_view::npos) end += 1;
    } else {
      s.remove_prefix(1);
      const std::string_view name = s.substr(0, s.find_first_of(" \t\r\n/>"));
      const std::size_t colon = name.find(':');
      return colon == std::string_view::npos ? name : name.substr(colon + 1);
    }
    if (end == std::string_view::npos) return "";
    s.remove_prefix(end + 1);
  }
}

}  // namespace

geo::Route readRouteFile(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_regular_file(path, ec)) {
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (!ec && size > kMaxRouteFileBytes)
      throw InputError(path, 0, "",
                       "is " + std::to_string(size) + " bytes; the limit for a route file is " +
                           std::to_string(kMaxRouteFileBytes) + " bytes");
  }
  const std::string text = readTextFile(path);
  const std::string_view root = rootName(text);
  const std::string extension = lowerAscii(std::filesystem::path(path).extension().string());
  if (root == "gpx" || (root != "route" && extension == ".gpx")) return readGpxRoute(text, path);
  return readRtz(text, path);
}

void writeRouteFile(const std::string& path, const geo::Route& route) {
  writeTextFile(path, writeRtz(route));
}

}  // namespace reckoner::io
