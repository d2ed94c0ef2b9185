#pragma once
// What a watch keeps of a live run besides its filters (docs/outputs.md, "Live input"): the alerts of
// the own-ship and radar-track frames (sim::AlertFeed, the simulation's conditions), the AIS target
// table with range, bearing, CPA and TCPA from own ship (track::AisTargetTable) and its alerts
// (alerts::AisAlertFeed), all under one alerts::AlertManager, so that reckoner-cli live and the
// window's Live mode raise the same alerts.
//
// Clocks: the AIS table runs on UTC (LiveAisMessage::utc, the own-ship stream's clock, else the
// receive clock); the alert manager on microseconds since the first time the watch saw (a frame or an
// AIS message), never going back. A time an hour or more behind the latest is another clock (AIS heard
// before a recording's first own-ship time was stamped by the receive clock): the AIS table starts
// again (counted) and the manager's clock goes on from where it was. Own ship is the DRKF's estimate of the
// latest frame while it is at most ownShipFreshS old; else the own ship that the AIS transponder reports in
// !xxVDO, when it has a position (a boat whose only position source on the bus is its AIS transponder). Plain
// C++; per-call work never throws.
#include <cstdint>
#include <optional>
#include <vector>

#include "alerts/ais_alert.h"
#include "alerts/alert_manager.h"
#include "geo/local_frame.h"
#include "sim/alert_feed.h"
#include "sim/live_session.h"
#include "tracking/ais_targets.h"

namespace reckoner::sim {

struct LiveWatchSettings {
  AlertFeedSettings alerts;   ///< own ship and radar tracks (CPA limits, DR limit, discrepancy)
  track::AisTableLimits ais;  ///< the AIS table; its CPA/TCPA limits also set the AIS CPA alert's
  /// The DRKF's estimate is own ship while its latest frame is at most this old (s, on the AIS clock).
  double ownShipFreshS = 10.0;
  /// The AIS table's range, bearing, CPA and lost states are brought up to date at most this often
  /// (s of the AIS clock; 0: at every call). The figure: 2000 targets with CPA every second.
  double aisUpdatePeriodS = 1.0;
};
/// Throws std::invalid_argument naming the field.
void validate(const LiveWatchSettings& s);

/// Where the watch's own ship came from at its latest update.
enum class LiveOwnShipSource : std::uint8_t { None, Drkf, AisVdo };

class LiveWatch {
 public:
  explicit LiveWatch(const LiveWatchSettings& settings = {});

  /// One frame of the session (LiveSession::takeFrames, in order) of a run that started at utc0 in the
  /// grid frame geo: its alert conditions, own ship for the AIS table, the AIS table's alerts.
  void frame(const SimFrame& f, UtcUs utc0, const geo::LocalFrame& geo);
  /// Decoded AIS messages (LiveSession::takeAisMessages), in arrival order.
  void ais(const std::vector<LiveAisMessage>& messages);
  /// Advances the AIS table and its alerts to utc without a frame (AIS alone, or own ship silent):
  /// targets become lost, CPA against the !xxVDO own ship. Times before the latest are ignored.
  void tick(UtcUs utc);
  /// What LiveSession produced since the last call: its frames and its AIS messages (taken from the
  /// session, absorbed and returned for whoever else reads them: the files, the window), then a tick
  /// at the session's clock now (receivedUtc: the receive clock).
  struct Taken {
    std::vector<SimFrame> frames;
    std::vector<LiveAisMessage> ais;
  };
  Taken absorb(LiveSession& session, std::optional<UtcUs> receivedUtc);

  // Operator actions (the window's).
  bool acknowledge(alerts::AlertId id) { return manager_.acknowledge(nowUs_, id); }
  int silenceAll() { return manager_.silenceAll(nowUs_); }
  bool activate(std::uint32_t mmsi, bool on) { return changed(table_.activate(mmsi, on)); }
  bool select(std::uint32_t mmsi) { return changed(table_.select(mmsi)); }
  /// New CPA/TCPA limits for radar tracks and AIS targets alike, from now on.
  void setCpaLimits(double cpaM, double tcpaS);
  void setDrLimit(double metres);

  [[nodiscard]] const alerts::AlertManager& alerts() const { return manager_; }
  alerts::AlertManager& alerts() { return manager_; }
  [[nodiscard]] const track::AisTargetTable& aisTable() const { return table_; }
  /// The alert manager's clock now (microseconds since the watch's zero) and its UTC.
  [[nodiscard]] TimeUs nowUs() const { return nowUs_; }
  [[nodiscard]] UtcUs nowUtc() const { return zeroUtc_.value_or(0) + nowUs_; }
  /// The UTC of the manager's zero (0 before the watch has seen a time).
  [[nodiscard]] UtcUs zeroUtc() const { return zeroUtc_.value_or(0); }
  [[nodiscard]] LiveOwnShipSource ownShipSource() const { return ownSource_; }
  /// The UTC the AIS table was last brought up to (0 before it was).
  [[nodiscard]] UtcUs aisUtc() const { return lastAisUpdate_.value_or(0); }
  /// Times the AIS table started again because the clock went back an hour or more (the receive
  /// clock of AIS heard before the own-ship stream's first time, giving way to the stream's).
  [[nodiscard]] long clockRebases() const { return clockRebases_; }
  /// Increases whenever the AIS table changes (a message, an update, an operator action).
  [[nodiscard]] std::uint64_t aisVersion() const { return aisVersion_; }
  [[nodiscard]] const LiveWatchSettings& settings() const { return settings_; }

 private:
  bool changed(bool yes) {
    if (yes) ++aisVersion_;
    return yes;
  }
  /// Times this far behind the latest are another clock (rebaseIfBehind).
  static constexpr TimeUs kClockRebaseUs = 3600 * kMicrosPerSecond;
  void rebaseIfBehind(UtcUs t);
  /// The manager's time of a UTC (and the watch's zero at its first call), never going back.
  TimeUs managerTime(UtcUs utc);
  /// The table brought to utc (at most every aisUpdatePeriodS unless forced) and its alerts reported.
  void updateAis(UtcUs utc, bool force);
  /// The !xxVDO own ship at t in vdoFrame_, while its reports are not older than its lost limit.
  [[nodiscard]] std::optional<track::AisOwnShip> vdoOwnShip(UtcUs t);

  LiveWatchSettings settings_;
  alerts::AlertManager manager_;
  AlertFeed feed_;
  track::AisTargetTable table_;
  alerts::AisAlertFeed aisFeed_;
  std::optional<UtcUs> zeroUtc_;
  TimeUs nowUs_ = 0;
  std::optional<UtcUs> aisUtc_;  ///< the AIS table's latest time
  std::optional<UtcUs> lastAisUpdate_;
  // Own ship of the latest frame: UTC, position, velocity over ground (grid) in its frame.
  std::optional<UtcUs> ownUtc_;
  track::AisOwnShip own_;
  std::optional<geo::LocalFrame> ownFrame_, vdoFrame_;
  LiveOwnShipSource ownSource_ = LiveOwnShipSource::None;
  std::uint64_t aisVersion_ = 0;
  long clockRebases_ = 0;
};

}  // namespace reckoner::sim
