#pragma once
// AIS (ITU-R M.1371-5) from NMEA 0183 !xxVDM / !xxVDO sentences (docs/ais.md): the sentence layer
// (fields, checksum, six-bit armour, fill bits), multi-fragment reassembly with bounded memory, and
// the decoding of message types 1, 2, 3, 4, 5, 14, 18, 19, 21, 24 and 27. Values the message marks "not
// available" come back as empty optionals. Nothing here throws on bad input: every rejected line is
// counted by reason in AisCounters.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace reckoner::io {

/// One AIS message as decoded; which fields are set depends on the type.
struct AisMessage {
  int type = 0;
  int repeat = 0;
  std::uint32_t mmsi = 0;
  std::optional<double> latDeg, lonDeg;  ///< WGS 84 degrees, north and east positive
  std::optional<double> sogKn;           ///< speed over ground, knots
  std::optional<double> cogDeg;          ///< course over ground, degrees true
  std::optional<int> headingDeg;         ///< true heading, degrees
  /// Rate of turn, degrees per minute, right positive: (ROT_AIS / 4.733)^2 with ROT_AIS's sign.
  std::optional<double> rotDegMin;
  /// +1 or -1 when ROT_AIS is +127 / -127: turning right / left faster than 5 degrees in 30 s, no
  /// rate given (rotDegMin stays empty).
  int rotFast = 0;
  std::optional<int> navStatus;  ///< 0..15 (types 1-3 and 27)
  std::optional<bool> accuracy;  ///< position accuracy flag (true: better than 10 m)
  std::optional<int> second;     ///< UTC second of the report (0..59)
  /// The time stamp when it is not a second and says how the position was made: 61 manual input, 62
  /// estimated (dead reckoning), 63 positioning system inoperative (60, not available, is empty).
  std::optional<int> positionNotFix;
  std::optional<int> epfd;  ///< type of position fixing device (0 undefined is empty)
  // Type 4: UTC date and time, each part empty when not available.
  std::optional<int> year, month, day, hour, minute, utcSecond;
  // Static data (5, 19, 21, 24).
  std::optional<std::uint32_t> imo;  ///< 0 (not available) is empty
  std::string name, callsign, destination, vendor;
  std::optional<int> shipType;  ///< 1..255; 0 (not available) is empty
  std::optional<int> toBowM, toSternM, toPortM, toStarboardM;
  std::optional<double> draughtM;  ///< 0 (not available) is empty
  /// Type 5 ETA, each part empty when not available (month 0, day 0, hour 24, minute 60).
  std::optional<int> etaMonth, etaDay, etaHour, etaMinute;
  std::optional<char> part;    ///< type 24: 'A' or 'B'
  std::optional<int> aidType;  ///< type 21
  std::optional<bool> virtualAid, offPosition;
  /// Type 14 (safety-related broadcast): the text, up to 161 characters ("SART ACTIVE", "MOB TEST", ...).
  std::string text;
};

/// Every line the decoder saw, by what became of it.
struct AisCounters {
  std::uint64_t lines = 0;            ///< lines fed
  std::uint64_t decoded = 0;          ///< messages decoded
  std::uint64_t notAis = 0;           ///< not a !xxVDM / !xxVDO sentence (blank lines, comments, $GPRMC)
  std::uint64_t badChecksum = 0;      ///< missing or wrong NMEA checksum
  std::uint64_t malformed = 0;        ///< wrong field count, bad fragment numbers, sequence id or channel
  std::uint64_t badArmour = 0;        ///< a payload character outside '0'..'W' and '`'..'w'
  std::uint64_t badFill = 0;          ///< fill bits not 0..5, or more than the payload has
  std::uint64_t tooLong = 0;          ///< a line longer than kAisMaxLine
  std::uint64_t orphanFragments = 0;  ///< a fragment out of order or without its first part
  std::uint64_t expiredPartials = 0;  ///< a partial message dropped because it grew too old
  std::uint64_t evictedPartials = 0;  ///< a partial message dropped to make room (kAisMaxPartials)
  std::uint64_t unsupportedType = 0;  ///< a complete message of a type not decoded here
  std::uint64_t tooShort = 0;         ///< a payload shorter than its type's fields
  /// Adds another decoder's counts (several files, one summary).
  AisCounters& operator+=(const AisCounters& c) {
    lines += c.lines;
    decoded += c.decoded;
    notAis += c.notAis;
    badChecksum += c.badChecksum;
    malformed += c.malformed;
    badArmour += c.badArmour;
    badFill += c.badFill;
    tooLong += c.tooLong;
    orphanFragments += c.orphanFragments;
    expiredPartials += c.expiredPartials;
    evictedPartials += c.evictedPartials;
    unsupportedType += c.unsupportedType;
    tooShort += c.tooShort;
    return *this;
  }
  std::uint64_t rejected() const {
    return notAis + badChecksum + malformed + badArmour + badFill + tooLong + tooShort;
  }
};

