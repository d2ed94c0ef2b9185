#pragma once
// The live connections (docs/connections.md): sources of NMEA 0183, AIS and radar plot lines (UDP,
// TCP, serial, gpsd, files), all in one I/O thread of the hub's own, so that the thread that owns the
// hub (the GUI thread, the CLI's main loop) never waits on a peer. Lines come out through a bounded
// queue (take()), each with its source, its receive time and a sequence number; every line that is not
// delivered is counted in its source's status, and the data monitor sees the raw lines in a bounded
// ring. Thread-safe: every public member may be called from the thread that owns the hub.
#include <QObject>
#include <QString>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/time.h"
#include "source_config.h"

class QThread;

namespace reckoner::conn {

using reckoner::UtcUs;

enum class State : std::uint8_t { Stopped, Connecting, Connected, WaitingRetry, Error, Finished, Disabled };
/// "stopped", "connecting", "connected", "waiting-retry", "error", "finished" (a file played to its
/// end), "disabled".
const char* stateName(State s);

struct ReceivedLine {
  std::string source;          ///< SourceConfig::name
  std::string line;            ///< without its terminator
  UtcUs receivedUtc = 0;       ///< the system clock (UTC microseconds) when the bytes were read
  std::uint64_t sequence = 0;  ///< hub-wide, increasing by one per line accepted into the queue
  Role role = Role::Nmea;
  int priority = 0;
};

struct SourceStatus {
  std::string name;
  Kind kind = Kind::Udp;
  Role role = Role::Nmea;
  State state = State::Stopped;
  double sentencesPerSecond = 0.0;   ///< lines delivered per second over the last second or more
  std::uint64_t lines = 0;           ///< delivered into the queue
  std::uint64_t bytes = 0;           ///< received
  std::uint64_t badChecksum = 0;     ///< sentences whose *hh does not match: not delivered
  std::uint64_t tooLong = 0;         ///< lines over the limit (framing)
  std::uint64_t binary = 0;          ///< lines with bytes no sentence has (framing)
  std::uint64_t partial = 0;         ///< half lines at a disconnect or the end of a file
  std::uint64_t filtered = 0;        ///< refused by the source's input filter (not errors)
  std::uint64_t dropped = 0;         ///< delivered but dropped from the full queue (the oldest go)
  std::uint64_t gpsdJson = 0;        ///< gpsd's JSON reports skipped (not errors)
  std::uint64_t connects = 0;        ///< times connected (opened, bound)
  std::size_t framerPeak = 0;        ///< the most bytes its framer ever held for one line (<= the limit)
  std::optional<UtcUs> lastSeenUtc;  ///< the last bytes received
  std::string lastError;             ///< the last error, with the peer or device named
  /// Lines lost to an error: bad checksum, too long, binary, partial, dropped.
  [[nodiscard]] std::uint64_t errors() const { return badChecksum + tooLong + binary + partial + dropped; }
};

/// What the hub did with a line the data monitor shows.
enum class Verdict : std::uint8_t { Delivered, Filtered, BadChecksum, GpsdJson };
const char* verdictName(Verdict v);

struct MonitorLine {
  std::string source;
  std::string line;
  UtcUs receivedUtc = 0;
  std::uint64_t index = 0;  ///< monitor-wide, increasing by one per line seen
  Verdict verdict = Verdict::Delivered;
};

struct MonitorFilter {
  std::string source;            ///< empty: every source
  std::string text;              ///< empty: every line; else lines that contain it
  std::uint64_t afterIndex = 0;  ///< only lines with a greater index (0: all kept)
};

struct HubOptions {
  std::size_t queueCapacity = 100'000;  ///< lines; ten seconds of a 10,000 sentence/s feed
  std::size_t monitorCapacity = 2'000;  ///< raw lines kept for the data monitor
  std::size_t maxLineLength = 1024;     ///< the framer's limit (io::LineFramer)
  int retryInitialMs = 1'000;           ///< first wait after a failure; doubles each failure
  int retryMaxMs = 30'000;              ///< the back-off's cap
  int connectTimeoutMs = 10'000;        ///< a TCP connect that has not completed is abandoned
};

struct HubCounters {
  std::size_t queued = 0, peakQueued = 0, capacity = 0;
  std::uint64_t dropped = 0;  ///< all sources
};

namespace detail {
class HubCore;
struct Slot;
}  // namespace detail

class ConnectionHub : public QObject {
  Q_OBJECT
 public:
  explicit ConnectionHub(QObject* parent = nullptr);
  explicit ConnectionHub(HubOptions options, QObject* parent = nullptr);
  ~ConnectionHub() override;
  ConnectionHub(const ConnectionHub&) = delete;
  ConnectionHub& operator=(const ConnectionHub&) = delete;

  /// Adds a source (started at once when the hub runs and the source is enabled). Throws
  /// std::invalid_argument when the name is empty or taken.
  void add(SourceConfig config);
  /// Stops and removes a source; false when there is none of that name.
  bool remove(const std::string& name);
  /// Enables (starts, when running) or disables (stops) a source; false when there is none.
  bool setEnabled(const std::string& name, bool enabled);
  /// Starts the I/O thread and every enabled source. Idempotent.
  void start();
  /// Stops every source (a half line each is counted as partial) and the I/O thread; waits for them
  /// (milliseconds: each source closes its socket, port or file). Lines already queued stay for take().
  void stop();
  [[nodiscard]] bool running() const;

  /// Up to max queued lines, oldest first; they leave the queue.
  std::vector<ReceivedLine> take(std::size_t max = std::numeric_limits<std::size_t>::max());
  [[nodiscard]] std::vector<SourceStatus> status() const;
  [[nodiscard]] std::vector<SourceConfig> sources() const;
  [[nodiscard]] HubCounters counters() const;
  /// The newest raw lines that pass filter, at most max, oldest first.
  [[nodiscard]] std::vector<MonitorLine> monitor(const MonitorFilter& filter = {},
                                                 std::size_t max = 500) const;
  [[nodiscard]] const HubOptions& options() const { return options_; }

 signals:
  /// Lines have arrived in an empty queue (once until the next take()); emitted from the I/O thread,
  /// so queued to receivers in other threads.
  void linesAvailable();
  /// A source's state changed (emitted from the I/O thread).
  void stateChanged(const QString& source);

 private:
  void startSource(const std::shared_ptr<detail::Slot>& slot);
  void stopSource(const std::shared_ptr<detail::Slot>& slot);

  HubOptions options_;
  std::unique_ptr<detail::HubCore> core_;
  QThread* thread_ = nullptr;
  QObject* io_ = nullptr;  ///< lives in thread_: sources are made, run and deleted through it
  std::vector<std::shared_ptr<detail::Slot>> slots_;
  bool running_ = false;
};

}  // namespace reckoner::conn
