// Loading cells: which files, read how (no blocking, bounded), checked how (structure, DSID counts, the
// update sequence, catalogue CRCs) before GDAL reads them (gdal_reader.h); failures named per file.
#include "charts/s57/s57_loader.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <system_error>

#include "charts/s57/gdal_reader.h"
#include "charts/s57/s57_checks.h"
#include "io/error_line.h"
#include "resources/embedded.h"

namespace reckoner::charts {
namespace fs = std::filesystem;
namespace {

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

/// Checks a cell's bytes (structure, DSID counts); throws naming `path`.
void checkCellBytes(const std::string& path, std::string_view bytes, s57::DataSetSummary& summary) {
  if (std::string why = s57::summarise(bytes, gdalio::classKinds(), summary, false); !why.empty())
    throw ChartLoadError(path, why);
  if (std::string why = s57::checkCounts(summary); !why.empty()) throw ChartLoadError(path, why);
}

std::string threeDigits(int n) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%03d", n);
  return buf;
}

/// A base cell read and checked: its bytes, what the walk found, its name and update number.
struct BaseCell {
  std::string bytes;
  s57::DataSetSummary summary;
  std::string name;  // DSID's DSNM stem, else the file's
  int update = 0;    // the UPDN of the cell itself (above 0 for a re-issue)
};

/// An update file that passed its checks, waiting for GDAL.
struct Pending {
  std::size_t file;  // index in the cell's update files
  std::string bytes;
  s57::DataSetSummary summary;
};

/// The first update left out, and why.
struct Bad {
  fs::path at;
  std::string problem;
  std::size_t after = 0;  // update files after it, also left out
  bool cancels = false;
};

/// What the checks keep of a cell's updates: the good ones in sequence, up to the first bad one.
struct UpdateSequence {
  std::vector<Pending> good;
  std::optional<Bad> bad;
};

/// Reads and checks the base cell at `path`: structure, DSID counts, the CRC where a catalogue lists
/// it. Throws naming the cell (or the catalogue, in strict mode).
BaseCell checkBase(const std::string& path, bool hasUpdates, const LoadContext& ctx) {
  const fs::path cellPath(path);
  BaseCell base;
  base.bytes = readChartFile(path);
  if (std::string why = s57::summarise(base.bytes, gdalio::classKinds(), base.summary, hasUpdates);
      !why.empty())
    throw ChartLoadError(path, why);
  if (std::string why = s57::checkCounts(base.summary); !why.empty()) throw ChartLoadError(path, why);
  if (const auto entry = catalogueEntry(cellPath, ctx))
    if (std::string why = s57::checkCrc(base.bytes, *entry); !why.empty()) throw ChartLoadError(path, why);
  base.name =
      s57::cellNameOf(base.summary).empty() ? cellPath.stem().string() : s57::cellNameOf(base.summary);
  base.update = std::max(0, static_cast<int>(std::strtol(base.summary.update.c_str(), nullptr, 10)));
  return base;
}

/// Reads and checks update `number` of the cell by itself (structure, the cell's name, edition and
/// number, CRC) into `p`: "" or the problem. Throws only the catalogue's error, in strict mode.
std::string checkUpdateFile(const fs::path& file, int number, const BaseCell& base, const LoadContext& ctx,
                            Pending& p, bool& cancels) {
  std::string problem;
  try {
    p.bytes = readChartFile(file.string());
    problem = s57::summarise(p.bytes, gdalio::classKinds(), p.summary);
    if (problem.empty()) problem = s57::checkUpdate(base.summary, p.summary, number, &cancels);
    if (problem.empty())
      if (const auto entry = catalogueEntry(file, ctx)) problem = s57::checkCrc(p.bytes, *entry);
  } catch (const ChartLoadError& e) {
    if (e.file() != file.string()) throw;  // the catalogue's, in strict mode
    problem = reasonOf(e);
  }
  return problem;
}

/// The updates, in sequence, up to the first bad one: each file by itself first, then their records
/// against the cell's.
UpdateSequence checkUpdates(const fs::path& cellPath, const std::vector<std::string>& files,
                            const BaseCell& base, const LoadContext& ctx) {
  UpdateSequence seq;
  int expected = base.update + 1;
  for (std::size_t i = 0; i < files.size() && !seq.bad; ++i) {
    const int number = std::stoi(files[i].substr(files[i].size() - 3));
    if (number <= base.update) continue;  // a re-issued cell already holds it
    const fs::path file = cellPath.parent_path() / files[i];
    if (number != expected) {
      seq.bad =
          Bad{cellPath.parent_path() / (cellPath.stem().string() + "." + threeDigits(expected)),
              "is missing, and " + files[i] + " is present (updates apply in sequence)", files.size() - i};
      break;
    }
    Pending p{i, {}, {}};
    bool cancels = false;
    if (std::string problem = checkUpdateFile(file, number, base, ctx, p, cancels); !problem.empty()) {
      seq.bad = Bad{file, problem, files.size() - i - 1, cancels};
      break;
    }
    seq.good.push_back(std::move(p));
    ++expected;
  }
  if (!seq.good.empty()) {
    std::vector<const s57::DataSetSummary*> summaries;
    for (const Pending& p : seq.good) summaries.push_back(&p.summary);
    s57::RecordIndex index(base.summary, summaries);
    for (std::size_t k = 0; k < seq.good.size(); ++k)
      if (std::string why = index.apply(seq.good[k].summary); !why.empty()) {
        seq.bad =
            Bad{cellPath.parent_path() / files[seq.good[k].file], why, files.size() - seq.good[k].file - 1};
        seq.good.resize(k);
        break;
      }
  }
  return seq;
}

/// A bad update: thrown when it cancels the cell or nothing is noted, else a note saying where the
/// cell stands without it.
void reportBadUpdate(const Bad& bad, const BaseCell& base, std::size_t goodCount, const LoadContext& ctx) {
  if (bad.cancels || !ctx.notes) throw ChartLoadError(bad.at.string(), bad.problem);
  std::string note = bad.problem + "; " + base.name + " is loaded at update " +
                     std::to_string(base.update + static_cast<int>(goodCount)) + " without it";
  if (bad.after > 0) note += " and the " + std::to_string(bad.after) + " update file(s) after it";
  ctx.notes->push_back({bad.at.string(), io::oneLine(note)});
}

/// GDAL reads the bytes we checked, from memory: the base and the good updates. Where GDAL stops
/// before the last update, the one after the update it reached failed; the cell is read again
/// without it and the ones after it.
CellPtr readWithUpdates(const std::string& path, const BaseCell& base, const std::vector<std::string>& files,
                        const std::vector<Pending>& good, const LoadContext& ctx) {
  const fs::path cellPath(path);
  gdalio::MemoryFiles mem;
  const std::string gdalPath = mem.add(cellPath.filename().string(), base.bytes, path);
  std::vector<std::string> applied;
  for (const Pending& p : good) {
    mem.add(files[p.file], p.bytes, (cellPath.parent_path() / files[p.file]).string());
    applied.push_back(files[p.file]);
  }
  const std::string realDir =
      cellPath.parent_path().empty() ? std::string() : cellPath.parent_path().string() + "/";
  for (;;) {
    CellPtr cell = gdalio::readCell(path, gdalPath, mem.dir(), realDir, applied);
    const int reached = cell->info().updateNumber;
    if (applied.empty() || reached >= base.update + static_cast<int>(applied.size())) return cell;
    const auto failed = static_cast<std::size_t>(std::max(0, reached - base.update));
    const std::string file = (cellPath.parent_path() / applied[failed]).string();
    const std::string problem =
        "GDAL's S-57 reader could not apply it (the cell stayed at update " + std::to_string(reached) + ")";
    if (!ctx.notes) throw ChartLoadError(file, problem);
    std::string note =
        problem + "; " + base.name + " is loaded at update " + std::to_string(reached) + " without it";
    if (applied.size() - failed > 1)
      note += " and the " + std::to_string(applied.size() - failed - 1) + " update file(s) after it";
    ctx.notes->push_back({file, io::oneLine(note)});
    for (std::size_t k = failed; k < applied.size(); ++k) mem.remove(applied[k]);
    applied.resize(failed);
  }
}

CellPtr loadFromDisk(const std::string& path, const LoadContext& ctx) {
  const std::vector<std::string> files = updateFiles(fs::path(path));
  const BaseCell base = checkBase(path, !files.empty(), ctx);
  const UpdateSequence seq = checkUpdates(fs::path(path), files, base, ctx);
  if (seq.bad) reportBadUpdate(*seq.bad, base, seq.good.size(), ctx);
  return readWithUpdates(path, base, files, seq.good, ctx);
}

CellPtr loadBuiltin(const std::string& path) {
  std::string name(path.substr(kBuiltinPrefix.size()));
  if (name == "default") name = std::string(resources::kDefaultChart);
  const resources::EmbeddedFile* chart = resources::findChart(name);
  if (!chart) throw ChartLoadError(path, "no such built-in chart (there is builtin:default)");
  // GDAL reads it from memory: a /vsimem/ file over the embedded bytes, made once.
  const std::string mem = "/vsimem/reckoner/" + name + "/" + name + ".000";
  if (!gdalio::addStaticMemoryFile(mem, chart->text))
    throw ChartLoadError(path, "cannot open the embedded chart in memory");
  // The same checks as any cell: the generator writes what a producer writes.
  s57::DataSetSummary summary;
  checkCellBytes(path, chart->text, summary);
  return gdalio::readCell(path, mem, "", "", {});
}

CellPtr loadCellWith(const std::string& path, const LoadContext& ctx) {
  gdalio::initialise();
  if (gdalio::catalogueDirectory().empty())
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

std::string gdalVersion() {
  return gdalio::versionText();
}

}  // namespace reckoner::charts
