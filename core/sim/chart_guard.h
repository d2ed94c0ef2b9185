#pragma once
// What a run asks of the charts, which core cannot read itself (charts/ is above it): the
// anti-grounding look-ahead against the safety contour and dangers, and whether a position is aground.
// charts/route/chart_safety.h implements it on the open cells; the engine (sim/voyage_watch.h) calls it
// each cycle when a run has charts, and puts the answers in the SimFrame for the alerts and the window.
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "geo/local_frame.h"
#include "navigation/look_ahead.h"

namespace reckoner::sim {

/// A hazard inside the look-ahead area.
struct HazardAhead {
  std::string kind;         ///< charts' hazard kind: "safety_contour", "land", "danger", ...
  std::string objectClass;  ///< e.g. "DEPARE", "WRECKS"
  std::string cell, lnam;
  geo::GeoPoint position;  ///< its point in the area nearest own ship
  std::optional<double> depthM;
  double probability = 0.0;  ///< of the sampled paths, the share that meets it first
};

/// The anti-grounding look-ahead at a time (docs/routes.md, "Anti-grounding").
struct GroundingOutlook {
  bool valid = false;
  TimeUs timeUs = 0;
  double horizonS = 0.0;
  /// Probability that own ship crosses the safety contour, or enters land or a prohibited area, within
  /// the look-ahead (already inside one counts).
  double crossingProbability = 0.0;
  /// Probability that own ship passes within the danger clearance of an isolated danger.
  double dangerProbability = 0.0;
  /// Median time to the first crossing over the paths that cross, s; NaN when none does.
  double medianCrossingS = std::numeric_limits<double>::quiet_NaN();
  std::vector<geo::GeoPoint> area;  ///< the look-ahead area: where own ship may be (95%) within the horizon
  std::vector<HazardAhead> ahead;   ///< the hazards meeting the area, most probable first
};

/// Where a ship has run aground: what it hit.
struct Grounding {
  std::string what;  ///< in words: "land (LNDARE)", "depth area 0 m (DEPARE)", "danger 1.2 m (WRECKS)"
  std::string objectClass, lnam;
  std::optional<double> depthM;
};

class ChartGuard {
 public:
  virtual ~ChartGuard() = default;
  /// The look-ahead's paths against the charts.
  [[nodiscard]] virtual GroundingOutlook outlook(const nav::LookAheadPrediction& prediction,
                                                 const geo::LocalFrame& frame) const = 0;
  /// Whether a ship of the guard's draught at p is aground (charted depth below the draught, land, or
  /// a danger shallower than the draught under it); nullopt when it floats or no chart covers p.
  [[nodiscard]] virtual std::optional<Grounding> grounding(const geo::GeoPoint& p) const = 0;
};

}  // namespace reckoner::sim
