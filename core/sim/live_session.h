#pragma once
// A live run: own-ship NMEA 0183 sentences as they arrive, through the replay's reader and engine
// (sim/replay.h), so that a recording fed sentence by sentence gives the replay's rows
// (docs/outputs.md, "Live"). What a file replay decides over the whole file, a live run decides as the
// data allow (sim/replay_stream.h): the rows of an epoch come out once the stream-time window after it
// has arrived.
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sim/replay.h"

namespace reckoner::sim {

namespace replay_input {
class NmeaStream;
struct Epoch;
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
};

class LiveSession {
 public:
  /// Throws io::InputError when the settings' tracker configuration is unusable.
  explicit LiveSession(LiveOptions options);
  ~LiveSession();
  LiveSession(const LiveSession&) = delete;
  LiveSession& operator=(const LiveSession&) = delete;

  /// One own-ship NMEA line as received (receivedUtc: the receive clock, when there is one).
  void nmea(std::string_view line, std::optional<UtcUs> receivedUtc = std::nullopt);
  /// The end of the input: what is held is decided and run, the filters' counts closed.
  void finish();

  /// The filters have started (a position fix has arrived): origin and utc0 are set.
  [[nodiscard]] bool started() const { return runner_ != nullptr; }
  /// The run so far: rows (unless taken), stats, sources, counters, warnings.
  [[nodiscard]] const ReplayResult& result() const { return res_; }
  /// The own-ship rows since the last call (they leave result().own).
  std::vector<ReplayOwnRow> takeOwnRows();

 private:
  void run(const replay_input::Epoch& e);
  void refreshSources();

  LiveOptions o_;
  ReplayResult res_;
  std::unique_ptr<replay_input::NmeaStream> stream_;
  std::unique_ptr<replay_runner::Runner> runner_;
  bool anyEpoch_ = false, finished_ = false;
};

}  // namespace reckoner::sim
