#include "hub_core.h"

#include <algorithm>

namespace reckoner::conn::detail {

namespace {

int hexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

/// A sentence ending in *hh whose XOR of the characters between '$'/'!' and '*' is not hh. Sentences
/// without a checksum are left to the reader (it requires one where the standard does).
bool badChecksum(const std::string& line) {
  std::size_t start = 0;
  if (!line.empty() && line.front() == '\\') {
    const auto close = line.find('\\', 1);
    if (close == std::string::npos) return false;
    start = close + 1;
  }
  if (start >= line.size() || (line[start] != '$' && line[start] != '!')) return false;
  const auto star = line.rfind('*');
  if (star == std::string::npos || star < start || star + 3 != line.size()) return false;
  const int hi = hexValue(line[star + 1]), lo = hexValue(line[star + 2]);
  if (hi < 0 || lo < 0) return true;
  unsigned sum = 0;
  for (std::size_t i = start + 1; i < star; ++i) sum ^= static_cast<unsigned char>(line[i]);
  return sum != static_cast<unsigned>(hi * 16 + lo);
}

}  // namespace

UtcUs nowUtc() {
  return std::chrono::duration_cast<std::chrono::microseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

void HubCore::deliver(Slot& slot, const std::shared_ptr<Slot>& owner, std::vector<std::string>& lines,
                      UtcUs receivedUtc, const reckoner::io::LineFramerCounters& framing) {
  bool notify = false;
  {
    std::lock_guard lock(mutex_);
    SourceStatus& st = slot.status;
    st.bytes = framing.bytes;
    st.tooLong = framing.tooLong;
    st.binary = framing.binary;
    st.partial = framing.partial;
    st.framerPeak = framing.peakBuffered;
    if (framing.bytes > 0) st.lastSeenUtc = receivedUtc;
    std::string talker, type;
    for (std::string& l : lines) {
      Verdict v = Verdict::Delivered;
      if (slot.config.kind == Kind::Gpsd && l.front() == '{') {
        v = Verdict::GpsdJson;
        ++st.gpsdJson;
      } else if (slot.config.role == Role::Nmea) {
        if (badChecksum(l)) {
          v = Verdict::BadChecksum;
          ++st.badChecksum;
        } else if (!slot.config.filter.empty() && sentenceId(l, talker, type) &&
                   !slot.config.filter.accepts(talker, type)) {
          v = Verdict::Filtered;
          ++st.filtered;
        }
      }
      if (options_.monitorCapacity > 0) {
        if (monitor_.size() >= options_.monitorCapacity) monitor_.pop_front();
        monitor_.push_back(MonitorLine{slot.config.name, l, receivedUtc, ++monitorIndex_, v});
      }
      if (v != Verdict::Delivered) continue;
      // Full: the oldest line goes (the estimator wants the freshest data), counted on its source.
      if (queue_.size() >= std::max<std::size_t>(options_.queueCapacity, 1)) {
        ++queue_.front().slot->status.dropped;
        ++dropped_;
        queue_.pop_front();
      }
      if (queue_.empty() && !notified_) notify = notified_ = true;
      queue_.push_back(Queued{ReceivedLine{slot.config.name, std::move(l), receivedUtc, ++sequence_,
                                           slot.config.role, slot.config.priority},
                              owner});
      ++st.lines;
      ++slot.rateLines;
    }
    peak_ = std::max(peak_, queue_.size());
    const auto now = std::chrono::steady_clock::now();
    const double dt = std::chrono::duration<double>(now - slot.rateStart).count();
    if (dt >= 1.0) {
      st.sentencesPerSecond = static_cast<double>(slot.rateLines) / dt;
      slot.rateLines = 0;
      slot.rateStart = now;
    }
  }
  if (notify && notifyLines) notifyLines();
}

void HubCore::setState(Slot& slot, State state, const std::string& error) {
  bool changed = false;
  {
    std::lock_guard lock(mutex_);
    changed = slot.status.state != state;
    slot.status.state = state;
    if (!error.empty()) slot.status.lastError = error;
  }
  if (changed && notifyState) notifyState(slot.config.name);
}

void HubCore::noteConnected(Slot& slot) {
  {
    std::lock_guard lock(mutex_);
    ++slot.status.connects;
    slot.rateStart = std::chrono::steady_clock::now();
    slot.rateLines = 0;
  }
  setState(slot, State::Connected);
}

std::vector<ReceivedLine> HubCore::take(std::size_t max) {
  std::vector<ReceivedLine> out;
  std::lock_guard lock(mutex_);
  const std::size_t n = std::min(max, queue_.size());
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    out.push_back(std::move(queue_.front().line));
    queue_.pop_front();
  }
  notified_ = false;
  return out;
}

SourceStatus HubCore::status(const Slot& slot) const {
  std::lock_guard lock(mutex_);
  SourceStatus st = slot.status;
  // A source gone quiet: its rate decays over the time since the last window closed.
  const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - slot.rateStart).count();
  if (dt >= 2.0) st.sentencesPerSecond = static_cast<double>(slot.rateLines) / dt;
  return st;
}

HubCounters HubCore::counters() const {
  std::lock_guard lock(mutex_);
  return HubCounters{queue_.size(), peak_, options_.queueCapacity, dropped_};
}

std::vector<MonitorLine> HubCore::monitor(const MonitorFilter& filter, std::size_t max) const {
  std::vector<MonitorLine> out;
  std::lock_guard lock(mutex_);
  for (auto it = monitor_.rbegin(); it != monitor_.rend() && out.size() < max; ++it) {
    if (it->index <= filter.afterIndex) break;
    if (!filter.source.empty() && it->source != filter.source) continue;
    if (!filter.text.empty() && it->line.find(filter.text) == std::string::npos) continue;
    out.push_back(*it);
  }
  std::reverse(out.begin(), out.end());
  return out;
}

}  // namespace reckoner::conn::detail
