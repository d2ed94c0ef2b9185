#pragma once
// Internal to sim/: the engine of a replay (sim/replay.h) and of a live run (sim/live_session.h): the
// DRKF and the track bank driven through own-ship epochs and radar plots in time order, their rows and
// counts written into a ReplayResult. One engine, so a live run fed a recording gives the replay's rows.
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "estimation/nis_window.h"
#include "navigation/dead_reckoning_monitor.h"
#include "navigation/drkf.h"
#include "sim/replay.h"
#include "sim/replay_input.h"
#include "sim/simulation_engine.h"
#include "tracking/track_manager.h"

namespace reckoner::sim::replay_runner {

using replay_input::Epoch;
using replay_input::Plot;

/// The replay's grid frame: the settings' origin when asked for and the data lie within its reach,
/// else the first fix (with a warning naming the settings when they were asked for).
geo::GeoPoint chooseOrigin(const ReplayOptions& o, const Epoch& first, const std::string& nmeaName,
                           std::vector<std::string>& warnings);
/// The track manager's configuration of a replay (nearest-neighbour or known association).
track::TrackManagerConfig trackerConfigOf(const ReplayOptions& o);

/// Drives the DRKF and the track bank (with radar) through the epochs and plots in time order. res.origin
/// and res.utc0 must be set before; rows are appended to res.own and res.tracks.
class Runner {
 public:
  Runner(const ReplayOptions& o, ReplayResult& res, bool withRadar)
      : o_(o),
        res_(res),
        frame_(res.origin.latDeg, res.origin.lonDeg),
        config_(drkfConfigFor(o.settings)),
        sweepUs_(fromSeconds(o.settings.radar.sweepPeriodS)),
        maxGapUs_(fromSeconds(o.maxGapS)) {
    if (withRadar) bank_.emplace(trackerConfigOf(o));
  }

  void ownShip(const Epoch& e);
  void plot(const Plot& p);
  void finish();
  /// A live run's frames: after every own-ship epoch the DRKF ran, a SimFrame without truth (estimate,
  /// samples, update report, sensors heard, tracks, the sweeps closed and plots taken since the
  /// previous frame, track events, dead reckoning) goes to the sink. None without one.
  void setFrameSink(std::function<void(SimFrame&&)> sink) { sink_ = std::move(sink); }
  /// The DRKF now (null between a failure restart and the next fix).
  [[nodiscard]] const nav::Drkf* drkf() const { return drkf_ ? &*drkf_ : nullptr; }

 private:
  [[nodiscard]] TimeUs rel(UtcUs u) const { return u - res_.utc0; }
  /// Per-axis variance of the epoch's GNSS fix: the receiver's GST when it gave one, else the
  /// configured variance (that of a fix with HDOP 1) times HDOP squared (HDOP held to [0.5, 20]).
  [[nodiscard]] double gpsVarianceOf(const Epoch& e) const {
    if (e.gpsVarM2) return std::max(*e.gpsVarM2, 0.01);
    const double hdop = std::clamp(e.gpsHdop, 0.5, 20.0);
    return o_.settings.gps.positionVarM2 * hdop * hdop;
  }
  [[nodiscard]] std::optional<geo::GridPoint> inFrame(const std::optional<geo::GeoPoint>& p);
  void start(const Epoch& e, TimeUs t, const std::optional<geo::GridPoint>& gps,
             const std::optional<geo::GridPoint>& loran);
  void stop();
  void count(const nav::DrkfUpdateReport& rep, const std::vector<sensors::OwnShipSample>& samples);
  [[nodiscard]] track::OwnShipInput ownInput() const;
  void closeSweepsUntil(TimeUs t);
  void emitFrame(TimeUs t, std::vector<sensors::OwnShipSample>&& samples, const nav::DrkfUpdateReport& rep,
                 const nav::DeadReckoningStatus& dr);

  const ReplayOptions& o_;
  ReplayResult& res_;
  geo::LocalFrame frame_;
  nav::DrkfConfig config_;
  std::optional<nav::Drkf> drkf_;
  std::optional<track::TrackManager> bank_;
  TimeUs sweepUs_, maxGapUs_;
  std::optional<TimeUs> nextSweepEnd_, lastEpochUs_;
  nav::DrkfNisWindows nis_{};
  nav::DeadReckoningMonitor deadReckoning_;
  bool restarted_ = false;
  int failedEpochs_ = 0;
  // The frame sink and what its next frame carries besides the epoch.
  std::function<void(SimFrame&&)> sink_;
  std::vector<SweepSnapshot> sweeps_;
  std::vector<sensors::RadarPlot> plots_;
  std::array<std::optional<TimeUs>, sensors::kOwnShipSensorCount> lastSampleUs_{};
  sensors::SpeedlogMode logMode_ = sensors::SpeedlogMode::GroundLock;
};

}  // namespace reckoner::sim::replay_runner
