#include "files/ais_output.h"

#include <array>
#include <cstdio>

#include "io/iso8601.h"
#include "io/json.h"

namespace reckoner::files {
namespace {

std::string number(double v, const char* format) {
  char buf[48];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

template <class T>
void addInt(AisFields& f, const char* name, const std::optional<T>& v) {
  if (v) f.emplace_back(name, std::to_string(*v));
}
void addReal(AisFields& f, const char* name, const std::optional<double>& v, const char* format) {
  if (v) f.emplace_back(name, number(*v, format));
}
void addText(AisFields& f, const char* name, const std::string& v) {
  if (!v.empty()) f.emplace_back(name, io::jsonQuote(v));
}

std::string two(int v) {
  return number(v, "%02.0f");
}

void addTimes(AisFields& f, const io::AisMessage& m) {
  if (m.etaMonth && m.etaDay && m.etaHour && m.etaMinute)
    f.emplace_back("eta", io::jsonQuote(two(*m.etaMonth) + "-" + two(*m.etaDay) + "T" + two(*m.etaHour) +
                                        ":" + two(*m.etaMinute)));
  if (m.year && m.month && m.day && m.hour && m.minute && m.utcSecond)
    f.emplace_back("utc",
                   io::jsonQuote(std::to_string(*m.year) + "-" + two(*m.month) + "-" + two(*m.day) + "T" +
                                 two(*m.hour) + ":" + two(*m.minute) + ":" + two(*m.utcSecond) + "Z"));
}

// The columns of ais.csv after utc and source, in the order aisFields gives them.
constexpr std::array<const char*, 31> kColumns{
    "type",       "mmsi",        "part",         "lat_deg",     "lon_deg",
    "sog_kn",     "cog_deg",     "heading_deg",  "rot_deg_min", "rot_fast",
    "nav_status", "name",        "callsign",     "imo",         "ship_type",
    "vendor",     "to_bow_m",    "to_stern_m",   "to_port_m",   "to_starboard_m",
    "draught_m",  "destination", "eta",          "utc_report",  "epfd",
    "aid_type",   "virtual",     "off_position", "second",      "position_not_fix",
    "text"};

/// A JSON value as a CSV field: text unquoted from JSON and quoted for CSV when it needs it.
std::string csvField(const std::string& json) {
  if (json.empty() || json.front() != '"') return json;
  std::string text;
  bool needsQuotes = false;
  for (std::size_t i = 1; i + 1 < json.size(); ++i) {
    char c = json[i];
    if (c == '\\' && i + 2 < json.size()) {
      c = json[++i];
      if (c == 'n' || c == 'r' || c == 't') c = ' ';  // AIS text has none of them; keep rows one line
    }
    if (c == ',' || c == '"') needsQuotes = true;
    if (c == '"') text += '"';
    text += c;
  }
  return needsQuotes ? "\"" + text + "\"" : text;
}

}  // namespace

AisFields aisFields(const io::AisMessage& m) {
  AisFields f{{"type", std::to_string(m.type)}, {"mmsi", std::to_string(m.mmsi)}};
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
  addInt(f, "second", m.second);
  addInt(f, "position_not_fix", m.positionNotFix);
  addText(f, "text", m.text);
  return f;
}

std::string aisFieldsLine(const AisFields& f, bool json) {
  std::string s = json ? "{" : "";
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (i > 0) s.append(json ? "," : " ");
    if (json)
      s.append(io::jsonQuote(f[i].first)).append(":").append(f[i].second);
    else
      s.append(f[i].first).append("=").append(f[i].second);
  }
  if (json) s.append("}");
  return s;
}

std::string aisCsvHeader() {
  std::string s = "utc,source";
  for (const char* c : kColumns) s.append(",").append(c);
  return s;
}

std::string aisCsvLine(UtcUs receivedUtc, std::string_view source, const io::AisMessage& m) {
  std::string s = io::formatIso8601(receivedUtc);
  s.append(",").append(csvField(io::jsonQuote(std::string(source))));
  const AisFields f = aisFields(m);
  const auto valueOf = [&f](std::string_view name) -> std::string {
    for (const auto& [k, v] : f)
      if (k == name) return v;
    return {};
  };
  for (const char* c : kColumns) {
    // The decode output calls a type 4 report's own time "utc"; in the CSV "utc" is the receive time.
    const std::string_view key = std::string_view(c) == "utc_report" ? "utc" : c;
    s.append(",").append(csvField(valueOf(key)));
  }
  return s;
}

}  // namespace reckoner::files
