#include "charts/s57/s57_loader.h"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_vsi.h>
#include <gdal.h>
#include <ogr_api.h>
#include <ogr_core.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <system_error>

#include "charts/s57/s57_checks.h"
#include "io/error_line.h"
#include "resources/embedded.h"

namespace reckoner::charts {
namespace fs = std::filesystem;
namespace {

/// Collects GDAL errors of the calling thread while alive (CPLPushErrorHandlerEx: per thread, so
/// nothing reaches stderr behind the caller's back).
class ErrorCapture {
 public:
  ErrorCapture() { CPLPushErrorHandlerEx(&ErrorCapture::handler, this); }
  ~ErrorCapture() { CPLPopErrorHandler(); }
  ErrorCapture(const ErrorCapture&) = delete;
  ErrorCapture& operator=(const ErrorCapture&) = delete;
  /// The first error as GDAL wrote it: possibly several lines, possibly with raw input bytes.
  [[nodiscard]] const std::string& firstError() const { return first_; }
  /// The first error on one line (io::oneLine), with the /vsimem/ folder GDAL read from replaced by
  /// the folder the files came from.
  [[nodiscard]] std::string firstErrorLine(const std::string& memDir, const std::string& realDir) const {
    std::string m = first_;
    if (!memDir.empty())
      for (std::size_t at = m.find(memDir); at != std::string::npos; at = m.find(memDir, at + realDir.size()))
        m.replace(at, memDir.size(), realDir);
    return io::oneLine(m);
  }

 private:
  static void CPL_STDCALL handler(CPLErr level, CPLErrorNum, const char* msg) {
    auto* self = static_cast<ErrorCapture*>(CPLGetErrorHandlerUserData());
    if (self && level >= CE_Failure && self->first_.empty()) self->first_ = msg ? msg : "unknown GDAL error";
  }
  std::string first_;
};

std::once_flag gdalInit;
std::string catalogueDir;
s57::ObjectClassKinds classKinds;  // from s57objectclasses.csv once the catalogue is found

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
    if (!catalogueDir.empty()) {
      std::ifstream in(fs::path(catalogueDir) / "s57objectclasses.csv", std::ios::binary);
      std::ostringstream text;
      text << in.rdbuf();
      classKinds = s57::ObjectClassKinds::fromCatalogue(text.str());
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

namespace {

/// The reason of a ChartLoadError without its "file: " prefix.
std::string reasonOf(const ChartLoadError& e) {
  return std::string(e.what()).substr(e.file().size() + 2);
}

/// "a FIFO (named pipe)" and the like for what is not a regular file or folder; null for those.
const char* specialKind(fs::file_type t) {
  switch (t) {
    case fs::file_type::fifo:
      return "a FIFO (named pipe)";
    case fs::file_type::socket:
      return "a socket";
    case fs::file_type::character:
      return "a character device";
    case fs::file_type::block:
      return "a block device";
    case fs::file_type::regular:
    case fs::file_type::directory:
    case fs::file_type::not_found:
    case fs::file_type::none:
      return nullptr;
    default:
      return "not a regular file";
  }
}

/// The ENC Product Specification keeps a cell file under 5 MB; anything far beyond is not one.
constexpr std::size_t kMaxChartFileBytes = std::size_t{256} << 20;

/// The whole of a chart file. The type is checked with stat() before anything is opened, and the
/// file is opened without blocking (a FIFO or device put there meanwhile is refused by fstat()).
std::string readChartFile(const std::string& path) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (st.type() == fs::file_type::not_found) throw ChartLoadError(path, "no such file");
  if (st.type() == fs::file_type::directory) throw ChartLoadError(path, "is a folder, not a cell file");
  if (const char* kind = specialKind(st.type()))
    throw ChartLoadError(path, std::string("is ") + kind + ", not a chart file");
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0)
    throw ChartLoadError(path,
                         "cannot be opened: " + std::error_code(errno, std::generic_category()).message());
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat info {};
  if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) throw ChartLoadError(path, "is not a regular file");
  const auto size = static_cast<std::size_t>(info.st_size);
  if (size > kMaxChartFileBytes)
    throw ChartLoadError(path, "is " + std::to_string(size >> 20) +
                                   " MiB, more than any S-57 file (this loader reads at most 256 MiB)");
  std::string bytes(size, '\0');
  std::size_t got = 0;
  while (got < size) {
    const ssize_t n = ::read(fd, bytes.data() + got, size - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0)
      throw ChartLoadError(path,
                           "cannot be read: " + std::error_code(errno, std::generic_category()).message());
    if (n == 0) break;  // shorter than it was a moment ago
    got += static_cast<std::size_t>(n);
  }
  bytes.resize(got);
  return bytes;
}

/// Files GDAL reads from memory: the bytes we checked, under /vsimem/, removed again at the end.
class MemoryFiles {
 public:
  MemoryFiles() {
    static std::atomic<unsigned long> counter{0};
    dir_ = "/vsimem/reckoner/load-" + std::to_string(++counter) + "/";
  }
  ~MemoryFiles() {
    for (const auto& n : names_) VSIUnlink(n.c_str());
  }
  MemoryFiles(const MemoryFiles&) = delete;
  MemoryFiles& operator=(const MemoryFiles&) = delete;
  /// The /vsimem/ path of `name` over `bytes`, which must outlive this object; throws naming `file`.
  std::string add(const std::string& name, const std::string& bytes, const std::string& file) {
    const std::string path = dir_ + name;
    VSILFILE* fp =
        VSIFileFromMemBuffer(path.c_str(), reinterpret_cast<GByte*>(const_cast<char*>(bytes.data())),
                             static_cast<vsi_l_offset>(bytes.size()), FALSE);
    if (!fp) throw ChartLoadError(file, "cannot be handed to GDAL in memory");
    VSIFCloseL(fp);
    names_.push_back(path);
    return path;
  }
  void remove(const std::string& name) {
    const std::string path = dir_ + name;
    VSIUnlink(path.c_str());
    names_.erase(std::remove(names_.begin(), names_.end(), path), names_.end());
  }
  [[nodiscard]] const std::string& dir() const { return dir_; }

