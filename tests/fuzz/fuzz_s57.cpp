// libFuzzer target: S-57 cells through the project's loader (charts/s57/s57_loader.h: our ISO 8211
// walker and S-57 checks, then GDAL's S57 driver underneath). The input is a base cell, optionally
// followed by "RKUPDATE" and an update file (.001), and by "RKCATLOG" and the exchange set's
// CATALOG.031; they are written to a scratch folder (in /dev/shm when there is one) and loaded with
// loadCell(), and with loadCharts() which records a bad update or catalogue as a failure and loads the
// cell without it. Checks what the loader promises beyond not crashing, whatever GDAL does with the
// bytes: loadCell() throws only ChartLoadError, naming one of the files, on one line; loadCharts()
// throws nothing and reports each failure on one line; a cell loaded has finite WGS-84 coordinates in
// range, bounds that hold every point, one depth per sounding, polygon starts inside their parts, and
// the same features from both calls when neither reported a problem (docs/robustness.md, "Fuzzing";
// docs/charts.md, "Damaged cells").
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "charts/s57/s57_loader.h"

namespace {
namespace fs = std::filesystem;
using namespace reckoner::charts;

void check(bool ok, int line = __builtin_LINE()) {
  if (ok) return;
  std::fprintf(stderr, "fuzz_s57: check failed at line %d\n", line);
  std::abort();
}

// Allocated once and never destroyed: the exit handler that removes the folder runs after the static
// objects are destroyed (it is registered before this one is constructed), so it must not read one.
const fs::path& scratchDir() {
  static const fs::path* dir = [] {
    const fs::path base = fs::is_directory("/dev/shm") ? fs::path("/dev/shm") : fs::temp_directory_path();
    auto* d = new fs::path(base / ("reckoner-fuzz-s57-" + std::to_string(::getpid())) / "FZ5CELL0");
    fs::create_directories(*d);
    std::atexit([] { fs::remove_all(scratchDir().parent_path()); });
    return d;
  }();
  return *dir;
}

void write(const fs::path& p, std::string_view bytes) {
  std::ofstream out(p, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

void oneLine(std::string_view s) {
  check(s.find_first_of("\r\n") == std::string_view::npos);
}

void checkPoint(const LatLon& p, const Bounds& b) {
  check(std::isfinite(p.latDeg) && std::abs(p.latDeg) <= 90.0);
  check(std::isfinite(p.lonDeg) && std::abs(p.lonDeg) <= 180.0);
  check(b.contains(p));
}

void checkCell(const ChartCell& cell) {
  for (const ChartFeature& f : cell.features()) {
    const Geometry& g = f.geometry;
    for (const auto& part : g.parts)
      for (const LatLon& p : part) {
        checkPoint(p, g.bounds);
        check(cell.bounds().contains(p));
      }
    if (!g.depthsM.empty()) {
      check(g.parts.size() == 1 && g.depthsM.size() == g.parts[0].size());
      for (const double d : g.depthsM) check(std::isfinite(d));
    }
    for (const std::size_t s : g.polygonStarts) check(s < g.parts.size());
  }
  (void)cell.countsByClass();
  (void)cell.soundingCount();
  (void)cell.covers(LatLon{0.0, 0.0});
}

std::size_t find(std::string_view s, std::string_view marker) {
  const std::size_t at = s.find(marker);
  return at == std::string_view::npos ? s.size() : at;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view all(reinterpret_cast<const char*>(data), size);
  const std::size_t upd = find(all, "RKUPDATE"), cat = find(all, "RKCATLOG");
  const std::size_t cellEnd = std::min(upd, cat);
  const fs::path& dir = scratchDir();
  const fs::path cell = dir / "FZ5CELL0.000", update = dir / "FZ5CELL0.001", catalogue = dir / "CATALOG.031";
  fs::remove(update);
  fs::remove(catalogue);
  write(cell, all.substr(0, cellEnd));
  if (upd < all.size()) write(update, all.substr(upd + 8, (cat > upd ? cat : all.size()) - upd - 8));
  if (cat < all.size()) write(catalogue, all.substr(cat + 8, (upd > cat ? upd : all.size()) - cat - 8));

  std::size_t features = 0;
  bool loaded = false;
  try {
    const CellPtr c = loadCell(cell.string());
    check(c != nullptr);
    checkCell(*c);
    features = c->features().size();
    loaded = true;
  } catch (const ChartLoadError& e) {
    oneLine(e.what());
    check(e.file() == cell.string() || e.file() == update.string() || e.file() == catalogue.string());
  } catch (...) {
    std::abort();
  }
  try {
    const LoadResult r = loadCharts({cell.string()});
    check(r.cells.size() <= 1);
    for (const LoadFailure& f : r.failures) {
      oneLine(f.file);
      oneLine(f.reason);
    }
    for (const CellPtr& c : r.cells) {
      checkCell(*c);
      if (loaded && r.failures.empty()) check(c->features().size() == features);
    }
  } catch (...) {
    std::abort();
  }
  return 0;
}
