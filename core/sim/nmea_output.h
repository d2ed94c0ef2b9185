#pragma once
// What Reckoner sends to other programs as NMEA 0183 (docs/outputs.md, "NMEA 0183 output"): own ship
// from the DRKF's estimate (RMC, GGA, VTG, HDT, GST; mode A and quality 1 while a position fix is
// recent, mode E and quality 6 while dead reckoning), the radar tracks (TTM and TLL per track, OSD),
// the alerts (ALR, ALF, ALC) and AIS lines passed through untouched. Fed with the rows the engine
// produces (run, replay or live), it returns the lines to send; io/nmea_out.h encodes them.
// Rate limits: own ship at most once per ownShipPeriodS of UTC, tracks once per sweep, each active
// alert on every change and again every alertRepeatS, the alert list (ALC) every alertRepeatS.
// Plain values; per-row calls never throw.
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "alerts/alert_manager.h"
#include "geo/local_frame.h"
#include "sim/alert_feed.h"
#include "sim/replay.h"
#include "sim/run_rows.h"
#include "sim/scenario.h"

namespace reckoner::sim {

/// Which alert sentences: ALR (the older, simple form), ALF with ALC (bridge alert management), or both.
enum class AlertSentences : std::uint8_t { Alr, AlfAlc, Both };

struct NmeaOutputOptions {
  std::string ownShipTalker = "IN";  ///< integrated navigation
  std::string radarTalker = "RA";    ///< radar / ARPA: TTM, TLL, OSD
  std::string alertTalker = "IN";
  bool ownShip = true, tracks = true, alerts = true;
  /// XTE, RMB and APB while a route is monitored (for an autopilot or a plotter), as often as own ship.
  bool route = true;
  std::string routeTalker = "EC";  ///< ECDIS
  bool ais = false;                ///< pass AIS lines through
  AlertSentences alertSentences = AlertSentences::Both;
  double ownShipPeriodS = 1.0;
  double alertRepeatS = 30.0;
};

/// Own ship as the sentences carry it: true directions, true metres (grid lengths divided by the
/// point scale), knots. NaN: not available (no HDT; OSD heading status V; no set and drift).
struct OwnShipFix {
  UtcUs utcUs = 0;
  double latDeg = 0, lonDeg = 0;
  double sogKn = 0, cogTrueDeg = 0;
  double headingTrueDeg = std::numeric_limits<double>::quiet_NaN();
  double varNorthM2 = 0, varEastM2 = 0, covNorthEastM2 = 0;
  double setTrueDeg = std::numeric_limits<double>::quiet_NaN();
  double driftKn = std::numeric_limits<double>::quiet_NaN();
  bool deadReckoning = false;
};
/// A run's row at utc (the run's UTC of the row's time).
OwnShipFix ownShipFixOf(const OwnShipRow& row, UtcUs utc, const geo::LocalFrame& frame);
/// A replay's (or live run's) row.
OwnShipFix ownShipFixOf(const ReplayOwnRow& row, const geo::LocalFrame& frame);

struct NmeaOutputCounters {
  long sentences = 0;         ///< lines returned (AIS included)
  long ownShipSkipped = 0;    ///< own-ship rows within ownShipPeriodS of the last one sent
  long sweepsSkipped = 0;     ///< sweeps given again (same time)
  long tracksUnnumbered = 0;  ///< track rows not sent: all 100 target numbers were in use
  long aisPassed = 0;
};

class NmeaOutput {
 public:
  explicit NmeaOutput(NmeaOutputOptions options = {});