 private:
  std::string dir_;
  std::vector<std::string> names_;
};

/// The catalogues (CATALOG.031) read during one loadCharts() call, each read once.
struct CatalogueCache {
  struct Entry {
    std::vector<s57::CatalogueEntry> entries;
    std::string problem;
    bool reported = false;
  };
  std::map<std::string, Entry> byPath;
};

/// How one cell is loaded: where the search for a catalogue stops, and where problems that need not
/// stop the cell go (null: they are thrown).
struct LoadContext {
  fs::path root;
  CatalogueCache* catalogues = nullptr;
  std::vector<LoadFailure>* notes = nullptr;
};

fs::path absolutePath(const fs::path& p) {
  std::error_code ec;
  const fs::path a = fs::absolute(p, ec);
  return (ec ? p : a).lexically_normal();
}

/// True when `dir` is `root` or below it (by their names).
bool isWithin(const fs::path& dir, const fs::path& root) {
  auto d = dir.begin();
  for (auto r = root.begin(); r != root.end(); ++r, ++d) {
    if (r->empty()) continue;  // the empty last element of a path ending in '/'
    if (d == dir.end() || *d != *r) return false;
  }
  return true;
}

/// The entry of `file` in the nearest catalogue that lists it, from the file's folder up to the
/// context's root; nullopt when none does. A damaged catalogue is thrown or noted once.
std::optional<s57::CatalogueEntry> catalogueEntry(const fs::path& file, const LoadContext& ctx) {
  CatalogueCache local;
  CatalogueCache& cache = ctx.catalogues ? *ctx.catalogues : local;
  const fs::path root = absolutePath(ctx.root);
  fs::path dir = absolutePath(file).parent_path();
  const bool bounded = isWithin(dir, root);
  for (int depth = 0; depth < 64; ++depth) {
    for (const char* name : {"CATALOG.031", "catalog.031"}) {
      const fs::path cat = dir / name;
      std::error_code ec;
      if (!fs::exists(cat, ec)) continue;
      auto [it, fresh] = cache.byPath.try_emplace(cat.string());
      CatalogueCache::Entry& e = it->second;
      if (fresh) {
        try {
          const std::string bytes = readChartFile(cat.string());
          e.problem = s57::readCatalogue(bytes, e.entries);
          if (!e.problem.empty()) e.problem = "damaged: " + e.problem;
        } catch (const ChartLoadError& err) {
          e.problem = reasonOf(err);
        }
        if (!e.problem.empty()) e.problem += "; the CRCs it lists are not checked";
      }
      if (!e.problem.empty()) {
        if (!ctx.notes) throw ChartLoadError(cat.string(), e.problem);
        if (!e.reported) ctx.notes->push_back({cat.string(), io::oneLine(e.problem)});
        e.reported = true;
        continue;
      }
      if (const s57::CatalogueEntry* found = s57::findEntry(e.entries, absolutePath(file))) return *found;
      break;  // "CATALOG.031" and "catalog.031" are the same file on a case-blind disk
    }
    if (!bounded || dir == root || dir.parent_path() == dir) break;
    dir = dir.parent_path();
  }
  return std::nullopt;
}

/// Reads a cell with GDAL at `gdalPath` (a /vsimem/ file), reporting it as `path`; `memDir` and
/// `realDir` translate the names in GDAL's messages.
CellPtr readCell(const std::string& path, const std::string& gdalPath, const std::string& memDir,
                 const std::string& realDir, std::vector<std::string> updatesApplied);

/// Checks a cell's bytes (structure, DSID counts); throws naming `path`.
void checkCellBytes(const std::string& path, std::string_view bytes, s57::DataSetSummary& summary) {
  if (std::string why = s57::summarise(bytes, classKinds, summary, false); !why.empty())
    throw ChartLoadError(path, why);
  if (std::string why = s57::checkCounts(summary); !why.empty()) throw ChartLoadError(path, why);
}

std::string threeDigits(int n) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%03d", n);
  return buf;
}

