// reckoner-chartgen OUT.000: writes the project's own fictional chart, "Reckoner Sound", as a real S-57
// ENC cell through GDAL's S-57 writer. FICTIONAL - NOT FOR NAVIGATION: the place, its depths and its
// aids are invented here (docs/charts.md, "The embedded default chart").
//
// The harbour is authored as a model, not digitised from anything: a mainland whose coast is a smooth
// curve with a bay, a depth field that deepens offshore (40 m (1 - exp(-d / 1.8 km)) at a distance d
// north of the coast) and around two islands, so depth areas, contours and soundings agree by
// construction. Aids, areas and routes are placed by hand below. The cell is written in S-57's
// chain-node topology: shared edges between connected nodes (a contour is one edge used by the contour
// and by the depth areas on both sides), isolated nodes for point features and the sounding array.
#include <cpl_conv.h>
#include <cpl_string.h>
#include <gdal.h>
#include <ogr_api.h>

#include <cmath>
#include <cstdio>
#include <deque>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

// ---- the place: local kilometres east (x) and north (y) of an invented origin in the open Atlantic
constexpr double kLat0 = 49.5, kLon0 = -29.5;
constexpr double kXMin = -8.0, kXMax = 8.0, kYMin = -6.0, kYMax = 6.0;
constexpr double kPi = 3.14159265358979323846;

struct P {
  double x = 0, y = 0;
};

double lonOf(const P& p) {
  return kLon0 + p.x / (111.32 * std::cos(kLat0 * kPi / 180.0));
}
double latOf(const P& p) {
  return kLat0 + p.y / 110.57;
}

/// The mainland's coast: gentle undulations and a bay centred at x = 0.6 km.
double coastY(double x) {
  return -3.0 + 0.5 * std::sin(x / 1.9) + 0.35 * std::sin(x / 0.7 + 1.0) -
         2.2 * std::exp(-std::pow((x - 0.6) / 1.1, 2));
}

/// Offshore depth at a distance d (km) north of the coast, and its inverse.
double mainDepth(double d) {
  return d <= 0 ? -1.0 : 40.0 * (1.0 - std::exp(-d / 1.8));
}
double distanceOfDepth(double depth) {
  return -1.8 * std::log(1.0 - depth / 40.0);
}

struct Island {
  P centre;
  double scale;  // the radii below times this
  const char* name;
  [[nodiscard]] double radius(double rBase, double theta) const {
    return scale * rBase * (1.0 + 0.08 * std::sin(3 * theta + centre.x) + 0.05 * std::cos(5 * theta));
  }
  /// Depth from the island's shore (r1) through the 10 m (r2) and 30 m (r3) contours, linear between.
  [[nodiscard]] double depth(const P& p) const {
    const double dx = p.x - centre.x, dy = p.y - centre.y;
    const double theta = std::atan2(dy, dx), r = std::hypot(dx, dy);
    const double r1 = radius(0.45, theta), r2 = radius(0.8, theta), r3 = radius(1.2, theta);
    if (r <= r1) return -1.0;
    if (r <= r2) return 10.0 * (r - r1) / (r2 - r1);
    if (r <= r3) return 10.0 + 20.0 * (r - r2) / (r3 - r2);
    return 30.0 + 20.0 * (r - r3);  // beyond r3 the offshore field takes over (it is at least 30 there)
  }
};

const Island kIslands[] = {{{-4.0, 3.2}, 1.0, "Gannet Island"}, {{5.0, 2.6}, 0.7, "Skerry Holm"}};
constexpr double kContours[] = {2.0, 5.0, 10.0, 20.0, 30.0};

double depthAt(const P& p) {
  double d = mainDepth(p.y - coastY(p.x));
  for (const auto& isl : kIslands) d = std::min(d, isl.depth(p));
  return d;
}

// ---- chain-node topology
struct Edge {
  int id = 0;
  std::vector<P> pts;  // including both end points
  int beginNode = 0, endNode = 0;
};

struct Ref {  // a feature's use of an edge
  int edge = 0;
  bool reversed = false;
  int usage = 255;  // 1 exterior ring, 2 interior ring, 255 line
};

struct Attr {
  std::string acronym, value;  // lists as "2,6"
};

