#pragma once
// A cell made ready to draw (internal to charts/render): every vertex projected once to Mercator,
// each feature's portrayal rule looked up once, the features sorted once into drawing order (display
// priority, then areas, lines, points). Built by cell_preparation.cpp, read by the painters.
#include <cstdint>
#include <limits>
#include <vector>

#include "charts/model/chart_model.h"
#include "charts/portrayal/portrayal.h"
#include "charts/render/viewport.h"

namespace reckoner::charts {

/// One part (ring, line string or point list) of a feature: its points in PreparedCell::points().
struct PartSpan {
  std::uint32_t first = 0, count = 0;
  MercatorPoint lo, hi;  // Mercator box of the part
};

/// Appends the part's points to `points` in Mercator and returns where they are and their box (cells
/// and the world background prepare their geometry alike).
PartSpan appendMercator(std::vector<MercatorPoint>& points, const std::vector<LatLon>& part);

/// One feature to draw: its rule, its parts in PreparedCell::parts(), its box and SCAMIN.
struct PreparedItem {
  const ChartFeature* f = nullptr;
  const PortrayalRule* rule = nullptr;
  std::uint32_t firstPart = 0, partCount = 0;
  MercatorPoint lo, hi;  // box of the feature
  double scamin = std::numeric_limits<double>::infinity();
};

class PreparedCell {
 public:
  PreparedCell(CellPtr cell, const PortrayalTable& table);

  [[nodiscard]] const ChartCell& cell() const { return *cell_; }
  /// The features that have a rule and a geometry, in drawing order.
  [[nodiscard]] const std::vector<PreparedItem>& items() const { return items_; }
  /// The cell's coverage (M_COVR areas with CATCOV 1 or no CATCOV).
  [[nodiscard]] const std::vector<PreparedItem>& coverage() const { return coverage_; }
  [[nodiscard]] const std::vector<PartSpan>& parts() const { return parts_; }
  [[nodiscard]] const std::vector<MercatorPoint>& points() const { return points_; }
  /// The depth contour values (DEPCNT VALDCO) of the cell, for the choice of the safety contour.
  [[nodiscard]] const std::vector<double>& contourValues() const { return contourValues_; }

 private:
  void addGeometry(const Geometry& g, PreparedItem& it);

  CellPtr cell_;
  std::vector<PreparedItem> items_;
  std::vector<PreparedItem> coverage_;
  std::vector<PartSpan> parts_;
  std::vector<MercatorPoint> points_;
  std::vector<double> contourValues_;
};

}  // namespace reckoner::charts
