#pragma once
// AIS targets (docs/ais.md, "Targets"): the table an ECDIS keeps of the AIS stations it hears, one entry
// per MMSI, fed with decoded messages (io/ais.h) and their receive times. Dynamic data (position, SOG,
// COG, heading, ROT, navigational status) comes from types 1-3, 18, 19, 27 (and 4 and 21 for base
// stations and aids to navigation); static data from types 5, 19, 21 and 24 A/B is merged field by
// field, a field the message marks "not available" never overwriting a known one. Own ship's !AIVDO
// reports are kept apart and are never a target.
//
// States after IEC 62388 / IEC 62288: sleeping (a small triangle, no vector), activated by the operator
// or automatically when dangerous (vector, heading line), selected (one at a time, pick report),
// dangerous (CPA and TCPA under the limits), lost (silent longer than its reporting interval allows,
// ITU-R M.1371-5 Annex 1 Table 1; see reportingIntervalS) and removed later. Capacity is bounded: at
// most maxActivated activated and maxSleeping sleeping targets; at the sleeping limit the sleeping
// target furthest from own ship is dropped (counted); an activation past the activated limit is refused
// (counted). Search and rescue devices (AIS-SART, MOB, EPIRB-AIS; aisDeviceOf) are activated whenever
// they are not in test, past the activated and sleeping limits, never dangerous (their alert is
// AisDistress, not CPA), and a lost one is kept (its last position); at most maxDevices of them are
// held (a new one past that takes the place of a device in test or lost, else is not added: counted).
// Plain C++, no Qt; per-message calls never throw.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "common/time.h"
#include "geo/local_frame.h"
#include "io/ais.h"
#include "tracking/cpa.h"

