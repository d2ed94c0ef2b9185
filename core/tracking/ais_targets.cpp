#include "tracking/ais_targets.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "common/angles.h"
#include "common/units.h"

namespace reckoner::track {

namespace {

constexpr double kEarthRadiusM = 6371008.8;  // mean radius, for the capacity rule's rough distance
/// The largest SOG taken as "at rest" when a report gives no COG (AIS SOG is in steps of 0.1 kn).
constexpr double kStationarySogKn = 0.1;

/// Navigational status 1 (at anchor) and 5 (moored): ITU-R M.1371 Table 1's "at anchor or moored".
bool anchoredOrMoored(const AisTarget& t) {
  return t.navStatus && (*t.navStatus == 1 || *t.navStatus == 5);
}

bool turning(const AisTarget& t, double turningRotDegMin) {
  return t.rotFast != 0 || (t.rotDegMin && std::abs(*t.rotDegMin) >= turningRotDegMin);
}

template <class T>
void keep(std::optional<T>& field, const std::optional<T>& value) {
  if (value) field = value;
}
void keep(std::string& field, const std::string& value) {
  if (!value.empty()) field = value;
}

/// The station's class after a message of `type`: position reports set it; static data (5, 24) and
/// long-range broadcasts (27, which class B "SO" units send too) only give one to a station without.
AisClass classAfter(AisClass known, int type) {
  switch (type) {
    case 1:
    case 2:
    case 3:
      return AisClass::A;
    case 18:
    case 19:
      return AisClass::B;
    case 4:
      return AisClass::BaseStation;
    case 21:
      return AisClass::AidToNavigation;
    case 5:
    case 27:
      return known == AisClass::Unknown ? AisClass::A : known;
    case 24:
      return known == AisClass::Unknown ? AisClass::B : known;
    default:
      return known;
  }
}

bool carriesPosition(int type) {
  switch (type) {
    case 1:
    case 2:
    case 3:
    case 4:
    case 18:
    case 19:
    case 21:
    case 27:
      return true;
    default:
      return false;
  }
}

}  // namespace

AisDevice aisDeviceOf(std::uint32_t mmsi) {
  switch (mmsi / 1000000) {
    case 970:
      return AisDevice::Sart;
    case 972:
      return AisDevice::Mob;
    case 974:
      return AisDevice::Epirb;
    default:
      return AisDevice::None;
  }
}

const char* aisDeviceName(AisDevice d) {
  switch (d) {
    case AisDevice::Sart:
      return "AIS-SART";
    case AisDevice::Mob:
      return "AIS-MOB";
    case AisDevice::Epirb:
      return "EPIRB-AIS";
    case AisDevice::None:
      break;
  }
  return "";
}

std::optional<bool> deviceTestText(std::string_view text) {
  // ACTIVE first: a text that says both is taken as a distress rather than missed as a test.
  if (text.find("ACTIVE") != std::string_view::npos) return false;
  if (text.find("TEST") != std::string_view::npos) return true;
  return std::nullopt;
}

const char* aisClassName(AisClass c) {
  switch (c) {
    case AisClass::A:
      return "A";
    case AisClass::B:
      return "B";
    case AisClass::BaseStation:
      return "base station";
    case AisClass::AidToNavigation:
      return "AtoN";
    case AisClass::Unknown:
      break;
  }
  return "?";
}

std::optional<double> AisStatic::lengthM() const {
  if (!toBowM || !toSternM || *toBowM + *toSternM <= 0) return std::nullopt;
  return static_cast<double>(*toBowM + *toSternM);
}

std::optional<double> AisStatic::beamM() const {
  if (!toPortM || !toStarboardM || *toPortM + *toStarboardM <= 0) return std::nullopt;
  return static_cast<double>(*toPortM + *toStarboardM);
}

std::optional<double> AisTarget::orientationDeg() const {
  if (headingDeg) return static_cast<double>(*headingDeg);
  return cogDeg;
}

void validate(const AisTableLimits& l) {
  auto positive = [](double v, const char* name) {
    if (!std::isfinite(v) || v <= 0.0)
      throw std::invalid_argument(std::string("AIS limits: ") + name + " must be finite and positive");
  };
  if (l.maxActivated < 1) throw std::invalid_argument("AIS limits: maxActivated must be at least 1");
  if (l.maxSleeping < 1) throw std::invalid_argument("AIS limits: maxSleeping must be at least 1");
  if (l.maxDevices < 1) throw std::invalid_argument("AIS limits: maxDevices must be at least 1");
  if (!(l.nearCapacityFraction > 0.0 && l.nearCapacityFraction <= 1.0))
    throw std::invalid_argument("AIS limits: nearCapacityFraction must lie in (0, 1]");
  positive(l.lostFactor, "lostFactor");
  positive(l.minLostS, "minLostS");
  positive(l.removeAfterLostS, "removeAfterLostS");
  positive(l.cpaLimitM, "cpaLimitM");
  positive(l.tcpaLimitS, "tcpaLimitS");
  positive(l.turningRotDegMin, "turningRotDegMin");
}

double reportingIntervalS(const AisTarget& t, double turningRotDegMin) {
  if (t.device != AisDevice::None) return 60.0;  // eight reports once a minute (IEC 61097-14)
  // Long-range broadcasts (type 27) come every 3 minutes whatever the speed (ITU-R M.1371-5 Annex 4).
  if (t.longRange && t.cls != AisClass::BaseStation && t.cls != AisClass::AidToNavigation) return 180.0;
  const double sog = t.sogKn.value_or(0.0);
  switch (t.cls) {
    case AisClass::A:
      if (anchoredOrMoored(t) && sog <= 3.0) return 180.0;
      if (sog > 23.0) return 2.0;
      if (sog > 14.0) return turning(t, turningRotDegMin) ? 2.0 : 6.0;
      return turning(t, turningRotDegMin) ? 10.0 / 3.0 : 10.0;
    case AisClass::B:
      return sog > 2.0 ? 30.0 : 180.0;
    case AisClass::BaseStation:
      return 10.0;
    case AisClass::AidToNavigation:
      return 180.0;
    case AisClass::Unknown:
      break;
  }
  return 360.0;  // static data only: class A's static report interval (6 min)
}

bool isOwnShipSentence(std::string_view line) {
  if (!line.empty() && line.front() == '\\') {  // NMEA 4.0 tag block
    const auto end = line.find('\\', 1);
    if (end == std::string_view::npos) return false;
    line.remove_prefix(end + 1);
  }
  return line.size() >= 6 && (line[0] == '!' || line[0] == '$') && line.substr(3, 3) == "VDO";
}

AisTargetTable::AisTargetTable(AisTableLimits limits) : limits_(limits) {
  validate(limits_);
}

double AisTargetTable::lostAfterS(const AisTarget& t) const {
  return std::max(limits_.minLostS, limits_.lostFactor * reportingIntervalS(t, limits_.turningRotDegMin));
}

void AisTargetTable::merge(AisTarget& t, const io::AisMessage& m, TimeUs rxUs) const {
  t.cls = classAfter(t.cls, m.type);
  if (t.reports == 0) t.firstReportUs = rxUs;
  ++t.reports;
  t.lastReportUs = rxUs;
  // A lost target is found again by the report its lost rule waits for (a position, or any report
  // from a station never heard with one).
  if (t.lost && (carriesPosition(m.type) || !t.hasPosition())) {
    t.lost = false;
    t.lostSinceUs = 0;
  }
  // A type 27 is coarse (1/10 minute, whole knots and degrees): it does not replace a finer report that
  // is still within its class's lost time, and counts then as a report without a position.
  const bool coarse = m.type == 27 && t.hasPosition() && !t.longRange && !t.lost &&
                      toSeconds(rxUs - t.lastPositionUs) <= lostAfterS(t);
  if (carriesPosition(m.type) && !coarse) {
    t.longRange = m.type == 27;
    // A position report is a snapshot: what it marks not available is not available now.
    t.latDeg = m.latDeg;
    t.lonDeg = m.lonDeg;
    if (m.latDeg && m.lonDeg) t.lastPositionUs = rxUs;
    const bool moving = m.type != 4 && m.type != 21;
    t.sogKn = moving ? m.sogKn : std::optional<double>{};
    t.cogDeg = moving ? m.cogDeg : std::optional<double>{};
    t.headingDeg = moving ? m.headingDeg : std::optional<int>{};
    t.rotDegMin = m.rotDegMin;
    t.rotFast = m.rotFast;
    t.navStatus = m.navStatus;
    t.positionNotFix = m.positionNotFix;
    // A device's navigational status says its mode: 14 active, 15 test (IEC 61097-14).
    if (t.device != AisDevice::None && m.navStatus && (*m.navStatus == 14 || *m.navStatus == 15))
      deviceMode(t, *m.navStatus == 15, rxUs);
  }
  if (m.type == 14) {
    t.safetyText = m.text;
    if (t.device != AisDevice::None)
      if (const auto test = deviceTestText(m.text)) deviceMode(t, *test, rxUs);
  }
  // Static and voyage data: merged, a field not available keeps what was known.
  AisStatic& s = t.info;
  keep(s.name, m.name);
  keep(s.callsign, m.callsign);
  keep(s.destination, m.destination);
  keep(s.vendor, m.vendor);
  keep(s.imo, m.imo);
  keep(s.shipType, m.shipType);
  // The four dimensions are one set (a 0 among them is the reference point at that edge); all four 0
  // is "not available" (ITU-R M.1371) and keeps the set known, as a type 19 or 24 B of a unit not set up.
  const auto zero = [](const std::optional<int>& d) { return !d || *d == 0; };
  if (!(zero(m.toBowM) && zero(m.toSternM) && zero(m.toPortM) && zero(m.toStarboardM))) {
    s.toBowM = m.toBowM;
    s.toSternM = m.toSternM;
    s.toPortM = m.toPortM;
    s.toStarboardM = m.toStarboardM;
  }
  keep(s.draughtM, m.draughtM);
  if (m.type == 5) {  // the ETA is one field: a type 5 replaces all of it
    s.etaMonth = m.etaMonth;
    s.etaDay = m.etaDay;
    s.etaHour = m.etaHour;
    s.etaMinute = m.etaMinute;
  }
  keep(s.aidType, m.aidType);
  keep(s.virtualAid, m.virtualAid);
}

void AisTargetTable::deviceMode(AisTarget& t, bool test, TimeUs rxUs) {
  if (!test) {
    t.deviceTest = false;
    t.deviceActiveUs = rxUs;
  } else if (t.deviceActiveUs < 0 || toSeconds(rxUs - t.deviceActiveUs) > kDeviceActiveHoldS) {
    t.deviceTest = true;
  }
}

bool AisTargetTable::makeRoomForDevice() {
  auto victim = targets_.end();
  for (auto it = targets_.begin(); it != targets_.end(); ++it) {
    const AisTarget& t = it->second;
    if (t.device == AisDevice::None || (t.distress() && !t.lost)) continue;
    if (victim == targets_.end() || t.lastReportUs < victim->second.lastReportUs) victim = it;
  }
  ++counters_.droppedAtCapacity;
  if (victim == targets_.end()) return false;
  if (victim->first == selected_) selected_ = 0;
  targets_.erase(victim);
  return true;
}

void AisTargetTable::activateDistress(AisTarget& t) {
  // A distress is always shown activated, past the activated limit too (IEC 62388: the SART symbol is
  // never filtered); the activation is automatic, and stays when the device goes to test.
  if (t.distress() && !t.activated) t.activated = t.autoActivated = true;
}

double AisTargetTable::distanceFromOwnM(const AisTarget& t) const {
  if (!t.hasPosition()) return std::numeric_limits<double>::infinity();
  if (!lastOwnPosition_) return 0.0;  // no own ship: every positioned target is as near
  const double lat0 = degToRad(lastOwnPosition_->latDeg);
  const double dLat = degToRad(*t.latDeg - lastOwnPosition_->latDeg);
  const double dLon = wrapPi(degToRad(*t.lonDeg - lastOwnPosition_->lonDeg));
  return kEarthRadiusM * std::hypot(dLat, dLon * std::cos(lat0));
}

bool AisTargetTable::makeRoomForSleeping(const AisTarget& incoming) {
  // The sleeping target furthest from own ship goes; ties (no own ship) the one silent longest.
  auto worse = [this](const AisTarget& a, const AisTarget& b) {  // a should go before b
    const double da = distanceFromOwnM(a), db = distanceFromOwnM(b);
    if (da != db) return da > db;
    return a.lastReportUs < b.lastReportUs;
  };
  auto victim = targets_.end();
  for (auto it = targets_.begin(); it != targets_.end(); ++it) {
    if (it->second.activated) continue;
    if (victim == targets_.end() || worse(it->second, victim->second)) victim = it;
  }
  ++counters_.droppedAtCapacity;
  if (victim == targets_.end() || !worse(victim->second, incoming)) return false;
  if (victim->first == selected_) selected_ = 0;
  targets_.erase(victim);
  return true;
}

void AisTargetTable::feed(const io::AisMessage& m, TimeUs rxUs, bool ownShip) {
  if (ownShip) {
    ++counters_.ownShipMessages;
    if (!own_) own_ = AisTarget{};
    own_->mmsi = m.mmsi;
    merge(*own_, m, rxUs);
    return;
  }
  if (m.mmsi == 0) {
    ++counters_.invalidMmsi;
    return;
  }
  ++counters_.messages;
  auto it = targets_.find(m.mmsi);
  if (it != targets_.end()) {
    merge(it->second, m, rxUs);
    activateDistress(it->second);
    return;
  }
  AisTarget t;
  t.mmsi = m.mmsi;
  t.device = aisDeviceOf(m.mmsi);
  if (t.device != AisDevice::None) {
    const auto devices = static_cast<std::size_t>(std::count_if(
        targets_.begin(), targets_.end(), [](const auto& e) { return e.second.device != AisDevice::None; }));
    if (devices >= limits_.maxDevices && !makeRoomForDevice()) return;
  }
  merge(t, m, rxUs);
  activateDistress(t);
  const std::size_t sleeping = targets_.size() - activatedCount();
  if (!t.activated && sleeping >= limits_.maxSleeping && !makeRoomForSleeping(t)) return;
  targets_.emplace(t.mmsi, std::move(t));
}

void AisTargetTable::update(TimeUs now) {
  std::vector<std::uint32_t> gone;
  for (auto& [mmsi, t] : targets_) {
    const TimeUs last = t.hasPosition() ? t.lastPositionUs : t.lastReportUs;
    if (!t.lost && toSeconds(now - last) > lostAfterS(t)) {
      t.lost = true;
      t.lostSinceUs = now;
      t.dangerous = false;
      ++counters_.lostEvents;
    }
    // A lost distress stays, crossed out at its last position: where the person in the water was heard.
    if (t.lost && !t.distress() && toSeconds(now - t.lostSinceUs) > limits_.removeAfterLostS)
      gone.push_back(mmsi);
  }
  for (const std::uint32_t mmsi : gone) {
    if (mmsi == selected_) selected_ = 0;
    targets_.erase(mmsi);
    ++counters_.removed;
  }
}

void AisTargetTable::applyOwnShip(AisTarget& t, TimeUs now, const geo::LocalFrame& frame,
                                  const AisOwnShip& own) const {
  t.rangeValid = t.cpaValid = false;
  if (!t.hasPosition()) return;
  const geo::GridPoint o = frame.toLocal(own.position);
  geo::GridPoint p = frame.toLocal({*t.latDeg, *t.lonDeg});
  if (!std::isfinite(o.xM) || !std::isfinite(p.xM)) return;
  double vx = 0.0, vy = 0.0;
  // The target's motion is known with SOG and COG, and with a SOG of at most 0.1 kn without COG (anchored
  // and moored ships, class B boats at rest report COG "not available"): its velocity is then taken as
  // nil, which moves the CPA by at most 0.1 kn times the TCPA (19 m at 6 minutes). Without SOG, or with
  // a speed but no course, there is no CPA.
  const bool stationary = t.sogKn && !t.cogDeg && *t.sogKn <= kStationarySogKn;
  const bool moving = t.sogKn && t.cogDeg;
  if (moving) {
    // COG is true; the grid course is true minus the convergence at the target.
    const double course = degToRad(*t.cogDeg) - frame.gridInfo(p).convergenceRad;
    const double speed = knotsToMps(*t.sogKn);
    vx = speed * std::sin(course);
    vy = speed * std::cos(course);
    const double dtS = toSeconds(now - t.lastPositionUs);  // dead reckoned to now from the report
    p.xM += vx * dtS;
    p.yM += vy * dtS;
  }
  const double rx = p.xM - o.xM, ry = p.yM - o.yM;
  t.rangeM = std::hypot(rx, ry);
  t.bearingRad = wrapTwoPi(bearingOf(rx, ry) + frame.gridInfo(o).convergenceRad);
  t.rangeValid = true;
  if (!moving && !stationary) return;
  est::Vec<4> rel;
  rel << rx, ry, vx - own.velEastMps, vy - own.velNorthMps;
  t.cpa = cpaOf(rel, est::Mat<4>::Zero());
  t.cpaValid = true;  // no relative motion: cpa is the present range, tcpa 0 (cpa.h)
}

void AisTargetTable::update(TimeUs now, const geo::LocalFrame& frame, const AisOwnShip& own) {
  update(now);
  lastOwnPosition_ = own.position;
  std::size_t activated = activatedCount();
  for (auto& entry : targets_) {
    AisTarget& t = entry.second;
    applyOwnShip(t, now, frame, own);
    const bool was = t.dangerous;
    // A device is never dangerous: its alert is the distress itself (alerts::AlertKind::AisDistress).
    t.dangerous = t.device == AisDevice::None && !t.lost && t.cpaValid &&
                  withinDangerLimits(t.cpa, limits_.cpaLimitM, limits_.tcpaLimitS);
    if (t.dangerous && !t.activated && limits_.autoActivateDangerous) {
      if (activated < limits_.maxActivated) {
        t.activated = t.autoActivated = true;
        ++activated;
      } else if (!was) {
        ++counters_.activationRefused;
      }
    }
  }
}

std::size_t AisTargetTable::activatedCount() const {
  return static_cast<std::size_t>(
      std::count_if(targets_.begin(), targets_.end(), [](const auto& e) { return e.second.activated; }));
}

bool AisTargetTable::setDangerLimits(double cpaM, double tcpaS) {
  if (!(std::isfinite(cpaM) && cpaM > 0.0 && std::isfinite(tcpaS) && tcpaS > 0.0)) return false;
  limits_.cpaLimitM = cpaM;
  limits_.tcpaLimitS = tcpaS;
  return true;
}

bool AisTargetTable::activate(std::uint32_t mmsi, bool on) {
  auto it = targets_.find(mmsi);
  if (it == targets_.end()) return false;
  AisTarget& t = it->second;
  if (!on) {
    if (t.distress()) return false;  // a distress stays activated
    t.activated = t.autoActivated = false;
    return true;
  }
  if (t.activated) {
    t.autoActivated = false;  // the operator's now
    return true;
  }
  if (activatedCount() >= limits_.maxActivated) {
    ++counters_.activationRefused;
    return false;
  }
  t.activated = true;
  return true;
}

bool AisTargetTable::select(std::uint32_t mmsi) {
  if (mmsi != 0 && !targets_.contains(mmsi)) return false;
  if (auto old = targets_.find(selected_); old != targets_.end()) old->second.selected = false;
  selected_ = mmsi;
  if (mmsi != 0) targets_.at(mmsi).selected = true;
  return true;
}

const AisTarget* AisTargetTable::find(std::uint32_t mmsi) const {
  auto it = targets_.find(mmsi);
  return it == targets_.end() ? nullptr : &it->second;
}

std::vector<AisTarget> AisTargetTable::targets() const {
  std::vector<AisTarget> out;
  out.reserve(targets_.size());
  for (const auto& entry : targets_) out.push_back(entry.second);
  std::sort(out.begin(), out.end(), [](const AisTarget& a, const AisTarget& b) { return a.mmsi < b.mmsi; });
  return out;
}

AisTableCounts AisTargetTable::counts() const {
  AisTableCounts c = counters_;
  c.targets = targets_.size();
  for (const auto& entry : targets_) {
    const AisTarget& t = entry.second;
    if (t.activated) ++c.activated;
    if (t.dangerous) ++c.dangerous;
    if (t.lost) ++c.lost;
  }
  c.sleeping = c.targets - c.activated;
  const double f = limits_.nearCapacityFraction;
  c.nearCapacity = static_cast<double>(c.activated) >= f * static_cast<double>(limits_.maxActivated) ||
                   static_cast<double>(c.sleeping) >= f * static_cast<double>(limits_.maxSleeping);
  return c;
}

}  // namespace reckoner::track
