#pragma once
// GSHHG's binned shorelines (the netCDF files GMT reads; Debian's gmt-gshhg-low installs them in
// /usr/share/gmt-gshhg) decoded into filled land and water areas and shoreline pieces per bin, in
// longitude/latitude. The format and the assembly are described in docs/charts.md ("World background").
//
// decodeGshhg() is plain C++ over the file's variables (no GDAL, no files), so bad values can be fed
// to it directly; loadGshhg() reads the variables through GDAL (charts/s57/gdal_variables.h) first.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "charts/model/chart_model.h"
#include "charts/s57/gdal_variables.h"

namespace reckoner::charts::world {

/// GSHHG's resolutions that Debian's gmt-gshhg-low ships: crude (25 km Douglas-Peucker tolerance),
/// low (5 km) and intermediate (1 km).
enum class ShoreResolution : std::uint8_t { Crude, Low, Intermediate };

/// 'c', 'l' or 'i', as in the file names (binned_GSHHS_c.nc).
char resolutionLetter(ShoreResolution r);
/// "crude", "low" or "intermediate".
std::string_view resolutionName(ShoreResolution r);

/// A filled area: a closed ring (first point not repeated) of one level. Levels: 1 land, 2 lake,
/// 3 island in a lake, 4 pond on such an island; odd is land, even is water.
struct ShoreArea {
  int level = 1;
  std::vector<LatLon> ring;
};

/// A piece of shoreline inside one bin, as the file holds it (the line a chart draws).
struct ShoreLine {
  int level = 1;
  std::vector<LatLon> points;
};

/// One bin of the file's grid. Longitudes run from westDeg (0 to 360) eastwards, not wrapped.
struct ShoreBin {
  double westDeg = 0.0, southDeg = 0.0;
  /// Areas in painting order (ascending level): painted over a water background, each in the colour
  /// of its level's parity, they give the bin's land and water.
  std::vector<ShoreArea> areas;
  std::vector<ShoreLine> lines;
};

class Shoreline {
 public:
  Shoreline(std::string file, ShoreResolution resolution, double binSizeDeg, int columns, int rows,
            std::vector<ShoreBin> bins);

  [[nodiscard]] const std::string& file() const { return file_; }
  [[nodiscard]] ShoreResolution resolution() const { return resolution_; }
  [[nodiscard]] double binSizeDeg() const { return binSizeDeg_; }
  [[nodiscard]] int columns() const { return columns_; }
  [[nodiscard]] int rows() const { return rows_; }
  /// Row by row from the north (row 0: 90°N down to 90° - bin size), each row from 0°E eastwards.
  [[nodiscard]] const std::vector<ShoreBin>& bins() const { return bins_; }
  [[nodiscard]] const ShoreBin& bin(int row, int column) const {
    return bins_[static_cast<std::size_t>(row) * static_cast<std::size_t>(columns_) +
                 static_cast<std::size_t>(column)];
  }
  /// The bin holding a point (any longitude; latitude clamped to the grid).
  [[nodiscard]] const ShoreBin& binAt(const LatLon& p) const;
  /// The level at a point: 0 sea, 1 land, 2 lake, 3 island in a lake, 4 pond (odd is land).
  [[nodiscard]] int levelAt(const LatLon& p) const;
  [[nodiscard]] bool isLand(const LatLon& p) const { return levelAt(p) % 2 == 1; }
  /// Vertices over all areas and lines (a measure of the memory and drawing it costs).
  [[nodiscard]] std::size_t vertexCount() const;

 private:
  std::string file_;
  ShoreResolution resolution_;
  double binSizeDeg_;
  int columns_, rows_;
  std::vector<ShoreBin> bins_;
};

/// The variables decodeGshhg() needs; Embedded_ANT_flag is optional (GSHHG before 2.3 lacks it).
const std::vector<std::string>& gshhgRequiredVariables();
const std::vector<std::string>& gshhgOptionalVariables();

/// Decodes the variables of a binned GSHHS file (`file` names it in errors). Throws ChartLoadError
/// naming the file and the variable at fault when a value is out of range or the arrays disagree
/// (a damaged or truncated file): "binned_GSHHS_c.nc: variable 'Id_of_first_point_in_a_segment':
/// segment 17 starts at point 14200, the file holds 14138".
Shoreline decodeGshhg(const gdalio::IntegerVariables& variables, const std::string& file,
                      ShoreResolution resolution);

/// Reads the file through GDAL and decodes it; throws ChartLoadError as readIntegerVariables() and
/// decodeGshhg() do.
Shoreline loadGshhg(const std::string& path, ShoreResolution resolution);

}  // namespace reckoner::charts::world
