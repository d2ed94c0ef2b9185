#pragma once
// The GUI thread's record of a run: every own-ship step and every track at every sweep end since the
// scenario was loaded, built from the LiveFrame batches; the latest frame; the alerts now (the
// worker's alerts::AlertManager decides them) and their history. The chart overlay, the target table,
// the plots and the alert list all read it.
#include <QString>
#include <deque>
#include <map>
#include <vector>

#include "ui/bridge/live_frame.h"

namespace reckoner::ui {

/// "ALARM  CPA/TCPA  track 5: CPA 0.42 NM in 6.5 min" and the like (for the list, banner and log).
QString alertTitle(const alerts::Alert& a);
QString alertLogLine(const alerts::AlertLogEntry& e);

class SimHistory {
 public:
  /// Entries of the alert history kept (older ones dropped).
  static constexpr std::size_t kAlertHistoryLimit = 2000;

  void clear();
  /// Appends a frame's batches and makes it the latest.
  void append(const LiveFrame& frame);

  [[nodiscard]] bool empty() const { return latest_.sequence == 0; }
  [[nodiscard]] const LiveFrame& latest() const { return latest_; }
  [[nodiscard]] const std::vector<OwnSample>& own() const { return own_; }
  /// Sweep-end samples of one track, oldest first (empty if unknown).
  [[nodiscard]] const std::vector<TrackSample>& track(int trackId) const;
  [[nodiscard]] const std::map<int, std::vector<TrackSample>>& tracks() const { return tracks_; }
  /// Every radar fix (matched picture) of the run, oldest first.
  [[nodiscard]] const std::vector<RadarFixSample>& radarFixes() const { return radarFixes_; }

  /// The alerts of the latest frame, most urgent first.
  [[nodiscard]] const std::vector<alerts::Alert>& alerts() const { return latest_.alerts; }
  [[nodiscard]] const alerts::Alert* alert(alerts::AlertId id) const;
  /// An alert of this id that still waits for acknowledgement (unacknowledged or silenced).
  [[nodiscard]] bool unacknowledged(alerts::AlertId id) const;
  /// The alert log of the run, oldest first (at most kAlertHistoryLimit entries).
  [[nodiscard]] const std::deque<alerts::AlertLogEntry>& alertHistory() const { return alertHistory_; }
  /// Alert log entries appended since clear(), dropped ones included.
  [[nodiscard]] std::uint64_t alertHistoryCount() const { return alertHistoryCount_; }

 private:
  LiveFrame latest_;
  std::vector<OwnSample> own_;
  std::map<int, std::vector<TrackSample>> tracks_;
  std::vector<RadarFixSample> radarFixes_;
  std::deque<alerts::AlertLogEntry> alertHistory_;
  std::uint64_t alertHistoryCount_ = 0;
};

}  // namespace reckoner::ui