struct Feature {
  std::string cls;
  int prim = 1;  // 1 point, 2 line, 3 area
  std::vector<Attr> attrs;
  std::vector<Ref> edges;
  std::optional<P> point;
  std::vector<std::pair<P, double>> soundings;
};

class S57Writer;

class Chart {
 public:
  int node(const P& p) {
    const auto key = std::make_pair(std::lround(p.x * 1e6), std::lround(p.y * 1e6));
    auto it = nodes_.find(key);
    if (it != nodes_.end()) return it->second.first;
    const int id = static_cast<int>(nodes_.size()) + 1;
    nodes_.emplace(key, std::make_pair(id, p));
    return id;
  }
  int edge(std::vector<P> pts) {
    if (pts.size() < 2) throw std::logic_error("an edge needs two points");
    Edge e;
    e.id = static_cast<int>(edges_.size()) + 1;
    e.beginNode = node(pts.front());
    e.endNode = node(pts.back());
    e.pts = std::move(pts);
    edges_.push_back(e);
    return e.id;
  }
  Feature& add(std::string cls, int prim, std::vector<Attr> attrs) {
    features_.push_back({std::move(cls), prim, std::move(attrs), {}, {}, {}});
    return features_.back();
  }
  Feature& point(std::string cls, P at, std::vector<Attr> attrs) {
    Feature& f = add(std::move(cls), 1, std::move(attrs));
    f.point = at;
    return f;
  }
  /// A closed ring as a single edge (island shores, contours around islands).
  int ring(const Island& isl, double rBase) {
    std::vector<P> pts;
    for (int k = 0; k <= 72; ++k) {
      const double theta = 2 * kPi * (k % 72) / 72.0;
      const double r = isl.radius(rBase, theta);
      pts.push_back({isl.centre.x + r * std::cos(theta), isl.centre.y + r * std::sin(theta)});
    }
    return edge(pts);
  }
  /// A straight-sided polygon of its own edges (one per side).
  std::vector<Ref> polygon(const std::vector<P>& corners, int usage = 1) {
    std::vector<Ref> refs;
    for (std::size_t i = 0; i < corners.size(); ++i)
      refs.push_back({edge({corners[i], corners[(i + 1) % corners.size()]}), false, usage});
    return refs;
  }
  void write(const std::string& path) const;

 private:
  void writeTopology(const S57Writer& w) const;
  std::map<std::pair<long, long>, std::pair<int, P>> nodes_;
  std::vector<Edge> edges_;
  std::deque<Feature> features_;  // add() hands out references: they must survive later add()s
};

std::map<std::string, int> objectCodes() {
  const char* csv = CPLFindFile("gdal", "s57objectclasses.csv");
  if (!csv) csv = CPLFindFile("s57", "s57objectclasses.csv");
  if (!csv) throw std::runtime_error("GDAL's s57objectclasses.csv was not found (install gdal-data)");
  std::ifstream in(csv);
  std::map<std::string, int> codes;
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    // Code,ObjectClass,Acronym,...: the acronym is the third field; the second may be quoted.
    char** tokens = CSLTokenizeString2(line.c_str(), ",", CSLT_HONOURSTRINGS | CSLT_ALLOWEMPTYTOKENS);
    std::vector<std::string> fields;
    for (int i = 0; tokens && tokens[i]; ++i) fields.emplace_back(tokens[i]);
    CSLDestroy(tokens);
    if (fields.size() >= 3) codes[fields[2]] = std::atoi(fields[0].c_str());
  }
  return codes;
}

std::string cat(std::string a, const std::string& b);

void check(OGRErr err, const std::string& what) {
  if (err != OGRERR_NONE) throw std::runtime_error("GDAL could not write " + what);
}

/// GDAL's S-57 writer: its layers and fields by name, each missing one an error that names it.
class S57Writer {
 public:
  explicit S57Writer(GDALDatasetH ds) : ds_(ds) {}
  [[nodiscard]] OGRLayerH layer(const char* name) const {
    OGRLayerH l = GDALDatasetGetLayerByName(ds_, name);
    if (!l) throw std::runtime_error(std::string("the S57 writer has no layer ") + name);
    return l;
  }
  static void setInt(OGRFeatureH f, const char* field, int v) {
    OGR_F_SetFieldInteger(f, fieldIndex(f, field), v);
  }
  static void setList(OGRFeatureH f, const char* field, const std::vector<int>& v) {
    OGR_F_SetFieldIntegerList(f, fieldIndex(f, field), static_cast<int>(v.size()), v.data());
  }

