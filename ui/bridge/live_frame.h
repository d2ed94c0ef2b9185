#pragma once
// What the simulation worker sends to the GUI: one value per emitted frame (queued signal, at most one
// in flight). It carries the latest engine frame and, because frames are decimated at high rates, the
// compact history samples of every step and sweep since the previous emitted frame, so plots miss
// nothing. Plain values only: no pointers into the worker's state.
#include <QMetaType>
#include <QString>
#include <algorithm>
#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "alerts/alert.h"
#include "files/voyage_record.h"
#include "radar/land_mask.h"
#include "sim/live_watch.h"
#include "sim/scenario.h"
#include "sim/simulation_engine.h"
#include "sim/trial_manoeuvre.h"
#include "studies/own_ship_filters.h"
#include "tracking/ais_targets.h"
#include "ui/bridge/radar_raster.h"

namespace reckoner::ui {

/// Own ship at one output step: truth and DRKF estimate in the grid frame, with standard deviations
/// (sim::OwnShipRow and sim::OwnShipDetailRow as the plots take them).
struct OwnSample {
  double tS = 0.0;
  std::array<double, 2> truePos{}, estPos{};  ///< grid m
  std::array<double, 2> trueVel{}, estVel{};  ///< over ground, grid m/s
  std::array<double, 2> sdPos{}, sdVel{};
  std::array<double, 2> trueCurrent{}, estCurrent{};
  std::array<double, 2> trueLoran{}, estLoran{};  ///< Loran-C Gauss-Markov error, m
  std::array<double, 2> sdCurrent{}, sdLoran{};
  double trueLogBias = 0.0, estLogBias = 0.0;  ///< speedlog error, m/s
  double sdLogBias = 0.0;
  double nees = 0.0;      ///< the DRKF's NEES against the truth (ownship.csv's nees)
  double error95M = 0.0;  ///< semi-major axis of the 95% position ellipse
};

/// A track at the end of a sweep, with the truth of the target it follows (when it follows one), from its
/// sim::TrackRow.
struct TrackSample {
  double tS = 0.0;
  int trackId = 0;
  int targetId = -1;
  bool hasTruth = false;
  std::array<double, 2> estPos{}, estVel{}, sdPos{}, sdVel{};  ///< grid, target absolute
  std::array<double, 2> truePos{}, trueVel{};
  /// NEES of the target's position and velocity (4 dof), not targets.csv's 12-state nees
  /// (docs/outputs.md, "Two track NEES").
  double positionVelocityNees4 = 0.0;
  bool manoeuvring = false;  ///< input estimation's flag at this sweep end
};

/// A radar plot placed on the chart (relative to the estimated own-ship position, as a radar does).
struct ShownPlot {
  double tS = 0.0;
  double xM = 0.0, yM = 0.0;  ///< grid
  int sweep = 0;              ///< sweep counter (the display fades older sweeps)
};

struct LastFix {
  bool valid = false;
  double tS = 0.0;
  double xM = 0.0, yM = 0.0;
  bool accepted = false;
};

/// A radar picture matched to the chart (seed 004): the fix it gave against the truth at its time
/// (sim::RadarFixRow in degrees).
struct RadarFixSample {
  double tS = 0.0;
  bool informative = false, applied = false;
  int echoes = 0, used = 0;
  double x = 0.0, y = 0.0, headingDeg = 0.0;  ///< the fix: grid m and grid heading
  double sdX = 0.0, sdY = 0.0, sdHeadingDeg = 0.0;
  double trueX = 0.0, trueY = 0.0, trueHeadingDeg = 0.0;
  /// NEES (3 dof) of the fix less the part of its error the DRKF's motion error explains
  /// (RadarFixReport::motionSensitivity), i.e. of what its covariance claims.
  double nees = 0.0;
  double rmsResidual = 0.0;  ///< matched echoes off their contours, in their sd
  double nis = 0.0;          ///< the DRKF's update with it
  int dim = 0;
};

/// The echoes of the latest matched picture: as placed from the estimate, after the fix, and the chart
/// contour points they were matched to (grid m).
struct RadarMatchShown {
  double tS = 0.0;
  std::vector<est::Vec<2>> raw, corrected, chart;
};

/// The last update of one DRKF measurement block.
struct BlockStatus {
  bool seen = false;
  double tS = 0.0;
  double nis = 0.0;
  int dim = 0;
  bool accepted = false;
};

struct LiveFrame {
  quint64 sequence = 0;
  quint64 loadGeneration = 0;             ///< which load() the frame belongs to (older ones are dropped)
  sim::SimFrame frame;                    ///< the latest step (sweeps moved into trackHistory)
  std::vector<OwnSample> ownHistory;      ///< every step since the previous emitted frame
  std::vector<TrackSample> trackHistory;  ///< every track at every sweep end since then
  std::vector<ShownPlot> recentPlots;     ///< plots of the last few sweeps
  std::vector<track::TrackEvent> events;  ///< track events since the previous emitted frame
  /// The alerts now (alerts::AlertManager::alerts(): most urgent first) and the alert log entries since
  /// the previous emitted frame (docs/alerts.md).
  std::vector<alerts::Alert> alerts;
  std::vector<alerts::AlertLogEntry> alertLog;
  bool alertAudible = false;
  bool autoAcquire = true;              ///< the tracker acquires automatically (the operator's switch)
  std::array<LastFix, 2> lastFix{};     ///< GPS, Loran-C
  std::array<BlockStatus, 5> blocks{};  ///< per nav::DrkfBlock
  bool positionFixUsed = true;          ///< not frame.deadReckoning.active (a recent position fix)
  std::optional<double> drHorizonS;     ///< time until the 95% error exceeds the limit (DR only)
  double drLimitM = 0.0;
  double error95M = 0.0;
  /// Seed 002's own-ship filters beside the DRKF (geodetic KF, least squares): [x, y, vx, vy] over
  /// ground, grid frame, with covariance; empty before the first step.
  std::optional<std::array<est::Gaussian<4>, 2>> seed002;
  /// Radar overlay (seed 004): the latest picture as a raster (when pictures are wanted), the echoes
  /// of the latest match, every fix since the previous frame, the charted land (grid rings), and
  /// whether matching is on and the loaded charts give contours to match.
  std::shared_ptr<const RadarRaster> radarRaster;
  std::shared_ptr<const RadarMatchShown> radarMatch;
  std::vector<RadarFixSample> radarFixes;
  std::optional<RadarFixSample> lastRadarFix;  ///< the latest, kept across frames
  std::shared_ptr<const radar::LandMask> land;
  bool radarMatching = false;
  int chartContourSegments = 0;
  /// The voyage (sim/voyage_watch.h; frame.route holds the monitoring of the latest step): the route
  /// own ship is monitored against (null: none), whether the autopilot follows it, the latest
  /// anti-grounding look-ahead (null before the first, or without charts) and whether the ship is
  /// aground (and on what).
  std::shared_ptr<const geo::Route> route;
  bool followingRoute = false;
  std::shared_ptr<const sim::GroundingOutlook> lookAhead;
  std::optional<sim::Grounding> aground;
  double rate = 0.0;          ///< requested rate (0: paused, < 0: as fast as possible)
  double achievedRate = 0.0;  ///< simulated seconds per wall second, measured
  bool radarOn = false;
  track::TrackerKind trackerKind = track::TrackerKind::Ekf;  ///< the filter for new tracks, now
  bool running = false;
  bool finished = false;
  double durationS = 0.0;

