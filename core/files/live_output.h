#pragma once
// The files of a live run (docs/outputs.md, "Live input"): ownship.csv and targets.csv in the replay's
// formats, ais.csv and alerts.csv, each written a row at a time as the run goes (flushed once per
// batch, so a killed run leaves whole rows up to its last batch), and summary.json when it ends.
#include <cstdio>
#include <span>
#include <string>
#include <vector>

#include "sim/live_session.h"
#include "sim/live_watch.h"

namespace reckoner::files {

/// The rows one append() wrote, for whatever else wants them (the NMEA output of reckoner-cli live).
struct LiveBatch {
  std::vector<sim::ReplayOwnRow> own;
  std::vector<sim::TrackRow> tracks;
  std::vector<UtcUs> trackUtc;                ///< per track row
  std::vector<alerts::AlertLogEntry> alerts;  ///< the watch's alert log entries written (alerts.csv)
  UtcUs alertZeroUtc = 0;                     ///< the watch's zero then: an entry's UTC is this + timeUs
  /// Route monitoring of each frame that had it (LiveOptions::voyage): its UTC, the status and whether
  /// own ship was dead reckoning then (the autopilot sentences' data valid flag). Filled by LiveRun.
  struct RouteRow {
    UtcUs utc = 0;
    nav::RouteStatus status;
    bool deadReckoning = false;
  };
  std::vector<RouteRow> route;
};

class LiveOutputWriter {
 public:
  /// Creates (truncates) dir/ownship.csv, dir/ais.csv, dir/alerts.csv and, with radar,
  /// dir/targets.csv. Throws io::InputError naming the file when one cannot be written.
  LiveOutputWriter(const std::string& dir, bool radar);
  ~LiveOutputWriter();
  LiveOutputWriter(const LiveOutputWriter&) = delete;
  LiveOutputWriter& operator=(const LiveOutputWriter&) = delete;

  /// Appends what the session produced since the last call (rows taken from it), the AIS messages
  /// decoded since (taken from the session by whoever else reads them) and the watch's alert log since,
  /// and flushes; returns the own-ship and track rows and the alert log entries written.
  LiveBatch append(sim::LiveSession& session, const std::vector<sim::LiveAisMessage>& ais,
                   sim::LiveWatch& watch);
  /// After session.finish() and the watch's last absorb: the last rows (returned), then summary.json
  /// (the replay's, with "ais" objects of the decoder's counts and the AIS table's, and "alerts").
  LiveBatch finish(sim::LiveSession& session, const std::vector<sim::LiveAisMessage>& ais,
                   sim::LiveWatch& watch, const std::string& inputName);

  [[nodiscard]] long ownRows() const { return ownRows_; }
  [[nodiscard]] long trackRows() const { return trackRows_; }
  [[nodiscard]] long aisRows() const { return aisRows_; }
  [[nodiscard]] long alertRows() const { return alertRows_; }
  [[nodiscard]] const std::string& dir() const { return dir_; }

 private:
  struct File {
    std::string path;
    std::FILE* f = nullptr;
  };
  static File open(const std::string& path, const std::string& header);
  static void put(File& file, const std::string& line);
  static void flush(File& file);

  std::string dir_;
  File own_, targets_, ais_, alerts_;
  long ownRows_ = 0, trackRows_ = 0, aisRows_ = 0, alertRows_ = 0;
  std::optional<TimeUs> firstOwn_, lastOwn_;
};

}  // namespace reckoner::files
