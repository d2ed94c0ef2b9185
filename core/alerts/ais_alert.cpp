#include "alerts/ais_alert.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "common/angles.h"
#include "common/units.h"

namespace reckoner::alerts {

namespace {
std::string targetName(const track::AisTarget& t) {
  std::string s = std::string("AIS ") + std::to_string(t.mmsi);
  if (!t.info.name.empty()) s += std::string(" ") + t.info.name;
  return s;
}
std::string cpaText(const track::AisTarget& t) {
  char buf[64];
  std::snprintf(buf, sizeof buf, ": CPA %.2f NM in %.1f min", t.cpa.cpaM / kMetresPerNauticalMile,
                t.cpa.tcpaS / 60.0);
  return targetName(t) + buf;
}
/// "AIS-SART 970012345 ACTIVE 1.20 NM bearing 045" (range and bearing from own ship when known), with the
/// position's caveat when the device reports it is not a fix.
std::string distressText(const track::AisTarget& t) {
  std::string s = std::string(track::aisDeviceName(t.device)) + " " + std::to_string(t.mmsi) + " ACTIVE";
  if (t.rangeValid) {
    char buf[48];
    std::snprintf(buf, sizeof buf, " %.2f NM bearing %03.0f", t.rangeM / kMetresPerNauticalMile,
                  std::fmod(std::round(radToDeg(t.bearingRad)), 360.0));
    s += buf;
  }
  if (t.positionNotFix) s += " (position not a fix)";
  return s;
}

}  // namespace

void AisDistressFeed::report(AlertManager& m, TimeUs now, const std::vector<track::AisTarget>& targets) {
  std::set<int> held;
  for (const track::AisTarget& t : targets)
    if (t.distress() && !t.lost) {
      const int id = static_cast<int>(t.mmsi);
      held.insert(id);
      m.report(now, {AlertKind::AisDistress, id}, true, distressText(t));
    }
  for (const int id : held_)
    if (!held.contains(id)) m.report(now, {AlertKind::AisDistress, id}, false);
  held_ = std::move(held);
}

AisAlertFeed::AisAlertFeed(CpaAlertLimits limits) : cpa_(limits) {}

void AisAlertFeed::setLimits(CpaAlertLimits limits) {
  cpa_ = CpaAlertCondition(limits);  // the hysteresis starts again; the alerts held are ended or kept
}

void AisAlertFeed::report(AlertManager& m, TimeUs now, const track::AisTargetTable& table) {
  std::set<int> cpaNow, lostNow;
  const std::vector<track::AisTarget> targets = table.targets();
  distress_.report(m, now, targets);
  for (const track::AisTarget& t : targets) {
    const int id = static_cast<int>(t.mmsi);  // an MMSI has 9 digits: it fits
    // A device's alert is its distress, never a CPA alarm (docs/ais.md, "Search and rescue devices").
    if (t.cpaValid && !t.lost && t.device == track::AisDevice::None) {
      if (cpa_.update(id, now, t.cpa)) {
        cpaNow.insert(id);
        m.report(now, {AlertKind::AisCpaTcpa, id}, true, cpaText(t));
      }
    } else {
      cpa_.forget(id);
    }
    if (t.lost && t.activated) {
      lostNow.insert(id);
      m.report(now, {AlertKind::LostAisTarget, id}, true, targetName(t) + std::string(" lost"));
    }
  }
  for (const int id : cpaHeld_)
    if (!cpaNow.contains(id)) {
      m.report(now, {AlertKind::AisCpaTcpa, id}, false);
      if (!table.find(static_cast<std::uint32_t>(id))) cpa_.forget(id);
    }
  for (const int id : lostHeld_)
    if (!lostNow.contains(id)) m.report(now, {AlertKind::LostAisTarget, id}, false);
  cpaHeld_ = std::move(cpaNow);
  lostHeld_ = std::move(lostNow);
  const track::AisTableCounts c = table.counts();
  m.report(now, {AlertKind::Capacity, kAisCapacitySource}, c.nearCapacity,
           std::string("AIS targets near capacity: ") + std::to_string(c.activated) +
               std::string(" activated, ") + std::to_string(c.sleeping) + std::string(" sleeping"));
}

}  // namespace reckoner::alerts
