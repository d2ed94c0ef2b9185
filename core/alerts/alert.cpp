#include "alerts/alert.h"

#include <array>

namespace reckoner::alerts {

namespace {

// Priorities after the performance standards: the ECDIS's "positioning system failure" is an alarm
// (MSC.232(82) appendix 5), the radar's CPA/TCPA an alarm and lost target a warning (MSC.192(79)),
// capacity a caution; the route monitoring's crossing of the safety contour and deviation from route
// alarms, approach to a waypoint a warning (MSC.232(82) appendix 5). docs/alerts.md gives the reasons
// for the rest (the filter resets: warnings that wait for acknowledgement, like a lost target; an active
// AIS-SART, MOB or EPIRB-AIS: an alarm held until acknowledged, a distress no officer may miss).
constexpr std::array<AlertKindTraits, kAlertKindCount> kTraits{{
    {"CPA/TCPA", Priority::Alarm, false, false},
    {"GUARD ZONE", Priority::Warning, true, true},
    {"LOST TARGET", Priority::Warning, true, true},
    {"LOST AIS TARGET", Priority::Warning, true, true},
    {"POSITION SOURCE LOST", Priority::Alarm, false, true},
    {"DEAD RECKONING LIMIT", Priority::Warning, true, false},
    {"POSITION DISCREPANCY", Priority::Warning, true, false},
    {"SENSOR NOISE", Priority::Caution, false, false},
    {"CAPACITY", Priority::Caution, false, false},
    {"AIS CPA/TCPA", Priority::Alarm, false, false},
    {"SAFETY CONTOUR AHEAD", Priority::Alarm, false, false},
    {"DANGER AHEAD", Priority::Warning, true, false},
    {"GROUNDED", Priority::Alarm, false, true},
    {"OFF TRACK", Priority::Alarm, false, false},
    {"WAYPOINT APPROACH", Priority::Warning, false, true},
    {"ARRIVAL", Priority::Warning, false, true},
    {"DR FILTER RESET", Priority::Warning, false, true},
    {"TRACK FILTER RESET", Priority::Warning, false, true},
    {"AIS SART/MOB/EPIRB", Priority::Alarm, false, true},
}};

}  // namespace

const AlertKindTraits& traitsOf(AlertKind kind) {
  return kTraits.at(static_cast<std::size_t>(kind));
}

const char* priorityName(Priority p) {
  switch (p) {
    case Priority::Alarm:
      return "alarm";
    case Priority::Warning:
      return "warning";
    case Priority::Caution:
      return "caution";
  }
  return "?";
}

const char* stateName(AlertState s) {
  switch (s) {
    case AlertState::Unacknowledged:
      return "unacknowledged";
    case AlertState::Silenced:
      return "silenced";
    case AlertState::Acknowledged:
      return "acknowledged";
    case AlertState::Rectified:
      return "rectified";
  }
  return "?";
}

const char* eventName(AlertLogEntry::Event e) {
  using E = AlertLogEntry::Event;
  switch (e) {
    case E::Raised:
      return "raised";
    case E::Escalated:
      return "escalated";
    case E::Silenced:
      return "silenced";
    case E::Unsilenced:
      return "silence ended";
    case E::Acknowledged:
      return "acknowledged";
    case E::Rectified:
      return "rectified";
    case E::Cleared:
      return "cleared";
  }
  return "?";
}

}  // namespace reckoner::alerts
