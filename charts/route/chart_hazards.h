#pragma once
// What in the open charts a ship must keep clear of, for a safety contour and depth (MSC.232(82) 11.3.5
// and 11.4.4, the route check and the anti-grounding look-ahead alike): areas shallower than the safety
// contour and unsurveyed areas, land, isolated dangers above the safety depth (wrecks, obstructions,
// rocks; those without VALSOU are dangerous), prohibited and restricted areas, and the areas for which
// special conditions exist (traffic separation, anchorages, caution areas, ...; docs/routes.md has the
// list). Built once from the cells and then read-only (safe to share between threads):
//  - every hazard's geometry in spherical Mercator (as the chart draws it), its edges (and its points as
//    edges of length 0) in one uniform grid (geo/grid_index.h);
//  - touching(): the hazards a convex polygon meets, each once, with a point of the meeting;
//  - containing(): the areas holding a point, by counting an eastward ray's crossings along one row of
//    the grid (so a polygon of thousands of vertices costs only the edges near that row).
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "charts/model/chart_model.h"
#include "charts/render/viewport.h"
#include "geo/grid_index.h"

namespace reckoner::charts {

enum class HazardKind : std::uint8_t {
  SafetyContour,  ///< an area shallower than the safety contour (DEPARE, DRGARE) or unsurveyed (UNSARE)
  Land,           ///< LNDARE
  Danger,         ///< an isolated danger: WRECKS, OBSTRN, UWTROC above the safety depth or of unknown depth
  Prohibited,     ///< RESARE with entry prohibited or an area to be avoided
  Restricted,     ///< RESARE with entry restricted, military practice areas
  SpecialArea,    ///< the other areas for which special conditions exist
};
/// "safety_contour", "land", "danger", "prohibited_area", "restricted_area", "special_area".
const char* hazardKindName(HazardKind kind);
/// Whether the kind is one a ship must not enter: the safety contour, land, dangers and prohibited
/// areas. Restricted and special areas are cautions: entry is allowed under conditions.
constexpr bool isDangerous(HazardKind kind) {
  return kind != HazardKind::SpecialArea && kind != HazardKind::Restricted;
}

struct SafetySettings {
  double safetyContourM = 10.0;        ///< areas with DRVAL1 below it are unsafe
  std::optional<double> safetyDepthM;  ///< isolated dangers with VALSOU below it; none: the contour
  bool specialAreas = true;            ///< report the areas for which special conditions exist
  [[nodiscard]] double dangerDepthM() const { return safetyDepthM.value_or(safetyContourM); }
};

/// Why a feature is a hazard under the settings; nullopt when it is not one.
struct HazardClass {
  HazardKind kind = HazardKind::Danger;
  std::optional<double> depthM;  ///< DRVAL1 of an area, VALSOU of a danger, where known
};
std::optional<HazardClass> classifyHazard(const ChartFeature& feature, const SafetySettings& settings);

struct Hazard {
  HazardKind kind = HazardKind::Danger;
  std::optional<double> depthM;
  std::uint32_t cell = 0;  ///< index into ChartHazards::cells()
  const ChartFeature* feature = nullptr;
};

/// A hazard met, and a point of the meeting (Mercator).
struct HazardContact {
  std::uint32_t hazard = 0;
  MercatorPoint at;
};

class ChartHazards {
 public:
  ChartHazards(std::vector<CellPtr> cells, const SafetySettings& settings);

  [[nodiscard]] const std::vector<Hazard>& hazards() const { return hazards_; }
  [[nodiscard]] const std::vector<CellPtr>& cells() const { return cells_; }
  [[nodiscard]] const SafetySettings& settings() const { return settings_; }
  [[nodiscard]] std::size_t edgeCount() const { return edges_.size(); }

  /// The hazards whose edges or points meet the convex polygon `poly` (Mercator, either winding), each
  /// once, appended to `out` with their point inside the polygon nearest `poly[0]`. Hazards h with
  /// skip[h] != 0 are passed over (skip empty: none). Areas that hold the whole polygon have no edge
  /// in it: see containing().
  void touching(std::span<const MercatorPoint> poly, std::vector<HazardContact>& out,
                std::span<const std::uint8_t> skip = {}) const;
  /// The area hazards that hold the point, appended to `out` in ascending order.
  void containing(MercatorPoint p, std::vector<std::uint32_t>& out) const;

 private:
  struct Edge {
    MercatorPoint a, b;
    std::uint32_t hazard = 0;
    bool area = false;  ///< a ring's edge (counted by containing())
  };
  void addFeature(std::uint32_t hazard, const Geometry& g);

  std::vector<CellPtr> cells_;
  SafetySettings settings_;
  std::vector<Hazard> hazards_;
  std::vector<Edge> edges_;
  geo::GridIndex grid_;
};

}  // namespace reckoner::charts
