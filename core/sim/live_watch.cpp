#include "sim/live_watch.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/angles.h"
#include "common/units.h"
#include "estimation/models/drkf_state.h"
#include "geo/geodesic.h"

namespace reckoner::sim {

void validate(const LiveWatchSettings& s) {
  validate(s.alerts);
  track::validate(s.ais);
  if (!(std::isfinite(s.ownShipFreshS) && s.ownShipFreshS > 0.0))
    throw std::invalid_argument("own_ship_fresh_s: must be finite and above 0");
  if (!(std::isfinite(s.aisUpdatePeriodS) && s.aisUpdatePeriodS >= 0.0))
    throw std::invalid_argument("ais_update_period_s: must be finite and at least 0");
}

namespace {
/// The !xxVDO own ship's grid frame is made again at its position when it has moved this far from it.
constexpr double kVdoFrameReachM = 100e3;

alerts::CpaAlertLimits aisCpaLimits(const LiveWatchSettings& s) {
  alerts::CpaAlertLimits l = s.alerts.cpa;
  l.cpaM = s.ais.cpaLimitM;
  l.tcpaS = s.ais.tcpaLimitS;
  return l;
}
}  // namespace

LiveWatch::LiveWatch(const LiveWatchSettings& settings)
    : settings_((validate(settings), settings)),
      feed_(settings.alerts),
      table_(settings.ais),
      aisFeed_(aisCpaLimits(settings)) {}

TimeUs LiveWatch::managerTime(UtcUs utc) {
  if (!zeroUtc_) zeroUtc_ = utc;
  if (utc - *zeroUtc_ < nowUs_ - kClockRebaseUs) zeroUtc_ = utc - nowUs_;  // another clock: go on from now
  nowUs_ = std::max(nowUs_, utc - *zeroUtc_);
  return nowUs_;
}

void LiveWatch::rebaseIfBehind(UtcUs t) {
  if (!aisUtc_ || t >= *aisUtc_ - kClockRebaseUs) return;
  // Times an hour or more behind the table's: the receive clock gave way to the stream's (a recording
  // whose AIS came before its first own-ship time). The table's times cannot be compared across the
  // two: it starts again, counted.
  track::AisTableLimits limits = settings_.ais;
  table_ = track::AisTargetTable(limits);
  aisUtc_.reset();
  lastAisUpdate_.reset();
  ++clockRebases_;
  changed(true);
}

void LiveWatch::frame(const SimFrame& f, UtcUs utc0, const geo::LocalFrame& geo) {
  const UtcUs utc = utc0 + f.timeUs;
  const TimeUs now = managerTime(utc);
  feed_.feed(f, manager_, now - f.timeUs);
  namespace dk = est::drkf;
  ownUtc_ = utc;
  own_.position = geo.toGeodetic({f.estimate.x[dk::kPosX], f.estimate.x[dk::kPosY]});
  own_.velEastMps = dk::groundVx(f.estimate.x);
  own_.velNorthMps = dk::groundVy(f.estimate.x);
  if (!ownFrame_ || ownFrame_->origin().latDeg != geo.origin().latDeg ||
      ownFrame_->origin().lonDeg != geo.origin().lonDeg)
    ownFrame_.emplace(geo.origin().latDeg, geo.origin().lonDeg);
  updateAis(utc, false);
}

void LiveWatch::ais(const std::vector<LiveAisMessage>& messages) {
  for (const LiveAisMessage& m : messages) {
    if (m.utc > 0) rebaseIfBehind(m.utc);
    UtcUs t = m.utc > 0 ? m.utc : aisUtc_.value_or(0);
    if (aisUtc_) t = std::max(t, *aisUtc_);  // the table's times never go back
    aisUtc_ = t;
    table_.feed(m.message, t, m.ownShip);
  }
  changed(!messages.empty());
}

void LiveWatch::tick(UtcUs utc) {
  // Nothing heard yet: no clock to advance (a receive-clock tick must not set the table's time before
  // the stream's first time is known).
  if (utc > 0 && aisUtc_) updateAis(utc, false);
}

LiveWatch::Taken LiveWatch::absorb(LiveSession& session, std::optional<UtcUs> receivedUtc) {
  Taken t{session.takeFrames(), session.takeAisMessages()};
  if (session.started())
    for (const SimFrame& f : t.frames) frame(f, session.result().utc0, session.frame());
  ais(t.ais);
  if (const std::optional<UtcUs> now = session.clockAt(receivedUtc)) tick(*now);
  return t;
}

void LiveWatch::setCpaLimits(double cpaM, double tcpaS) {
  AlertFeedSettings a = settings_.alerts;
  a.cpa.cpaM = cpaM;
  a.cpa.tcpaS = tcpaS;
  LiveWatchSettings s = settings_;
  s.alerts = a;
  s.ais.cpaLimitM = cpaM;
  s.ais.tcpaLimitS = tcpaS;
  validate(s);  // throws, changing nothing
  feed_.setSettings(a);
  table_.setDangerLimits(cpaM, tcpaS);
  aisFeed_.setLimits(aisCpaLimits(s));
  settings_ = s;
  updateAis(aisUtc_.value_or(0), true);
}

void LiveWatch::setDrLimit(double metres) {
  AlertFeedSettings a = settings_.alerts;
  a.drLimitM = metres;
  feed_.setSettings(a);  // throws, changing nothing
  settings_.alerts = a;
}

std::optional<track::AisOwnShip> LiveWatch::vdoOwnShip(UtcUs t) {
  const std::optional<track::AisTarget>& vdo = table_.ownShip();
  if (!vdo || !vdo->hasPosition() || toSeconds(t - vdo->lastPositionUs) > table_.lostAfterS(*vdo))
    return std::nullopt;
  const geo::GeoPoint p{*vdo->latDeg, *vdo->lonDeg};
  if (!vdoFrame_ || geo::rangeBearing(vdoFrame_->origin(), p).rangeM > kVdoFrameReachM)
    vdoFrame_.emplace(p.latDeg, p.lonDeg);
  track::AisOwnShip own;
  own.position = p;
  if (vdo->sogKn && vdo->cogDeg) {
    const double course = degToRad(*vdo->cogDeg) - vdoFrame_->gridInfo(vdoFrame_->toLocal(p)).convergenceRad;
    own.velEastMps = knotsToMps(*vdo->sogKn) * std::sin(course);
    own.velNorthMps = knotsToMps(*vdo->sogKn) * std::cos(course);
  }
  return own;
}

void LiveWatch::updateAis(UtcUs utc, bool force) {
  if (utc <= 0) return;
  rebaseIfBehind(utc);
  const UtcUs t = aisUtc_ ? std::max(*aisUtc_, utc) : utc;
  aisUtc_ = t;
  if (!force && lastAisUpdate_ && toSeconds(t - *lastAisUpdate_) < settings_.aisUpdatePeriodS) return;
  lastAisUpdate_ = t;
  if (ownUtc_ && toSeconds(t - *ownUtc_) <= settings_.ownShipFreshS) {
    // The DRKF's own ship, carried on to the table's time along its velocity over ground.
    const double dtS = toSeconds(t - *ownUtc_);
    geo::GridPoint g = ownFrame_->toLocal(own_.position);
    g.xM += own_.velEastMps * dtS;
    g.yM += own_.velNorthMps * dtS;
    track::AisOwnShip own = own_;
    own.position = ownFrame_->toGeodetic(g);
    table_.update(t, *ownFrame_, own);
    ownSource_ = LiveOwnShipSource::Drkf;
  } else if (const std::optional<track::AisOwnShip> vdo = vdoOwnShip(t)) {
    table_.update(t, *vdoFrame_, *vdo);
    ownSource_ = LiveOwnShipSource::AisVdo;
  } else {
    table_.update(t);
    ownSource_ = LiveOwnShipSource::None;
  }
  changed(true);
  const TimeUs now = managerTime(t);
  aisFeed_.report(manager_, now, table_);
  manager_.tick(now);
}

}  // namespace reckoner::sim