 private:
  static int fieldIndex(OGRFeatureH f, const char* field) {
    const int i = OGR_F_GetFieldIndex(f, field);
    if (i < 0) throw std::runtime_error(std::string("the S57 writer has no field ") + field);
    return i;
  }
  GDALDatasetH ds_;
};

/// The pointers of a feature to its spatial records (FSPT): NAME_RCNM, NAME_RCID, ORNT, USAG, MASK.
struct SpatialPointers {
  std::vector<int> rcnm, ids, ornt, usag, mask;
};

/// The dataset's general information (DSID, DSSI): edition, scale, comment and the record counts.
GDALDatasetH createCell(const std::string& path, int isolatedNodes, std::size_t connectedNodes,
                        std::size_t edges, int metaFeatures, std::size_t features) {
  GDALAllRegister();
  GDALDriverH driver = GDALGetDriverByName("S57");
  if (!driver) throw std::runtime_error("GDAL has no S57 driver");
  const std::string noin = cat("S57_NOIN=", std::to_string(isolatedNodes));
  const std::string nocn = cat("S57_NOCN=", std::to_string(connectedNodes));
  const std::string noed = cat("S57_NOED=", std::to_string(edges));
  const std::string nomr = cat("S57_NOMR=", std::to_string(metaFeatures));
  const std::string nogr =
      cat("S57_NOGR=", std::to_string(features - static_cast<std::size_t>(metaFeatures)));
  const char* options[] = {
      "S57_EXPP=1",
      "S57_INTU=5",
      "S57_EDTN=1",
      "S57_UPDN=0",
      "S57_ISDT=20261123",
      "S57_UADT=20261123",
      "S57_AGEN=0",
      "S57_CSCL=20000",
      "S57_COMT=FICTIONAL CHART - NOT FOR NAVIGATION (Reckoner Sound, authored by the Reckoner project)",
      noin.c_str(),
      nocn.c_str(),
      noed.c_str(),
      nomr.c_str(),
      nogr.c_str(),
      nullptr};
  GDALDatasetH ds = GDALCreate(driver, path.c_str(), 0, 0, 0, GDT_Unknown, const_cast<char**>(options));
  if (!ds) throw std::runtime_error("GDAL could not create " + path);
  return ds;
}

/// Connected nodes, then edges (interior vertices only: the end points are their nodes).
void Chart::writeTopology(const S57Writer& w) const {
  OGRLayerH vc = w.layer("ConnectedNode");
  for (const auto& [key, idp] : nodes_) {
    OGRFeatureH f = OGR_F_Create(OGR_L_GetLayerDefn(vc));
    S57Writer::setInt(f, "RCNM", 120);
    S57Writer::setInt(f, "RCID", idp.first);
    OGRGeometryH g = OGR_G_CreateGeometry(wkbPoint);
    OGR_G_SetPoint_2D(g, 0, lonOf(idp.second), latOf(idp.second));
    OGR_F_SetGeometryDirectly(f, g);
    check(OGR_L_CreateFeature(vc, f), "a connected node");
    OGR_F_Destroy(f);
  }
  OGRLayerH ve = w.layer("Edge");
  for (const auto& e : edges_) {
    OGRFeatureH f = OGR_F_Create(OGR_L_GetLayerDefn(ve));
    S57Writer::setInt(f, "RCNM", 130);
    S57Writer::setInt(f, "RCID", e.id);
    OGRGeometryH g = OGR_G_CreateGeometry(wkbLineString);
    for (std::size_t i = 1; i + 1 < e.pts.size(); ++i) OGR_G_AddPoint_2D(g, lonOf(e.pts[i]), latOf(e.pts[i]));
    OGR_F_SetGeometryDirectly(f, g);
    for (int k = 0; k < 2; ++k) {
      const std::string s = cat("_", std::to_string(k));
      S57Writer::setInt(f, cat("NAME_RCNM", s).c_str(), 120);
      S57Writer::setInt(f, cat("NAME_RCID", s).c_str(), k == 0 ? e.beginNode : e.endNode);
      S57Writer::setInt(f, cat("ORNT", s).c_str(), 255);
      S57Writer::setInt(f, cat("USAG", s).c_str(), 255);
      S57Writer::setInt(f, cat("TOPI", s).c_str(), k == 0 ? 1 : 2);
      S57Writer::setInt(f, cat("MASK", s).c_str(), 255);
    }
    check(OGR_L_CreateFeature(ve, f), "an edge");
    OGR_F_Destroy(f);
  }
}