CellPtr loadFromDisk(const std::string& path, const LoadContext& ctx) {
  const fs::path cellPath(path);
  const std::vector<std::string> files = updateFiles(cellPath);
  const std::string base = readChartFile(path);
  s57::DataSetSummary baseSummary;
  if (std::string why = s57::summarise(base, classKinds, baseSummary, !files.empty()); !why.empty())
    throw ChartLoadError(path, why);
  if (std::string why = s57::checkCounts(baseSummary); !why.empty()) throw ChartLoadError(path, why);
  if (const auto entry = catalogueEntry(cellPath, ctx))
    if (std::string why = s57::checkCrc(base, *entry); !why.empty()) throw ChartLoadError(path, why);
  const std::string cellName =
      s57::cellNameOf(baseSummary).empty() ? cellPath.stem().string() : s57::cellNameOf(baseSummary);

  // The updates, in sequence, up to the first bad one: each file by itself first, then their records
  // against the cell's.
  const int baseUpdate = std::max(0, static_cast<int>(std::strtol(baseSummary.update.c_str(), nullptr, 10)));
  struct Pending {
    std::size_t file;  // index in `files`
    std::string bytes;
    s57::DataSetSummary summary;
  };
  std::vector<Pending> good;
  struct Bad {
    fs::path at;
    std::string problem;
    std::size_t after = 0;  // update files after it, also left out
    bool cancels = false;
  };
  std::optional<Bad> bad;
  int expected = baseUpdate + 1;
  for (std::size_t i = 0; i < files.size() && !bad; ++i) {
    const int number = std::stoi(files[i].substr(files[i].size() - 3));
    if (number <= baseUpdate) continue;  // a re-issued cell already holds it
    const fs::path file = cellPath.parent_path() / files[i];
    if (number != expected) {
      bad = Bad{cellPath.parent_path() / (cellPath.stem().string() + "." + threeDigits(expected)),
                "is missing, and " + files[i] + " is present (updates apply in sequence)", files.size() - i};
      break;
    }
    Pending p{i, {}, {}};
    std::string problem;
    bool cancels = false;
    try {
      p.bytes = readChartFile(file.string());
      problem = s57::summarise(p.bytes, classKinds, p.summary);
      if (problem.empty()) problem = s57::checkUpdate(baseSummary, p.summary, number, &cancels);
      if (problem.empty())
        if (const auto entry = catalogueEntry(file, ctx)) problem = s57::checkCrc(p.bytes, *entry);
    } catch (const ChartLoadError& e) {
      if (e.file() != file.string()) throw;  // the catalogue's, in strict mode
      problem = reasonOf(e);
    }
    if (!problem.empty()) {
      bad = Bad{file, problem, files.size() - i - 1, cancels};
      break;
    }
    good.push_back(std::move(p));
    ++expected;
  }
  if (!good.empty()) {
    std::vector<const s57::DataSetSummary*> summaries;
    for (const Pending& p : good) summaries.push_back(&p.summary);
    s57::RecordIndex index(baseSummary, summaries);
    for (std::size_t k = 0; k < good.size(); ++k)
      if (std::string why = index.apply(good[k].summary); !why.empty()) {
        bad = Bad{cellPath.parent_path() / files[good[k].file], why, files.size() - good[k].file - 1};
        good.resize(k);
        break;
      }
  }
  if (bad) {
    if (bad->cancels || !ctx.notes) throw ChartLoadError(bad->at.string(), bad->problem);
    std::string note = bad->problem + "; " + cellName + " is loaded at update " +
                       std::to_string(baseUpdate + static_cast<int>(good.size())) + " without it";
    if (bad->after > 0) note += " and the " + std::to_string(bad->after) + " update file(s) after it";
    ctx.notes->push_back({bad->at.string(), io::oneLine(note)});
  }

  // GDAL reads the bytes we checked, from memory.
  MemoryFiles mem;
  const std::string gdalPath = mem.add(cellPath.filename().string(), base, path);
  std::vector<std::string> applied;
  for (const Pending& p : good) {
    mem.add(files[p.file], p.bytes, (cellPath.parent_path() / files[p.file]).string());
    applied.push_back(files[p.file]);
  }
  const std::string realDir =
      cellPath.parent_path().empty() ? std::string() : cellPath.parent_path().string() + "/";
  for (;;) {
    CellPtr cell = readCell(path, gdalPath, mem.dir(), realDir, applied);
    const int reached = cell->info().updateNumber;
    if (applied.empty() || reached >= baseUpdate + static_cast<int>(applied.size())) return cell;
    // GDAL stopped before the last update: the one after `reached` failed. Read again without it.
    const auto failed = static_cast<std::size_t>(std::max(0, reached - baseUpdate));
    const std::string file = (cellPath.parent_path() / applied[failed]).string();
    const std::string problem =
        "GDAL's S-57 reader could not apply it (the cell stayed at update " + std::to_string(reached) + ")";
    if (!ctx.notes) throw ChartLoadError(file, problem);
    std::string note =
        problem + "; " + cellName + " is loaded at update " + std::to_string(reached) + " without it";
    if (applied.size() - failed > 1)
      note += " and the " + std::to_string(applied.size() - failed - 1) + " update file(s) after it";
    ctx.notes->push_back({file, io::oneLine(note)});
    for (std::size_t k = failed; k < applied.size(); ++k) mem.remove(applied[k]);
    applied.resize(failed);
  }
}

