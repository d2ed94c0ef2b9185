#pragma once
// Sources of one quantity in a recording (docs/outputs.md, "Replay: sources"). A source is a talker and
// a sentence ("GP:GGA", "HE:HDT", "HC:HDG"): two receivers are two sources, never fused as if their
// errors were independent. Each quantity has one active source at a time, chosen by a fixed priority
// like a type-approved radar's (THS, HDT, HDG, HDM, VHW for heading; GNS, GGA, RMC, GLL for position;
// RMC, VTG for velocity over ground; VBW, VHW for the log), and a sticky rule: the active source stays
// while it reports; when it has been silent for holdS, the best source that reports takes over; when a
// better source has reported continuously for holdS, it takes over again. A source of the same talker
// (the same instrument changing sentence: a log from bottom to water track, GGA to RMC) takes over at
// once.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "sim/stream_time.h"

namespace reckoner::sim::sources {

enum class Quantity : std::uint8_t { Position, Loran, Velocity, Heading, SpeedLog, Accuracy, Time, Other };
inline constexpr int kQuantityCount = 8;
const char* quantityName(Quantity q);

/// "GP:GGA": the talker and the sentence type.
using SourceId = std::string;

/// The quantity a sentence type gives and its rank within it (0 best); Other for what the filter does
/// not use (ROT, DTM).
struct Kind {
  Quantity quantity = Quantity::Other;
  int rank = 0;
};

/// One value offered by a source in an epoch; `index` points back to whatever the caller keeps.
struct Offer {
  SourceId source;
  Kind kind;
  std::size_t index = 0;
};

/// Chooses the active source of each quantity epoch by epoch.
class Selector {
 public:
  explicit Selector(std::int64_t holdUs) : holdUs_(holdUs) {}

  /// The offer to use at time t among those of one quantity (all of that quantity), or nullptr: the
  /// active source's first offer (sentences without a time of their own follow their epoch's stamp,
  /// so the first is the nearest to it). Epochs must come in time order.
  const Offer* choose(Quantity q, UtcUs t, const std::vector<const Offer*>& offers);

  /// The active source of q since the last choose() (empty when none).
  [[nodiscard]] const SourceId& active(Quantity q) const {
    return state_[static_cast<std::size_t>(q)].active;
  }

 private:
  struct Seen {
    UtcUs last = 0;   ///< last epoch it offered a value
    UtcUs since = 0;  ///< start of its current run of offers without a silence longer than hold
    int rank = 0;
    std::size_t order = 0;  ///< first-seen order (ties of rank)
  };
  struct State {
    SourceId active;
    std::map<SourceId, Seen> seen;
  };
  std::int64_t holdUs_;
  State state_[kQuantityCount];
  std::size_t order_ = 0;
};

/// Clock offset of a timed source against a reference source, from the order in which the file holds
/// them. A sentence stamped t arrived after the reference sentence before it (stamped p) and before
/// the one after it (n): its clock's offset lies in [t - n, t - p]. A source written in the same burst
/// as the reference (t - p or t - n near zero for most sentences: the same receiver) is synchronous and
/// its offset that small difference; otherwise the estimate is the middle of the intersection of those
/// intervals (their robust bounds), and its resolution half the intersection's width, at most half the
/// reference's interval (0.5 s for 1 Hz fixes).
struct ClockOffset {
  double offsetS = 0.0;      ///< estimated offset of the source's clock (positive: ahead)
  double resolutionS = 0.0;  ///< +- this
  long samples = 0;
};

/// Offsets of every timed source. `stamps` are (source, time) in file order; the reference is `ref`.
std::map<SourceId, ClockOffset> clockOffsets(const std::vector<std::pair<SourceId, UtcUs>>& stamps,
                                             const SourceId& ref);

}  // namespace reckoner::sim::sources
