#pragma once
// The GUI thread's record of a run: every own-ship step and every track at every sweep end since the
// scenario was loaded, built from the LiveFrame batches; the latest frame; and the alarms the operator
// has not yet acknowledged. The chart overlay, the target table and the plots all read it.
#include <QString>
#include <map>
#include <set>
#include <vector>

#include "ui/bridge/live_frame.h"

namespace reckoner::ui {

struct Alarm {
  /// SensorNoise: a DRKF block's windowed NIS above its band (SimFrame::noisierThanConfigured).
  enum class Kind { Dangerous, Lost, SensorNoise };
  Kind kind = Kind::Dangerous;
  int trackId = 0;  ///< SensorNoise: the nav::DrkfBlock
  double tS = 0.0;
  [[nodiscard]] QString text() const;
  friend bool operator<(const Alarm& a, const Alarm& b) {
    return a.kind != b.kind ? a.kind < b.kind : a.trackId < b.trackId;
  }
};

class SimHistory {
 public:
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

  [[nodiscard]] const std::set<Alarm>& alarms() const { return alarms_; }
  [[nodiscard]] bool unacknowledged(Alarm::Kind kind, int trackId) const;
  void acknowledgeAll() { alarms_.clear(); }

 private:
  LiveFrame latest_;
  std::vector<OwnSample> own_;
  std::map<int, std::vector<TrackSample>> tracks_;
  std::vector<RadarFixSample> radarFixes_;
  std::set<Alarm> alarms_;
  std::array<bool, nav::kDrkfBlockCount> noisy_{};  ///< the flags of the latest frame (rising edges alarm)
};

}  // namespace reckoner::ui
