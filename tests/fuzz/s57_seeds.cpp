// s57_seeds DIR: writes the seed corpus of fuzz_s57 (tests/fuzz/corpus/s57/), tiny S-57 cells of this
// project's own invention (a few features near an invented origin in the open Atlantic; FICTIONAL, NOT
// FOR NAVIGATION) through GDAL's S-57 writer, as resources/charts/reckoner_sound.cpp writes the default
// chart, so that a fuzzer starts from cells GDAL reads whole and can reach its driver cheaply:
//   points.000  a light (isolated node) and three soundings (a 3-D multipoint node);
//   area.000    a coverage area, a depth area and a contour on one closed edge, and a buoy;
//   update_pair a cell, "RKUPDATE" and a second cell as its update (refused: not an update of it).
#include <cpl_conv.h>
#include <cpl_string.h>
#include <gdal.h>
#include <ogr_api.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

constexpr double kLat0 = 49.52, kLon0 = -29.48;

struct Writer {
  GDALDatasetH ds = nullptr;
  int rcid = 0;

  Writer(const std::string& path, int isolated, int connected, int edges, int meta, int geo) {
    GDALDriverH driver = GDALGetDriverByName("S57");
    if (!driver) throw std::runtime_error("GDAL has no S57 driver");
    const std::string noin = "S57_NOIN=" + std::to_string(isolated),
                      nocn = "S57_NOCN=" + std::to_string(connected),
                      noed = "S57_NOED=" + std::to_string(edges), nomr = "S57_NOMR=" + std::to_string(meta),
                      nogr = "S57_NOGR=" + std::to_string(geo);
    const char* options[] = {
        "S57_EXPP=1", "S57_INTU=5",        "S57_EDTN=1",
        "S57_UPDN=0", "S57_ISDT=20261204", "S57_UADT=20261204",
        "S57_AGEN=0", "S57_CSCL=20000",    "S57_COMT=FICTIONAL FUZZ SEED - NOT FOR NAVIGATION",
        noin.c_str(), nocn.c_str(),        noed.c_str(),
        nomr.c_str(), nogr.c_str(),        nullptr};
    ds = GDALCreate(driver, path.c_str(), 0, 0, 0, GDT_Unknown, const_cast<char**>(options));
    if (!ds) throw std::runtime_error("GDAL could not create " + path);
  }
  ~Writer() {
    if (ds) GDALClose(ds);
  }
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  OGRLayerH layer(const char* name) const {
    OGRLayerH l = GDALDatasetGetLayerByName(ds, name);
    if (!l) throw std::runtime_error(std::string("the S57 writer has no layer ") + name);
    return l;
  }
  static void setInt(OGRFeatureH f, const char* field, int v) {
    const int i = OGR_F_GetFieldIndex(f, field);
    if (i < 0) throw std::runtime_error(std::string("no field ") + field);
    OGR_F_SetFieldInteger(f, i, v);
  }
  static void setList(OGRFeatureH f, const char* field, const std::vector<int>& v) {
    const int i = OGR_F_GetFieldIndex(f, field);
    if (i < 0) throw std::runtime_error(std::string("no field ") + field);
    OGR_F_SetFieldIntegerList(f, i, static_cast<int>(v.size()), v.data());
  }
  static void setText(OGRFeatureH f, const char* field, const char* v) {
    const int i = OGR_F_GetFieldIndex(f, field);
    if (i < 0) throw std::runtime_error(std::string("no field ") + field);
    if (OGR_Fld_GetType(OGR_F_GetFieldDefnRef(f, i)) == OFTStringList) {
      char** list = CSLTokenizeString2(v, ",", 0);
      OGR_F_SetFieldStringList(f, i, list);
      CSLDestroy(list);
    } else {
      OGR_F_SetFieldString(f, i, v);
    }
  }
  static void create(OGRLayerH l, OGRFeatureH f) {
    if (OGR_L_CreateFeature(l, f) != OGRERR_NONE) throw std::runtime_error("GDAL could not write a record");
    OGR_F_Destroy(f);
  }

  /// An isolated node (a point, or soundings as x, y, depth triples).
  void isolatedNode(int id, const std::vector<std::vector<double>>& pts) {
    OGRFeatureH n = OGR_F_Create(OGR_L_GetLayerDefn(layer("IsolatedNode")));
    setInt(n, "RCNM", 110);
    setInt(n, "RCID", id);
    OGRGeometryH g;
    if (pts.size() > 1 || pts[0].size() == 3) {
      g = OGR_G_CreateGeometry(wkbMultiPoint25D);
      for (const auto& p : pts) {
        OGRGeometryH pt = OGR_G_CreateGeometry(wkbPoint25D);
        OGR_G_SetPoint(pt, 0, p[0], p[1], p[2]);
        OGR_G_AddGeometryDirectly(g, pt);
      }
    } else {
      g = OGR_G_CreateGeometry(wkbPoint);
      OGR_G_SetPoint_2D(g, 0, pts[0][0], pts[0][1]);
    }
    OGR_F_SetGeometryDirectly(n, g);
    create(layer("IsolatedNode"), n);
  }

