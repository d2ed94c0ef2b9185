#pragma once
// The hub's shared state (internal): the queue, the statuses and the monitor ring behind one mutex,
// written by the sources in the I/O thread and read by the hub's owner. Every lock is held for a
// copy or a push, never across I/O.
#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "connection_hub.h"
#include "io/line_framer.h"

class QObject;

namespace reckoner::conn::detail {

struct Slot {
  SourceConfig config;
  SourceStatus status;
  QObject* source = nullptr;  ///< the running source (owned by the I/O thread), or null
  std::chrono::steady_clock::time_point rateStart{};
  std::uint64_t rateLines = 0;
};

class HubCore {
 public:
  explicit HubCore(const HubOptions& options) : options_(options) {}
  std::function<void()> notifyLines;                    ///< called (unlocked) when the queue fills from empty
  std::function<void(const std::string&)> notifyState;  ///< called (unlocked) on a state change

  /// Classifies lines (checksum, filter, gpsd JSON), queues the deliverable ones, updates the status
  /// with the framer's counters.
  void deliver(Slot& slot, const std::shared_ptr<Slot>& owner, std::vector<std::string>& lines,
               UtcUs receivedUtc, const reckoner::io::LineFramerCounters& framing);
  void setState(Slot& slot, State state, const std::string& error = {});
  void noteConnected(Slot& slot);

  std::vector<ReceivedLine> take(std::size_t max);
  SourceStatus status(const Slot& slot) const;
  HubCounters counters() const;
  std::vector<MonitorLine> monitor(const MonitorFilter& filter, std::size_t max) const;

 private:
  struct Queued {
    ReceivedLine line;
    std::shared_ptr<Slot> slot;
  };
  HubOptions options_;
  mutable std::mutex mutex_;
  std::deque<Queued> queue_;
  std::deque<MonitorLine> monitor_;
  std::uint64_t sequence_ = 0, monitorIndex_ = 0, dropped_ = 0;
  std::size_t peak_ = 0;
  bool notified_ = false;
};

/// The system clock in UTC microseconds.
UtcUs nowUtc();

}  // namespace reckoner::conn::detail
