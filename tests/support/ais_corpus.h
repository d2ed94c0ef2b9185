#pragma once
// AIS sentences of our own encoding (ITU-R M.1371-5 field by field): the builders the decoder's tests
// write messages with, and a corpus of every decoded type with edge and "not available" values that
// tests/app/tst_ais_cli.cpp gives both to gpsdecode and to `reckoner-cli ais decode`, and that seeds
// the decoder's fuzz target (docs/robustness.md).
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace reckoner::test::ais {

/// A payload written field by field, most significant bit first, then armoured into a sentence.
struct PayloadBuilder {
  std::vector<int> bits;
  PayloadBuilder& put(long long value, int width) {
    for (int i = width - 1; i >= 0; --i) bits.push_back(static_cast<int>((value >> i) & 1));
    return *this;
  }
  PayloadBuilder& text(const std::string& s, int chars) {
    for (int i = 0; i < chars; ++i) {
      const int c =
          i < static_cast<int>(s.size()) ? static_cast<unsigned char>(s[static_cast<std::size_t>(i)]) : '@';
      put(c >= 64 ? c - 64 : c, 6);
    }
    return *this;
  }
  PayloadBuilder& truncate(std::size_t n) {
    bits.resize(n);
    return *this;
  }
  /// The armoured payload and its fill bits.
  std::pair<std::string, int> armoured() const {
    std::string s;
    const int fill = static_cast<int>((6 - bits.size() % 6) % 6);
    for (std::size_t i = 0; i < bits.size(); i += 6) {
      int v = 0;
      for (std::size_t j = i; j < i + 6; ++j) v = (v << 1) | (j < bits.size() ? bits[j] : 0);
      s.push_back(static_cast<char>(v < 40 ? v + 48 : v + 56));
    }
    return {s, fill};
  }
};

inline std::string withSum(const std::string& body) {
  unsigned x = 0;
  for (const char c : body) x ^= static_cast<unsigned char>(c);
  char buf[8];
  std::snprintf(buf, sizeof buf, "*%02X", x);
  return "!" + body + buf;
}

inline std::string sentence(const std::string& payload, int fill, const std::string& frag = "1,1,",
                            char channel = 'A') {
  return withSum("AIVDM," + frag + "," + std::string(1, channel) + "," + payload + "," +
                 std::to_string(fill));
}

inline std::string sentence(const PayloadBuilder& p) {
  const auto [s, fill] = p.armoured();
  return sentence(s, fill);
}

/// Type 1-3 class A position report (168 bits); `stamp` the time stamp (a second, or 60-63).
inline PayloadBuilder classA(int type, long long mmsi, int status, int rot, int sog, long long lon,
                             long long lat, int cog, int heading, int stamp = 33) {
  PayloadBuilder p;
  p.put(type, 6).put(0, 2).put(mmsi, 30).put(status, 4).put(rot, 8).put(sog, 10).put(1, 1);
  p.put(lon, 28)
      .put(lat, 27)
      .put(cog, 12)
      .put(heading, 9)
      .put(stamp, 6)
      .put(0, 2)
      .put(0, 3)
      .put(0, 1)
      .put(0, 19);
  return p;
}

inline PayloadBuilder baseStation() {
  PayloadBuilder p;
  p.put(4, 6).put(0, 2).put(3669702, 30).put(2007, 14).put(5, 4).put(14, 5).put(19, 5).put(57, 6).put(39, 6);
  p.put(1, 1).put(-45811417, 28).put(22130260, 27).put(7, 4).put(0, 10).put(0, 1).put(0, 19);
  return p;
}

inline PayloadBuilder staticVoyage() {
  PayloadBuilder p;
  p.put(5, 6)
      .put(0, 2)
      .put(351759000, 30)
      .put(0, 2)
      .put(9134270, 30)
      .text("3FOF8", 7)
      .text("EVER DIADEM", 20);
  p.put(70, 8).put(225, 9).put(70, 9).put(1, 6).put(31, 6).put(1, 4).put(5, 4).put(15, 5).put(14, 5).put(0,
                                                                                                         6);
  p.put(122, 8).text("NEW YORK", 20).put(0, 1).put(0, 1);
  return p;
}

inline PayloadBuilder classB(int type) {
  PayloadBuilder p;
  p.put(type, 6).put(0, 2).put(338087471, 30).put(0, 8).put(1, 10).put(0, 1).put(-44443279, 28);
  p.put(24410724, 27).put(796, 12).put(511, 9).put(49, 6);
  if (type == 18) return p.put(0, 2).put(0x3f, 6).put(0, 1).put(0, 20);  // 168 bits
  p.put(0, 4).text("CAPT.J.RIMES", 20).put(70, 8).put(5, 9).put(21, 9).put(4, 6).put(4, 6).put(1, 4);
  return p.put(0, 1).put(0, 1).put(0, 1).put(0, 4);
}

inline PayloadBuilder aidToNavigation(const std::string& name, const std::string& extension) {
  PayloadBuilder p;
  p.put(21, 6).put(0, 2).put(123456789, 30).put(20, 5).text(name, 20).put(0, 1).put(-73619155, 28);
  p.put(28752371, 27).put(5, 9).put(5, 9).put(5, 6).put(5, 6).put(1, 4).put(50, 6).put(1, 1).put(165, 8);
  p.put(0, 1).put(1, 1).put(0, 1).put(0, 1);
  if (!extension.empty()) p.text(extension, static_cast<int>(extension.size()));
  return p;
}

inline PayloadBuilder staticReport(int part) {
  PayloadBuilder p;
  p.put(24, 6).put(0, 2).put(271041815, 30).put(part, 2);
  if (part == 0) return p.text("PROGUY", 20).put(0, 8);
  p.put(60, 8).text("1D0", 3).put(12, 4).put(199796, 20).text("TC6163", 7).put(0, 9).put(15, 9).put(0, 6);
  return p.put(5, 6).put(0, 6);
}

inline PayloadBuilder longRange(long long lon, long long lat, int sog, int cog) {
  PayloadBuilder p;
  p.put(27, 6).put(1, 2).put(206914217, 30).put(0, 1).put(0, 1).put(2, 4).put(lon, 18).put(lat, 17);
  return p.put(sog, 6).put(cog, 9).put(0, 1).put(0, 1);
}

/// Type 14 safety-related broadcast: the text, as many characters as it has (no padding).
inline PayloadBuilder safetyBroadcast(long long mmsi, const std::string& text) {
  PayloadBuilder p;
  p.put(14, 6).put(0, 2).put(mmsi, 30).put(0, 2);
  return p.text(text, static_cast<int>(text.size()));
}

/// A payload in fragments of at most maxChars armour characters (sequence id seq), as a long type 5 is
/// sent: the fill bits on the last fragment only.
inline std::vector<std::string> fragments(const PayloadBuilder& p, int seq, std::size_t maxChars = 60,
                                          char channel = 'B') {
  const auto [s, fill] = p.armoured();
  const std::size_t n = (s.size() + maxChars - 1) / maxChars;
  std::vector<std::string> out;
  for (std::size_t i = 0; i < n; ++i)
    out.push_back(sentence(s.substr(i * maxChars, maxChars), i + 1 == n ? fill : 0,
                           std::to_string(n) + "," + std::to_string(i + 1) + "," + std::to_string(seq),
                           channel));
  return out;
}

/// Every decoded type (1, 2, 3, 4, 5, 14, 18, 19, 21, 24 A and B, 27) with ordinary, edge and "not
/// available" values, one sentence per line (type 5 in two fragments); an AIS-SART's position reports
/// (MMSI 970xxyyyy, status 14 active and 15 test) with time stamps 60-63, and its type 14 texts.
inline std::vector<std::string> corpus() {
  std::vector<std::string> c;
  const auto add = [&c](const PayloadBuilder& p) { c.push_back(sentence(p)); };
  for (const int type : {1, 2, 3}) add(classA(type, 244740981, 5, 64, 101, 3442480, 31919541, 3599, 359));
  add(classA(1, 1, 0, -20, 0, 0, 0, 0, 0));                            // left turn
  add(classA(1, 2, 1, 127, 1022, -108000000, -54000000, 0, 0));        // fast right, 180 W
  add(classA(3, 3, 15, -128, 1023, 0x6791AC0, 0x3412140, 3600, 511));  // not available
  add(classA(2, 999999999, 8, 0, 5, 108000000, 54000000, 1800, 180));  // 180 E, 90 N
  add(classA(1, 211000001, 0, -126, 400, -1, -1, 1, 1));               // just west, south
  add(baseStation());
  for (const auto& f : fragments(staticVoyage(), 3)) c.push_back(f);
  add(classB(18));
  add(classB(19));
  add(aidToNavigation("SF APPROACH LIGHTED ", ""));
  add(aidToNavigation("NAME THAT IS LONGER ", "THAN TWENTY"));
  add(staticReport(0));
  add(staticReport(1));
  add(longRange(-73230, 24540, 12, 275));
  add(longRange(108600, 54600, 63, 511));                                          // not available
  add(classA(1, 970012345, 14, -128, 0, -73440000, 28380000, 3600, 511, 61));      // SART active, manual
  add(classA(1, 970012345, 14, -128, 3, -73440010, 28380010, 1234, 511, 62));      // dead reckoning
  add(classA(1, 972001002, 15, -128, 1023, 0x6791AC0, 0x3412140, 3600, 511, 63));  // MOB test, inoperative
  add(classA(1, 974001003, 14, -128, 1, -73440020, 28380020, 900, 511, 60));       // EPIRB, no second
  add(safetyBroadcast(970012345, "SART ACTIVE"));
  add(safetyBroadcast(972001002, "MOB TEST"));
  add(safetyBroadcast(2442000, std::string(161, 'W')));  // the longest text
  add(safetyBroadcast(2442001, ""));                     // no text
  return c;
}

}  // namespace reckoner::test::ais
