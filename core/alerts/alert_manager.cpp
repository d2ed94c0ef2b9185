#include "alerts/alert_manager.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace reckoner::alerts {

void validate(const AlertConfig& c) {
  const auto positive = [](double v, const char* field) {
    if (!std::isfinite(v) || v <= 0.0)
      throw std::invalid_argument(std::string("alerts: ") + field + " must be a finite number above 0");
  };
  positive(c.silenceS, "silence_s");
  positive(c.escalateAfterS, "escalate_after_s");
  if (c.historyLimit == 0) throw std::invalid_argument("alerts: history_limit must be at least 1");
}

AlertManager::AlertManager(AlertConfig config) : config_(config) {
  validate(config_);
}

void AlertManager::report(TimeUs now, AlertId id, bool holds, const std::string& text) {
  const auto it = alerts_.find(id);
  // Only what holds is remembered: a source that comes and goes (a track) leaves nothing behind.
  if (holds)
    holds_.insert(id);
  else
    holds_.erase(id);
  if (holds) {
    if (it == alerts_.end()) {
      raise(now, id, text);
      return;
    }
    Alert& a = it->second;
    if (!text.empty()) a.text = text;
    if (a.state == AlertState::Rectified) {  // the condition is back before anyone acknowledged it
      a.state = AlertState::Unacknowledged;
      a.changedUs = now;
      a.raisedUs = now;
      ++raised_[id.kind];
      log(AlertLogEntry::Event::Raised, now, a);
    }
    return;
  }
  if (it == alerts_.end() || it->second.state == AlertState::Rectified) return;
  rectify(now, it->second);
}

void AlertManager::raise(TimeUs now, AlertId id, const std::string& text) {
  Alert a;
  a.id = id;
  a.priority = traitsOf(id.kind).priority;
  a.state = AlertState::Unacknowledged;
  a.text = text;
  a.raisedUs = now;
  a.changedUs = now;
  ++raised_[id.kind];
  log(AlertLogEntry::Event::Raised, now, a);
  alerts_.emplace(id, std::move(a));
}

void AlertManager::rectify(TimeUs now, Alert& a) {
  const bool mustStay = traitsOf(a.id.kind).holdsUntilAcknowledged &&
                        (a.state == AlertState::Unacknowledged || a.state == AlertState::Silenced);
  if (!mustStay) {
    remove(now, a.id);
    return;
  }
  a.state = AlertState::Rectified;
  a.changedUs = now;
  log(AlertLogEntry::Event::Rectified, now, a);
}

void AlertManager::remove(TimeUs now, AlertId id) {
  const auto it = alerts_.find(id);
  if (it == alerts_.end()) return;
  log(AlertLogEntry::Event::Cleared, now, it->second);
  alerts_.erase(it);
}

void AlertManager::tick(TimeUs now) {
  const TimeUs escalateUs = fromSeconds(config_.escalateAfterS);
  for (auto& [id, a] : alerts_) {
    if (a.state == AlertState::Silenced && now >= a.silencedUntilUs) {
      a.state = AlertState::Unacknowledged;
      a.changedUs = now;
      log(AlertLogEntry::Event::Unsilenced, now, a);
    }
    const bool waiting = a.state == AlertState::Unacknowledged || a.state == AlertState::Silenced;
    if (waiting && a.priority == Priority::Warning && traitsOf(id.kind).escalates &&
        now - a.raisedUs >= escalateUs) {
      a.priority = Priority::Alarm;
      a.escalated = true;
      a.state = AlertState::Unacknowledged;  // an escalation is audible even if the warning was silenced
      a.changedUs = now;
      log(AlertLogEntry::Event::Escalated, now, a);
    }
  }
}

bool AlertManager::acknowledge(TimeUs now, AlertId id) {
  const auto it = alerts_.find(id);
  if (it == alerts_.end()) return false;
  Alert& a = it->second;
  if (a.priority == Priority::Caution || a.state == AlertState::Acknowledged) return false;
  log(AlertLogEntry::Event::Acknowledged, now, a);
  if (a.state == AlertState::Rectified || holds_.count(id) == 0) {
    remove(now, id);
    return true;
  }
  a.state = AlertState::Acknowledged;
  a.changedUs = now;
  return true;
}

bool AlertManager::silence(TimeUs now, AlertId id) {
  const auto it = alerts_.find(id);
  if (it == alerts_.end() || !it->second.audible()) return false;
  Alert& a = it->second;
  a.state = AlertState::Silenced;
  a.silencedUntilUs = now + fromSeconds(config_.silenceS);
  a.changedUs = now;
  log(AlertLogEntry::Event::Silenced, now, a);
  return true;
}

int AlertManager::silenceAll(TimeUs now) {
  std::vector<AlertId> loud;
  for (const auto& [id, a] : alerts_)
    if (a.audible()) loud.push_back(id);
  for (const AlertId& id : loud) silence(now, id);
  return static_cast<int>(loud.size());
}

std::vector<Alert> AlertManager::alerts() const {
  std::vector<Alert> out;
  out.reserve(alerts_.size());
  for (const auto& [id, a] : alerts_) out.push_back(a);
  const auto waiting = [](const Alert& a) { return a.state != AlertState::Acknowledged; };
  std::stable_sort(out.begin(), out.end(), [&](const Alert& a, const Alert& b) {
    if (a.priority != b.priority) return a.priority > b.priority;
    if (waiting(a) != waiting(b)) return waiting(a);
    return a.raisedUs > b.raisedUs;
  });
  return out;
}

const Alert* AlertManager::find(AlertId id) const {
  const auto it = alerts_.find(id);
  return it == alerts_.end() ? nullptr : &it->second;
}

bool AlertManager::audible() const {
  return std::any_of(alerts_.begin(), alerts_.end(), [](const auto& kv) { return kv.second.audible(); });
}

Priority AlertManager::audiblePriority() const {
  Priority p = Priority::Caution;
  for (const auto& [id, a] : alerts_)
    if (a.audible()) p = std::max(p, a.priority);
  return p;
}

std::vector<AlertLogEntry> AlertManager::takeLog() {
  std::vector<AlertLogEntry> out(untaken_.begin(), untaken_.end());
  untaken_.clear();
  return out;
}

int AlertManager::raisedCount(AlertKind kind) const {
  const auto it = raised_.find(kind);
  return it == raised_.end() ? 0 : it->second;
}

void AlertManager::log(AlertLogEntry::Event e, TimeUs now, const Alert& a) {
  untaken_.push_back({e, now, a.id, a.priority, a.text});
  if (untaken_.size() > config_.historyLimit) {  // nobody is taking the log: keep it bounded, count it
    untaken_.pop_front();
    ++dropped_;
  }
}

}  // namespace reckoner::alerts
