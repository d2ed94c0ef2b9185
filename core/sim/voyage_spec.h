#pragma once
// A run's voyage (docs/routes.md, docs/scenarios.md "voyage"): the route own ship follows or is
// monitored against, the ship's draught, the anti-grounding look-ahead and the alert probability. The
// charts themselves come from the program (charts/route/chart_safety.h through sim::ChartGuard): a
// run without charts monitors the route but has no look-ahead and never grounds.
#include <optional>
#include <string>
#include <vector>

#include "geo/route.h"
#include "navigation/look_ahead.h"
#include "navigation/route_monitor.h"

namespace reckoner::sim {

struct VoyageSpec {
  std::optional<geo::Route> route;  ///< the active route
  bool followRoute = false;         ///< own ship's autopilot steers along it (track control)
  nav::RouteMonitorSettings monitor;
  double draughtM = 5.0;               ///< own ship's draught: grounding and the safety depth's meaning
  double safetyContourM = 10.0;        ///< the look-ahead's safety contour
  std::optional<double> safetyDepthM;  ///< isolated dangers shallower than it; none: the contour
  double dangerClearanceM = 50.0;      ///< a path passing an isolated danger this close meets it
  double halfBeamM = 0.0;              ///< a path this close to an area meets it
  nav::LookAheadSettings lookAhead;
  double lookAheadPeriodS = 1.0;  ///< a look-ahead every this long (stream time)
  /// SAFETY CONTOUR AHEAD (and DANGER AHEAD) are raised once the probability of crossing within the
  /// look-ahead time plus the confirmation time has been at least alertProbability for the confirmation
  /// time (so the alert still comes a whole look-ahead time before the crossing, while a probability
  /// that flickers over the threshold with the velocity estimate's noise does not raise it), or at once
  /// when it is 50% or more.
  double alertProbability = 0.05;
  double alertConfirmationS = 60.0;
  /// The autopilot's cross-track law (nav::CrossTrackSteering): look-ahead distance, metres.
  double steeringLookaheadM = 463.0;
  /// What makes the voyage unusable, one line each naming the field (empty: none).
  [[nodiscard]] std::vector<std::string> problems() const;
};

}  // namespace reckoner::sim
