// The bit layouts of the AIS messages decoded (ITU-R M.1371-5, Annex 8), each field as (start bit,
// width) from the payload's first bit; "not available" values become empty optionals (docs/ais.md).
#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "io/ais.h"

namespace reckoner::io {
namespace {

template <class T>
std::optional<T> unless(T value, T notAvailable) {
  return value == notAvailable ? std::nullopt : std::optional<T>(value);
}

/// Position in 1/10000 minute (types 1-4, 18, 19, 21: 28 + 27 bits) or 1/10 minute (type 27: 18 + 17
/// bits); 181 / 91 degrees and anything outside the globe are empty.
void position(const AisBits& b, std::size_t lonBit, std::size_t lonWidth, double unitsPerDeg, AisMessage& m) {
  const double lon = b.s(lonBit, lonWidth) / unitsPerDeg;
  const double lat = b.s(lonBit + lonWidth, lonWidth - 1) / unitsPerDeg;
  if (std::abs(lon) <= 180.0) m.lonDeg = lon;
  if (std::abs(lat) <= 90.0) m.latDeg = lat;
}

/// SOG in 1/10 knot (1023 not available), COG in 1/10 degree (3600 not available, more is invalid),
/// heading in degrees (511 not available).
void motion(const AisBits& b, std::size_t sogBit, std::size_t cogBit, std::size_t headingBit, AisMessage& m) {
  const auto sog = b.u(sogBit, 10), cog = b.u(cogBit, 12), heading = b.u(headingBit, 9);
  if (sog != 1023) m.sogKn = sog / 10.0;
  if (cog < 3600) m.cogDeg = cog / 10.0;
  if (heading < 360) m.headingDeg = static_cast<int>(heading);
}

/// ROT_AIS = 4.733 sqrt(ROT_sensor) degrees per minute, sign kept; -128 not available; +-127 turning
/// faster than 5 degrees per 30 s without a rate.
void rateOfTurn(std::int32_t raw, AisMessage& m) {
  if (raw == -128) return;
  if (raw == 127 || raw == -127) {
    m.rotFast = raw > 0 ? 1 : -1;
    return;
  }
  const double r = raw / 4.733;
  m.rotDegMin = raw < 0 ? -r * r : r * r;
}

void dimensions(const AisBits& b, std::size_t bit, AisMessage& m) {
  m.toBowM = static_cast<int>(b.u(bit, 9));
  m.toSternM = static_cast<int>(b.u(bit + 9, 9));
  m.toPortM = static_cast<int>(b.u(bit + 18, 6));
  m.toStarboardM = static_cast<int>(b.u(bit + 24, 6));
}

std::optional<int> secondOf(std::uint32_t raw) {
  return raw < 60 ? std::optional<int>(static_cast<int>(raw)) : std::nullopt;
}

/// The time stamp (6 bits): a UTC second, or 60 not available, 61-63 how a position that is not a fix
/// was made (manual input, dead reckoning, positioning system inoperative).
void timeStamp(std::uint32_t raw, AisMessage& m) {
  m.second = secondOf(raw);
  if (raw >= 61) m.positionNotFix = static_cast<int>(raw);
}

void classA(const AisBits& b, AisMessage& m) {
  m.navStatus = static_cast<int>(b.u(38, 4));
  rateOfTurn(b.s(42, 8), m);
  m.accuracy = b.u(60, 1) != 0;
  position(b, 61, 28, 600000.0, m);
  motion(b, 50, 116, 128, m);
  timeStamp(b.u(137, 6), m);
}

void baseStation(const AisBits& b, AisMessage& m) {
  m.year = unless(static_cast<int>(b.u(38, 14)), 0);
  m.month = unless(static_cast<int>(b.u(52, 4)), 0);
  m.day = unless(static_cast<int>(b.u(56, 5)), 0);
  m.hour = unless(static_cast<int>(b.u(61, 5)), 24);
  m.minute = unless(static_cast<int>(b.u(66, 6)), 60);
  m.utcSecond = unless(static_cast<int>(b.u(72, 6)), 60);
  m.accuracy = b.u(78, 1) != 0;
  position(b, 79, 28, 600000.0, m);
  m.epfd = unless(static_cast<int>(b.u(134, 4)), 0);
}

void staticVoyage(const AisBits& b, AisMessage& m) {
  m.imo = unless(b.u(40, 30), 0u);
  m.callsign = b.text(70, 7);
  m.name = b.text(112, 20);
  m.shipType = unless(static_cast<int>(b.u(232, 8)), 0);
  dimensions(b, 240, m);
  m.epfd = unless(static_cast<int>(b.u(270, 4)), 0);
  m.etaMonth = unless(static_cast<int>(b.u(274, 4)), 0);
  m.etaDay = unless(static_cast<int>(b.u(278, 5)), 0);
  m.etaHour = unless(static_cast<int>(b.u(283, 5)), 24);
  m.etaMinute = unless(static_cast<int>(b.u(288, 6)), 60);
  const auto draught = b.u(294, 8);
  if (draught != 0) m.draughtM = draught / 10.0;
  m.destination = b.text(302, 20);
}

void classB(const AisBits& b, AisMessage& m) {
  motion(b, 46, 112, 124, m);
  m.accuracy = b.u(56, 1) != 0;
  position(b, 57, 28, 600000.0, m);
  timeStamp(b.u(133, 6), m);
}

void classBExtended(const AisBits& b, AisMessage& m) {
  classB(b, m);
  m.name = b.text(143, 20);
  m.shipType = unless(static_cast<int>(b.u(263, 8)), 0);
  dimensions(b, 271, m);
  m.epfd = unless(static_cast<int>(b.u(301, 4)), 0);
}

void aidToNavigation(const AisBits& b, AisMessage& m) {
  m.aidType = static_cast<int>(b.u(38, 5));
  // The name's last 14 characters are in the extension after bit 272 (as many as the payload holds),
  // which follows the first 20 as they are, spaces included, when those run to the end ('@'-free).
  m.name = b.text(43, 20);
  bool full = true;
  for (std::size_t i = 0; i < 20; ++i) full = full && b.u(43 + 6 * i, 6) != 0;
  if (full && b.size() >= 278) {
    const std::string extension = b.text(272, std::min<std::size_t>(14, (b.size() - 272) / 6));
    if (!extension.empty()) m.name = m.name + std::string(20 - m.name.size(), ' ') + extension;
  }
  m.accuracy = b.u(163, 1) != 0;
  position(b, 164, 28, 600000.0, m);
  dimensions(b, 219, m);
  m.epfd = unless(static_cast<int>(b.u(249, 4)), 0);
  timeStamp(b.u(253, 6), m);
  m.offPosition = b.u(259, 1) != 0;
  m.virtualAid = b.u(269, 1) != 0;
}

bool staticDataReport(const AisBits& b, AisMessage& m) {
  const auto part = b.u(38, 2);
  if (part > 1) return false;
  m.part = part == 0 ? 'A' : 'B';
  if (part == 0) {
    m.name = b.text(40, 20);
    return true;
  }
  m.shipType = unless(static_cast<int>(b.u(40, 8)), 0);
  m.vendor = b.text(48, 3);
  m.callsign = b.text(90, 7);
  if (m.mmsi / 10000000 != 98) dimensions(b, 132, m);  // an auxiliary craft gives its mothership
  return true;
}

void longRange(const AisBits& b, AisMessage& m) {
  m.accuracy = b.u(38, 1) != 0;
  m.navStatus = static_cast<int>(b.u(40, 4));
  position(b, 44, 18, 600.0, m);
  const auto sog = b.u(79, 6), cog = b.u(85, 9);
  if (sog != 63) m.sogKn = static_cast<double>(sog);
  if (cog < 360) m.cogDeg = static_cast<double>(cog);
}

/// Type 14, the safety-related broadcast: six-bit text from bit 40 to the end of the payload (at most
/// 161 characters in 1008 bits).
void safetyBroadcast(const AisBits& b, AisMessage& m) {
  m.text = b.text(40, std::min<std::size_t>(161, (b.size() - 40) / 6));
}

/// The bits each type's decoded fields need: up to RAIM or the last field read (radio state is not
/// decoded, so a payload that ends before it still decodes).
std::size_t minimumBits(int type, std::uint32_t part) {
  switch (type) {
    case 1:
    case 2:
    case 3:
    case 4:
      return 149;
    case 5:
      return 420;  // the destination's end: many transmitters send 420 bits, not 424 (gpsd accepts them)
    case 14:
      return 40;  // the text may be empty (as gpsd decodes it)
    case 18:
      return 148;
    case 19:
      return 306;
    case 21:
      return 272;
    case 24:
      return part == 0 ? 160 : 162;
    case 27:
      return 94;
    default:
      return 0;
  }
}

}  // namespace

AisDecodeResult decodeAisPayload(const AisBits& b, AisMessage& m) {
  if (b.size() < 38)
    return b.size() >= 6 && minimumBits(static_cast<int>(b.u(0, 6)), 0) == 0 ? AisDecodeResult::Unsupported
                                                                             : AisDecodeResult::TooShort;
  m = AisMessage{};
  m.type = static_cast<int>(b.u(0, 6));
  m.repeat = static_cast<int>(b.u(6, 2));
  m.mmsi = b.u(8, 30);
  const std::size_t need = minimumBits(m.type, b.u(38, 2));
  if (need == 0) return AisDecodeResult::Unsupported;
  if (b.size() < need) return AisDecodeResult::TooShort;
  switch (m.type) {
    case 1:
    case 2:
    case 3:
      classA(b, m);
      break;
    case 4:
      baseStation(b, m);
      break;
    case 5:
      staticVoyage(b, m);
      break;
    case 14:
      safetyBroadcast(b, m);
      break;
    case 18:
      classB(b, m);
      break;
    case 19:
      classBExtended(b, m);
      break;
    case 21:
      aidToNavigation(b, m);
      break;
    case 24:
      if (!staticDataReport(b, m)) return AisDecodeResult::Unsupported;
      break;
    case 27:
      longRange(b, m);
      break;
    default:
      return AisDecodeResult::Unsupported;
  }
  return AisDecodeResult::Ok;
}

}  // namespace reckoner::io
