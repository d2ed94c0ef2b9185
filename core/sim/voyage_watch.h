#pragma once
// The voyage side of a run, once per output cycle (sim::SimulationEngine owns one): route monitoring
// on the DRKF's estimate (nav::RouteMonitor), the autopilot that follows the route (helm orders toward
// the heading to steer, corrected for the estimated current), the anti-grounding look-ahead against
// the charts (sim::ChartGuard), and grounding of the true ship on the charts' depths (it stops: an
// event and an alarm). Results go into the cycle's SimFrame.
#include <memory>
#include <optional>

#include "navigation/drkf.h"
#include "navigation/route_monitor.h"
#include "sim/chart_guard.h"
#include "sim/vessel_motion.h"
#include "sim/voyage_spec.h"

namespace reckoner::sim {

struct SimFrame;

class VoyageWatch {
 public:
  /// Throws std::invalid_argument for a voyage with problems().
  explicit VoyageWatch(const VoyageSpec& spec);

  void setChartGuard(std::shared_ptr<const ChartGuard> guard) { guard_ = std::move(guard); }
  [[nodiscard]] const ChartGuard* chartGuard() const { return guard_.get(); }
  /// A new active route (none: monitoring stops), and whether the autopilot follows it.
  void setRoute(const std::optional<geo::Route>& route, bool follow);
  [[nodiscard]] const VoyageSpec& spec() const { return spec_; }
  [[nodiscard]] bool aground() const { return aground_.has_value(); }

  /// The cycle ending at t: monitoring and the look-ahead on the filter, grounding and the autopilot on
  /// the true ship; fills frame.route, frame.lookAhead, frame.grounded, frame.aground.
  void step(TimeUs t, const nav::Drkf& filter, VesselMotionModel& truth, const geo::LocalFrame& frame,
            SimFrame& out);
  /// Monitoring and the look-ahead only (a live run: no truth, no autopilot).
  void observe(TimeUs t, const nav::Drkf& filter, SimFrame& out);

 private:
  void steer(TimeUs t, const nav::Drkf& filter, VesselMotionModel& truth, const geo::LocalFrame& frame,
             const nav::RouteStatus& status);

  VoyageSpec spec_;
  std::shared_ptr<const ChartGuard> guard_;
  std::optional<nav::RouteMonitor> monitor_;
  std::optional<TimeUs> lastLookAheadUs_;
  std::optional<Grounding> aground_;
  std::optional<HelmOrder> lastOrder_;
};

/// Own ship for the route monitor from a DRKF belief: position, SOG and COG (true), covariance.
nav::OwnShipFix ownShipFixOf(const nav::Drkf& filter);

}  // namespace reckoner::sim
