#include "sim/alert_feed.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "navigation/dr_horizon.h"

namespace reckoner::sim {

using alerts::AlertId;
using alerts::AlertKind;

void validate(const AlertFeedSettings& s) {
  alerts::validate(s.cpa);
  if (!std::isfinite(s.drLimitM) || s.drLimitM < 0.0)
    throw std::invalid_argument("alerts: dr_limit_m must be a finite number of at least 0");
}

AlertFeedSettings alertFeedSettingsFor(const Scenario& scenario) {
  AlertFeedSettings s;
  s.cpa.cpaM = scenario.tracker.dangerCpaM;
  s.cpa.tcpaS = scenario.tracker.dangerTcpaS;
  s.guardZones = !scenario.tracker.zones.empty();
  return s;
}

AlertFeed::AlertFeed(AlertFeedSettings settings) : settings_(settings), cpa_(settings.cpa) {
  validate(settings_);
}

void AlertFeed::setSettings(const AlertFeedSettings& s) {
  validate(s);
  settings_ = s;
  cpa_ = alerts::CpaAlertCondition(s.cpa);  // the hysteresis starts again under the new limits
}

void AlertFeed::feed(const SimFrame& f, alerts::AlertManager& m) {
  feedTracks(f, m);
  feedOwnShip(f, m);
  m.tick(f.timeUs);
}

namespace {
std::string trackText(int trackId, const char* what) {
  std::string s = "track ";
  return s.append(std::to_string(trackId)).append(what);
}
}  // namespace

void AlertFeed::feedTracks(const SimFrame& f, alerts::AlertManager& m) {
  const TimeUs now = f.timeUs;
  std::set<int> present;
  for (const TrackSnapshot& t : f.tracks) {
    present.insert(t.trackId);
    const track::Cpa& cpa = t.kinematics.cpa;
    bool danger = false;
    if (t.status == track::TrackStatus::Confirmed)
      danger = cpa_.update(t.trackId, now, cpa);
    else
      cpa_.forget(t.trackId);
    // Texts only for conditions that hold (the manager ignores the text of one that does not): this
    // runs for every track at every step.
    const bool lost = t.status == track::TrackStatus::Lost;
    const bool intruder = settings_.guardZones && t.status == track::TrackStatus::Tentative && !t.manual;
    m.report(now, {AlertKind::CpaTcpa, t.trackId}, danger,
             danger ? alerts::cpaAlertText(t.trackId, cpa) : "");
    m.report(now, {AlertKind::LostTarget, t.trackId}, lost, lost ? trackText(t.trackId, " lost") : "");
    if (settings_.guardZones)
      m.report(now, {AlertKind::GuardZone, t.trackId}, intruder,
               intruder ? trackText(t.trackId, ": new target in a guard zone") : "");
  }
  for (const int gone : tracks_) {
    if (present.count(gone) != 0) continue;
    cpa_.forget(gone);
    for (const AlertKind k : {AlertKind::CpaTcpa, AlertKind::LostTarget, AlertKind::GuardZone})
      m.report(now, {k, gone}, false);
  }
  tracks_ = std::move(present);
}

void AlertFeed::feedOwnShip(const SimFrame& f, alerts::AlertManager& m) const {
  const TimeUs now = f.timeUs;
  m.report(now, {AlertKind::PositionSourceLost, 0}, f.deadReckoning.active,
           "no position fix: dead reckoning");
  if (settings_.drLimitM > 0.0) {
    const double e95 = nav::positionError95M(f.estimate);
    const bool above = e95 > settings_.drLimitM;
    char text[96] = "";
    if (above)
      std::snprintf(text, sizeof text, "95%% position error %.0f m, limit %.0f m", e95, settings_.drLimitM);
    m.report(now, {AlertKind::DeadReckoningLimit, 0}, above, text);
  } else {
    m.report(now, {AlertKind::DeadReckoningLimit, 0}, false);
  }
  for (int b = 0; b < nav::kDrkfBlockCount; ++b) {
    const bool noisy = f.noisierThanConfigured[static_cast<std::size_t>(b)];
    m.report(
        now, {AlertKind::SensorNoise, b}, noisy,
        noisy ? std::string(nav::blockName(static_cast<nav::DrkfBlock>(b))) + " larger than configured" : "");
  }
  m.report(now, {AlertKind::Capacity, 0}, f.capacityWarning, "track capacity near its limit");
}

}  // namespace reckoner::sim
