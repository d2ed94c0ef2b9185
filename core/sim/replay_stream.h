#pragma once
// Internal to sim/: the NMEA reader of replay_input.h one line at a time, for a live run
// (sim/live_session.h). The same parsing, day placement, stream-time policy and epoch assembly as a
// file's (docs/outputs.md, "Live: time"), decided as soon as the data allow:
//  - times of day wait for the first dated sentence (or, after kMaxUndated sentences without one, the
//    day of the receive clock, --date, or 1970-01-01 with a warning);
//  - each timed sentence waits for the policy's window of timed sentences after it, then is kept or
//    dropped as an isolated jump exactly as in a file (stream_time.h, isolatedTimeJumpAt);
//  - kept groups wait in a reorder buffer until the newest kept time is reorderHorizonUs past theirs,
//    then go out in time order (a file replay sorts the whole file: the two agree unless a stretch is
//    more than the horizon out of order);
//  - a source's clock offset is not corrected (a file replay measures it over the whole file).
//  - an untimed sentence received a second or more after the last timed one (the GNSS out, heading and
//    log still reporting) is stamped by the receive clock carried on from that timed sentence, so dead
//    reckoning goes on (a file replay gives such sentences the last timed sentence's time);
// Memory is bounded: the window, the reorder buffer (its horizon), kMaxUndated sentences and kMaxGroup
// untimed sentences per time.
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "sim/replay_nmea_detail.h"

namespace reckoner::sim::replay_input {

class NmeaStream {
 public:
  /// Sentences held for a date before the times of day are placed without one.
  static constexpr std::size_t kMaxUndated = 600;
  /// Untimed sentences one time holds at most (more are counted untimed and skipped).
  static constexpr std::size_t kMaxGroup = 256;
  /// An untimed sentence received this long after the last timed one is stamped by the receive clock.
  static constexpr std::int64_t kUntimedAfterUs = 1'000'000;

  /// Counts go into st (which must outlive the stream).
  NmeaStream(const NmeaOptions& o, std::string name, std::int64_t reorderHorizonUs, ReplayStats& st);

  /// One line as received (receivedUtc: the receive clock, when there is one).
  void push(std::string_view line, std::optional<UtcUs> receivedUtc);
  /// The end of the stream: everything still held is decided.
  void finish();
  /// The epochs decided since the last call, in replay order.
  std::vector<Epoch> takeEpochs();

  /// Every source seen, in first-seen order.
  [[nodiscard]] std::vector<SourceStats> sources() const;
  /// The stream's clock at a receive time: the latest timed sentence's UTC, carried on by the receive
  /// clock since it arrived (when both have one); nullopt before the first timed sentence is placed.
  [[nodiscard]] std::optional<UtcUs> clockAt(std::optional<UtcUs> receivedUtc) const;
  std::vector<std::string>& warnings() { return warnings_; }

 private:
  struct Group {
    UtcUs utc = 0;
    std::vector<detail::Parsed> sentences;  ///< the timed one first, then its untimed followers
  };
  void place(detail::Parsed p, std::optional<UtcUs> receivedUtc);
  void startDays(std::optional<UtcUs> receivedUtc);
  void decide(bool atEnd);
  void keep(Group g);
  void release(bool atEnd);

  NmeaOptions o_;
  std::string name_;
  std::int64_t horizonUs_;
  ReplayStats& st_;
  std::map<sources::SourceId, SourceStats> stats_;
  std::vector<sources::SourceId> firstSeen_;
  std::vector<std::string> warnings_;
  int lineNumber_ = 0;
  bool dtmWarned_ = false;
  // Before the day is known.
  struct Held {
    detail::Parsed p;
    std::optional<UtcUs> received;
  };
  std::vector<Held> undated_;
  std::optional<UtcUs> lastTimedUtc_, lastTimedReceived_;
  std::optional<detail::DayPlacer> days_;
  // Timed groups awaiting their jump decision, and the times before them (the window).
  std::deque<Group> pending_;
  std::deque<UtcUs> decidedTimes_;
  std::vector<UtcUs> scratch_, span_;
  // Kept groups awaiting release; the newest kept time.
  std::vector<Group> kept_;
  std::optional<UtcUs> newestKept_, released_;
  detail::EpochAssembler assembler_;
  std::vector<Epoch> epochs_;
};

/// Radar CSV rows one line at a time (the header `utc,range_m,bearing_deg[,target_id]` may come
/// first, and again after a reconnection; without one, three or four fields as the row has). The same
/// rules as a file's: exact repeats (among the last kRecentPlots) counted once, the isolated-jump rule
/// decided once the window after a plot has arrived, or once a plot has waited kDecideAfterUs on the
/// receive clock (a sparse radar: then as at the end of a file). Decided plots wait in time order.
class PlotStream {
 public:
  static constexpr std::size_t kRecentPlots = 4096;
  static constexpr std::size_t kMaxLabels = 10000;
  static constexpr std::int64_t kDecideAfterUs = 10'000'000;

  PlotStream(const StreamTimePolicy& policy, ReplayStats& st, std::vector<std::string>& labels);
  void push(std::string_view line, std::optional<UtcUs> receivedUtc);
  /// Decides the plots received before now - kDecideAfterUs.
  void expire(UtcUs now);
  void finish();
  /// The oldest undecided plot's time: plots before it may still come out.
  [[nodiscard]] std::optional<UtcUs> undecidedFrom() const;
  /// The decided plots older than t (all with nullopt), in time order; they leave the stream.
  std::vector<Plot> take(std::optional<UtcUs> before);

 private:
  void decide(bool all, std::optional<UtcUs> receivedBefore);

  StreamTimePolicy policy_;
  ReplayStats& st_;
  std::vector<std::string>& labels_;
  std::unordered_map<std::string, int> tagOf_;
  std::optional<bool> withId_;
  std::deque<Plot> recent_;
  std::deque<std::pair<Plot, std::optional<UtcUs>>> pending_;  ///< with its receive time
  std::deque<UtcUs> decidedTimes_;
  std::vector<UtcUs> span_, scratch_;
  std::vector<Plot> ready_;  ///< in time order
  std::optional<UtcUs> newest_;
};

}  // namespace reckoner::sim::replay_input
