#pragma once
// Reading replay inputs (sim/replay.h): NMEA 0183 sentences into own-ship epochs and radar CSV rows
// into plots, each in replay order by the stream-time policy (sim/stream_time.h). Internal to replay.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "geo/local_frame.h"
#include "io/iso8601.h"
#include "sensors/own_ship_samples.h"
#include "sim/replay.h"

namespace reckoner::sim::replay_input {

using io::kUsPerDay;

/// A line of a text file (CR LF or LF; a UTF-8 byte-order mark at the start dropped).
struct Line {
  int number;  ///< 1-based
  std::string_view text;
};
std::vector<Line> linesOf(std::string_view text);
/// A number with surrounding spaces allowed; nullopt unless the whole field is one finite number.
std::optional<double> toNumber(std::string_view field);
std::string_view trimmed(std::string_view field);

/// One own-ship epoch: what the active source of each quantity gave at one time (replay_sources.h).
struct Epoch {
  UtcUs utc = 0;
  std::optional<geo::GeoPoint> gps;
  std::optional<double> gpsVarM2;  ///< per axis, from the receiver's GST when it sent one
  double gpsHdop = 1.0;            ///< HDOP of the fix when given (1 otherwise)
  std::optional<std::pair<double, double>> gpsVelocity;  ///< sog m/s, cog true rad
  std::optional<geo::GeoPoint> loran;
  std::optional<double> headingRad;  ///< true
  bool headingMagnetic = false;      ///< from a magnetic compass (HDG, HDM, VHW's magnetic field)
  std::optional<std::pair<double, sensors::SpeedlogMode>> log;  ///< m/s
  /// No own-ship data: a time-only epoch (the recorder runs; the DRKF predicts, dead reckoning).
  [[nodiscard]] bool empty() const { return !gps && !gpsVelocity && !loran && !headingRad && !log; }
  [[nodiscard]] bool hasFix() const { return gps || loran; }
};

/// How an NMEA file is read (ReplayOptions gives them).
struct NmeaOptions {
  StreamTimePolicy time;
  std::optional<std::array<int, 3>> date;  ///< year, month, day for a log without dates
  std::optional<double> variationDeg;      ///< magnetic variation when the file gives none (east +)
  double holdS = 3.0;                      ///< replay_sources.h
  double clockCorrectionS = 1.0;           ///< a source's clock offset this large is corrected
};

struct Plot {
  UtcUs utc;
  double rangeM, bearingRad;
  int tag;
  friend bool operator==(const Plot&, const Plot&) = default;
};

/// The antenna's rotation period from the plots themselves: for each plot, the first later one within
/// 100 m and 1.5 degrees of it, 0.3 to 30 s on (the same echo one turn later); the median of those
/// intervals when there are at least 20 of them, else nullopt. Plots in time order.
std::optional<double> rotationPeriodS(const std::vector<Plot>& plots);

/// The own-ship epochs of an NMEA file in replay order (empty epochs dropped), each source's counts
/// and clock, and warnings. Counts into st; throws io::InputError for a file with no sentence Reckoner
/// reads or a datum other than WGS-84.
std::vector<Epoch> readNmea(const std::string& text, const std::string& name, const NmeaOptions& options,
                            ReplayStats& st, std::vector<SourceStats>& sources,
                            std::vector<std::string>& warnings);

/// The plots of a radar CSV in file order, exact repeats dropped (counted). Labels of target_id go to
/// `labels` (Plot::tag indexes it). Throws io::InputError for a bad header or a file whose every row is bad.
std::vector<Plot> readRadar(const std::string& text, const std::string& name, ReplayStats& st,
                            std::vector<std::string>& labels);

/// One data row of a radar CSV (no header): the plot, or nullopt with the field and reason in why.
/// Labels as readRadar gives them (tagOf: label to index).
std::optional<Plot> readRadarRow(std::string_view row, bool withId, std::vector<std::string>& labels,
                                 std::unordered_map<std::string, int>& tagOf, std::string& why);

/// Items in replay order by the stream-time policy (stream_time.h): isolated jumps dropped and
/// counted, the rest in stable time order.
template <class T, class TimeOf>
std::vector<T> inReplayOrder(std::vector<T> items, TimeOf timeOf, const StreamTimePolicy& policy, long& jumps,
                             long& reordered) {
  std::vector<UtcUs> times;
  times.reserve(items.size());
  for (const T& item : items) times.push_back(timeOf(item));
  const std::vector<char> drop = isolatedTimeJumps(times, policy);
  jumps += static_cast<long>(std::count(drop.begin(), drop.end(), 1));
  std::vector<T> out;
  out.reserve(items.size());
  for (const std::size_t i : replayOrder(times, drop, reordered)) out.push_back(std::move(items[i]));
  return out;
}

}  // namespace reckoner::sim::replay_input
