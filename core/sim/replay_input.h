#pragma once
// Reading replay inputs (sim/replay.h): NMEA 0183 sentences into own-ship epochs and radar CSV rows
// into plots, each in replay order by the stream-time policy (sim/stream_time.h). Internal to replay.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "geo/local_frame.h"
#include "sensors/own_ship_samples.h"
#include "sim/replay.h"

namespace reckoner::sim::replay_input {

/// One own-ship epoch being assembled from the sentences that share a timestamp.
struct Epoch {
  UtcUs utc = 0;
  std::optional<geo::GeoPoint> gps;
  std::optional<std::pair<double, double>> gpsVelocity;  ///< sog m/s, cog true rad
  std::optional<geo::GeoPoint> loran;
  std::optional<double> headingRad;
  std::optional<std::pair<double, sensors::SpeedlogMode>> log;  ///< m/s
  [[nodiscard]] bool empty() const { return !gps && !gpsVelocity && !loran && !headingRad && !log; }
  [[nodiscard]] bool hasFix() const { return gps || loran; }
};

struct Plot {
  UtcUs utc;
  double rangeM, bearingRad;
  int tag;
  friend bool operator==(const Plot&, const Plot&) = default;
};

/// The own-ship epochs of an NMEA file in replay order (empty epochs dropped). Counts into st; throws
/// io::InputError for a file with no sentence Reckoner reads or without a date.
std::vector<Epoch> readNmea(const std::string& text, const std::string& name, const StreamTimePolicy& policy,
                            ReplayStats& st);

/// The plots of a radar CSV in file order, exact repeats dropped (counted). Labels of target_id go to
/// `labels` (Plot::tag indexes it). Throws io::InputError for a bad header or a file whose every row is bad.
std::vector<Plot> readRadar(const std::string& text, const std::string& name, ReplayStats& st,
                            std::vector<std::string>& labels);

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
