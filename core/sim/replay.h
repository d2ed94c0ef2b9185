#pragma once
// Replay of recorded data through the same filters as the simulator: own-ship NMEA 0183 sentences
// into the DRKF and radar plots (CSV) into the track manager (formats: docs/outputs.md). Bad lines are
// counted and skipped; only an unusable file as a whole (unreadable, no date, no position fix, a
// radar header that is not ours, no usable plot) is an error. Time follows one policy for both
// streams (sim/stream_time.h): isolated clock jumps are dropped, the rest is replayed in time order,
// and after a gap longer than ReplayOptions::maxGapS the DRKF restarts at the next fix.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "estimation/nis_window.h"
#include "navigation/drkf.h"
#include "sim/scenario.h"
#include "sim/scenario_run.h"
#include "sim/sensor_profile.h"
#include "sim/stream_time.h"
#include "tracking/track_manager.h"

namespace reckoner::sim {

/// Speeds beyond this (over ground, through the water) are not a surface vessel's: the fastest craft
/// in service make 60-70 kn, so a field above it is a unit or transmission error, not data.
inline constexpr double kMaxPlausibleSpeedKn = 100.0;
/// Radar plots beyond this range are not a navigation radar's (their longest range scale is 96 NM).
inline constexpr double kMaxPlausiblePlotRangeM = 200.0 * 1852.0;

/// One source of a recording (replay_sources.h): a talker and a sentence type.
struct SourceStats {
  std::string source;    ///< "GP:GGA", "HC:HDG", ...
  std::string quantity;  ///< position, loran_c, velocity, heading, speed_log, accuracy, time, other
  long sentences = 0;
  long used = 0;      ///< what it gave went into the filter (or set the time)
  long standby = 0;   ///< valid, while another source of its quantity was active
  long repeated = 0;  ///< valid, but an earlier sentence of it gave the epoch's value
  long unusable = 0, notMeasured = 0, implausible = 0, timeJumps = 0;  ///< skipped, by reason
  double clockOffsetS = 0.0;  ///< against the reference (the best position source), positive: ahead
  double clockResolutionS = 0.0;
  bool clockCorrected = false;  ///< its times were shifted by the offset
  double activeS = 0.0;         ///< time it was the active source of its quantity
};

struct ReplayOptions {
  Scenario settings;                ///< sensors (noise), filter, tracker, radar and origin
  std::string settingsName;         ///< where the settings came from (error and warning lines)
  bool originFromSettings = false;  ///< else the first position fix
  bool assumeAssociation = false;   ///< associate plots by their target_id (seed 000's mode)
  /// No own-ship epoch for longer than this: the DRKF restarts at the next position fix (a recorder
  /// that stopped; the ship may be anywhere and its heading and speed anything).
  double maxGapS = 120.0;
  StreamTimePolicy time;
  std::optional<std::array<int, 3>> date;  ///< year, month, day for a log without dates (--date)
  std::optional<double> variationDeg;      ///< magnetic variation when the file gives none (--variation)
  double magneticHeadingSdDeg = 2.0;       ///< sd of a magnetic heading (HDG, HDM) after deviation
  double sourceHoldS = 3.0;                ///< a source silent this long loses its quantity
  /// The radar's sweep period is the antenna's rotation as the plots show it (replay_input::
  /// rotationPeriodS), when they show one, rather than settings.radar's.
  bool sweepFromPlots = false;
};

/// The options of a replay or live run of recorded data that has no settings of its own (the window's
/// Live mode, `replay` and `live` without --config): `defaults` (the built-in default scenario) with a
/// sensor profile (real sensors: the realistic one; the paper's figures are seed 000's Table I), the
/// radar assumed as assumeRadar() does, and the antenna's rotation taken from the plots.
ReplayOptions recordedDataOptions(Scenario defaults, SensorProfile profile = SensorProfile::Realistic);
/// Settings without a radar get the plot noise a replay assumes of one: 20 m in range, 0.5 deg in bearing.
void assumeRadar(Scenario& s);

/// Outcome of the DRKF updates of one sensor block over the replay (all restarts summed).
struct SensorUpdateCounts {
  long accepted = 0;  ///< applied (gated, or forced after a persistent rejection)
  long gated = 0;     ///< rejected by the chi-square gate
  long failed = 0;    ///< not applied for any other reason: not finite, numerical, not linearisable, stale
  /// Online consistency: NIS of the applied and gated updates in windows of 60 (est::NisWindow).
  est::NisWindowCounts nis;
};

struct ReplayStats {
  long nmeaLines = 0, sentencesUsed = 0, badChecksum = 0, unknownSentences = 0, proprietary = 0,
       malformed = 0;
  long comments = 0;      ///< lines starting with '#'
  long untimed = 0;       ///< before any timed sentence
  long timeJumps = 0;     ///< timed sentences stamped far from both neighbourhoods (stream_time.h)
  long reordered = 0;     ///< timed sentences older than one before them in the file (replayed in order)
  long unusable = 0;      ///< well formed but not usable (no fix, V status, velocity without position)
  long notGnss = 0;       ///< fixes whose quality or mode says estimated, manual, simulator or invalid
  long implausible = 0;   ///< sentences with a value beyond physical limits (kMaxPlausibleSpeedKn)
  long standby = 0;       ///< valid sentences of a source that was not the active one of its quantity
  long repeated = 0;      ///< valid, but their source gave the epoch's value already (a 10 Hz HDG in 1 s)
  long notUsed = 0;       ///< read but of no use to the filter (ROT, DTM of WGS-84, GST without its fix)
  long noVariation = 0;   ///< magnetic headings without a magnetic variation (file or --variation)
  long outsideFrame = 0;  ///< position fixes too far from the replay's origin for its grid frame (not used)
  long epochs = 0, epochsBeforeFix = 0;
  long epochsAwaitingFix = 0;  ///< after a restart, before the next position fix
  long epochsTimeOnly = 0;     ///< seconds with sentences but no own-ship data: dead-reckoning rows
  long radarLines = 0, radarPlots = 0, radarBad = 0, radarDuplicates = 0, radarTimeJumps = 0,
       radarReordered = 0, radarBeforeFix = 0;
  long radarLate = 0;  ///< live: plots decided after the epoch that followed them had run (skipped)
  long late = 0;  ///< live: sentences of a time older than an epoch already given to the filters (skipped)
  long restartsAfterGap = 0;      ///< DRKF restarted at a fix after more than maxGapS without data
  long restartsAfterFailure = 0;  ///< DRKF restarted after updates failed numerically epoch after epoch
  [[nodiscard]] long nmeaSkipped() const {
    return comments + badChecksum + unknownSentences + proprietary + malformed + untimed + timeJumps +
           unusable + notGnss + implausible + noVariation + late;
  }
};
/// The DRKF's current and sensor calibration estimates of one row (grid axes; sd the square roots of
/// the covariance diagonal). The calibration states are 0 with sd 0 when the profile does not model them.
struct CalibrationEstimate {
  double currentXMps = 0, currentYMps = 0, sdCurrentXMps = 0, sdCurrentYMps = 0;
  double headingBiasRad = 0, sdHeadingBiasRad = 0;
  double logScale = 0, sdLogScale = 0;
  double logOffsetMps = 0, sdLogOffsetMps = 0;
};

struct ReplayOwnRow {
  TimeUs timeUs = 0;  ///< since the first NMEA timestamp
  UtcUs utcUs = 0;
  GroundEstimate estimate;
  CalibrationEstimate calibration;
  std::string sensors;  ///< the sensors of the epoch's samples
  int rowsApplied = 0;
  bool deadReckoning = false;  ///< no recent position fix (nav::DeadReckoningMonitor's rule)
};

struct ReplayResult {
  geo::GeoPoint origin;
  UtcUs utc0 = 0;  ///< first NMEA timestamp
  std::vector<ReplayOwnRow> own;
  std::vector<TrackRow> tracks;      ///< hasTruth false; targetId: the plots' target_id, if given
  std::vector<UtcUs> trackRowUtc;    ///< utc of each track row
  std::vector<SourceStats> sources;  ///< every source of the NMEA file, in first-seen order
  /// The radar file's target_id labels; TrackRow::targetId indexes this (-1: none).
  std::vector<std::string> targetLabels;
  double sweepPeriodS = 0.0;    ///< the radar sweep period used (with a radar file)
  bool sweepFromPlots = false;  ///< ... found in the plots (ReplayOptions::sweepFromPlots)
  ReplayStats stats;
  nav::DrkfCounters drkf;                                          ///< summed over restarts
  std::array<SensorUpdateCounts, nav::kDrkfBlockCount> updates{};  ///< indexed by nav::DrkfBlock
  track::TrackCounters tracking;
  /// The adaptive GNSS noise's scale on R per grid axis at the end (empty: not adaptive).
  std::optional<std::array<double, 2>> gnssNoiseScale;
  /// One line each: what the replay changed or doubted (an origin far from the data, a file written out
  /// of time order, ...). The command line prints them as warnings.
  std::vector<std::string> warnings;
};

/// Runs the replay. nmeaName and radarName are used in error messages. Throws io::InputError for an
/// unusable file.
ReplayResult replay(const std::string& nmeaText, const std::string& nmeaName, const std::string* radarCsv,
                    const std::string& radarName, const ReplayOptions& options);

}  // namespace reckoner::sim