namespace reckoner::track {

enum class AisClass : std::uint8_t { Unknown, A, B, BaseStation, AidToNavigation };
const char* aisClassName(AisClass c);

/// Search and rescue devices by their MMSI (ITU-R M.585-9 Annex 2): 970xxyyyy an AIS-SART, 972xxyyyy an
/// AIS man overboard device, 974xxyyyy an EPIRB-AIS.
enum class AisDevice : std::uint8_t { None, Sart, Mob, Epirb };
AisDevice aisDeviceOf(std::uint32_t mmsi);
/// "AIS-SART", "AIS-MOB", "EPIRB-AIS"; "" for None.
const char* aisDeviceName(AisDevice d);
/// Whether a device's type 14 text says it is in test ("SART TEST", "MOB TEST", "EPIRB TEST": IEC
/// 61097-14), or active ("... ACTIVE"; a text with both is active); empty when the text says neither.
std::optional<bool> deviceTestText(std::string_view text);

/// The static and voyage data of a station, merged from every static message heard.
struct AisStatic {
  std::string name, callsign, destination, vendor;  ///< empty: not available
  std::optional<std::uint32_t> imo;
  std::optional<int> shipType;  ///< 1..255
  std::optional<int> toBowM, toSternM, toPortM, toStarboardM;
  std::optional<double> draughtM;
  std::optional<int> etaMonth, etaDay, etaHour, etaMinute;
  std::optional<int> aidType;
  std::optional<bool> virtualAid;
  /// Length and beam when both parts of each are known and not 0.
  [[nodiscard]] std::optional<double> lengthM() const;
  [[nodiscard]] std::optional<double> beamM() const;
};

/// One AIS station as the table knows it.
struct AisTarget {
  std::uint32_t mmsi = 0;
  AisClass cls = AisClass::Unknown;
  // Dynamic data of the latest position report (empty: not available).
  std::optional<double> latDeg, lonDeg, sogKn, cogDeg;
  std::optional<int> headingDeg;
  std::optional<double> rotDegMin;  ///< right positive
  int rotFast = 0;                  ///< +1 / -1: turning right / left faster than 5 deg per 30 s
  std::optional<int> navStatus;
  /// 61 manual input, 62 dead reckoning, 63 positioning system inoperative: the latest position is not a
  /// fix (io::AisMessage::positionNotFix); empty for a fix.
  std::optional<int> positionNotFix;
  AisStatic info;
  /// The latest type 14 (safety-related broadcast) text; empty when none was heard.
  std::string safetyText;
  AisDevice device = AisDevice::None;
  /// A device in test: a position report with navigational status 15 (14 is active) or a type 14 that
  /// says TEST, and no sign of being active (status 14, "ACTIVE") in the last kDeviceActiveHoldS. A
  /// device is taken as active unless it says it is in test.
  bool deviceTest = false;
  TimeUs deviceActiveUs = -1;  ///< the latest sign of being active (< 0: none)
  /// A device that is not in test: a distress (an alarm, the SART symbol).
  [[nodiscard]] bool distress() const { return device != AisDevice::None && !deviceTest; }
  TimeUs firstReportUs = 0;
  TimeUs lastReportUs = 0;    ///< any message
  TimeUs lastPositionUs = 0;  ///< the latest message with a position
  /// The position came from a type 27 (long-range broadcast: every 3 minutes, 1/10 minute, whole knots and
  /// degrees); a type 27 does not replace a finer report that is not yet lost.
  bool longRange = false;
  std::uint64_t reports = 0;
  // Display state.
  bool activated = false;  ///< by the operator or automatically (dangerous)
  bool autoActivated = false;
  bool selected = false;
  bool dangerous = false;
  bool lost = false;
  TimeUs lostSinceUs = 0;
  // From own ship at the latest update() that had own ship: range and bearing when the target has a
  // position (rangeValid), CPA and TCPA when it also has SOG and COG (cpaValid).
  bool rangeValid = false;
  bool cpaValid = false;
  Cpa cpa;
  double rangeM = 0.0;
  double bearingRad = 0.0;  ///< true, [0, 2 pi)
  [[nodiscard]] bool hasPosition() const { return latDeg.has_value() && lonDeg.has_value(); }
  /// Heading if reported, else COG (degrees true), else empty: what the symbol is oriented by.
  [[nodiscard]] std::optional<double> orientationDeg() const;
};

struct AisTableLimits {
  std::size_t maxActivated = 200;  ///< IEC 62388: at least 200 activated ...
  std::size_t maxSleeping = 2000;  ///< ... and 2000 sleeping targets
  /// Search and rescue devices held at most (they pass the two limits above; this bounds a feed of
  /// made-up 97x MMSIs).
  std::size_t maxDevices = 100;
  double nearCapacityFraction = 0.95;
  double lostFactor = 5.0;          ///< lost after lostFactor reporting intervals without a report
  double minLostS = 20.0;           ///< and never sooner than this
  double removeAfterLostS = 300.0;  ///< a lost target is removed this long after it became lost
  double cpaLimitM = 1852.0;        ///< dangerous: CPA within this ...
  double tcpaLimitS = 720.0;        ///< ... and 0 <= TCPA within this
  bool autoActivateDangerous = true;
  /// A target turns (reporting intervals of ITU-R M.1371 Table 1 for "changing course") when |ROT| is
  /// at least this, or ROT is "fast".
  double turningRotDegMin = 5.0;
};
/// A device's sign of being in test is taken only this long (s) after its latest sign of being active:
/// a unit whose position reports and texts disagree is not switched in and out of distress each burst.
inline constexpr double kDeviceActiveHoldS = 300.0;

/// Throws std::invalid_argument naming the field for a limit that is not finite and positive (the
/// sizes at least 1, the fraction in (0, 1]).
void validate(const AisTableLimits& l);

/// Own ship: position and grid velocity (the LocalFrame's x east, y north), metres per second.
struct AisOwnShip {
  geo::GeoPoint position;
  double velEastMps = 0.0;
  double velNorthMps = 0.0;
};

struct AisTableCounts {
  std::size_t targets = 0, activated = 0, sleeping = 0, dangerous = 0, lost = 0;
  bool nearCapacity = false;            ///< activated or sleeping at nearCapacityFraction of its limit
  std::uint64_t messages = 0;           ///< messages fed for targets
  std::uint64_t ownShipMessages = 0;    ///< !AIVDO reports
  std::uint64_t invalidMmsi = 0;        ///< MMSI 0: skipped
  std::uint64_t droppedAtCapacity = 0;  ///< sleeping targets (devices) dropped or not added at maxSleeping
                                        ///< (maxDevices)
  std::uint64_t activationRefused = 0;  ///< activations refused at maxActivated
  std::uint64_t lostEvents = 0;         ///< targets that became lost
  std::uint64_t removed = 0;            ///< lost targets removed
};

/// ITU-R M.1371-5 Annex 1 Table 1 (and Table 2 for class B), the nominal interval between position
/// reports, seconds: a search and rescue device 60 (a burst of eight reports a minute, IEC 61097-14);
/// class A at anchor or moored and not faster than 3 kn 180 s; 0-14 kn 10 s (3.33 s
/// turning); 14-23 kn 6 s (2 s turning); above 23 kn 2 s; class B above 2 kn 30 s, else 180 s; base
/// station 10 s; aid to navigation 180 s; a station heard only by static data 360 s. Unknown SOG is
/// taken as slow (the longest interval of its class that is not the anchored one).
double reportingIntervalS(const AisTarget& t, double turningRotDegMin = 5.0);

/// Whether a line is an own-ship sentence (!xxVDO).
bool isOwnShipSentence(std::string_view line);

class AisTargetTable {
 public:
  explicit AisTargetTable(AisTableLimits limits = {});