CellPtr loadBuiltin(const std::string& path) {
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
  // The same checks as any cell: the generator writes what a producer writes.
  s57::DataSetSummary summary;
  checkCellBytes(path, chart->text, summary);
  return readCell(path, mem, "", "", {});
}

CellPtr loadCellWith(const std::string& path, const LoadContext& ctx) {
  initialiseGdal();
  if (catalogueDir.empty())
    throw ChartLoadError(path,
                         "GDAL's S-57 catalogue (s57objectclasses.csv) was not found; install gdal-data");
  if (path.rfind(kBuiltinPrefix, 0) == 0) return loadBuiltin(path);
  return loadFromDisk(path, ctx);
}

/// For a cell named by itself, the catalogue may be in its folder or the folder above (an ENC_ROOT
/// with CATALOG.031 and a folder per cell).
fs::path defaultRoot(const std::string& cell) {
  return absolutePath(cell).parent_path().parent_path();
}

}  // namespace

CellPtr loadCell(const std::string& path) {
  return loadCellWith(path, LoadContext{defaultRoot(path), nullptr, nullptr});
}

CellPtr loadCell(const std::string& path, std::vector<LoadFailure>& notes) {
  return loadCellWith(path, LoadContext{defaultRoot(path), nullptr, &notes});
}

std::vector<std::string> findCells(const std::string& path) {
  if (path.rfind(kBuiltinPrefix, 0) == 0) return {path};
  std::error_code ec;
  const fs::path p(path);
  const fs::file_status st = fs::status(p, ec);  // stat(): nothing is opened
  if (!fs::exists(st)) throw ChartLoadError(path, "no such file or folder");
  if (const char* kind = specialKind(st.type()))
    throw ChartLoadError(path, std::string("is ") + kind + ", not a chart file");
  if (fs::is_regular_file(st)) {
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
    throw ChartLoadError(path,
                         "damaged (GDAL's S-57 reader: " + errors.firstErrorLine(memDir, realDir) + ")");
  if (info.edition.empty())
    throw ChartLoadError(path, "no data set identification (DSID): not an S-57 base cell");
  info.updatesApplied = std::move(updatesApplied);
  return std::make_shared<const ChartCell>(std::move(info), std::move(features));
}
}  // namespace

LoadResult loadCharts(const std::vector<std::string>& paths, const LoadProgress& progress,
                      const std::atomic<bool>* cancel) {
  LoadResult r;
  std::vector<std::string> cells;
  std::vector<fs::path> roots;  // where each cell's search for a catalogue stops
  for (const auto& p : paths) {
    try {
      const auto found = findCells(p);
      std::error_code ec;
      const fs::path root = fs::is_directory(p, ec) ? fs::path(p) : defaultRoot(p);
      cells.insert(cells.end(), found.begin(), found.end());
      roots.insert(roots.end(), found.size(), root);
    } catch (const ChartLoadError& e) {
      r.failures.push_back({e.file(), io::oneLine(reasonOf(e))});
    }
  }
  CatalogueCache catalogues;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (cancel && cancel->load()) break;
    try {
      r.cells.push_back(loadCellWith(cells[i], LoadContext{roots[i], &catalogues, &r.failures}));
    } catch (const ChartLoadError& e) {
      r.failures.push_back({e.file(), io::oneLine(reasonOf(e))});
    } catch (const std::exception& e) {
      r.failures.push_back({cells[i], io::oneLine(e.what())});
    }
    if (progress) progress(i + 1, cells.size(), cells[i]);
  }
  return r;
}

}  // namespace reckoner::charts
