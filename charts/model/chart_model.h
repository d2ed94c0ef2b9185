#pragma once
// The chart model: immutable cells of features with typed S-57 attributes and WGS-84 geometry, built
// once by a loader (charts/s57) and then shared read-only between threads (shared_ptr<const ChartCell>).
// No GDAL and no Qt here.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace reckoner::charts {

struct LatLon {
  double latDeg = 0.0;
  double lonDeg = 0.0;
};

struct Bounds {
  double minLatDeg = 90.0, maxLatDeg = -90.0, minLonDeg = 180.0, maxLonDeg = -180.0;
  [[nodiscard]] bool empty() const { return minLatDeg > maxLatDeg; }
  void add(const LatLon& p);
  void add(const Bounds& b);
  [[nodiscard]] bool contains(const LatLon& p) const;
  [[nodiscard]] bool intersects(const Bounds& b) const;
};

/// S-57 geometric primitive of a feature (PRIM): point, line, area, or none (meta and collections).
enum class Primitive : std::uint8_t { None, Point, Line, Area };

/// Geometry in WGS-84. Points: one part (several points for a multipoint, e.g. soundings).
/// Lines: one part per line string. Areas: rings, each polygon's outer ring first, `polygonStarts`
/// giving the index of each polygon's first ring.
struct Geometry {
  Primitive primitive = Primitive::None;
  std::vector<std::vector<LatLon>> parts;
  std::vector<std::size_t> polygonStarts;  ///< areas only
  std::vector<double> depthsM;             ///< soundings: one depth per point of parts[0]
  Bounds bounds;

  /// Areas: whether p lies inside (even-odd over all rings, so holes are outside).
  [[nodiscard]] bool contains(const LatLon& p) const;
};

/// An attribute value as S-57 types it: enumerated and integer -> integer, float -> real, list -> a
/// list of integers, string and coded string -> text.
using AttributeValue = std::variant<std::int64_t, double, std::string, std::vector<std::int64_t>>;

struct Attribute {
  std::string acronym;  ///< e.g. "DRVAL1", "COLOUR"
  AttributeValue value;
};

struct ChartFeature {
  std::string objectClass;  ///< acronym, e.g. "DEPARE"
  int objectCode = 0;       ///< OBJL, e.g. 42
  std::string lnam;         ///< long name (agency, feature id), unique in a cell
  std::vector<Attribute> attributes;
  Geometry geometry;

  [[nodiscard]] const AttributeValue* attribute(std::string_view acronym) const;
  [[nodiscard]] std::optional<double> number(std::string_view acronym) const;  ///< integer or real
  [[nodiscard]] std::optional<std::string> text(std::string_view acronym) const;
  [[nodiscard]] std::vector<std::int64_t> list(
      std::string_view acronym) const;  ///< a single integer as a list of one
};

/// The navigational purpose bands of S-57 (DSID_INTU; the third character of a cell's name).
enum class UsageBand : std::uint8_t { Unknown, Overview, General, Coastal, Approach, Harbour, Berthing };

struct CellInfo {
  std::string name;          ///< DSID_DSNM without extension, e.g. "US5WA22M"
  std::string path;          ///< the .000 file
  std::string edition;       ///< DSID_EDTN
  int updateNumber = 0;      ///< DSID_UPDN after the updates applied
  std::string issueDate;     ///< DSID_ISDT, YYYYMMDD
  std::string updateDate;    ///< DSID_UADT
  int agency = 0;            ///< DSID_AGEN (550: NOAA)
  int intendedUsage = 0;     ///< DSID_INTU, the navigational purpose band 1 (overview) to 6 (berthing)
  int compilationScale = 0;  ///< DSPM_CSCL, 1:N
  std::string comment;       ///< DSID_COMT (the fictional default chart says "NOT FOR NAVIGATION" here)
  std::vector<std::string> updatesApplied;  ///< file names of the update files found and applied
};

/// The cell's band: DSID_INTU when it is 1 to 6, else the digit the name carries third (S-57
/// Appendix B.1, e.g. the 5 of US5WA22M), else Unknown.
UsageBand usageBand(const CellInfo& info);
/// "Overview", "General", "Coastal", "Approach", "Harbour", "Berthing" or "Unknown".
const char* usageBandName(UsageBand band);

class ChartCell {
 public:
  ChartCell(CellInfo info, std::vector<ChartFeature> features);
  ChartCell(const ChartCell&) = delete;  // coverage() points into features()
  ChartCell& operator=(const ChartCell&) = delete;
  ChartCell(ChartCell&&) = default;
  ChartCell& operator=(ChartCell&&) = default;

  [[nodiscard]] const CellInfo& info() const { return info_; }
  [[nodiscard]] const std::vector<ChartFeature>& features() const { return features_; }
  /// Coverage: the M_COVR areas with CATCOV = 1 (data present).
  [[nodiscard]] const std::vector<const ChartFeature*>& coverage() const { return coverage_; }
  [[nodiscard]] const Bounds& bounds() const { return bounds_; }
  /// The box of the coverage areas, or of the features when the cell has no coverage.
  [[nodiscard]] const Bounds& coverageBounds() const { return coverageBounds_; }
  /// Whether p lies in the cell's coverage (in its bounds when it has no coverage areas).
  [[nodiscard]] bool covers(const LatLon& p) const;
  /// Feature count per object class, sorted by class acronym.
  [[nodiscard]] std::vector<std::pair<std::string, std::size_t>> countsByClass() const;
  [[nodiscard]] std::size_t soundingCount() const;

 private:
  CellInfo info_;
  std::vector<ChartFeature> features_;
  std::vector<const ChartFeature*> coverage_;
  Bounds bounds_;
  Bounds coverageBounds_;
};

using CellPtr = std::shared_ptr<const ChartCell>;

}  // namespace reckoner::charts