/// A point feature's isolated node (a point, or the sounding array as one 3-D multipoint) with the
/// given id; the feature's pointer to it.
SpatialPointers writeIsolatedNode(const S57Writer& w, const Feature& feat, int id) {
  OGRLayerH vi = w.layer("IsolatedNode");
  OGRFeatureH n = OGR_F_Create(OGR_L_GetLayerDefn(vi));
  S57Writer::setInt(n, "RCNM", 110);
  S57Writer::setInt(n, "RCID", id);
  OGRGeometryH g;
  if (!feat.soundings.empty()) {
    g = OGR_G_CreateGeometry(wkbMultiPoint25D);
    for (const auto& [p, depth] : feat.soundings) {
      OGRGeometryH pt = OGR_G_CreateGeometry(wkbPoint25D);
      OGR_G_SetPoint(pt, 0, lonOf(p), latOf(p), depth);
      OGR_G_AddGeometryDirectly(g, pt);
    }
  } else {
    g = OGR_G_CreateGeometry(wkbPoint);
    OGR_G_SetPoint_2D(g, 0, lonOf(*feat.point), latOf(*feat.point));
  }
  OGR_F_SetGeometryDirectly(n, g);
  check(OGR_L_CreateFeature(vi, n), "an isolated node");
  OGR_F_Destroy(n);
  return {{110}, {id}, {255}, {255}, {255}};
}

/// A line or area feature's pointers to its edges (usage only for areas: exterior or interior ring).
SpatialPointers edgePointers(const Feature& feat) {
  SpatialPointers sp;
  for (const auto& r : feat.edges) {
    sp.rcnm.push_back(130);
    sp.ids.push_back(r.edge);
    sp.ornt.push_back(r.reversed ? 2 : 1);
    sp.usag.push_back(feat.prim == 3 ? r.usage : 255);
    sp.mask.push_back(255);
  }
  return sp;
}

/// The feature record: identity, object class, pointers and attributes (a list attribute split at commas).
void writeFeature(const S57Writer& w, const Feature& feat, int rcid, int objectCode,
                  const SpatialPointers& sp) {
  OGRLayerH l = w.layer(feat.cls.c_str());
  OGRFeatureH f = OGR_F_Create(OGR_L_GetLayerDefn(l));
  S57Writer::setInt(f, "RCID", rcid);
  S57Writer::setInt(f, "PRIM", feat.prim);
  const bool skinOfEarth = feat.cls == "DEPARE" || feat.cls == "LNDARE" || feat.cls == "DRGARE" ||
                           feat.cls == "UNSARE" || feat.cls == "PONTON" || feat.cls == "HULKES";
  S57Writer::setInt(f, "GRUP", skinOfEarth ? 1 : 2);
  S57Writer::setInt(f, "OBJL", objectCode);
  S57Writer::setInt(f, "AGEN", 0);
  S57Writer::setInt(f, "FIDN", rcid);
  S57Writer::setInt(f, "FIDS", 1);
  S57Writer::setList(f, "NAME_RCNM", sp.rcnm);
  S57Writer::setList(f, "NAME_RCID", sp.ids);
  S57Writer::setList(f, "ORNT", sp.ornt);
  S57Writer::setList(f, "USAG", sp.usag);
  S57Writer::setList(f, "MASK", sp.mask);
  for (const auto& a : feat.attrs) {
    const int i = OGR_F_GetFieldIndex(f, a.acronym.c_str());
    if (i < 0) throw std::runtime_error(feat.cls + " has no attribute " + a.acronym);
    if (OGR_Fld_GetType(OGR_F_GetFieldDefnRef(f, i)) == OFTStringList) {
      char** list = CSLTokenizeString2(a.value.c_str(), ",", 0);
      OGR_F_SetFieldStringList(f, i, list);
      CSLDestroy(list);
    } else {
      OGR_F_SetFieldString(f, i, a.value.c_str());
    }
  }
  check(OGR_L_CreateFeature(l, f), "feature " + feat.cls);
  OGR_F_Destroy(f);
}

