#include "ui/bridge/sim_history.h"

#include <algorithm>

namespace reckoner::ui {

QString Alarm::text() const {
  if (kind == Kind::SensorNoise)
    return QStringLiteral("SENSOR NOISE  %1 larger than configured")
        .arg(QString::fromLatin1(nav::blockName(static_cast<nav::DrkfBlock>(trackId))));
  const QString what =
      kind == Kind::Dangerous ? QStringLiteral("DANGEROUS TARGET") : QStringLiteral("LOST TARGET");
  return QStringLiteral("%1  track %2").arg(what).arg(trackId);
}

void SimHistory::clear() {
  latest_ = LiveFrame{};
  own_.clear();
  tracks_.clear();
  radarFixes_.clear();
  alarms_.clear();
  noisy_ = {};
}

void SimHistory::append(const LiveFrame& frame) {
  latest_ = frame;
  own_.insert(own_.end(), frame.ownHistory.begin(), frame.ownHistory.end());
  for (const TrackSample& s : frame.trackHistory) tracks_[s.trackId].push_back(s);
  radarFixes_.insert(radarFixes_.end(), frame.radarFixes.begin(), frame.radarFixes.end());
  const auto& noisy = frame.frame.noisierThanConfigured;
  for (std::size_t b = 0; b < noisy.size(); ++b) {
    if (noisy[b] && !noisy_[b])
      alarms_.insert({Alarm::Kind::SensorNoise, static_cast<int>(b), toSeconds(frame.frame.timeUs)});
    noisy_[b] = noisy[b];
  }
  for (const auto& e : frame.events) {
    using K = track::TrackEvent::Kind;
    const double t = toSeconds(e.timeUs);
    if (e.kind == K::Dangerous) alarms_.insert({Alarm::Kind::Dangerous, e.trackId, t});
    if (e.kind == K::Lost) alarms_.insert({Alarm::Kind::Lost, e.trackId, t});
    if (e.kind == K::Removed || e.kind == K::Cancelled || e.kind == K::Dropped) {
      alarms_.erase({Alarm::Kind::Dangerous, e.trackId, 0.0});
      alarms_.erase({Alarm::Kind::Lost, e.trackId, 0.0});
    }
  }
}

const std::vector<TrackSample>& SimHistory::track(int trackId) const {
  static const std::vector<TrackSample> kNone;
  const auto it = tracks_.find(trackId);
  return it == tracks_.end() ? kNone : it->second;
}

bool SimHistory::unacknowledged(Alarm::Kind kind, int trackId) const {
  return alarms_.count({kind, trackId, 0.0}) > 0;
}

}  // namespace reckoner::ui
