#pragma once
// A live run: own-ship NMEA 0183 sentences as they arrive, through the replay's reader and engine
// (sim/replay.h), so that a recording fed sentence by sentence gives the replay's rows
// (docs/outputs.md, "Live"). What a file replay decides over the whole file, a live run decides as the
// data allow (sim/replay_stream.h): the rows of an epoch come out once the stream-time window after it
// has arrived.
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geo/local_frame.h"
#include "io/ais.h"
#include "sim/replay.h"
#include "sim/simulation_engine.h"

namespace reckoner::sim {

namespace replay_input {
class NmeaStream;
class PlotStream;
struct Epoch;
struct Plot;
}  // namespace replay_input
namespace replay_runner {
class Runner;
}

struct LiveOptions {
  ReplayOptions replay;
  std::string name = "live";  ///< names the stream in warnings
  /// Kept groups wait this long behind the newest time before they go to the filters (sentences out
  /// of order by more are skipped and counted as late).
  double reorderHorizonS = 0.0;
  /// A radar plot source is connected (radar CSV rows through radar()): the track bank runs.
  bool radar = false;
  /// Keep a SimFrame (without truth) of every own-ship epoch run, for takeFrames(): the alerts and the
  /// window read them. At most kMaxFrames are held; older ones are dropped (counted).
  bool frames = false;
};

/// An AIS message decoded from a live stream, with when and where it arrived.
struct LiveAisMessage {
  /// On the own-ship stream's clock (the latest timed sentence's UTC carried on by the receive clock)
  /// once there is one, else the receive time; 0 when neither is known.
  UtcUs utc = 0;
  bool ownShip = false;  ///< it came in a !xxVDO sentence
  std::string source;    ///< the connection's name
  io::AisMessage message;
};

class LiveSession {
 public:
  /// Throws io::InputError when the settings' tracker configuration is unusable.
  explicit LiveSession(LiveOptions options);
  ~LiveSession();
  LiveSession(const LiveSession&) = delete;
  LiveSession& operator=(const LiveSession&) = delete;

  /// One NMEA line as received (receivedUtc: the receive clock, when there is one). AIS sentences
  /// (!xxVDM, !xxVDO, after an optional tag block) go to the AIS decoder; the rest to own ship.
  void nmea(std::string_view line, std::optional<UtcUs> receivedUtc = std::nullopt,
            std::string_view source = {});
  /// One radar CSV row (or its header) as received. An own-ship epoch waits while a plot older than it
  /// is undecided (the stream-time window after it, or 10 s on the receive clock), so the bank gets the
  /// plots between two epochs before the second, as in a file replay.
  void radar(std::string_view line, std::optional<UtcUs> receivedUtc = std::nullopt);
  /// The end of the input: what is held is decided and run, the filters' counts closed.
  void finish();

  // Route monitoring and the anti-grounding look-ahead on the estimate of each frame (VoyageWatch's
  // observe(): frame.route, frame.lookAhead; with frames only), under the settings' voyage block
  // (replay.settings.voyage: its route is monitored from the start; a voyage a recording keeps).
  /// The route monitored from the next frame on (none: monitoring stops).
  void setRoute(const std::optional<geo::Route>& route) { voyage_.setRoute(route, false); }
  /// The charts' answers for the look-ahead (null: no look-ahead).
  void setChartGuard(std::shared_ptr<const ChartGuard> guard) { voyage_.setChartGuard(std::move(guard)); }
  [[nodiscard]] const VoyageWatch& voyage() const { return voyage_; }

  /// The filters have started (a position fix has arrived): origin and utc0 are set.
  [[nodiscard]] bool started() const { return runner_ != nullptr; }
  /// The run so far: rows (unless taken), stats, sources, counters, warnings.
  [[nodiscard]] const ReplayResult& result() const { return res_; }
  /// The own-ship rows since the last call (they leave result().own).
  std::vector<ReplayOwnRow> takeOwnRows();
  /// The track rows since the last call, with the UTC of each (they leave result().tracks).
  std::vector<TrackRow> takeTrackRows(std::vector<UtcUs>* utc = nullptr);
  /// The AIS messages decoded since the last call.
  std::vector<LiveAisMessage> takeAisMessages();
  /// With LiveOptions::frames: the frames of the epochs run since the last call, in time order.
  std::vector<SimFrame> takeFrames();
  static constexpr std::size_t kMaxFrames = 10000;
  /// Frames dropped because no one took them in time.
  [[nodiscard]] long framesDropped() const { return framesDropped_; }
  /// The grid frame of the run (origin of result()); only once started().
  [[nodiscard]] const geo::LocalFrame& frame() const { return *frame_; }
  /// The stream's clock at a receive time (LiveAisMessage::utc's rule); nullopt before any time.
  [[nodiscard]] std::optional<UtcUs> clockAt(std::optional<UtcUs> receivedUtc) const;
  /// What became of the AIS lines (decoded, rejected by reason, fragments).
  [[nodiscard]] const io::AisCounters& aisCounters() const { return ais_.counters(); }

 private:
  void run(const replay_input::Epoch& e);
  void drain(bool atEnd);
  void plot(const replay_input::Plot& p);
  void refreshSources();

  LiveOptions o_;
  ReplayResult res_;
  std::unique_ptr<replay_input::NmeaStream> stream_;
  std::unique_ptr<replay_input::PlotStream> plots_;
  std::unique_ptr<replay_runner::Runner> runner_;
  io::AisDecoder ais_;
  std::vector<LiveAisMessage> aisOut_;
  std::deque<SimFrame> frames_;
  VoyageWatch voyage_;
  long framesDropped_ = 0;
  std::optional<geo::LocalFrame> frame_;
  std::optional<UtcUs> receivedAtLastRun_;
  std::deque<replay_input::Epoch> waiting_;  ///< decided, waiting for older plots to be decided
  std::optional<UtcUs> lastRun_;
  bool anyEpoch_ = false, finished_ = false;
};

}  // namespace reckoner::sim
