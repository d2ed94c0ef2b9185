#include "files/alert_output.h"

#include <cstdio>

#include "io/iso8601.h"

namespace reckoner::files {
namespace {
/// A text field as CSV writes it: quoted (quotes doubled) when it holds a comma or a quote.
std::string csvText(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string q = "\"";
  for (const char c : s) {
    if (c == '"') q += '"';
    q += (c == '\r' || c == '\n') ? ' ' : c;
  }
  return q + "\"";
}
}  // namespace

std::string alertCsvHeader() {
  return "utc,t_s,event,priority,kind,source,text";
}

std::string alertCsvLine(const alerts::AlertLogEntry& e, UtcUs zeroUtc) {
  char t[32];
  std::snprintf(t, sizeof t, "%.3f", toSeconds(e.timeUs));
  return io::formatIso8601(zeroUtc + e.timeUs) + "," + t + "," + alerts::eventName(e.event) + "," +
         alerts::priorityName(e.priority) + "," + csvText(alerts::traitsOf(e.id.kind).name) + "," +
         std::to_string(e.id.source) + "," + csvText(e.text);
}

}  // namespace reckoner::files
