#include "charts/pick/pick_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <type_traits>

#include "charts/s57/s57_loader.h"

namespace reckoner::charts {
namespace {

/// One CSV line into fields ("a","b, c",d -> a | b, c | d).
std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  bool quoted = false;
  for (char ch : line) {
    if (ch == '"') {
      quoted = !quoted;
    } else if (ch == ',' && !quoted) {
      out.push_back(cur);
      cur.clear();
    } else if (ch != '\r') {
      cur += ch;
    }
  }
  out.push_back(cur);
  return out;
}

std::vector<std::vector<std::string>> readCsv(const std::string& path, std::size_t minFields) {
  std::ifstream in(path);
  if (!in) throw ChartLoadError(path, "cannot read the S-57 catalogue file");
  std::vector<std::vector<std::string>> rows;
  std::string line;
  std::getline(in, line);  // header
  int lineNo = 1;
  while (std::getline(in, line)) {
    ++lineNo;
    if (line.empty() || line == "\r") continue;
    auto fields = splitCsv(line);
    if (fields.size() < minFields)
      throw ChartLoadError(path, "line " + std::to_string(lineNo) + ": expected " +
                                     std::to_string(minFields) + " fields, got " +
                                     std::to_string(fields.size()));
    rows.push_back(std::move(fields));
  }
  return rows;
}

long long toInt(const std::string& s, const std::string& file) {
  char* end = nullptr;
  const long long v = std::strtoll(s.c_str(), &end, 10);
  if (end == s.c_str()) throw ChartLoadError(file, "not a number: '" + s + "'");
  return v;
}

double segmentDistance(double px, double py, double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(px - (ax + t * dx), py - (ay + t * dy));
}

}  // namespace

S57Catalogue::S57Catalogue(const std::string& directory) {
  const std::string classes = directory + "/s57objectclasses.csv";
  for (const auto& r : readCsv(classes, 3)) classes_[r[2]] = r[1];
  const std::string attributes = directory + "/s57attributes.csv";
  for (const auto& r : readCsv(attributes, 3))
    attributes_[r[2]] = {static_cast<int>(toInt(r[0], attributes)), r[1]};
  const std::string values = directory + "/s57expectedinput.csv";
  for (const auto& r : readCsv(values, 3))
    values_[{static_cast<int>(toInt(r[0], values)), toInt(r[1], values)}] = r[2];
  if (classes_.empty() || attributes_.empty()) throw ChartLoadError(classes, "empty S-57 catalogue");
}

const S57Catalogue& S57Catalogue::installed() {
  static const S57Catalogue c = [] {
    const std::string dir = s57CatalogueDirectory();
    if (dir.empty())
      throw ChartLoadError("s57objectclasses.csv", "GDAL's S-57 catalogue was not found; install gdal-data");
    return S57Catalogue(dir);
  }();
  return c;
}

std::string S57Catalogue::className(const std::string& acronym) const {
  const auto it = classes_.find(acronym);
  return it == classes_.end() ? acronym : it->second;
}

std::string S57Catalogue::attributeName(const std::string& acronym) const {
  const auto it = attributes_.find(acronym);
  return it == attributes_.end() ? acronym : it->second.second;
}

namespace {

/// The unit of a measured attribute's value (IHO S-57 appendix A: depths, heights and clearances in
/// metres, directions in degrees, periods in seconds, nominal ranges in nautical miles, current
/// velocities in knots); empty for the rest.
const char* unitOf(const std::string& acronym) {
  static const std::map<std::string, const char*, std::less<>> kUnits{
      {"VALSOU", "m"}, {"DRVAL1", "m"}, {"DRVAL2", "m"}, {"VALDCO", "m"}, {"HEIGHT", "m"},  {"ELEVAT", "m"},
      {"VERCLR", "m"}, {"VERCCL", "m"}, {"VERCOP", "m"}, {"HORCLR", "m"}, {"HORLEN", "m"},  {"HORWID", "m"},
      {"ORIENT", "°"}, {"SECTR1", "°"}, {"SECTR2", "°"}, {"SIGPER", "s"}, {"VALNMR", "NM"}, {"CURVEL", "kn"}};
  const auto it = kUnits.find(acronym);
  return it == kUnits.end() ? "" : it->second;
}

std::string withUnit(std::string number, const char* unit) {
  if (*unit == '\0') return number;
  return number.append(std::strcmp(unit, "°") == 0 ? "" : " ").append(unit);
}

}  // namespace

