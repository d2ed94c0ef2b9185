// ais decode FILE... [--json]: the AIS messages of NMEA files (docs/ais.md), one line each on stdout,
// JSON Lines with --json; lines that are not AIS or are rejected are counted in one summary line on
// stderr.
#include <cstdio>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cli/cli_options.h"
#include "cli/commands.h"
#include "io/ais.h"
#include "io/json.h"
#include "io/text_file.h"

namespace reckoner::cli {
namespace {

struct AisArgs {
  std::vector<std::string> files;
  bool json = false;
};

using Fields = std::vector<std::pair<std::string, std::string>>;  // name, JSON value

std::string number(double v, const char* format) {
  char buf[48];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

template <class T>
void addInt(Fields& f, const char* name, const std::optional<T>& v) {
  if (v) f.emplace_back(name, std::to_string(*v));
}
void addReal(Fields& f, const char* name, const std::optional<double>& v, const char* format) {
  if (v) f.emplace_back(name, number(*v, format));
}
void addText(Fields& f, const char* name, const std::string& v) {
  if (!v.empty()) f.emplace_back(name, io::jsonQuote(v));
}

std::string two(int v) {
  return number(v, "%02.0f");
}

void addTimes(Fields& f, const io::AisMessage& m) {
  if (m.etaMonth && m.etaDay && m.etaHour && m.etaMinute)
    f.emplace_back("eta", io::jsonQuote(two(*m.etaMonth) + "-" + two(*m.etaDay) + "T" + two(*m.etaHour) +
                                        ":" + two(*m.etaMinute)));
  if (m.year && m.month && m.day && m.hour && m.minute && m.utcSecond)
    f.emplace_back("utc",
                   io::jsonQuote(std::to_string(*m.year) + "-" + two(*m.month) + "-" + two(*m.day) + "T" +
                                 two(*m.hour) + ":" + two(*m.minute) + ":" + two(*m.utcSecond) + "Z"));
}

Fields fieldsOf(const io::AisMessage& m) {
  Fields f{{"type", std::to_string(m.type)}, {"mmsi", std::to_string(m.mmsi)}};
  if (m.part) f.emplace_back("part", io::jsonQuote(std::string(1, *m.part)));
  addReal(f, "lat_deg", m.latDeg, "%.7f");
  addReal(f, "lon_deg", m.lonDeg, "%.7f");
  addReal(f, "sog_kn", m.sogKn, "%.1f");
  addReal(f, "cog_deg", m.cogDeg, "%.1f");
  addInt(f, "heading_deg", m.headingDeg);
  addReal(f, "rot_deg_min", m.rotDegMin, "%.3f");
  if (m.rotFast != 0) f.emplace_back("rot_fast", io::jsonQuote(m.rotFast > 0 ? "right" : "left"));
  addInt(f, "nav_status", m.navStatus);
  addText(f, "name", m.name);
  addText(f, "callsign", m.callsign);
  addInt(f, "imo", m.imo);
  addInt(f, "ship_type", m.shipType);
  addText(f, "vendor", m.vendor);
  addInt(f, "to_bow_m", m.toBowM);
  addInt(f, "to_stern_m", m.toSternM);
  addInt(f, "to_port_m", m.toPortM);
  addInt(f, "to_starboard_m", m.toStarboardM);
  addReal(f, "draught_m", m.draughtM, "%.1f");
  addText(f, "destination", m.destination);
  addTimes(f, m);
  addInt(f, "epfd", m.epfd);
  addInt(f, "aid_type", m.aidType);
  if (m.virtualAid) f.emplace_back("virtual", *m.virtualAid ? "true" : "false");
  if (m.offPosition) f.emplace_back("off_position", *m.offPosition ? "true" : "false");
  return f;
}

std::string lineOf(const Fields& f, bool json) {
  std::string s = json ? "{" : "";
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (i > 0) s.append(json ? "," : " ");
    if (json)
      s.append(io::jsonQuote(f[i].first)).append(":").append(f[i].second);
    else
      s.append(f[i].first).append("=").append(f[i].second);
  }
  if (json) s.append("}");
  return s.append("\n");
}

void printSummary(const io::AisCounters& c) {
  std::fprintf(
      stderr,
      "ais: %llu lines, %llu decoded, %llu not AIS, %llu bad checksum, %llu malformed, %llu bad "
      "armour, %llu bad fill bits, %llu too long, %llu orphan fragments, %llu partials expired, "
      "%llu partials evicted, %llu unsupported types, %llu too short\n",
      static_cast<unsigned long long>(c.lines), static_cast<unsigned long long>(c.decoded),
      static_cast<unsigned long long>(c.notAis), static_cast<unsigned long long>(c.badChecksum),
      static_cast<unsigned long long>(c.malformed), static_cast<unsigned long long>(c.badArmour),
      static_cast<unsigned long long>(c.badFill), static_cast<unsigned long long>(c.tooLong),
      static_cast<unsigned long long>(c.orphanFragments), static_cast<unsigned long long>(c.expiredPartials),
      static_cast<unsigned long long>(c.evictedPartials), static_cast<unsigned long long>(c.unsupportedType),
      static_cast<unsigned long long>(c.tooShort));
}

int aisDecode(const AisArgs& a) {
  if (a.files.empty()) throw UsageError("ais decode needs at least one FILE");
  std::vector<std::string> texts;
  for (const auto& file : a.files) texts.push_back(io::readTextFile(file));  // throws naming the file
  io::AisCounters total;
  for (const auto& text : texts) {
    io::AisDecoder decoder;  // fragments never join across files
    std::string_view rest = text;
    while (!rest.empty()) {
      const auto nl = rest.find('\n');
      const std::string_view line = rest.substr(0, nl);
      rest.remove_prefix(nl == std::string_view::npos ? rest.size() : nl + 1);
      if (const auto m = decoder.feed(line)) std::fputs(lineOf(fieldsOf(*m), a.json).c_str(), stdout);
    }
    total += decoder.counters();
  }
  printSummary(total);
  return 0;
}

}  // namespace

void addAisCommands(CLI::App& root, Commands& out) {
  CLI::App* ais = root.add_subcommand("ais", "AIS messages from NMEA files (!AIVDM / !AIVDO)");
  ais->require_subcommand(1);
  auto a = std::make_shared<AisArgs>();
  CLI::App* decode = ais->add_subcommand(
      "decode",
      "Decode the AIS messages of FILEs (types 1-5, 18, 19, 21, 24, 27), one line each; a summary "
      "of skipped lines on stderr");
  addListArgument(*decode, "FILE", a->files, 1, "NMEA files with !AIVDM / !AIVDO sentences");
  addFlag(*decode, "json", a->json, "JSON Lines: one object per message, absent values left out");
  out.push_back({decode, [a] { return aisDecode(*a); }, ""});
}

}  // namespace reckoner::cli
