#include "ui/bridge/sim_history.h"

#include <algorithm>

namespace reckoner::ui {

namespace {

QString clock(TimeUs t) {
  const long long s = std::max<long long>(0, static_cast<long long>(t / kMicrosPerSecond));
  return QStringLiteral("%1:%2:%3")
      .arg(s / 3600, 2, 10, QLatin1Char('0'))
      .arg(s / 60 % 60, 2, 10, QLatin1Char('0'))
      .arg(s % 60, 2, 10, QLatin1Char('0'));
}

}  // namespace

QString alertTitle(const alerts::Alert& a) {
  QString s = QString::fromLatin1(alerts::priorityName(a.priority)).toUpper();
  s += QStringLiteral("  ") + QString::fromLatin1(alerts::traitsOf(a.id.kind).name);
  if (!a.text.empty()) s += QStringLiteral("  ") + QString::fromStdString(a.text);
  return s;
}

QString alertLogLine(const alerts::AlertLogEntry& e) {
  return QStringLiteral("T+%1  %2  %3  %4%5")
      .arg(clock(e.timeUs), QString::fromLatin1(alerts::priorityName(e.priority)).toUpper(),
           QString::fromLatin1(alerts::traitsOf(e.id.kind).name),
           QString::fromLatin1(alerts::eventName(e.event)),
           e.text.empty() ? QString() : QStringLiteral(": ") + QString::fromStdString(e.text));
}

void SimHistory::clear() {
  latest_ = LiveFrame{};
  own_.clear();
  tracks_.clear();
  radarFixes_.clear();
  alertHistory_.clear();
  alertHistoryCount_ = 0;
}

void SimHistory::append(const LiveFrame& frame) {
  latest_ = frame;
  own_.insert(own_.end(), frame.ownHistory.begin(), frame.ownHistory.end());
  for (const TrackSample& s : frame.trackHistory) tracks_[s.trackId].push_back(s);
  radarFixes_.insert(radarFixes_.end(), frame.radarFixes.begin(), frame.radarFixes.end());
  alertHistory_.insert(alertHistory_.end(), frame.alertLog.begin(), frame.alertLog.end());
  alertHistoryCount_ += frame.alertLog.size();
  while (alertHistory_.size() > kAlertHistoryLimit) alertHistory_.pop_front();
}

const std::vector<TrackSample>& SimHistory::track(int trackId) const {
  static const std::vector<TrackSample> kNone;
  const auto it = tracks_.find(trackId);
  return it == tracks_.end() ? kNone : it->second;
}

const alerts::Alert* SimHistory::alert(alerts::AlertId id) const {
  const auto& list = latest_.alerts;
  const auto it = std::find_if(list.begin(), list.end(), [&](const alerts::Alert& a) { return a.id == id; });
  return it == list.end() ? nullptr : &*it;
}

bool SimHistory::unacknowledged(alerts::AlertId id) const {
  const alerts::Alert* a = alert(id);
  return a && (a->state == alerts::AlertState::Unacknowledged || a->state == alerts::AlertState::Silenced);
}

}  // namespace reckoner::ui