void Chart::write(const std::string& path) const {
  int isolatedNodes = 0, meta = 0;
  for (const auto& f : features_) {
    isolatedNodes += f.prim == 1 ? 1 : 0;
    meta += f.cls.rfind("M_", 0) == 0 ? 1 : 0;
  }
  GDALDatasetH ds = createCell(path, isolatedNodes, nodes_.size(), edges_.size(), meta, features_.size());
  const S57Writer w(ds);
  writeTopology(w);
  // Isolated nodes for the point features and the soundings, each before its feature.
  const auto codes = objectCodes();
  int isolated = 0, rcid = 0;
  for (const auto& feat : features_) {
    ++rcid;
    const auto code = codes.find(feat.cls);
    const SpatialPointers sp = feat.prim == 1 ? writeIsolatedNode(w, feat, ++isolated) : edgePointers(feat);
    if (code == codes.end()) throw std::runtime_error("unknown object class " + feat.cls);
    writeFeature(w, feat, rcid, code->second, sp);
  }
  GDALClose(ds);
}

/// a + b without GCC 12's false -Wrestrict on operator+(const char*, std::string&&).
std::string cat(std::string a, const std::string& b) {
  a.append(b);
  return a;
}

std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  return buf;
}

// ---- the harbour
/// The coast and the depth contours as curves across the cell, and the cell's boundary cut where they meet
/// it.
struct Frame {
  std::vector<int> curves;      // curves[0]: the coast; curves[k]: the contour of kContours[k - 1]
  std::vector<int> west, east;  // west[k]: from curve k - 1 to curve k (k = 0: from the bottom corner)
  int bottom = 0, top = 0;
};

Frame authorFrame(Chart& c) {
  Frame fr;
  // Curves sampled every 100 m from the west edge of the cell to the east edge.
  const auto curve = [](double offsetKm) {
    std::vector<P> pts;
    for (int i = 0; i <= 160; ++i) {
      const double x = kXMin + (kXMax - kXMin) * i / 160.0;
      pts.push_back({x, coastY(x) + offsetKm});
    }
    return pts;
  };
  std::vector<double> offsets{0.0};
  for (double d : kContours) offsets.push_back(distanceOfDepth(d));
  fr.curves.reserve(offsets.size());
  for (double o : offsets) fr.curves.push_back(c.edge(curve(o)));
  // The cell boundary, cut where the curves meet it: west side bottom-up, east side bottom-up.
  const auto side = [&](double x, std::vector<int>& out) {
    std::vector<P> stops{{x, kYMin}};
    for (double o : offsets) stops.push_back({x, coastY(x) + o});
    stops.push_back({x, kYMax});
    for (std::size_t i = 0; i + 1 < stops.size(); ++i) out.push_back(c.edge({stops[i], stops[i + 1]}));
  };
  side(kXMin, fr.west);
  side(kXMax, fr.east);
  fr.bottom = c.edge({{kXMin, kYMin}, {kXMax, kYMin}});
  fr.top = c.edge({{kXMin, kYMax}, {kXMax, kYMax}});
  return fr;
}

