#pragma once
// Replay of recorded data through the same filters as the simulator: own-ship NMEA 0183 sentences
// into the DRKF and radar plots (CSV) into the track manager (formats: docs/outputs.md). Bad lines are
// counted and skipped; only an unusable file as a whole (unreadable, no date, no position fix, a
// radar header that is not ours) is an error.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "navigation/drkf.h"
#include "sim/scenario.h"
#include "sim/scenario_run.h"
#include "tracking/track_manager.h"

namespace reckoner::sim {

/// UTC as microseconds since 1970-01-01T00:00:00Z.
using UtcUs = std::int64_t;
/// "2024-05-01T12:00:01.250Z" -> UTC; nullopt when malformed (Z required).
std::optional<UtcUs> parseIso8601(std::string_view s);
/// UTC -> "2024-05-01T12:00:01.250000Z".
std::string formatIso8601(UtcUs t);
/// Days since 1970-01-01 of a civil date.
std::int64_t daysFromCivil(int year, int month, int day);

struct ReplayOptions {
  Scenario settings;                ///< sensors (noise), filter, tracker, radar and origin
  bool originFromSettings = false;  ///< else the first position fix
  bool assumeAssociation = false;   ///< associate plots by their target_id (seed 000's mode)
};

struct ReplayStats {
  long nmeaLines = 0, sentencesUsed = 0, badChecksum = 0, unknownSentences = 0, malformed = 0;
  long untimed = 0;     ///< before any timed sentence
  long outOfOrder = 0;  ///< older than the epoch being assembled
  long unusable = 0;    ///< well formed but not usable (no fix, V status, velocity without position)
  long epochs = 0, epochsBeforeFix = 0;
  long radarLines = 0, radarPlots = 0, radarBad = 0, radarOutOfOrder = 0, radarBeforeFix = 0;
  [[nodiscard]] long nmeaSkipped() const {
    return badChecksum + unknownSentences + malformed + untimed + outOfOrder + unusable;
  }
};

struct ReplayOwnRow {
  TimeUs timeUs = 0;  ///< since the first NMEA timestamp
  UtcUs utcUs = 0;
  GroundEstimate estimate;
  std::string sensors;  ///< the sensors of the epoch's samples
  int rowsApplied = 0;
};

struct ReplayResult {
  geo::GeoPoint origin;
  UtcUs utc0 = 0;  ///< first NMEA timestamp
  std::vector<ReplayOwnRow> own;
  std::vector<TrackRow> tracks;    ///< hasTruth false; targetId: the plots' target_id, if given
  std::vector<UtcUs> trackRowUtc;  ///< utc of each track row
  ReplayStats stats;
  nav::DrkfCounters drkf;
  track::TrackCounters tracking;
};

/// Runs the replay. nmeaName and radarName are used in error messages. Throws io::InputError for an
/// unusable file.
ReplayResult replay(const std::string& nmeaText, const std::string& nmeaName, const std::string* radarCsv,
                    const std::string& radarName, const ReplayOptions& options);

}  // namespace reckoner::sim