inline constexpr std::size_t kAisMaxLine = 1024;    ///< longest line accepted, characters
inline constexpr std::size_t kAisMaxPartials = 64;  ///< partial multi-fragment messages kept at once

/// The fields of one !xxVDM / !xxVDO sentence.
struct AisSentence {
  std::string talker;  ///< "AI", "BS", ...
  bool own = false;    ///< VDO (own ship) rather than VDM
  int total = 0, number = 0;
  int sequence = -1;                  ///< 0..9, -1 when empty
  char channel = 0;                   ///< 'A', 'B', '1', '2' or 0 when empty
  std::vector<std::uint8_t> sixbits;  ///< the payload de-armoured, one 6-bit value each
  int fill = 0;
};

enum class AisLineResult : std::uint8_t { Ok, NotAis, BadChecksum, Malformed, BadArmour, BadFill, TooLong };

/// Parses one line (an optional NMEA 4.0 tag block "\...\" before it and any text after the checksum
/// are ignored).
AisLineResult parseAisSentence(std::string_view line, AisSentence& out);

/// The payload's bits, most significant first, each 6-bit value giving six.
class AisBits {
 public:
  AisBits(const std::vector<std::uint8_t>& sixbits, int fill);
  std::size_t size() const { return size_; }
  std::uint32_t u(std::size_t start, std::size_t width) const;  ///< width <= 32; 0 past the end
  std::int32_t s(std::size_t start, std::size_t width) const;   ///< two's complement
  /// Up to count six-bit characters ('@' 0 .. '_' 31, ' ' 32 .. '?' 63): the text ends at the first '@'
  /// (padding), trailing spaces removed.
  std::string text(std::size_t start, std::size_t count) const;

 private:
  const std::vector<std::uint8_t>& six_;
  std::size_t size_;
};

enum class AisDecodeResult : std::uint8_t { Ok, Unsupported, TooShort };

/// Decodes a complete payload into out.
AisDecodeResult decodeAisPayload(const AisBits& bits, AisMessage& out);

/// A stream of lines in, messages out. Partials of multi-fragment messages are keyed by (sequence
/// id, channel, fragment count); one older than maxAgeLines lines or maxAgeSeconds seconds (when the
/// caller gives times) is dropped and counted.
class AisDecoder {
 public:
  struct Limits {
    std::uint64_t maxAgeLines = 100;
    double maxAgeSeconds = 60.0;
    std::size_t maxPartials = kAisMaxPartials;
  };
  AisDecoder();
  explicit AisDecoder(Limits limits);
  /// Feeds one line; the decoded message when the line completes one. timeSeconds (when not negative)
  /// is the line's reception time for the age limit.
  std::optional<AisMessage> feed(std::string_view line, double timeSeconds = -1.0);
  const AisCounters& counters() const { return counters_; }
  std::size_t partialsInFlight() const { return partials_.size(); }

 private:
  struct Partial {
    int sequence = -1, total = 0, next = 0;
    char channel = 0;
    std::uint64_t firstLine = 0;
    double firstTime = -1.0;
    std::vector<std::uint8_t> sixbits;
  };
  void expire(double timeSeconds);
  std::optional<AisMessage> complete(const std::vector<std::uint8_t>& sixbits, int fill);
  std::optional<AisMessage> fragment(AisSentence& s, double timeSeconds);

  Limits limits_;
  AisCounters counters_;
  std::vector<Partial> partials_;
};

}  // namespace reckoner::io
