#pragma once
// The alert conditions of the AIS target table (docs/ais.md, "Alerts"): AIS CPA/TCPA (an alarm, with the
// hysteresis of cpa_alert.h, per MMSI) for each dangerous target, LOST AIS TARGET (a warning held until
// acknowledged) for each activated target that became lost, AIS SART/MOB/EPIRB (an alarm held until
// acknowledged, per MMSI) for each search and rescue device heard active and not lost, and CAPACITY
// (source 1, a caution) while the table is near its limits. Each report() gives the manager every
// condition that holds and ends those that held at the previous call and no longer do (a target removed
// from the table included).
#include <cstdint>
#include <set>
#include <vector>

#include "alerts/alert_manager.h"
#include "alerts/cpa_alert.h"
#include "tracking/ais_targets.h"

namespace reckoner::alerts {

/// The Capacity alert's source for the AIS table (0 is the radar tracker's).
inline constexpr int kAisCapacitySource = 1;

/// AIS SART/MOB/EPIRB alone: an alarm for each search and rescue device that is a distress and not lost
/// (track::AisTarget::distress), ended when it no longer is. A simulation reports it from its frames'
/// AIS targets (sim::AlertFeed): there the AIS stations' CPA and loss are their radar tracks' alerts.
class AisDistressFeed {
 public:
  /// Reports the targets' distresses at now and ends those of the previous call that are gone.
  void report(AlertManager& m, TimeUs now, const std::vector<track::AisTarget>& targets);

 private:
  std::set<int> held_;
};

class AisAlertFeed {
 public:
  /// The CPA limits of the AIS CPA/TCPA alert (the table's own limits decide the dangerous flag).
  explicit AisAlertFeed(CpaAlertLimits limits = {});
  /// Reports the table's conditions at now (times must not decrease).
  void report(AlertManager& m, TimeUs now, const track::AisTargetTable& table);
  /// New CPA limits from the next report(), keeping what is held (so that the next report ends the
  /// alerts that no longer hold: a new feed would not know them).
  void setLimits(CpaAlertLimits limits);

 private:
  CpaAlertCondition cpa_;
  AisDistressFeed distress_;
  std::set<int> cpaHeld_, lostHeld_;
};

}  // namespace reckoner::alerts
