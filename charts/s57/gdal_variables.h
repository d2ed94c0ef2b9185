#pragma once
// Whole one-dimensional integer variables of a netCDF file, read by name through GDAL's
// multidimensional API (GDALOpenEx with GDAL_OF_MULTIDIM_RASTER, then the root group's GDALMDArrays).
// The world background (charts/world/) reads GSHHG's binned shorelines with it; GDAL stays in s57/.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace reckoner::charts::gdalio {

/// Variables by name, each read whole and converted to 32-bit integers.
using IntegerVariables = std::map<std::string, std::vector<std::int32_t>>;

/// Reads `required` (each must be there) and `optional` (read when there) from the netCDF file at
/// `path`. Each variable must have one dimension, an integer type of at most 32 bits and at most
/// `maxValues` values. Throws ChartLoadError naming `path`, and the variable where one is at fault:
/// "no such file", "cannot be opened as netCDF (GDAL: ...)", "has no variable 'X'", "variable 'X':
/// cannot be read (GDAL: ...)" for damaged data, and so on; GDAL's own messages are captured, one line.
IntegerVariables readIntegerVariables(const std::string& path, const std::vector<std::string>& required,
                                      const std::vector<std::string>& optional = {},
                                      std::uint64_t maxValues = 50'000'000);

}  // namespace reckoner::charts::gdalio