  /// One decoded message received at rxUs (times must not decrease); ownShip: it came in a !xxVDO.
  void feed(const io::AisMessage& m, TimeUs rxUs, bool ownShip = false);
  /// Advances to now: lost and removed targets, and (with own ship) range, bearing, CPA and TCPA from
  /// each target's reported motion, the dangerous flag and auto-activation.
  void update(TimeUs now);
  void update(TimeUs now, const geo::LocalFrame& frame, const AisOwnShip& own);

  /// Operator activation (true) or deactivation; false when the target is unknown or the activated
  /// limit is reached (counted).
  bool activate(std::uint32_t mmsi, bool on = true);
  /// The operator's CPA (m) and TCPA (s) limits of the dangerous flag from the next update(); false,
  /// changing nothing, unless both are finite and positive.
  bool setDangerLimits(double cpaM, double tcpaS);
  /// Selects one target (0: none); false when the MMSI is unknown.
  bool select(std::uint32_t mmsi);

  [[nodiscard]] const AisTarget* find(std::uint32_t mmsi) const;
  /// The targets, by MMSI.
  [[nodiscard]] std::vector<AisTarget> targets() const;
  [[nodiscard]] std::size_t size() const { return targets_.size(); }
  /// Own ship from !AIVDO, when any was heard.
  [[nodiscard]] const std::optional<AisTarget>& ownShip() const { return own_; }
  [[nodiscard]] AisTableCounts counts() const;
  [[nodiscard]] const AisTableLimits& limits() const { return limits_; }
  /// Silence after which a target is lost, seconds (lostFactor intervals, at least minLostS).
  [[nodiscard]] double lostAfterS(const AisTarget& t) const;

 private:
  void merge(AisTarget& t, const io::AisMessage& m, TimeUs rxUs) const;
  bool makeRoomForSleeping(const AisTarget& incoming);
  static void activateDistress(AisTarget& t);
  /// Room for a new device at maxDevices: drops the device in test or lost heard longest ago; false
  /// when every device held is a live distress.
  bool makeRoomForDevice();
  /// A device's mode from a sign of being active (false) or in test (true) at rxUs.
  static void deviceMode(AisTarget& t, bool test, TimeUs rxUs);
  void applyOwnShip(AisTarget& t, TimeUs now, const geo::LocalFrame& frame, const AisOwnShip& own) const;
  /// Rough distance from the latest own-ship position (equirectangular), for the capacity rule;
  /// infinity without a position.
  [[nodiscard]] double distanceFromOwnM(const AisTarget& t) const;
  [[nodiscard]] std::size_t activatedCount() const;

  AisTableLimits limits_;
  std::unordered_map<std::uint32_t, AisTarget> targets_;
  std::optional<AisTarget> own_;
  std::optional<geo::GeoPoint> lastOwnPosition_;
  std::uint32_t selected_ = 0;
  AisTableCounts counters_;
};

}  // namespace reckoner::track