/// Coverage, marks system, the mainland and its coast, the depth areas and contours, and the islands.
void authorSeabed(Chart& c, const Frame& fr) {
  const std::vector<int>& curves = fr.curves;
  const std::vector<int>& west = fr.west;
  const std::vector<int>& east = fr.east;
  const int bottom = fr.bottom, top = fr.top;
  // Coverage and the navigational system of marks (IALA A).
  {
    Feature& f = c.add("M_COVR", 3, {{"CATCOV", "1"}});
    f.edges.push_back({bottom, false, 1});
    for (int e : east) f.edges.push_back({e, false, 1});
    f.edges.push_back({top, true, 1});
    for (auto it = west.rbegin(); it != west.rend(); ++it) f.edges.push_back({*it, true, 1});
    Feature& n = c.add("M_NSYS", 3, {{"MARSYS", "1"}});
    n.edges = f.edges;
  }
  // Land: the mainland south of the coast; the coast itself.
  {
    Feature& land = c.add("LNDARE", 3, {{"OBJNAM", "Reckoner Mainland"}});
    land.edges = {{bottom, false, 1}, {east[0], false, 1}, {curves[0], true, 1}, {west[0], true, 1}};
    Feature& coast = c.add("COALNE", 2, {{"CATCOA", "6"}});
    coast.edges = {{curves[0], false, 255}};
  }
  // Depth bands between the curves, the last one up to the top of the cell with the islands as holes.
  const double bands[][2] = {{0, 2}, {2, 5}, {5, 10}, {10, 20}, {20, 30}, {30, 50}};
  std::vector<int> islandOuter;
  for (const auto& isl : kIslands) islandOuter.push_back(c.ring(isl, 1.2));
  for (std::size_t k = 0; k < 6; ++k) {
    Feature& f = c.add("DEPARE", 3, {{"DRVAL1", num(bands[k][0])}, {"DRVAL2", num(bands[k][1])}});
    f.edges.push_back({curves[k], false, 1});
    f.edges.push_back({east[k + 1], false, 1});
    if (k + 1 < curves.size())
      f.edges.push_back({curves[k + 1], true, 1});
    else
      f.edges.push_back({top, true, 1});
    f.edges.push_back({west[k + 1], true, 1});
    if (k == 5)
      for (int ring : islandOuter) f.edges.push_back({ring, false, 2});
  }
  for (std::size_t k = 0; k < 5; ++k) {
    Feature& f = c.add("DEPCNT", 2, {{"VALDCO", num(kContours[k])}});
    f.edges = {{curves[k + 1], false, 255}};
  }
  // Islands: shore, a 0-10 m ring, a 10-30 m ring, contours at 10 and 30 m, a name and a landmark.
  for (std::size_t i = 0; i < 2; ++i) {
    const Island& isl = kIslands[i];
    const int shore = c.ring(isl, 0.45), ten = c.ring(isl, 0.8);
    c.add("LNDARE", 3, {{"OBJNAM", isl.name}}).edges = {{shore, false, 1}};
    c.add("COALNE", 2, {{"CATCOA", "1"}}).edges = {{shore, false, 255}};
    c.add("DEPARE", 3, {{"DRVAL1", "0.0"}, {"DRVAL2", "10.0"}}).edges = {{ten, false, 1}, {shore, false, 2}};
    c.add("DEPARE", 3, {{"DRVAL1", "10.0"}, {"DRVAL2", "30.0"}}).edges = {{islandOuter[i], false, 1},
                                                                          {ten, false, 2}};
    c.add("DEPCNT", 2, {{"VALDCO", "10.0"}}).edges = {{ten, false, 255}};
    c.add("DEPCNT", 2, {{"VALDCO", "30.0"}}).edges = {{islandOuter[i], false, 255}};
  }
}

/// Named places and built structures: a landmark, a region, the sea area, the port, the breakwater.
void authorPlaces(Chart& c) {
  c.point("LNDMRK", {-4.0, 3.2}, {{"CATLMK", "17"}, {"CONVIS", "1"}, {"OBJNAM", "Gannet Island Tower"}});
  c.point("LNDRGN", {-5.5, -4.6}, {{"OBJNAM", "Reckoner Point"}});
  c.add("SEAARE", 3, {{"OBJNAM", "Reckoner Sound (fictional)"}}).edges =
      c.polygon({{-7.6, 1.0}, {7.6, 1.0}, {7.6, 4.4}, {-7.6, 4.4}});
  c.add("BUAARE", 3, {{"OBJNAM", "Port Reckoner"}}).edges =
      c.polygon({{-0.6, -5.85}, {1.8, -5.85}, {1.8, -5.25}, {-0.6, -5.25}});
  // A breakwater from the bay's eastern shore.
  {
    const P root{1.9, coastY(1.9)};
    c.add("SLCONS", 2, {{"CATSLC", "1"}, {"OBJNAM", "East Breakwater"}}).edges = {
        {c.edge({root, {1.6, root.y + 0.45}, {1.25, root.y + 0.6}}), false, 255}};
  }
}

