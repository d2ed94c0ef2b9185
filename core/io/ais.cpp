// AIS sentences, their six-bit payloads and the reassembly of multi-fragment messages (docs/ais.md).
// The message layouts are in ais_messages.cpp.
#include "io/ais.h"

#include <algorithm>
#include <array>

namespace reckoner::io {
namespace {

int hexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

/// "!AIVDM,...*hh" with the tag block removed: the body between '!' and '*', or empty when the line is
/// no AIS sentence at all.
std::string_view sentenceStart(std::string_view line) {
  if (!line.empty() && line.front() == '\\') {
    const auto end = line.find('\\', 1);
    if (end == std::string_view::npos) return {};
    line.remove_prefix(end + 1);
  }
  if (line.size() < 7 || line[0] != '!') return {};
  const std::string_view kind = line.substr(3, 4);
  if (kind != "VDM," && kind != "VDO,") return {};
  return line;
}

/// The comma-separated fields of body (without '!' and the checksum).
std::vector<std::string_view> splitFields(std::string_view body) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  for (;;) {
    const auto comma = body.find(',', start);
    fields.push_back(body.substr(start, comma == std::string_view::npos ? comma : comma - start));
    if (comma == std::string_view::npos || fields.size() > 8) return fields;
    start = comma + 1;
  }
}

/// A one-digit field in [min, max], else -1.
int digit(std::string_view f, int min, int max) {
  if (f.size() != 1 || f[0] < '0' || f[0] > '9') return -1;
  const int v = f[0] - '0';
  return v < min || v > max ? -1 : v;
}

bool armour(std::string_view payload, std::vector<std::uint8_t>& out) {
  out.clear();
  out.reserve(payload.size());
  for (const char c : payload) {
    if (c >= '0' && c <= 'W')
      out.push_back(static_cast<std::uint8_t>(c - '0'));
    else if (c >= '`' && c <= 'w')
      out.push_back(static_cast<std::uint8_t>(c - '8'));
    else
      return false;
  }
  return true;
}

/// The checksum: '*' and two hex digits equal to the XOR of body's characters.
bool checksumOk(std::string_view afterBang, std::string_view& body) {
  const auto star = afterBang.find('*');
  if (star == std::string_view::npos || afterBang.size() < star + 3) return false;
  const int hi = hexDigit(afterBang[star + 1]), lo = hexDigit(afterBang[star + 2]);
  if (hi < 0 || lo < 0) return false;
  body = afterBang.substr(0, star);
  unsigned x = 0;
  for (const char c : body) x ^= static_cast<unsigned char>(c);
  return x == static_cast<unsigned>(hi * 16 + lo);
}

}  // namespace

AisLineResult parseAisSentence(std::string_view line, AisSentence& out) {
  if (line.size() > kAisMaxLine) return AisLineResult::TooLong;
  while (!line.empty() && (line.back() == '\r' || line.back() == '\n')) line.remove_suffix(1);
  const std::string_view start = sentenceStart(line);
  if (start.empty()) return AisLineResult::NotAis;
  std::string_view body;
  if (!checksumOk(start.substr(1), body)) return AisLineResult::BadChecksum;
  const auto f = splitFields(body);
  if (f.size() != 7 || f[0].size() != 5) return AisLineResult::Malformed;  // e.g. "!M,VDO,..."
  out.talker = std::string(f[0].substr(0, 2));
  out.own = f[0].substr(2) == "VDO";
  out.total = digit(f[1], 1, 9);
  out.number = digit(f[2], 1, 9);
  out.sequence = f[3].empty() ? -1 : digit(f[3], 0, 9);
  const bool channelOk =
      f[4].size() <= 1 && (f[4].empty() || std::string_view("AB12").find(f[4][0]) != std::string_view::npos);
  if (out.total < 0 || out.number < 0 || out.number > out.total || (!f[3].empty() && out.sequence < 0) ||
      !channelOk)
    return AisLineResult::Malformed;
  out.channel = f[4].empty() ? '\0' : f[4][0];
  if (!armour(f[5], out.sixbits)) return AisLineResult::BadArmour;
  out.fill = digit(f[6], 0, 5);
  if (out.fill < 0 || (out.sixbits.empty() && out.fill > 0)) return AisLineResult::BadFill;
  return AisLineResult::Ok;
}

AisBits::AisBits(const std::vector<std::uint8_t>& sixbits, int fill)
    : six_(sixbits), size_(sixbits.size() * 6 - std::min<std::size_t>(sixbits.size() * 6, fill)) {}

