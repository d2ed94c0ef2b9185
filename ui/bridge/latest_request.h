#pragma once
// "Latest request wins", the one rule of every background job in the window (chart renders, chart
// loads, scenario loads): the requesting thread numbers each request with issue(), and a newer number
// supersedes every older one. The worker skips a request that is no longer the latest when it comes
// to it (begin()), a long job polls cancelFlag() and stops when a newer request arrives, and the
// requester keeps only the answers that carry the latest number (isCurrent()). A worker answers its
// requests in the order they were queued, so once the latest request's answer has arrived no older
// answer can follow it. Thread-safe: the counter and the flag are atomics.
#include <QtGlobal>
#include <atomic>

namespace reckoner::ui {

class LatestRequest {
 public:
  /// Requesting side: the number of a new request (1, 2, ...). It supersedes every older request and
  /// raises the cancel flag, so a job in progress for an older one stops.
  quint64 issue() {
    const quint64 g = latest_.fetch_add(1) + 1;
    cancel_.store(true);
    return g;
  }
  /// The number of the latest request (0 before the first).
  [[nodiscard]] quint64 latest() const { return latest_.load(); }
  /// Whether request (or answer) g is the latest one.
  [[nodiscard]] bool isCurrent(quint64 g) const { return g == latest_.load(); }
  /// Worker side, when the job for request g starts: false if it has been superseded already (skip
  /// it), else true with the cancel flag lowered. (The flag is lowered before the check, so a request
  /// issued in between still cancels the job.)
  bool begin(quint64 g) {
    cancel_.store(false);
    return isCurrent(g);
  }
  /// The flag a long job polls (charts::ChartRenderer::render, charts::loadCharts): raised by issue().
  [[nodiscard]] const std::atomic<bool>* cancelFlag() const { return &cancel_; }

 private:
  std::atomic<quint64> latest_{0};
  std::atomic<bool> cancel_{false};
};

}  // namespace reckoner::ui
