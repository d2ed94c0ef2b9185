#pragma once
// The alert conditions of a simulation, replay or live run, read from each SimFrame and reported to an
// alerts::AlertManager (docs/alerts.md), so that the window and the command line raise the same alerts:
//   CPA/TCPA            per confirmed track, with hysteresis (alerts::CpaAlertCondition)
//   LOST TARGET         per track while it is lost
//   GUARD ZONE          per track while it is a new (tentative, automatically acquired) track, when the
//                       tracker acquires in zones only
//   POSITION SOURCE LOST while own ship is dead reckoning (nav::DeadReckoningMonitor's rule)
//   DEAD RECKONING LIMIT while the 95% position radius is above the limit (when one is set)
//   SENSOR NOISE        per DRKF block while its NIS window is above its band
//   CAPACITY            while the track bank is at its warning level
#include <set>

#include "alerts/alert_manager.h"
#include "alerts/cpa_alert.h"
#include "sim/simulation_engine.h"

namespace reckoner::sim {

struct AlertFeedSettings {
  alerts::CpaAlertLimits cpa;
  double drLimitM = 0.0;    ///< the 95% radius above which DEAD RECKONING LIMIT holds; 0: no such alert
  bool guardZones = false;  ///< new tracks are guard-zone intrusions (the tracker acquires in zones)
};
/// Throws std::invalid_argument naming the field (the CPA limits', or dr_limit_m not finite and >= 0).
void validate(const AlertFeedSettings& s);

/// The settings a scenario implies: its tracker's CPA/TCPA limits and whether it acquires in zones.
AlertFeedSettings alertFeedSettingsFor(const Scenario& scenario);

class AlertFeed {
 public:
  explicit AlertFeed(AlertFeedSettings settings = {});

  /// Reports every condition of `f` to `m`, then advances m's timers to f.timeUs.
  void feed(const SimFrame& f, alerts::AlertManager& m);
  /// New limits from the next frame on (throws as validate does).
  void setSettings(const AlertFeedSettings& s);
  [[nodiscard]] const AlertFeedSettings& settings() const { return settings_; }

 private:
  void feedTracks(const SimFrame& f, alerts::AlertManager& m);
  void feedOwnShip(const SimFrame& f, alerts::AlertManager& m) const;

  AlertFeedSettings settings_;
  alerts::CpaAlertCondition cpa_;
  std::set<int> tracks_;  ///< the tracks of the previous frame
};

}  // namespace reckoner::sim