  // Live mode (LiveWorker, docs/gui.md "Live"): the frames carry no truth (frame.hasTruth false).
  bool live = false;
  /// The live run's grid origin (its first position fix) and the UTC of its time zero.
  std::optional<geo::GeoPoint> liveOrigin;
  UtcUs liveUtc0 = 0;
  /// The AIS target table (shared, replaced when the table changed), its own ship from !xxVDO, its
  /// counts, the UTC its targets were last brought up to (the symbols are dead reckoned from there),
  /// and where the watch's own ship came from.
  std::shared_ptr<const std::vector<track::AisTarget>> aisTargets;
  std::optional<track::AisTarget> aisOwnShip;
  track::AisTableCounts aisCounts;
  UtcUs aisUtc = 0;
  sim::LiveOwnShipSource ownShipSource = sim::LiveOwnShipSource::None;
  /// The trial manoeuvre shown (sim/trial_manoeuvre.h; null when off), computed on this frame.
  std::shared_ptr<const sim::TrialResult> trial;
  /// Playback of a voyage record (LiveWorker::startPlayback): the record's file and span, the clock, its
  /// rate (0 paused, < 0 as fast as possible), whether all was played, and the record's alert log (the
  /// timeline's marks). None in a live run or a simulation.
  struct Playback {
    QString path;
    UtcUs first = 0, last = 0, clock = 0;  ///< receive times (the clock the batches are played to)
    /// The stream's UTC of the first and last own-ship estimate: the alerts' times are on this clock,
    /// placed on the receive clock by the line through the two spans (exact for a live run, 1:1 but for
    /// latency, and for a file played at a constant --file-rate).
    UtcUs streamFirst = 0, streamLast = 0;
    /// The receive time of a stream UTC (by the line above).
    [[nodiscard]] UtcUs receiveTimeOf(UtcUs stream) const {
      if (streamLast <= streamFirst) return std::clamp(stream, first, last);
      const double f =
          static_cast<double>(stream - streamFirst) / static_cast<double>(streamLast - streamFirst);
      return first + static_cast<UtcUs>(f * static_cast<double>(last - first));
    }
    double rate = 0.0;
    bool atEnd = false;
    std::shared_ptr<const std::vector<files::RecordedAlert>> alerts;
  };
  std::optional<Playback> playback;
  /// The first frame of a run started again (a playback's seek back): the window drops its history.
  bool restarted = false;
  /// Lines the live run has taken from the connections, and its session's counts.
  std::uint64_t liveLines = 0;
  long liveRows = 0;

  /// After a frame is sent: the batches since the previous frame are emptied, the state kept.
  void clearBatches() {
    ownHistory.clear();
    alertLog.clear();
    trackHistory.clear();
    events.clear();
    radarFixes.clear();
  }
};

}  // namespace reckoner::ui

Q_DECLARE_METATYPE(reckoner::ui::LiveFrame)
Q_DECLARE_METATYPE(reckoner::sim::Scenario)
