#pragma once
// The alert manager: every condition that can raise an alert reports whether it holds, the operator
// silences and acknowledges, and the manager moves each alert through the states of MSC.302(87)
// (docs/alerts.md):
//
//   condition holds           -> Unacknowledged (alarm, warning: audible; caution: shown only)
//   silence (alarm, warning)  -> Silenced for silenceS, then Unacknowledged again if still not acknowledged
//   acknowledge               -> Acknowledged while the condition holds; removed once it does not
//   condition rectified       -> unacknowledged, of a kind that holds until acknowledged: Rectified
//                                (shown, quiet, until acknowledged); otherwise removed
//   condition returns         -> a removed alert is raised anew; a Rectified one is Unacknowledged again
//   warning of an escalating kind unacknowledged for escalateAfterS -> escalated to an alarm
//
// Acknowledging never removes an alert whose condition still holds. Plain C++, deterministic in the
// times it is given; per-cycle calls never throw.
#include <cstddef>
#include <deque>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "alerts/alert.h"

namespace reckoner::alerts {

struct AlertConfig {
  double silenceS = 30.0;        ///< MSC.302(87) 7.3.5: the audible signal starts again after 30 s
  double escalateAfterS = 60.0;  ///< an escalating warning unacknowledged this long becomes an alarm
  /// Log entries kept for whoever writes the log when nobody takes them (oldest dropped first, counted).
  std::size_t historyLimit = 2000;
};
/// Throws std::invalid_argument naming the field when a time is not finite and positive or the
/// history limit is 0.
void validate(const AlertConfig& c);

class AlertManager {
 public:
  explicit AlertManager(AlertConfig config = {});

  /// Whether the condition `id` holds at `now`, with the text to show. A condition that is not reported
  /// keeps its last value. Raises, re-raises, rectifies or clears the alert; times must not decrease.
  void report(TimeUs now, AlertId id, bool holds, const std::string& text = {});
  /// Advances the timers to `now`: silences run out, escalating warnings become alarms.
  void tick(TimeUs now);

  /// Acknowledges one alarm or warning (false: no such alert, a caution, or already acknowledged).
  bool acknowledge(TimeUs now, AlertId id);
  /// Silences one unacknowledged alarm or warning for silenceS (false when there is nothing to silence).
  bool silence(TimeUs now, AlertId id);
  /// Silences every audible alert; returns how many.
  int silenceAll(TimeUs now);

  /// The alerts shown: highest priority first, then those needing acknowledgement, then newest first.
  [[nodiscard]] std::vector<Alert> alerts() const;
  [[nodiscard]] const Alert* find(AlertId id) const;
  /// True when some alarm or warning is unacknowledged and not silenced.
  [[nodiscard]] bool audible() const;
  /// The most urgent audible priority (meaningful when audible()).
  [[nodiscard]] Priority audiblePriority() const;

  /// Log entries since the previous call, oldest first (for a log file, the record and the window's
  /// history, which each keep what they need: the manager keeps none once taken).
  std::vector<AlertLogEntry> takeLog();
  /// Entries not taken yet (at most historyLimit).
  [[nodiscard]] std::size_t untakenLogEntries() const { return untaken_.size(); }
  /// Entries dropped from the untaken log (takeLog not called for historyLimit entries).
  [[nodiscard]] std::size_t droppedLogEntries() const { return dropped_; }
  /// How many times alerts of `kind` were raised (each occurrence, re-raises included).
  [[nodiscard]] int raisedCount(AlertKind kind) const;

  [[nodiscard]] const AlertConfig& config() const { return config_; }

 private:
  void raise(TimeUs now, AlertId id, const std::string& text);
  void rectify(TimeUs now, Alert& a);
  void remove(TimeUs now, AlertId id);
  void log(AlertLogEntry::Event e, TimeUs now, const Alert& a);

  AlertConfig config_;
  std::map<AlertId, Alert> alerts_;
  std::set<AlertId> holds_;  ///< the conditions that hold now
  std::deque<AlertLogEntry> untaken_;
  std::size_t dropped_ = 0;
  std::map<AlertKind, int> raised_;
};

}  // namespace reckoner::alerts