std::uint32_t AisBits::u(std::size_t start, std::size_t width) const {
  std::uint32_t v = 0;
  for (std::size_t i = start; i < start + width; ++i) {
    const std::uint32_t bit = i < size_ ? (six_[i / 6] >> (5 - i % 6)) & 1u : 0u;
    v = (v << 1) | bit;
  }
  return v;
}

std::int32_t AisBits::s(std::size_t start, std::size_t width) const {
  const std::uint32_t v = u(start, width);
  const std::uint32_t sign = 1u << (width - 1);
  return static_cast<std::int32_t>(v ^ sign) - static_cast<std::int32_t>(sign);
}

std::string AisBits::text(std::size_t start, std::size_t count) const {
  std::string t;
  for (std::size_t i = 0; i < count && start + 6 * (i + 1) <= size_; ++i) {
    const auto v = u(start + 6 * i, 6);
    if (v == 0) break;  // '@' ends the text
    t.push_back(static_cast<char>(v < 32 ? v + 64 : v));
  }
  while (!t.empty() && t.back() == ' ') t.pop_back();
  return t;
}

AisDecoder::AisDecoder() : AisDecoder(Limits{}) {}
AisDecoder::AisDecoder(Limits limits) : limits_(limits) {}

void AisDecoder::expire(double timeSeconds) {
  const auto old = [&](const Partial& p) {
    if (counters_.lines - p.firstLine > limits_.maxAgeLines) return true;
    return timeSeconds >= 0 && p.firstTime >= 0 && timeSeconds - p.firstTime > limits_.maxAgeSeconds;
  };
  const auto before = partials_.size();
  partials_.erase(std::remove_if(partials_.begin(), partials_.end(), old), partials_.end());
  counters_.expiredPartials += before - partials_.size();
}

std::optional<AisMessage> AisDecoder::complete(const std::vector<std::uint8_t>& sixbits, int fill) {
  if (fill > 0 && sixbits.size() * 6 < static_cast<std::size_t>(fill)) {
    ++counters_.badFill;
    return std::nullopt;
  }
  AisMessage m;
  switch (decodeAisPayload(AisBits(sixbits, fill), m)) {
    case AisDecodeResult::Ok:
      ++counters_.decoded;
      return m;
    case AisDecodeResult::Unsupported:
      ++counters_.unsupportedType;
      return std::nullopt;
    case AisDecodeResult::TooShort:
      ++counters_.tooShort;
      return std::nullopt;
  }
  return std::nullopt;
}

std::optional<AisMessage> AisDecoder::fragment(AisSentence& s, double timeSeconds) {
  const auto it = std::find_if(partials_.begin(), partials_.end(), [&](const Partial& p) {
    return p.sequence == s.sequence && p.channel == s.channel && p.total == s.total;
  });
  if (s.number == 1) {
    if (it != partials_.end()) {  // a new message under the same key: the old one never finished
      ++counters_.orphanFragments;
      partials_.erase(it);
    }
    if (partials_.size() >= limits_.maxPartials) {
      partials_.erase(partials_.begin());  // the oldest
      ++counters_.evictedPartials;
    }
    partials_.push_back(
        {s.sequence, s.total, 2, s.channel, counters_.lines, timeSeconds, std::move(s.sixbits)});
    return std::nullopt;
  }
  if (it == partials_.end() || it->next != s.number) {
    ++counters_.orphanFragments;
    if (it != partials_.end()) partials_.erase(it);
    return std::nullopt;
  }
  it->sixbits.insert(it->sixbits.end(), s.sixbits.begin(), s.sixbits.end());
  ++it->next;
  if (s.number < s.total) return std::nullopt;
  const std::vector<std::uint8_t> whole = std::move(it->sixbits);
  partials_.erase(it);
  return complete(whole, s.fill);
}

std::optional<AisMessage> AisDecoder::feed(std::string_view line, double timeSeconds) {
  ++counters_.lines;
  expire(timeSeconds);
  AisSentence s;
  switch (parseAisSentence(line, s)) {
    case AisLineResult::Ok:
      break;
    case AisLineResult::NotAis:
      ++counters_.notAis;
      return std::nullopt;
    case AisLineResult::BadChecksum:
      ++counters_.badChecksum;
      return std::nullopt;
    case AisLineResult::Malformed:
      ++counters_.malformed;
      return std::nullopt;
    case AisLineResult::BadArmour:
      ++counters_.badArmour;
      return std::nullopt;
    case AisLineResult::BadFill:
      ++counters_.badFill;
      return std::nullopt;
    case AisLineResult::TooLong:
      ++counters_.tooLong;
      return std::nullopt;
  }
  if (s.total == 1) return complete(s.sixbits, s.fill);
  return fragment(s, timeSeconds);
}

}  // namespace reckoner::io
