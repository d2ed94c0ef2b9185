#pragma once
// The charts' answers to a run (sim::ChartGuard, core/sim/chart_guard.h): the anti-grounding look-ahead
// and whether own ship is aground, on the open cells (docs/routes.md, "Anti-grounding").
//  - outlook(): each sampled path of the look-ahead (nav::LookAheadPrediction) is followed step by step
//    against the hazards of the safety settings (chart_hazards.h): the first step at which it meets the
//    safety contour, land or a prohibited area (the ship's half-beam about the path), or passes within
//    the danger clearance of an isolated danger. The shares of paths give the probabilities; the area
//    is the convex hull of the 95% position ellipses over the horizon, and the hazards meeting it are
//    listed. Paths are mapped from the grid to Mercator with each step's local Jacobian (exact to
//    millimetres over the paths' spread).
//  - grounding(): land or a depth area whose least depth (DRVAL1) is below the draught holding the
//    position, or a danger shallower than the draught (or of unknown depth) within the half-beam
//    (at least 5 m) of it. A depth area gives its depth as a band: the least depth is taken, so a ship
//    grounds as soon as the chart cannot promise it water under its keel.
#include <optional>
#include <vector>

#include "charts/route/chart_hazards.h"
#include "sim/chart_guard.h"
#include "sim/voyage_spec.h"

namespace reckoner::charts {

struct AntiGroundingSettings {
  SafetySettings safety;           ///< the safety contour and depth the look-ahead is tested against
  double draughtM = 5.0;           ///< own ship's draught, for grounding
  double dangerClearanceM = 50.0;  ///< a path passing an isolated danger this close meets it
  double halfBeamM = 0.0;          ///< a path this close to an area meets it (0: the path itself)
  /// What makes the settings unusable, one line each (empty: none).
  [[nodiscard]] std::vector<std::string> problems() const;
};

/// A voyage's settings (its safety contour and depth, draught, clearance, half-beam) for the guard.
AntiGroundingSettings antiGroundingSettingsOf(const sim::VoyageSpec& voyage);

class ChartSafety : public sim::ChartGuard {
 public:
  /// Throws std::invalid_argument for settings with problems().
  ChartSafety(const std::vector<CellPtr>& cells, const AntiGroundingSettings& settings);

  [[nodiscard]] sim::GroundingOutlook outlook(const nav::LookAheadPrediction& prediction,
                                              const geo::LocalFrame& frame) const override;
  [[nodiscard]] std::optional<sim::Grounding> grounding(const geo::GeoPoint& p) const override;

  [[nodiscard]] const ChartHazards& hazards() const { return hazards_; }
  [[nodiscard]] const AntiGroundingSettings& settings() const { return settings_; }

 private:
  AntiGroundingSettings settings_;
  ChartHazards hazards_;    ///< under the safety settings
  ChartHazards grounding_;  ///< at the draught
};

}  // namespace reckoner::charts