  /// A feature of class cls (OBJL code) on vector records (rcnm, id, orientation, usage) with attributes.
  void feature(const char* cls, int code, int prim, int rcnm, const std::vector<int>& ids, int usage,
               const std::vector<std::pair<const char*, const char*>>& attrs) {
    OGRLayerH l = layer(cls);
    OGRFeatureH f = OGR_F_Create(OGR_L_GetLayerDefn(l));
    ++rcid;
    setInt(f, "RCID", rcid);
    setInt(f, "PRIM", prim);
    setInt(f, "GRUP", std::string(cls) == "DEPARE" ? 1 : 2);
    setInt(f, "OBJL", code);
    setInt(f, "AGEN", 0);
    setInt(f, "FIDN", rcid);
    setInt(f, "FIDS", 1);
    const std::vector<int> all(ids.size(), rcnm), ornt(ids.size(), prim == 1 ? 255 : 1),
        usag(ids.size(), usage), mask(ids.size(), 255);
    setList(f, "NAME_RCNM", all);
    setList(f, "NAME_RCID", ids);
    setList(f, "ORNT", ornt);
    setList(f, "USAG", usag);
    setList(f, "MASK", mask);
    for (const auto& [k, v] : attrs) setText(f, k, v);
    create(l, f);
  }
};

void points(const std::string& path) {
  Writer w(path, 2, 0, 0, 0, 2);
  w.isolatedNode(1, {{kLon0, kLat0}});
  w.isolatedNode(
      2, {{kLon0 + 0.01, kLat0 + 0.01, 12.5}, {kLon0 + 0.012, kLat0, 7.1}, {kLon0, kLat0 + 0.011, 3.3}});
  w.feature("LIGHTS", 75, 1, 110, {1}, 255,
            {{"COLOUR", "3"}, {"LITCHR", "2"}, {"SIGPER", "4"}, {"VALNMR", "8"}});
  w.feature("SOUNDG", 129, 1, 110, {2}, 255, {});
}

void area(const std::string& path) {
  Writer w(path, 1, 1, 1, 1, 3);
  {
    OGRFeatureH f = OGR_F_Create(OGR_L_GetLayerDefn(w.layer("ConnectedNode")));
    Writer::setInt(f, "RCNM", 120);
    Writer::setInt(f, "RCID", 1);
    OGRGeometryH g = OGR_G_CreateGeometry(wkbPoint);
    OGR_G_SetPoint_2D(g, 0, kLon0, kLat0);
    OGR_F_SetGeometryDirectly(f, g);
    Writer::create(w.layer("ConnectedNode"), f);
  }
  {
    OGRFeatureH f = OGR_F_Create(OGR_L_GetLayerDefn(w.layer("Edge")));
    Writer::setInt(f, "RCNM", 130);
    Writer::setInt(f, "RCID", 1);
    OGRGeometryH g = OGR_G_CreateGeometry(wkbLineString);
    OGR_G_AddPoint_2D(g, kLon0 + 0.02, kLat0);
    OGR_G_AddPoint_2D(g, kLon0 + 0.02, kLat0 + 0.02);
    OGR_G_AddPoint_2D(g, kLon0, kLat0 + 0.02);
    OGR_F_SetGeometryDirectly(f, g);
    for (int k = 0; k < 2; ++k) {
      const std::string s = "_" + std::to_string(k);
      Writer::setInt(f, ("NAME_RCNM" + s).c_str(), 120);
      Writer::setInt(f, ("NAME_RCID" + s).c_str(), 1);
      Writer::setInt(f, ("ORNT" + s).c_str(), 255);
      Writer::setInt(f, ("USAG" + s).c_str(), 255);
      Writer::setInt(f, ("TOPI" + s).c_str(), k == 0 ? 1 : 2);
      Writer::setInt(f, ("MASK" + s).c_str(), 255);
    }
    Writer::create(w.layer("Edge"), f);
  }
  w.isolatedNode(1, {{kLon0 + 0.005, kLat0 + 0.005}});
  w.feature("M_COVR", 302, 3, 130, {1}, 1, {{"CATCOV", "1"}});
  w.feature("DEPARE", 42, 3, 130, {1}, 1, {{"DRVAL1", "5"}, {"DRVAL2", "10"}});
  w.feature("DEPCNT", 43, 2, 130, {1}, 255, {{"VALDCO", "5"}});
  w.feature("BOYLAT", 17, 1, 110, {1}, 255, {{"BOYSHP", "2"}, {"CATLAM", "1"}, {"COLOUR", "3"}});
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: s57_seeds DIR\n");
    return 2;
  }
  try {
    GDALAllRegister();
    const std::filesystem::path dir(argv[1]);
    std::filesystem::create_directories(dir);
    points((dir / "points.000").string());
    area((dir / "area.000").string());
    std::ofstream(dir / "update_pair", std::ios::binary)
        << slurp(dir / "area.000") << "RKUPDATE" << slurp(dir / "points.000");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "s57_seeds: %s\n", e.what());
    return 1;
  }
  return 0;
}
