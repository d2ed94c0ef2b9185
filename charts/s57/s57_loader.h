#pragma once
// Loading S-57 ENC cells through GDAL's S57 driver: the only GDAL code of the project.
//  - A path is a cell (.000) or a folder searched recursively for cells (an ENC_ROOT, with or without
//    CATALOG.031). A FIFO, socket or device is refused without being opened.
//  - Before GDAL sees a file, our own ISO 8211 walker (iso8211.h) and the S-57 checks (s57_checks.h)
//    read it once: a cell cut at a record boundary or inside a record, records missing against the
//    DSID's counts, an update of another cell, edition or place in the sequence, and a CRC that
//    disagrees with the exchange set's CATALOG.031 are errors naming the file at fault.
//  - Each cell's update files (.001, .002, ...) beside it are applied in order by the driver. A bad
//    update stops the sequence there: loadCell() throws, naming the update; loadCharts() loads the
//    cell at the update before it and lists the update among the failures (docs/charts.md, "Damaged
//    cells").
//  - GDAL's S-57 catalogue files (s57objectclasses.csv, s57attributes.csv) are found without the user
//    setting anything: GDAL's own search, then the data directories of the installed GDAL.
//  - Failures name the file and the reason, on one line, and never throw out of loadCharts(): one
//    bad cell in a folder does not stop the others.
#include <atomic>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "charts/model/chart_model.h"

namespace reckoner::charts {

class ChartLoadError : public std::runtime_error {
 public:
  ChartLoadError(std::string file, const std::string& reason)
      : std::runtime_error(file + ": " + reason), file_(std::move(file)) {}
  [[nodiscard]] const std::string& file() const { return file_; }

 private:
  std::string file_;
};

/// Paths naming the charts compiled into the program: "builtin:default" is the fictional default
/// chart (resources/charts/reckoner_sound.cpp), also reachable by its cell name, "builtin:RK5SOUND".
inline constexpr std::string_view kBuiltinPrefix = "builtin:";
inline constexpr std::string_view kDefaultChartPath = "builtin:default";

struct LoadFailure {
  std::string file;
  std::string reason;
};

/// Loads one cell (.000) with its updates, or a built-in chart. Throws ChartLoadError naming the file
/// at fault: the cell, one of its updates, or the catalogue (CATALOG.031 in the cell's folder or the
/// folder above it) that lists their CRCs.
CellPtr loadCell(const std::string& path);

/// As loadCell(), but what need not stop the cell is added to `notes` instead of thrown: a bad update
/// (the cell loads at the update before it, without it and the updates after it) and a damaged
/// catalogue (the CRCs are then not checked). A cancelled cell (an update with edition 0) still throws.
CellPtr loadCell(const std::string& path, std::vector<LoadFailure>& notes);

/// The cells (.000 files) a path names: the file itself, or every cell below a folder, sorted.
/// Throws ChartLoadError when the path does not exist, is a FIFO, socket or device, or holds no cell.
std::vector<std::string> findCells(const std::string& path);

struct LoadResult {
  std::vector<CellPtr> cells;
  std::vector<LoadFailure> failures;
};

/// Progress: cells done, cells in all, the file just finished.
using LoadProgress = std::function<void(std::size_t done, std::size_t total, const std::string& file)>;

/// Loads every cell the paths name; never throws. A set cancel flag stops between cells. A catalogue
/// (CATALOG.031) is looked for from each cell's folder up to the folder given; a bad update or a
/// damaged catalogue is a failure while the cell still loads (see loadCell() with notes).
LoadResult loadCharts(const std::vector<std::string>& paths, const LoadProgress& progress = {},
                      const std::atomic<bool>* cancel = nullptr);

/// Where the S-57 catalogue files were found (empty if nowhere).
std::string s57CatalogueDirectory();

/// The GDAL release the loader runs on (for the About box).
std::string gdalVersion();

}  // namespace reckoner::charts