  /// RMC, GGA, VTG, HDT (with a heading), GST; OSD too when tracks are on. Empty while rate limited.
  std::vector<std::string> ownShip(const OwnShipFix& fix);
  /// TTM and TLL of every track of one sweep at utc (the rows' time). Target numbers 00-99 follow
  /// the track ids: a track keeps its number while it is in the sweeps, a number freed by a track that
  /// is gone is given again only after the others (round robin).
  std::vector<std::string> sweep(UtcUs utc, std::span<const TrackRow> tracks);
  /// XTE, RMB and APB of the route monitoring's status at utc (nav::xteOf, rmbOf, apbOf): mode E while
  /// dead reckoning. Empty while rate limited (ownShipPeriodS) or with route off.
  std::vector<std::string> route(UtcUs utc, const nav::RouteStatus& status, const geo::Route& route,
                                 bool deadReckoning);
  /// The alerts shown now (alerts::AlertManager::alerts()) at run time `now` and UTC utc.
  std::vector<std::string> alerts(TimeUs now, UtcUs utc, const std::vector<alerts::Alert>& shown);
  /// An AIS line (!AIVDM, !AIVDO) as it came, without CR LF; nothing when AIS is off or it is not AIS.
  std::vector<std::string> ais(std::string_view line);

  /// The target number of a track id, while it has one.
  [[nodiscard]] std::optional<int> targetNumber(int trackId) const;
  [[nodiscard]] const NmeaOutputCounters& counters() const { return counters_; }
  [[nodiscard]] const NmeaOutputOptions& options() const { return options_; }

 private:
  struct Sent {
    alerts::AlertState state = alerts::AlertState::Unacknowledged;
    alerts::Priority priority = alerts::Priority::Warning;
    bool escalated = false;
    int revision = 1;
    TimeUs sentUs = 0;
    alerts::Alert last;
    int alrNumber = 0;  ///< ALR's alarm number, unique among the alerts sent (1-999)
    int instance = 0;   ///< ALF's and ALC's instance, unique among the alerts of its identifier
  };
  /// A new alert's ALR number and ALF instance, free among those sent (sent_ without it).
  void number(const alerts::AlertId& id, Sent& s) const;
  void emitAlert(std::vector<std::string>& out, const alerts::Alert& a, const Sent& s, UtcUs changedUtc,
                 bool cleared);
  int nextSequence() { return sequence_ = (sequence_ + 1) % 10; }
  std::vector<std::string>& counted(std::vector<std::string>& v) {
    counters_.sentences += static_cast<long>(v.size());
    return v;
  }

  NmeaOutputOptions options_;
  NmeaOutputCounters counters_;
  std::optional<UtcUs> lastOwnUtc_, lastSweepUtc_, lastRouteUtc_;
  std::map<int, int> numbers_;  ///< track id -> target number
  int nextNumber_ = 1;
  std::map<alerts::AlertId, Sent> sent_;
  std::optional<TimeUs> lastListUs_;
  int sequence_ = 9;
};

/// The NMEA output of a simulated run frame by frame: own ship and tracks from the rows, alerts from the
/// scenario's alert conditions (sim::AlertFeed into an alerts::AlertManager), stamped utc0 + frame time.
class RunNmeaOutput {
 public:
  RunNmeaOutput(const Scenario& scenario, UtcUs utc0, NmeaOutputOptions options = {});
  /// The lines of one frame, given its own-ship row and the track rows of the sweeps that ended in it.
  std::vector<std::string> frame(const SimFrame& f, const OwnShipRow& row, std::span<const TrackRow> tracks);
  [[nodiscard]] const NmeaOutput& output() const { return out_; }

 private:
  geo::LocalFrame geo_;
  UtcUs utc0_;
  NmeaOutput out_;
  AlertFeed feed_;
  alerts::AlertManager manager_;
  std::optional<geo::Route> route_;
};

/// The NMEA output of own-ship rows and the track rows (with their UTC) of the same stretch, the sweeps
/// in UTC order between the own-ship rows: a finished replay at once, or a live run batch by batch.
std::vector<std::string> rowsNmea(NmeaOutput& out, std::span<const ReplayOwnRow> own,
                                  std::span<const TrackRow> tracks, std::span<const UtcUs> trackUtc,
                                  const geo::LocalFrame& frame);
/// The NMEA output of a finished replay: own-ship rows and track sweeps in UTC order.
std::vector<std::string> replayNmea(const ReplayResult& r, NmeaOutputOptions options = {});

}  // namespace reckoner::sim
