// netCDF variables through GDAL's multidimensional API (gdal_variables.h).
#include "charts/s57/gdal_variables.h"

#include <gdal.h>

#include <filesystem>
#include <memory>
#include <system_error>

#include "charts/s57/gdal_reader.h"
#include "charts/s57/s57_loader.h"

namespace reckoner::charts::gdalio {
namespace {

struct DatasetCloser {
  void operator()(void* h) const { GDALClose(h); }
};
struct GroupReleaser {
  void operator()(GDALGroupHS* h) const { GDALGroupRelease(h); }
};
struct ArrayReleaser {
  void operator()(GDALMDArrayHS* h) const { GDALMDArrayRelease(h); }
};
struct TypeReleaser {
  void operator()(GDALExtendedDataTypeHS* h) const { GDALExtendedDataTypeRelease(h); }
};
using Dataset = std::unique_ptr<void, DatasetCloser>;
using Group = std::unique_ptr<GDALGroupHS, GroupReleaser>;
using Array = std::unique_ptr<GDALMDArrayHS, ArrayReleaser>;
using Type = std::unique_ptr<GDALExtendedDataTypeHS, TypeReleaser>;

std::string gdalSays(const ErrorCapture& errors) {
  return errors.firstError().empty() ? std::string() : " (GDAL: " + errors.firstErrorLine() + ")";
}

bool integerOfAtMost32Bits(GDALDataType t) {
  switch (t) {
    case GDT_Byte:
    case GDT_Int16:
    case GDT_UInt16:
    case GDT_Int32:
      return true;
    default:
      return false;
  }
}

/// The length of a one-dimensional integer array; throws naming the variable otherwise.
std::uint64_t checkedLength(GDALMDArrayH array, const std::string& path, const std::string& name,
                            std::uint64_t maxValues) {
  const std::string what = "variable '" + name + "': ";
  Type type(GDALMDArrayGetDataType(array));
  if (!type || GDALExtendedDataTypeGetClass(type.get()) != GEDTC_NUMERIC ||
      !integerOfAtMost32Bits(GDALExtendedDataTypeGetNumericDataType(type.get())))
    throw ChartLoadError(path, what + "is not of an integer type of at most 32 bits");
  std::size_t nDims = 0;
  GDALDimensionH* dims = GDALMDArrayGetDimensions(array, &nDims);
  const std::uint64_t length = nDims == 1 ? GDALDimensionGetSize(dims[0]) : 0;
  GDALReleaseDimensions(dims, nDims);
  if (nDims != 1)
    throw ChartLoadError(path, what + "has " + std::to_string(nDims) + " dimensions, 1 expected");
  if (length > maxValues)
    throw ChartLoadError(path, what + "holds " + std::to_string(length) + " values, at most " +
                                   std::to_string(maxValues) + " expected");
  return length;
}

std::vector<std::int32_t> readVariable(GDALMDArrayH array, const std::string& path, const std::string& name,
                                       std::uint64_t maxValues) {
  const std::uint64_t length = checkedLength(array, path, name, maxValues);
  std::vector<std::int32_t> values(static_cast<std::size_t>(length));
  if (length == 0) return values;
  ErrorCapture errors;
  const GUInt64 start = 0;
  const std::size_t count = values.size();
  Type int32(GDALExtendedDataTypeCreate(GDT_Int32));
  if (!GDALMDArrayRead(array, &start, &count, nullptr, nullptr, int32.get(), values.data(), values.data(),
                       values.size() * sizeof(std::int32_t)))
    throw ChartLoadError(path,
                         "variable '" + name + "': cannot be read (damaged or truncated)" + gdalSays(errors));
  return values;
}

}  // namespace

IntegerVariables readIntegerVariables(const std::string& path, const std::vector<std::string>& required,
                                      const std::vector<std::string>& optional, std::uint64_t maxValues) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw ChartLoadError(path, "no such file");
  if (!std::filesystem::is_regular_file(path, ec)) throw ChartLoadError(path, "is not a regular file");
  initialise();
  ErrorCapture errors;
  const char* const drivers[] = {"netCDF", nullptr};
  Dataset ds(GDALOpenEx(path.c_str(), GDAL_OF_MULTIDIM_RASTER | GDAL_OF_READONLY, drivers, nullptr, nullptr));
  if (!ds)
    throw ChartLoadError(
        path, "cannot be opened as netCDF (damaged, truncated or another format)" + gdalSays(errors));
  Group root(GDALDatasetGetRootGroup(ds.get()));
  if (!root) throw ChartLoadError(path, "has no root group" + gdalSays(errors));
  IntegerVariables out;
  for (const auto* names : {&required, &optional})
    for (const std::string& name : *names) {
      Array array(GDALGroupOpenMDArray(root.get(), name.c_str(), nullptr));
      if (!array) {
        if (names == &optional) continue;
        throw ChartLoadError(path, "has no variable '" + name + "'" + gdalSays(errors));
      }
      out[name] = readVariable(array.get(), path, name, maxValues);
    }
  return out;
}

}  // namespace reckoner::charts::gdalio