/// The buoyed channel into the bay, its fairway buoy and the headland lighthouse with its sectors.
void authorChannel(Chart& c) {
  // The buoyed channel into the bay (IALA A, entering southwards: red cans to port, on the east side: CATLAM
  // 1, port-hand; green cones CATLAM 2, starboard-hand).
  c.add("FAIRWY", 3, {{"OBJNAM", "Sound Channel"}, {"ORIENT", "180"}}).edges =
      c.polygon({{0.35, 1.5}, {0.85, 1.5}, {0.85, -4.2}, {0.35, -4.2}});
  const double pairs[] = {1.0, -0.3, -1.6, -2.9, -4.0};
  for (int k = 0; k < 5; ++k) {
    const std::string n = std::to_string(2 * k + 2), m = std::to_string(2 * k + 1);
    const std::string nameN = cat("Sound Channel Buoy ", n), nameM = cat("Sound Channel Buoy ", m);
    c.point("BOYLAT", {0.85, pairs[k]},
            {{"BOYSHP", "2"}, {"CATLAM", "1"}, {"COLOUR", "3"}, {"OBJNAM", nameN}});
    c.point("BOYLAT", {0.35, pairs[k]},
            {{"BOYSHP", "1"}, {"CATLAM", "2"}, {"COLOUR", "4"}, {"OBJNAM", nameM}});
    c.point("TOPMAR", {0.85, pairs[k]}, {{"TOPSHP", "5"}, {"COLOUR", "3"}});
    c.point("TOPMAR", {0.35, pairs[k]}, {{"TOPSHP", "1"}, {"COLOUR", "4"}});
    if (k < 2) {
      const std::string grp = k == 0 ? "()" : "(2)", per = k == 0 ? "4" : "6";
      c.point("LIGHTS", {0.85, pairs[k]},
              {{"LITCHR", "2"}, {"SIGGRP", grp}, {"SIGPER", per}, {"COLOUR", "3"}, {"VALNMR", "3"}});
      c.point("LIGHTS", {0.35, pairs[k]},
              {{"LITCHR", "2"}, {"SIGGRP", grp}, {"SIGPER", per}, {"COLOUR", "4"}, {"VALNMR", "3"}});
    }
  }
  // Safe-water mark at the entrance: red and white vertical stripes, red sphere, isophase light.
  c.point("BOYSAW", {0.6, 2.2},
          {{"BOYSHP", "3"}, {"COLOUR", "3,1"}, {"COLPAT", "2"}, {"OBJNAM", "Sound Fairway Buoy"}});
  c.point("TOPMAR", {0.6, 2.2}, {{"TOPSHP", "3"}, {"COLOUR", "3"}});
  c.point("LIGHTS", {0.6, 2.2}, {{"LITCHR", "7"}, {"SIGPER", "4"}, {"COLOUR", "1"}, {"VALNMR", "5"}});
  // Headland lighthouse with a sectored light leading to the channel entrance (bearings from seaward).
  {
    const P at{-2.0, coastY(-2.0) - 0.15};
    c.point("LNDMRK", at,
            {{"CATLMK", "17"}, {"FUNCTN", "33"}, {"CONVIS", "1"}, {"OBJNAM", "Reckoner Head Lighthouse"}});
    const char* sectors[][4] = {
        {"4", "190", "203", "9"}, {"1", "203", "210", "12"}, {"3", "210", "225", "9"}};
    for (const auto& s : sectors)
      c.point("LIGHTS", at,
              {{"LITCHR", "8"},
               {"SIGPER", "5"},
               {"COLOUR", s[0]},
               {"SECTR1", s[1]},
               {"SECTR2", s[2]},
               {"HEIGHT", "18"},
               {"VALNMR", s[3]},
               {"OBJNAM", "Reckoner Head"}});
  }
}

