// GDAL's S57 driver: start-up, /vsimem/ files, and OGR features read into ChartFeatures (gdal_reader.h).
#include "charts/s57/gdal_reader.h"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_vsi.h>
#include <gdal.h>
#include <ogr_api.h>
#include <ogr_core.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>

#include "charts/s57/s57_loader.h"
#include "io/error_line.h"

namespace reckoner::charts::gdalio {

std::string versionText() {
  return GDALVersionInfo("RELEASE_NAME");
}
namespace fs = std::filesystem;

namespace {
void CPL_STDCALL captureError(CPLErr level, CPLErrorNum, const char* msg) {
  auto* self = static_cast<ErrorCapture*>(CPLGetErrorHandlerUserData());
  if (self && level >= CE_Failure) self->note(msg ? msg : "unknown GDAL error");
}
}  // namespace

ErrorCapture::ErrorCapture() {
  CPLPushErrorHandlerEx(&captureError, this);
}

ErrorCapture::~ErrorCapture() {
  CPLPopErrorHandler();
}

void ErrorCapture::note(const char* message) {
  if (first_.empty()) first_ = message;
}

std::string ErrorCapture::firstErrorLine(const std::string& memDir, const std::string& realDir) const {
  std::string m = first_;
  if (!memDir.empty())
    for (std::size_t at = m.find(memDir); at != std::string::npos; at = m.find(memDir, at + realDir.size()))
      m.replace(at, memDir.size(), realDir);
  return io::oneLine(m);
}

namespace {

std::once_flag gdalInit;
std::string catalogueDir;
s57::ObjectClassKinds kinds;  // from s57objectclasses.csv once the catalogue is found

}  // namespace

void initialise() {
  std::call_once(gdalInit, [] {
    GDALAllRegister();
    // The S-57 catalogue: GDAL's own search first, then the usual data directories.
    if (const char* found = CPLFindFile("gdal", "s57objectclasses.csv")) {
      catalogueDir = fs::path(found).parent_path().string();
    } else {
      for (const char* dir : {"/usr/share/gdal", "/usr/local/share/gdal", "/usr/share/gdal/3.6"}) {
        if (fs::exists(fs::path(dir) / "s57objectclasses.csv")) {
          catalogueDir = dir;
          CPLSetConfigOption("S57_CSV", dir);
          break;
        }
      }
    }
    if (!catalogueDir.empty()) {
      std::ifstream in(fs::path(catalogueDir) / "s57objectclasses.csv", std::ios::binary);
      std::ostringstream text;
      text << in.rdbuf();
      kinds = s57::ObjectClassKinds::fromCatalogue(text.str());
    }
  });
}

const std::string& catalogueDirectory() {
  return catalogueDir;
}

const s57::ObjectClassKinds& classKinds() {
  return kinds;
}

MemoryFiles::MemoryFiles() {
  static std::atomic<unsigned long> counter{0};
  dir_ = "/vsimem/reckoner/load-" + std::to_string(++counter) + "/";
}

MemoryFiles::~MemoryFiles() {
  for (const auto& n : names_) VSIUnlink(n.c_str());
}

std::string MemoryFiles::add(const std::string& name, const std::string& bytes, const std::string& file) {
  std::string path = dir_ + name;
  VSILFILE* fp = VSIFileFromMemBuffer(path.c_str(), reinterpret_cast<GByte*>(const_cast<char*>(bytes.data())),
                                      static_cast<vsi_l_offset>(bytes.size()), FALSE);
  if (!fp) throw ChartLoadError(file, "cannot be handed to GDAL in memory");
  VSIFCloseL(fp);
  names_.push_back(path);
  return path;
}

void MemoryFiles::remove(const std::string& name) {
  const std::string path = dir_ + name;
  VSIUnlink(path.c_str());
  names_.erase(std::remove(names_.begin(), names_.end(), path), names_.end());
}

bool addStaticMemoryFile(const std::string& memPath, std::string_view bytes) {
  static std::mutex memMutex;
  const std::lock_guard lock(memMutex);
  VSIStatBufL st;
  if (VSIStatL(memPath.c_str(), &st) == 0) return true;
  VSILFILE* fp =
      VSIFileFromMemBuffer(memPath.c_str(), reinterpret_cast<GByte*>(const_cast<char*>(bytes.data())),
                           static_cast<vsi_l_offset>(bytes.size()), FALSE);
  if (!fp) return false;
  VSIFCloseL(fp);
  return true;
}

namespace {

const std::vector<std::string>& recordFields() {
  static const std::vector<std::string> fields{"RCID", "PRIM", "GRUP", "OBJL",      "RVER",     "AGEN",
                                               "FIDN", "FIDS", "LNAM", "LNAM_REFS", "FFPT_RIND"};
  return fields;
}

void readRings(OGRGeometryH g, Geometry& out) {
  const OGRwkbGeometryType t = wkbFlatten(OGR_G_GetGeometryType(g));
  const auto addRing = [&](OGRGeometryH ring) {
    std::vector<LatLon> pts;
    const int n = OGR_G_GetPointCount(ring);
    pts.reserve(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
      const LatLon p{OGR_G_GetY(ring, i), OGR_G_GetX(ring, i)};
      pts.push_back(p);
      out.bounds.add(p);
    }
    out.parts.push_back(std::move(pts));
  };
  if (t == wkbPolygon) {
    // An empty polygon (GDAL gives one for an area whose edges a corrupt cell or update has lost) has no
    // ring for its start to point at: it adds nothing (fuzz_s57's finding, docs/robustness.md).
    const int rings = OGR_G_GetGeometryCount(g);
    if (rings == 0) return;
    out.polygonStarts.push_back(out.parts.size());
    for (int r = 0; r < rings; ++r) addRing(OGR_G_GetGeometryRef(g, r));
  } else if (t == wkbLineString) {
    addRing(g);
  } else if (t == wkbMultiPolygon || t == wkbMultiLineString || t == wkbGeometryCollection) {
    for (int k = 0; k < OGR_G_GetGeometryCount(g); ++k) readRings(OGR_G_GetGeometryRef(g, k), out);
  }
}

Geometry readGeometry(OGRGeometryH g, bool sounding) {
  Geometry out;
  if (!g) return out;
  const OGRwkbGeometryType t = wkbFlatten(OGR_G_GetGeometryType(g));
  if (t == wkbPoint || t == wkbMultiPoint) {
    out.primitive = Primitive::Point;
    std::vector<LatLon> pts;
    const auto addPoint = [&](OGRGeometryH p) {
      const LatLon ll{OGR_G_GetY(p, 0), OGR_G_GetX(p, 0)};
      pts.push_back(ll);
      out.bounds.add(ll);
      if (sounding) out.depthsM.push_back(OGR_G_GetZ(p, 0));
    };
    if (t == wkbPoint) {
      addPoint(g);
    } else {
      for (int k = 0; k < OGR_G_GetGeometryCount(g); ++k) addPoint(OGR_G_GetGeometryRef(g, k));
    }
    out.parts.push_back(std::move(pts));
  } else if (t == wkbLineString || t == wkbMultiLineString) {
    out.primitive = Primitive::Line;
    readRings(g, out);
  } else if (t == wkbPolygon || t == wkbMultiPolygon) {
    out.primitive = Primitive::Area;
    readRings(g, out);
  }
  return out;
}

std::optional<AttributeValue> readField(OGRFeatureH f, int i, OGRFieldDefnH def) {
  if (!OGR_F_IsFieldSetAndNotNull(f, i)) return std::nullopt;
  switch (OGR_Fld_GetType(def)) {
    case OFTInteger:
    case OFTInteger64:
      return AttributeValue{static_cast<std::int64_t>(OGR_F_GetFieldAsInteger64(f, i))};
    case OFTReal:
      return AttributeValue{OGR_F_GetFieldAsDouble(f, i)};
    case OFTIntegerList: {
      int n = 0;
      const int* v = OGR_F_GetFieldAsIntegerList(f, i, &n);
      return AttributeValue{std::vector<std::int64_t>(v, v + n)};
    }
    case OFTStringList: {
      // S-57 list attributes (COLOUR, STATUS, ...): enumerated values.
      char** v = OGR_F_GetFieldAsStringList(f, i);
      std::vector<std::int64_t> out;
      for (int k = 0; v && v[k]; ++k) {
        char* end = nullptr;
        const long long x = std::strtoll(v[k], &end, 10);
        if (end == v[k] || *end != '\0') return AttributeValue{std::string(OGR_F_GetFieldAsString(f, i))};
        out.push_back(x);
      }
      return AttributeValue{out};
    }
    default:
      return AttributeValue{std::string(OGR_F_GetFieldAsString(f, i))};
  }
}

std::string fieldString(OGRFeatureH f, const char* name) {
  const int i = OGR_F_GetFieldIndex(f, name);
  return i >= 0 && OGR_F_IsFieldSetAndNotNull(f, i) ? std::string(OGR_F_GetFieldAsString(f, i))
                                                    : std::string();
}

int fieldInt(OGRFeatureH f, const char* name) {
  const int i = OGR_F_GetFieldIndex(f, name);
  return i >= 0 && OGR_F_IsFieldSetAndNotNull(f, i) ? OGR_F_GetFieldAsInteger(f, i) : 0;
}

struct DatasetCloser {
  void operator()(void* ds) const {
    if (ds) GDALClose(ds);
  }
};

/// The cell's metadata from its DSID feature (with DSPM's compilation scale).
void readDataSetInfo(OGRFeatureH f, CellInfo& info) {
  const std::string dsnm = fieldString(f, "DSID_DSNM");
  if (!dsnm.empty()) info.name = fs::path(dsnm).stem().string();
  info.edition = fieldString(f, "DSID_EDTN");
  info.updateNumber = fieldInt(f, "DSID_UPDN");
  info.issueDate = fieldString(f, "DSID_ISDT");
  info.updateDate = fieldString(f, "DSID_UADT");
  info.agency = fieldInt(f, "DSID_AGEN");
  info.intendedUsage = fieldInt(f, "DSID_INTU");
  info.comment = fieldString(f, "DSID_COMT");
  info.compilationScale = fieldInt(f, "DSPM_CSCL");
}

/// One OGR feature of the layer of class `cls` as a ChartFeature: the attributes that are not record
/// fields, with their types, and the geometry (with depths for soundings).
ChartFeature readFeature(OGRFeatureH f, OGRFeatureDefnH defn, int nFields, const std::string& cls) {
  ChartFeature cf;
  cf.objectClass = cls;
  cf.objectCode = fieldInt(f, "OBJL");
  cf.lnam = fieldString(f, "LNAM");
  for (int i = 0; i < nFields; ++i) {
    OGRFieldDefnH fd = OGR_FD_GetFieldDefn(defn, i);
    const std::string name = OGR_Fld_GetNameRef(fd);
    if (std::find(recordFields().begin(), recordFields().end(), name) != recordFields().end()) continue;
    if (auto v = readField(f, i, fd)) cf.attributes.push_back({name, std::move(*v)});
  }
  cf.geometry = readGeometry(OGR_F_GetGeometryRef(f), cls == "SOUNDG");
  return cf;
}

/// Every coordinate of a feature finite and on the Earth, every depth finite: a corrupt cell (a
/// coordinate multiplication factor of 1, say, or mangled coordinates) is refused, not drawn at
/// latitude 5e8 (found by fuzz_s57).
void checkCoordinates(const ChartFeature& cf, const std::string& path) {
  for (const auto& part : cf.geometry.parts)
    for (const LatLon& p : part)
      if (!std::isfinite(p.latDeg) || !std::isfinite(p.lonDeg) || std::abs(p.latDeg) > 90.0 ||
          std::abs(p.lonDeg) > 180.0) {
        char ll[80];
        std::snprintf(ll, sizeof ll, "(%.9g, %.9g)", p.latDeg, p.lonDeg);
        throw ChartLoadError(path,
                             "a " + cf.objectClass + " feature has a coordinate off the Earth, " + ll +
                                 " (latitude, longitude): corrupt coordinates or multiplication factor");
      }
  for (const double d : cf.geometry.depthsM)
    if (!std::isfinite(d))
      throw ChartLoadError(path, "a " + cf.objectClass + " sounding has no finite depth");
}

}  // namespace

CellPtr readCell(const std::string& path, const std::string& gdalPath, const std::string& memDir,
                 const std::string& realDir, std::vector<std::string> updatesApplied) {
  ErrorCapture errors;
  const char* const drivers[] = {"S57", nullptr};
  const char* const options[] = {
      "UPDATES=APPLY",       "SPLIT_MULTIPOINT=OFF", "ADD_SOUNDG_DEPTH=OFF", "RETURN_PRIMITIVES=OFF",
      "RETURN_LINKAGES=OFF", "LNAM_REFS=ON",         "RECODE_BY_DSSI=ON",    nullptr};
  std::unique_ptr<void, DatasetCloser> ds(
      GDALOpenEx(gdalPath.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, drivers, options, nullptr));
  if (!ds) {
    const std::string why = errors.firstErrorLine(memDir, realDir);
    throw ChartLoadError(path, why.empty() ? "not an S-57 cell (GDAL's S57 driver cannot open it)"
                                           : "not readable as S-57: " + why);
  }
  CellInfo info;
  info.path = path;
  info.name = fs::path(gdalPath).stem().string();
  std::vector<ChartFeature> features;
  const int layers = GDALDatasetGetLayerCount(ds.get());
  for (int l = 0; l < layers; ++l) {
    OGRLayerH layer = GDALDatasetGetLayer(ds.get(), l);
    const std::string cls = OGR_L_GetName(layer);
    OGRFeatureDefnH defn = OGR_L_GetLayerDefn(layer);
    const int nFields = OGR_FD_GetFieldCount(defn);
    OGR_L_ResetReading(layer);
    while (OGRFeatureH f = OGR_L_GetNextFeature(layer)) {
      if (cls == "DSID")
        readDataSetInfo(f, info);
      else
        features.push_back(readFeature(f, defn, nFields, cls));
      OGR_F_Destroy(f);
    }
  }
  if (!errors.firstError().empty())
    throw ChartLoadError(path,
                         "damaged (GDAL's S-57 reader: " + errors.firstErrorLine(memDir, realDir) + ")");
  // After GDAL's own complaint, which names the cause when there is one.
  for (const ChartFeature& cf : features) checkCoordinates(cf, path);
  if (info.edition.empty())
    throw ChartLoadError(path, "no data set identification (DSID): not an S-57 base cell");
  info.updatesApplied = std::move(updatesApplied);
  return std::make_shared<const ChartCell>(std::move(info), std::move(features));
}

}  // namespace reckoner::charts::gdalio

namespace reckoner::charts {

std::string s57CatalogueDirectory() {
  gdalio::initialise();
  return gdalio::catalogueDirectory();
}

}  // namespace reckoner::charts
