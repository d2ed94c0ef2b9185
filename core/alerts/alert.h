#pragma once
// Alerts as the IMO's bridge alert management (MSC.302(87)) defines them: a priority (alarm, warning,
// caution), a state (unacknowledged, silenced, acknowledged, rectified but unacknowledged), and an
// identity (the kind of condition and its source: a track, a zone, a sensor block). Plain values; the
// rules that move an alert between states are in alert_manager.h, the kinds' defaults in alert.cpp.
#include <cstdint>
#include <string>

#include "common/time.h"

namespace reckoner::alerts {

/// Highest last, so that a larger value is more urgent.
enum class Priority { Caution, Warning, Alarm };

/// The conditions Reckoner raises alerts for (docs/alerts.md).
enum class AlertKind {
  CpaTcpa,              ///< a target's CPA and TCPA under the operator's limits (with hysteresis)
  GuardZone,            ///< a new target inside a guard zone
  LostTarget,           ///< a confirmed radar track no longer updated
  LostAisTarget,        ///< an AIS target silent for longer than its reporting interval allows
  PositionSourceLost,   ///< no position fix: own ship is dead reckoning
  DeadReckoningLimit,   ///< the dead-reckoned position's 95% radius above the operator's limit
  PositionDiscrepancy,  ///< primary and secondary position sources further apart than a limit
  SensorNoise,          ///< a sensor's innovations larger than its configured noise explains
  Capacity,             ///< the tracker (source 0) or the AIS target table (source 1) near its capacity
  AisCpaTcpa,           ///< an AIS target's CPA and TCPA under the limits (source: its MMSI)
  SafetyContourAhead,   ///< own ship may cross the safety contour (or land, a prohibited area) within the
                        ///< look-ahead, with at least the alert probability
  DangerAhead,       ///< own ship may pass within the clearance of an isolated danger within the look-ahead
  Grounded,          ///< own ship is aground (the simulator's, on the charts' depths)
  OffTrack,          ///< the cross-track distance beyond the leg's limit (deviation from route)
  WaypointApproach,  ///< the wheel-over point of the next waypoint within the warning time (source: waypoint
                     ///< id)
  Arrival,           ///< own ship has arrived at the route's last waypoint
  DrFilterReset,     ///< the own-ship filter diverged and is restarted (or was) at a GNSS fix
  TrackFilterReset,  ///< a track's filter diverged and was restarted on a plot (source: track)
  AisDistress,       ///< an active AIS-SART, AIS-MOB or EPIRB-AIS heard (source: its MMSI)
};
inline constexpr int kAlertKindCount = 19;

/// Which condition, from which source (a track number, a zone index, a DRKF block; 0 when the kind has
/// one source only).
struct AlertId {
  AlertKind kind = AlertKind::CpaTcpa;
  int source = 0;
  friend bool operator==(const AlertId&, const AlertId&) = default;
  friend auto operator<=>(const AlertId&, const AlertId&) = default;
};

/// What every alert of a kind shares. Warnings escalate to alarms when escalates is set and they stay
/// unacknowledged. An unacknowledged alert whose condition ends stays (Rectified) until it is
/// acknowledged when holdsUntilAcknowledged is set: the alarms (except CPA/TCPA, for which
/// MSC.302(87) 7.3.7 lets the indication end with the condition) and the events an officer must not
/// miss even when they are over (a lost target, a new target in a guard zone).
struct AlertKindTraits {
  const char* name = "";  ///< short upper-case title: "CPA/TCPA"
  Priority priority = Priority::Warning;
  bool escalates = false;
  bool holdsUntilAcknowledged = false;
};
const AlertKindTraits& traitsOf(AlertKind kind);
const char* priorityName(Priority p);

enum class AlertState {
  Unacknowledged,  ///< active, audible (alarm and warning) and flashing
  Silenced,        ///< active, audible signal off until silencedUntilUs, still unacknowledged
  Acknowledged,    ///< active, steady; stays while the condition holds
  Rectified,       ///< condition gone but never acknowledged (holdsUntilAcknowledged kinds)
};
const char* stateName(AlertState s);

struct Alert {
  AlertId id;
  Priority priority = Priority::Warning;  ///< now (a warning escalated to alarm reads Alarm)
  AlertState state = AlertState::Unacknowledged;
  std::string text;            ///< the latest description the condition gave
  TimeUs raisedUs = 0;         ///< when the condition began (this occurrence)
  TimeUs changedUs = 0;        ///< the latest state or priority change
  TimeUs silencedUntilUs = 0;  ///< while Silenced
  bool escalated = false;
  /// Audible: an unacknowledged alarm or warning that is not silenced (cautions are never audible).
  [[nodiscard]] bool audible() const {
    return priority != Priority::Caution && state == AlertState::Unacknowledged;
  }
};

/// One line of the alert history (and of the log file).
struct AlertLogEntry {
  enum class Event { Raised, Escalated, Silenced, Unsilenced, Acknowledged, Rectified, Cleared };
  Event event = Event::Raised;
  TimeUs timeUs = 0;
  AlertId id;
  Priority priority = Priority::Warning;
  std::string text;
};
const char* eventName(AlertLogEntry::Event e);

}  // namespace reckoner::alerts
