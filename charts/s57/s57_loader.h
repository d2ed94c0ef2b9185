#pragma once
// Loading S-57 ENC cells through GDAL's S57 driver: the only GDAL code of the project.
//  - A path is a cell (.000) or a folder searched recursively for cells (an ENC_ROOT, with or without
//    CATALOG.031). Each cell's update files (.001, .002, ...) beside it are applied in order by the
//    driver; a cell whose update number stays below its last update file fails ("unreadable update").
//  - GDAL's S-57 catalogue files (s57objectclasses.csv, s57attributes.csv) are found without the user
//    setting anything: GDAL's own search, then the data directories of the installed GDAL.
//  - Failures name the file and the reason and never throw out of loadCharts(): one bad cell in a
//    folder does not stop the others.
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

/// Loads one cell (.000) with its updates, or a built-in chart. Throws ChartLoadError.
CellPtr loadCell(const std::string& path);

/// The cells (.000 files) a path names: the file itself, or every cell below a folder, sorted.
/// Throws ChartLoadError when the path does not exist or holds no cell.
std::vector<std::string> findCells(const std::string& path);

struct LoadFailure {
  std::string file;
  std::string reason;
};

struct LoadResult {
  std::vector<CellPtr> cells;
  std::vector<LoadFailure> failures;
};

/// Progress: cells done, cells in all, the file just finished.
using LoadProgress = std::function<void(std::size_t done, std::size_t total, const std::string& file)>;

/// Loads every cell the paths name; never throws. A set cancel flag stops between cells.
LoadResult loadCharts(const std::vector<std::string>& paths, const LoadProgress& progress = {},
                      const std::atomic<bool>* cancel = nullptr);

/// Where the S-57 catalogue files were found (empty if nowhere).
std::string s57CatalogueDirectory();

}  // namespace reckoner::charts
