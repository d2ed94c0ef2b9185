#include "charts/s57/s57_loader.h"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_vsi.h>
#include <gdal.h>
#include <ogr_api.h>
#include <ogr_core.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <mutex>

#include "resources/embedded.h"

namespace reckoner::charts {
namespace fs = std::filesystem;
namespace {

/// Collects GDAL errors of the calling thread while alive.
class ErrorCapture {
 public:
  ErrorCapture() { CPLPushErrorHandlerEx(&ErrorCapture::handler, this); }
  ~ErrorCapture() { CPLPopErrorHandler(); }
  ErrorCapture(const ErrorCapture&) = delete;
  ErrorCapture& operator=(const ErrorCapture&) = delete;
  [[nodiscard]] const std::string& firstError() const { return first_; }

 private:
  static void CPL_STDCALL handler(CPLErr level, CPLErrorNum, const char* msg) {
    auto* self = static_cast<ErrorCapture*>(CPLGetErrorHandlerUserData());
    if (self && level >= CE_Failure && self->first_.empty()) self->first_ = msg ? msg : "unknown GDAL error";
  }
  std::string first_;
};

std::once_flag gdalInit;
std::string catalogueDir;

void initialiseGdal() {
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
  });
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

bool isCellFile(const fs::path& p) {
  return upper(p.extension().string()) == ".000";
}

/// Update files beside a cell: NAME.001, NAME.002, ... in order.
std::vector<std::string> updateFiles(const fs::path& cell) {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(cell.parent_path(), ec)) {
    const fs::path& p = e.path();
    const std::string ext = p.extension().string();
    if (p.stem() != cell.stem() || ext.size() != 4 || ext == ".000") continue;
    if (!std::all_of(ext.begin() + 1, ext.end(),
                     [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
      continue;
    out.push_back(p.filename().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

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
    out.polygonStarts.push_back(out.parts.size());
    for (int r = 0; r < OGR_G_GetGeometryCount(g); ++r) addRing(OGR_G_GetGeometryRef(g, r));
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
}  // namespace

std::string s57CatalogueDirectory() {
  initialiseGdal();
  return catalogueDir;
}

std::vector<std::string> findCells(const std::string& path) {
  if (path.rfind(kBuiltinPrefix, 0) == 0) return {path};
  std::error_code ec;
  const fs::path p(path);
  if (!fs::exists(p, ec)) throw ChartLoadError(path, "no such file or folder");
  if (fs::is_regular_file(p, ec)) {
    if (!isCellFile(p)) throw ChartLoadError(path, "not an S-57 base cell (expected a .000 file)");
    return {p.string()};
  }
  std::vector<std::string> out;
  for (auto it = fs::recursive_directory_iterator(p, fs::directory_options::skip_permission_denied, ec);
       !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
    if (it->is_regular_file(ec) && isCellFile(it->path())) out.push_back(it->path().string());
  if (out.empty()) throw ChartLoadError(path, "no S-57 cell (.000) in this folder");
  std::sort(out.begin(), out.end());
  return out;
}

namespace {
/// Reads a cell at `gdalPath` (a file, or /vsimem/ for an embedded chart), reporting it as `path`.
CellPtr readCell(const std::string& path, const std::string& gdalPath, bool withUpdates);
}  // namespace

CellPtr loadCell(const std::string& path) {
  initialiseGdal();
  if (catalogueDir.empty())
    throw ChartLoadError(path,
                         "GDAL's S-57 catalogue (s57objectclasses.csv) was not found; install gdal-data");
  if (path.rfind(kBuiltinPrefix, 0) == 0) {
    std::string name(path.substr(kBuiltinPrefix.size()));
    if (name == "default") name = std::string(resources::kDefaultChart);
    const resources::EmbeddedFile* chart = resources::findChart(name);
    if (!chart) throw ChartLoadError(path, "no such built-in chart (there is builtin:default)");
    // GDAL reads it from memory: a /vsimem/ file over the embedded bytes, made once.
    const std::string mem = "/vsimem/reckoner/" + name + "/" + name + ".000";
    static std::mutex memMutex;
    {
      const std::lock_guard lock(memMutex);
      VSIStatBufL st;
      if (VSIStatL(mem.c_str(), &st) != 0) {
        VSILFILE* fp =
            VSIFileFromMemBuffer(mem.c_str(), reinterpret_cast<GByte*>(const_cast<char*>(chart->text.data())),
                                 static_cast<vsi_l_offset>(chart->text.size()), FALSE);
        if (!fp) throw ChartLoadError(path, "cannot open the embedded chart in memory");
        VSIFCloseL(fp);
      }
    }
    return readCell(path, mem, false);
  }
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw ChartLoadError(path, "no such file");
  return readCell(path, path, true);
}

namespace {
CellPtr readCell(const std::string& path, const std::string& gdalPath, bool withUpdates) {
  ErrorCapture errors;
  const char* const drivers[] = {"S57", nullptr};
  const char* const options[] = {
      "UPDATES=APPLY",       "SPLIT_MULTIPOINT=OFF", "ADD_SOUNDG_DEPTH=OFF", "RETURN_PRIMITIVES=OFF",
      "RETURN_LINKAGES=OFF", "LNAM_REFS=ON",         "RECODE_BY_DSSI=ON",    nullptr};
  std::unique_ptr<void, DatasetCloser> ds(
      GDALOpenEx(gdalPath.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, drivers, options, nullptr));
  if (!ds) {
    const std::string why = errors.firstError();
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
      if (cls == "DSID") {
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
        OGR_F_Destroy(f);
        continue;
      }
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
      features.push_back(std::move(cf));
      OGR_F_Destroy(f);
    }
  }
  if (!errors.firstError().empty())
    throw ChartLoadError(path, "truncated or corrupt: " + errors.firstError());
  if (info.edition.empty())
    throw ChartLoadError(path, "no data set identification (DSID): not an S-57 base cell");
  if (withUpdates) info.updatesApplied = updateFiles(fs::path(path));
  if (!info.updatesApplied.empty()) {
    const std::string& last = info.updatesApplied.back();
    const int lastNumber = std::stoi(last.substr(last.size() - 3));
    if (info.updateNumber < lastNumber)
      throw ChartLoadError(path, "unreadable update: the cell is at update " +
                                     std::to_string(info.updateNumber) + " but " + last + " is present");
  }
  return std::make_shared<const ChartCell>(std::move(info), std::move(features));
}
}  // namespace

LoadResult loadCharts(const std::vector<std::string>& paths, const LoadProgress& progress,
                      const std::atomic<bool>* cancel) {
  LoadResult r;
  std::vector<std::string> cells;
  for (const auto& p : paths) {
    try {
      const auto found = findCells(p);
      cells.insert(cells.end(), found.begin(), found.end());
    } catch (const ChartLoadError& e) {
      r.failures.push_back({e.file(), std::string(e.what()).substr(e.file().size() + 2)});
    }
  }
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (cancel && cancel->load()) break;
    try {
      r.cells.push_back(loadCell(cells[i]));
    } catch (const ChartLoadError& e) {
      r.failures.push_back({e.file(), std::string(e.what()).substr(e.file().size() + 2)});
    } catch (const std::exception& e) {
      r.failures.push_back({cells[i], e.what()});
    }
    if (progress) progress(i + 1, cells.size(), cells[i]);
  }
  return r;
}

}  // namespace reckoner::charts
