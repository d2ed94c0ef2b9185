#pragma once
// The GDAL side of the loader (internal to charts/s57): GDAL's start-up and S-57 catalogue, bytes
// handed to GDAL as /vsimem/ files, and a cell read through GDAL's S57 driver into a ChartCell (OGR
// features converted to ChartFeature: typed attributes, WGS-84 geometry, sounding depths).
// s57_loader.cpp decides what is read (files, update sequence, catalogue CRCs); this file reads it.
#include <string>
#include <string_view>
#include <vector>

#include "charts/model/chart_model.h"
#include "charts/s57/s57_checks.h"

namespace reckoner::charts::gdalio {

/// Collects GDAL errors of the calling thread while alive (CPLPushErrorHandlerEx: per thread, so
/// nothing reaches stderr behind the caller's back).
class ErrorCapture {
 public:
  ErrorCapture();
  ~ErrorCapture();
  ErrorCapture(const ErrorCapture&) = delete;
  ErrorCapture& operator=(const ErrorCapture&) = delete;
  /// The first error as GDAL wrote it: possibly several lines, possibly with raw input bytes.
  [[nodiscard]] const std::string& firstError() const { return first_; }
  /// The first error on one line (io::oneLine), with the /vsimem/ folder GDAL read from (`memDir`)
  /// replaced by the folder the files came from (`realDir`).
  [[nodiscard]] std::string firstErrorLine(const std::string& memDir = {},
                                           const std::string& realDir = {}) const;
  /// Keeps `message` if it is the first error (GDAL's handler calls it).
  void note(const char* message);

 private:
  std::string first_;
};

/// Registers GDAL's drivers and finds the S-57 catalogue, once per process (thread-safe).
void initialise();
/// GDAL's release name, "3.6.2" (of the library loaded, not the headers).
std::string versionText();
/// The folder of s57objectclasses.csv, empty if not found. Call initialise() first.
const std::string& catalogueDirectory();
/// The object classes' kinds from s57objectclasses.csv (empty if not found). Call initialise() first.
const s57::ObjectClassKinds& classKinds();

/// Files GDAL reads from memory: the bytes we checked, under /vsimem/, removed again at the end.
class MemoryFiles {
 public:
  MemoryFiles();
  ~MemoryFiles();
  MemoryFiles(const MemoryFiles&) = delete;
  MemoryFiles& operator=(const MemoryFiles&) = delete;
  /// The /vsimem/ path of `name` over `bytes`, which must outlive this object; throws naming `file`.
  std::string add(const std::string& name, const std::string& bytes, const std::string& file);
  void remove(const std::string& name);
  [[nodiscard]] const std::string& dir() const { return dir_; }

 private:
  std::string dir_;
  std::vector<std::string> names_;
};

/// Makes the /vsimem/ file `memPath` over `bytes` (static data: it is never removed) unless it is
/// there already; false when GDAL cannot make it. Thread-safe.
bool addStaticMemoryFile(const std::string& memPath, std::string_view bytes);

/// Reads a cell with GDAL at `gdalPath` (a /vsimem/ file), reporting it as `path`; `memDir` and
/// `realDir` translate the names in GDAL's messages. Throws ChartLoadError naming `path`.
CellPtr readCell(const std::string& path, const std::string& gdalPath, const std::string& memDir,
                 const std::string& realDir, std::vector<std::string> updatesApplied);

}  // namespace reckoner::charts::gdalio
