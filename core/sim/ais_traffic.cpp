#include "sim/ais_traffic.h"

#include <algorithm>
#include <cmath>

namespace reckoner::sim {

sensors::AisHullState hullOf(const VesselTruth& v) {
  sensors::AisHullState h;
  h.timeUs = v.timeUs;
  h.position = v.position;
  h.vxMps = v.groundVxMps();
  h.vyMps = v.groundVyMps();
  h.headingRad = v.headingRad;
  // d/dt of the course atan2(vx, vy), clockwise positive (the water velocity turns the hull).
  const double v2 = v.waterVxMps * v.waterVxMps + v.waterVyMps * v.waterVyMps;
  h.turnRateRadPerS = v2 > 1e-6 ? (v.waterVyMps * v.accelXMps2 - v.waterVxMps * v.accelYMps2) / v2 : 0.0;
  return h;
}

AisTraffic::AisTraffic(const Scenario& scenario, std::uint64_t seed)
    : seed_(seed), fusion_(scenario.tracker.aisAssociation) {
  table_.setDangerLimits(std::max(scenario.tracker.dangerCpaM, 1.0),
                         std::max(scenario.tracker.dangerTcpaS, 1.0));
  for (std::size_t i = 0; i < scenario.targets.size(); ++i)
    addTarget(i, scenario.targets[i], scenario.targets[i].appearUs);
}

void AisTraffic::addTarget(std::size_t index, const TargetSpec& target, TimeUs startUs) {
  if (transmitters_.size() <= index) {
    transmitters_.resize(index + 1);
    leaveUs_.resize(index + 1);
  }
  leaveUs_[index] = target.leaveUs;
  if (!target.ais) return;
  transmitters_[index].emplace(*target.ais, target.id, Rng(seed_, kStreamAisBase + index), startUs);
  any_ = true;
}

AisCycle AisTraffic::step(TimeUs end, const std::vector<VesselMotionModel>& targets,
                          const std::vector<std::uint8_t>& present, const geo::LocalFrame& frame,
                          track::TrackManager& bank, const track::OwnShipInput& own) {
  AisCycle c;
  for (std::size_t i = 0; i < transmitters_.size() && i < targets.size(); ++i) {
    if (!transmitters_[i]) continue;
    if (i < present.size() && present[i])
      transmitters_[i]->advance(hullOf(targets[i].state()), frame, c.received);
    if (leaveUs_[i] && end >= *leaveUs_[i]) transmitters_[i].reset();  // gone for good: nothing in flight
  }
  std::stable_sort(c.received.begin(), c.received.end(),
                   [](const auto& a, const auto& b) { return a.rxUs < b.rxUs; });
  for (const auto& r : c.received) {
    table_.feed(r.message, r.rxUs);
    if (const track::AisTarget* t = table_.find(r.message.mmsi))
      fusion_.addReport(r.message, r.rxUs, t->info, frame);
  }
  const geo::GeoPoint ownGeo = frame.toGeodetic({own.x[0], own.x[1]});
  table_.update(end, frame, {ownGeo, own.x[2], own.x[3]});
  fusion_.update(end, bank, table_);
  c.targets = std::make_shared<const std::vector<track::AisTarget>>(table_.targets());
  c.associations = fusion_.associations();
  c.events = fusion_.takeEvents();
  return c;
}

std::size_t AisTraffic::transponders() const {
  return static_cast<std::size_t>(
      std::count_if(transmitters_.begin(), transmitters_.end(), [](const auto& t) { return t.has_value(); }));
}

}  // namespace reckoner::sim
