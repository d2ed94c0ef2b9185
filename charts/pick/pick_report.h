#pragma once
// Pick reports: the features at a point of the chart, with object classes, attribute names and
// enumerated values in plain words, decoded from GDAL's S-57 catalogue files (s57objectclasses.csv,
// s57attributes.csv, s57expectedinput.csv), found where the loader finds them. Plain C++ (the
// catalogue directory comes from charts/s57).
#include <map>
#include <string>
#include <vector>

#include "charts/model/chart_model.h"
#include "charts/render/viewport.h"

namespace reckoner::charts {

/// The S-57 object catalogue as GDAL ships it.
class S57Catalogue {
 public:
  /// Reads the three CSV files in `directory`; throws ChartLoadError naming a missing or malformed file.
  explicit S57Catalogue(const std::string& directory);
  /// The catalogue of the installed GDAL (read once; throws if GDAL's data files are missing).
  static const S57Catalogue& installed();

  /// "Buoy, lateral" for "BOYLAT"; the acronym itself when unknown.
  [[nodiscard]] std::string className(const std::string& acronym) const;
  /// "Buoy shape" for "BOYSHP"; the acronym itself when unknown.
  [[nodiscard]] std::string attributeName(const std::string& acronym) const;
  /// The value in words: enumerations and lists decoded ("conical (nun, ogival)", "red, white"),
  /// numbers and text as they are.
  [[nodiscard]] std::string valueText(const std::string& acronym, const AttributeValue& value) const;
  [[nodiscard]] std::size_t classCount() const { return classes_.size(); }

 private:
  std::map<std::string, std::string, std::less<>> classes_;                     // acronym -> name
  std::map<std::string, std::pair<int, std::string>, std::less<>> attributes_;  // acronym -> code, name
  std::map<std::pair<int, long long>, std::string> values_;                     // (code, value) -> meaning
};

struct PickedAttribute {
  std::string acronym, name, value;
};

struct PickedFeature {
  std::string cell;         ///< cell name
  std::string objectClass;  ///< acronym
  std::string className;    ///< in words
  std::string primitive;    ///< "point", "line" or "area"
  std::string lnam;
  std::vector<PickedAttribute> attributes;
  double distancePx = 0;  ///< from the picked point (0 inside an area)
};

/// One feature of a cell in words (distancePx 0): what a pick report lists for it.
PickedFeature describeFeature(const ChartCell& cell, const ChartFeature& feature,
                              const S57Catalogue& catalogue = S57Catalogue::installed());

/// Features of `cells` at screen point `at` of `view`: points and lines within `tolerancePx` of it, and
/// areas containing it; for soundings the nearest sounding with its depth. Points first, then lines,
/// then areas, nearest first; finer cells before coarser ones.
std::vector<PickedFeature> pickFeatures(const std::vector<CellPtr>& cells, const Viewport& view,
                                        ScreenPoint at, double tolerancePx = 8.0,
                                        const S57Catalogue& catalogue = S57Catalogue::installed());

}  // namespace reckoner::charts
