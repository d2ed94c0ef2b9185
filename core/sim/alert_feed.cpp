#include "sim/alert_feed.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <variant>

#include "estimation/models/drkf_state.h"
#include "navigation/dr_horizon.h"

namespace reckoner::sim {

using alerts::AlertId;
using alerts::AlertKind;

void validate(const AlertFeedSettings& s) {
  alerts::validate(s.cpa);
  if (!std::isfinite(s.drLimitM) || s.drLimitM < 0.0)
    throw std::invalid_argument("alerts: dr_limit_m must be a finite number of at least 0");
  if (!std::isfinite(s.positionDiscrepancyM) || s.positionDiscrepancyM < 0.0)
    throw std::invalid_argument("alerts: position_discrepancy_m must be a finite number of at least 0");
  if (!(s.groundingAlertProbability > 0.0 && s.groundingAlertProbability < 1.0))
    throw std::invalid_argument("alerts: the grounding alert probability must be in (0, 1)");
  if (!(s.groundingConfirmationS >= 0.0 && s.groundingConfirmationS <= 120.0))
    throw std::invalid_argument("alerts: the grounding alert's confirmation time must be in [0, 120] s");
}

AlertFeedSettings alertFeedSettingsFor(const Scenario& scenario) {
  AlertFeedSettings s;
  s.cpa.cpaM = scenario.tracker.dangerCpaM;
  s.cpa.tcpaS = scenario.tracker.dangerTcpaS;
  s.groundingAlertProbability = scenario.voyage.alertProbability;
  s.groundingConfirmationS = scenario.voyage.alertConfirmationS;
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

void AlertFeed::feed(const SimFrame& f, alerts::AlertManager& m, TimeUs clockOffsetUs) {
  offsetUs_ = clockOffsetUs;
  feedTracks(f, m);
  feedOwnShip(f, m);
  feedDiscrepancy(f, m);
  feedVoyage(f, m);
  distress_.report(m, f.timeUs + offsetUs_, f.aisTargets ? *f.aisTargets : std::vector<track::AisTarget>{});
  m.tick(f.timeUs + offsetUs_);
}

namespace {
std::string trackText(int trackId, const char* what) {
  std::string s = "track ";
  return s.append(std::to_string(trackId)).append(what);
}
}  // namespace

void AlertFeed::feedTracks(const SimFrame& f, alerts::AlertManager& m) {
  const TimeUs now = f.timeUs + offsetUs_;
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
    const bool intruder =
        settings_.guardZones && !f.zones.empty() && t.status == track::TrackStatus::Tentative && !t.manual;
    m.report(now, {AlertKind::CpaTcpa, t.trackId}, danger,
             danger ? alerts::cpaAlertText(t.trackId, cpa) : "");
    m.report(now, {AlertKind::LostTarget, t.trackId}, lost, lost ? trackText(t.trackId, " lost") : "");
    if (settings_.guardZones)
      m.report(now, {AlertKind::GuardZone, t.trackId}, intruder,
               intruder ? trackText(t.trackId, ": new target in a guard zone") : "");
  }
  // Filter resets are events: raised in their frame, ended in the next (they wait for acknowledgement).
  for (const int id : resetTracks_) m.report(now, {AlertKind::TrackFilterReset, id}, false);
  resetTracks_.clear();
  for (const track::TrackEvent& e : f.trackEvents) {
    if (e.kind != track::TrackEvent::Kind::FilterReset) continue;
    m.report(now, {AlertKind::TrackFilterReset, e.trackId}, true,
             trackText(e.trackId, ": filter restarted (") + est::divergenceReasonText(e.reason) + ")");
    resetTracks_.insert(e.trackId);
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
  const TimeUs now = f.timeUs + offsetUs_;
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
  // The DRKF's divergence guard: the condition holds while the filter is marked diverged and in the
  // frame of its restart; a frame without an epoch leaves it as it was.
  if (f.updates.empty()) return;
  est::DivergenceReason restarted = est::DivergenceReason::None;
  for (const nav::DrkfUpdateReport& u : f.updates)
    if (u.reset != est::DivergenceReason::None) restarted = u.reset;
  const est::DivergenceReason diverged = f.updates.back().diverged;
  std::string text;
  if (diverged != est::DivergenceReason::None)
    text = std::string("own-ship filter diverged (") + est::divergenceReasonText(diverged) +
           "): it restarts at the next GNSS fix";
  else if (restarted != est::DivergenceReason::None)
    text =
        std::string("own-ship filter restarted at a GNSS fix (") + est::divergenceReasonText(restarted) + ")";
  m.report(now, {AlertKind::DrFilterReset, 0}, !text.empty(), text);
}

void AlertFeed::feedDiscrepancy(const SimFrame& f, alerts::AlertManager& m) {
  for (const sensors::OwnShipSample& s : f.measurements) {
    if (const auto* g = std::get_if<sensors::GpsSample>(&s)) gps_ = Fix{g->timeUs, g->position};
    if (const auto* l = std::get_if<sensors::LoranSample>(&s)) loran_ = Fix{l->timeUs, l->position};
  }
  const double limit = settings_.positionDiscrepancyM;
  const auto fresh = [&](const std::optional<Fix>& x) {
    return x && toSeconds(f.timeUs - x->timeUs) <= kDiscrepancyFreshS;
  };
  double apartM = 0.0;
  const bool comparable = limit > 0.0 && fresh(gps_) && fresh(loran_);
  if (comparable) {
    // The GPS fix moved to the Loran-C fix's time along the estimated velocity over ground.
    const double dt = toSeconds(loran_->timeUs - gps_->timeUs);
    const auto& x = f.estimate.x;
    apartM = std::hypot(loran_->position.xM - (gps_->position.xM + est::drkf::groundVx(x) * dt),
                        loran_->position.yM - (gps_->position.yM + est::drkf::groundVy(x) * dt));
  }
  if (!comparable) {
    discrepant_ = false;
  } else if (apartM > limit) {
    discrepant_ = true;
    closeSinceUs_.reset();
  } else if (discrepant_ && apartM < kDiscrepancyClearFraction * limit) {
    if (!closeSinceUs_) closeSinceUs_ = f.timeUs;
    if (toSeconds(f.timeUs - *closeSinceUs_) >= kDiscrepancyClearAfterS) discrepant_ = false;
  } else {
    closeSinceUs_.reset();
  }
  if (!discrepant_) closeSinceUs_.reset();
  char text[96] = "";
  if (discrepant_)
    std::snprintf(text, sizeof text, "GPS and Loran-C %.0f m apart, limit %.0f m", apartM, limit);
  m.report(f.timeUs + offsetUs_, {AlertKind::PositionDiscrepancy, 0}, discrepant_, text);
}

void AlertFeed::feedVoyage(const SimFrame& f, alerts::AlertManager& m) {
  const TimeUs now = f.timeUs + offsetUs_;
  if (f.lookAhead && f.lookAhead->valid) {
    const GroundingOutlook& o = *f.lookAhead;
    const double p = settings_.groundingAlertProbability;
    char text[128];
    // confirmed by lasting, or at once when more likely than not (a turn towards the shallows)
    const auto confirmed = [&](double probability, std::optional<TimeUs>& since) {
      const bool above = probability >= p;
      if (!above) since.reset();
      if (above && !since) since = f.timeUs;
      return probability >= kGroundingImmediateProbability ||
             (above && toSeconds(f.timeUs - *since) >= settings_.groundingConfirmationS);
    };
    contourAhead_ = confirmed(o.crossingProbability, contourSinceUs_);
    std::snprintf(text, sizeof text,
                  "P %.0f%% of crossing the safety contour within %.0f min (median %.0f s)",
                  100.0 * o.crossingProbability, o.horizonS / 60.0, o.medianCrossingS);
    contourText_ = text;
    dangerAhead_ = confirmed(o.dangerProbability, dangerSinceUs_);
    std::snprintf(text, sizeof text, "P %.0f%% of passing a danger within %.0f min",
                  100.0 * o.dangerProbability, o.horizonS / 60.0);
    dangerText_ = text;
  }
  m.report(now, {AlertKind::SafetyContourAhead, 0}, contourAhead_, contourText_);
  m.report(now, {AlertKind::DangerAhead, 0}, dangerAhead_, dangerText_);
  if (f.grounded) groundedText_ = "aground on " + f.grounded->what;
  m.report(now, {AlertKind::Grounded, 0}, f.aground, groundedText_);
  // the route's conditions; approach and arrival are events: raised in their frame, ended in the next
  // (they stay until acknowledged)
  for (const int source : routeEvents_) {
    m.report(now, {source < 0 ? AlertKind::Arrival : AlertKind::WaypointApproach, std::max(source, 0)},
             false);
  }
  routeEvents_.clear();
  if (!f.route) {
    m.report(now, {AlertKind::OffTrack, 0}, false);
    return;
  }
  const nav::RouteStatus& r = *f.route;
  char text[128];
  std::snprintf(text, sizeof text, "cross-track %.0f m %s, limit %.0f m", std::abs(r.crossTrackM),
                r.side == nav::TrackSide::Port ? "port" : "starboard", r.crossTrackLimitM);
  m.report(now, {AlertKind::OffTrack, 0}, r.valid && r.offTrack, text);
  for (const nav::RouteEvent& e : r.events) {
    if (e.kind == nav::RouteEventKind::ApproachingWaypoint) {
      const int wp = static_cast<int>(e.waypoint);
      std::snprintf(text, sizeof text, "waypoint %d: wheel over in %.0f s", wp + 1, r.timeToWheelOverS);
      m.report(now, {AlertKind::WaypointApproach, wp}, true, text);
      routeEvents_.insert(wp);
    } else if (e.kind == nav::RouteEventKind::ArrivedFinal) {
      m.report(now, {AlertKind::Arrival, 0}, true, "arrived at the last waypoint");
      routeEvents_.insert(-1);
    }
  }
}

}  // namespace reckoner::sim