std::string S57Catalogue::valueText(const std::string& acronym, const AttributeValue& value) const {
  const auto attr = attributes_.find(acronym);
  const int code = attr == attributes_.end() ? -1 : attr->second.first;
  const auto decode = [&](long long v) {
    const auto it = values_.find({code, v});
    return it == values_.end() ? std::to_string(v) : it->second;
  };
  return std::visit(
      [&](const auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::int64_t>) {
          return *unitOf(acronym) ? withUnit(std::to_string(v), unitOf(acronym)) : decode(v);
        } else if constexpr (std::is_same_v<T, double>) {
          char buf[64];
          std::snprintf(buf, sizeof buf, "%g", v);
          return withUnit(buf, unitOf(acronym));
        } else if constexpr (std::is_same_v<T, std::string>) {
          return v;
        } else {
          std::string out;
          for (auto x : v) {
            if (!out.empty()) out.append(", ");
            out.append(decode(x));
          }
          return out;
        }
      },
      value);
}

PickedFeature describeFeature(const ChartCell& cell, const ChartFeature& f, const S57Catalogue& catalogue) {
  PickedFeature p;
  p.cell = cell.info().name;
  p.objectClass = f.objectClass;
  p.className = catalogue.className(f.objectClass);
  const Primitive prim = f.geometry.primitive;
  p.primitive = prim == Primitive::Point ? "point" : prim == Primitive::Line ? "line" : "area";
  p.lnam = f.lnam;
  for (const auto& a : f.attributes)
    p.attributes.push_back(
        {a.acronym, catalogue.attributeName(a.acronym), catalogue.valueText(a.acronym, a.value)});
  return p;
}

std::vector<PickedFeature> pickFeatures(const std::vector<CellPtr>& cells, const Viewport& view,
                                        ScreenPoint at, double tolerancePx, const S57Catalogue& catalogue) {
  std::vector<std::pair<std::pair<int, double>, PickedFeature>> found;  // (primitive rank, distance)
  std::vector<CellPtr> order = cells;
  std::sort(order.begin(), order.end(), [](const CellPtr& a, const CellPtr& b) {
    return a->info().compilationScale < b->info().compilationScale;
  });
  const LatLon here = view.toLatLon(at);
  for (std::size_t ci = 0; ci < order.size(); ++ci) {
    const ChartCell& cell = *order[ci];
    for (const auto& f : cell.features()) {
      const Geometry& g = f.geometry;
      if (g.parts.empty()) continue;
      double dist = 1e300;
      std::vector<PickedAttribute> extra;
      if (g.primitive == Primitive::Point) {
        std::size_t nearest = 0;
        for (std::size_t i = 0; i < g.parts[0].size(); ++i) {
          const ScreenPoint p = view.toScreen(g.parts[0][i]);
          const double d = std::hypot(p.x - at.x, p.y - at.y);
          if (d < dist) {
            dist = d;
            nearest = i;
          }
        }
        if (!g.depthsM.empty() && nearest < g.depthsM.size()) {
          char buf[32];
          std::snprintf(buf, sizeof buf, "%.1f m", g.depthsM[nearest]);
          extra.push_back({"DEPTH", "Depth of the nearest sounding", buf});
        }
      } else if (g.primitive == Primitive::Line) {
        for (const auto& part : g.parts)
          for (std::size_t i = 1; i < part.size(); ++i) {
            const ScreenPoint a = view.toScreen(part[i - 1]), b = view.toScreen(part[i]);
            dist = std::min(dist, segmentDistance(at.x, at.y, a.x, a.y, b.x, b.y));
          }
      } else if (g.primitive == Primitive::Area) {
        if (g.contains(here)) dist = 0;
      }
      if (dist > tolerancePx) continue;
      PickedFeature p = describeFeature(cell, f, catalogue);
      p.distancePx = dist;
      p.attributes.insert(p.attributes.end(), extra.begin(), extra.end());
      const int rank = static_cast<int>(ci) * 3 + (g.primitive == Primitive::Point  ? 0
                                                   : g.primitive == Primitive::Line ? 1
                                                                                    : 2);
      found.emplace_back(std::pair<int, double>{rank, dist}, std::move(p));
    }
  }
  std::stable_sort(found.begin(), found.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<PickedFeature> out;
  out.reserve(found.size());
  for (auto& [key, p] : found) out.push_back(std::move(p));
  return out;
}

}  // namespace reckoner::charts