/// Dangers with their marks, and the regulated areas: restricted, anchorage, traffic separation.
void authorDangersAndAreas(Chart& c) {
  // A dangerous wreck with a north cardinal buoy; an obstruction under an isolated-danger buoy; a rock.
  c.point("WRECKS", {2.8, 1.8}, {{"CATWRK", "2"}, {"VALSOU", "4.2"}, {"WATLEV", "3"}});
  c.point(
      "BOYCAR", {2.8, 2.1},
      {{"BOYSHP", "4"}, {"CATCAM", "1"}, {"COLOUR", "2,6"}, {"COLPAT", "1"}, {"OBJNAM", "Wreck North Buoy"}});
  c.point("TOPMAR", {2.8, 2.1}, {{"TOPSHP", "13"}, {"COLOUR", "2"}});
  c.point("LIGHTS", {2.8, 2.1}, {{"LITCHR", "4"}, {"COLOUR", "1"}, {"VALNMR", "5"}});
  c.point("OBSTRN", {-1.6, 0.9}, {{"CATOBS", "6"}, {"VALSOU", "6.5"}, {"WATLEV", "3"}});
  c.point("BOYISD", {-1.6, 0.9},
          {{"BOYSHP", "4"}, {"COLOUR", "2,3,2"}, {"COLPAT", "1"}, {"OBJNAM", "Middle Ground Buoy"}});
  c.point("TOPMAR", {-1.6, 0.9}, {{"TOPSHP", "4"}, {"COLOUR", "2"}});
  c.point("LIGHTS", {-1.6, 0.9},
          {{"LITCHR", "2"}, {"SIGGRP", "(2)"}, {"SIGPER", "5"}, {"COLOUR", "1"}, {"VALNMR", "5"}});
  c.point("UWTROC", {-6.4, -2.9}, {{"VALSOU", "1.5"}, {"WATLEV", "3"}});
  // A special mark at the outfall.
  c.point("BOYSPP", {3.6, -0.9},
          {{"BOYSHP", "3"}, {"COLOUR", "6"}, {"CATSPM", "9"}, {"OBJNAM", "Outfall Buoy"}});
  c.point("TOPMAR", {3.6, -0.9}, {{"TOPSHP", "7"}, {"COLOUR", "6"}});
  // Areas: restricted (no anchoring over the outfall), anchorage, and a traffic separation scheme.
  c.add("RESARE", 3, {{"CATREA", "14"}, {"RESTRN", "1"}, {"OBJNAM", "Outfall Area"}}).edges =
      c.polygon({{3.1, -1.5}, {4.1, -1.5}, {4.1, -0.4}, {3.1, -0.4}});
  c.add("ACHARE", 3, {{"CATACH", "1"}, {"OBJNAM", "Outer Anchorage"}}).edges =
      c.polygon({{-3.8, -1.8}, {-2.2, -1.8}, {-2.2, -0.3}, {-3.8, -0.3}});
  c.add("TSSLPT", 3, {{"ORIENT", "90"}, {"CATTSS", "1"}}).edges =
      c.polygon({{-7.5, 4.6}, {7.5, 4.6}, {7.5, 5.1}, {-7.5, 5.1}});
  c.add("TSEZNE", 3, {}).edges = c.polygon({{-7.5, 5.1}, {7.5, 5.1}, {7.5, 5.35}, {-7.5, 5.35}});
  c.add("TSSLPT", 3, {{"ORIENT", "270"}, {"CATTSS", "1"}}).edges =
      c.polygon({{-7.5, 5.35}, {7.5, 5.35}, {7.5, 5.85}, {-7.5, 5.85}});
  c.add("TSSBND", 2, {}).edges = {{c.edge({{-7.5, 4.6}, {7.5, 4.6}}), false, 255}};
  c.add("TSSBND", 2, {}).edges = {{c.edge({{-7.5, 5.85}, {7.5, 5.85}}), false, 255}};
}

/// Soundings: a 600 m grid, nudged so the figures do not line up, where the water is deeper than 0.5 m.
void authorSoundings(Chart& c) {
  {
    Feature& s = c.point("SOUNDG", {0, 0}, {});
    for (int i = 0; i < 27; ++i)
      for (int j = 0; j < 20; ++j) {
        const P p{kXMin + 0.3 + 0.6 * i + 0.12 * std::sin(7.1 * i + 3.3 * j),
                  kYMin + 0.3 + 0.6 * j + 0.12 * std::cos(5.7 * i + 2.9 * j)};
        const double d = depthAt(p);
        const bool inCell = p.x > kXMin + 0.1 && p.x < kXMax - 0.1 && p.y > kYMin + 0.1 && p.y < kYMax - 0.1;
        if (d > 0.5 && inCell) s.soundings.push_back({p, std::round(d * 10.0) / 10.0});
      }
    s.point.reset();
  }
}

Chart author() {
  Chart c;
  const Frame fr = authorFrame(c);
  authorSeabed(c, fr);
  authorPlaces(c);
  authorChannel(c);
  authorDangersAndAreas(c);
  authorSoundings(c);
  return c;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: reckoner-chartgen OUT.000\n");
    return 2;
  }
  try {
    author().write(argv[1]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "reckoner-chartgen: %s: %s\n", argv[1], e.what());
    return 1;
  }
  return 0;
}
