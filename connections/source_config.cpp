#include "source_config.h"

#include <algorithm>
#include <charconv>
#include <sstream>
#include <stdexcept>

namespace reckoner::conn {

namespace {

[[noreturn]] void fail(const std::string& spec, const std::string& field, const std::string& why) {
  throw std::invalid_argument("connection spec '" + spec + "': " + field + ": " + why);
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  std::istringstream in(s);
  while (std::getline(in, cur, sep)) {
    if (!cur.empty()) out.push_back(cur);
  }
  return out;
}

std::string join(const std::vector<std::string>& v) {
  std::string out;
  for (const std::string& s : v) out += (out.empty() ? "" : ",") + s;
  return out;
}

long long parseInt(const std::string& spec, const std::string& field, const std::string& text, long long lo,
                   long long hi) {
  long long v = 0;
  const auto* end = text.data() + text.size();
  const auto r = std::from_chars(text.data(), end, v);
  if (text.empty() || r.ec != std::errc() || r.ptr != end)
    fail(spec, field, "'" + text + "' is not an integer");
  if (v < lo || v > hi)
    fail(spec, field,
         std::to_string(v) + " is out of range " + std::to_string(lo) + ".." + std::to_string(hi));
  return v;
}

double parsePositive(const std::string& spec, const std::string& field, const std::string& text) {
  std::size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    fail(spec, field, "'" + text + "' is not a number");
  }
  if (used != text.size() || !(v > 0.0) || v > 1e6)
    fail(spec, field, "'" + text + "' is not a number in (0, 1e6]");
  return v;
}

/// "HOST:PORT", ":PORT", "[v6]:PORT" or "HOST" -> host and port text.
void splitHostPort(const std::string& spec, const std::string& rest, std::string& host, std::string& port) {
  if (!rest.empty() && rest.front() == '[') {
    const auto close = rest.find(']');
    if (close == std::string::npos) fail(spec, "host", "'[' without ']'");
    host = rest.substr(1, close - 1);
    const std::string after = rest.substr(close + 1);
    if (!after.empty() && after.front() != ':') fail(spec, "port", "expected ':' after ']'");
    port = after.empty() ? "" : after.substr(1);
    return;
  }
  const auto colon = rest.rfind(':');
  if (colon == std::string::npos) {
    host = rest;
    port.clear();
  } else {
    host = rest.substr(0, colon);
    port = rest.substr(colon + 1);
  }
}

bool isMulticast(const std::string& host) {
  if (host.size() >= 2 && (host.compare(0, 2, "ff") == 0 || host.compare(0, 2, "FF") == 0) &&
      host.find(':') != std::string::npos)
    return true;
  const auto dot = host.find('.');
  if (dot == std::string::npos) return false;
  int first = 0;
  const auto r = std::from_chars(host.data(), host.data() + dot, first);
  return r.ec == std::errc() && r.ptr == host.data() + dot && first >= 224 && first <= 239;
}

std::string hostText(const std::string& host) {
  return host.find(':') != std::string::npos ? "[" + host + "]" : host;
}

std::string baseName(const std::string& path) {
  const auto slash = path.rfind('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string rateText(const FileRate& r) {
  std::ostringstream o;
  if (r.ownTime && r.speedFactor == 1.0) return "realtime";
  if (r.ownTime)
    o << 'x' << r.speedFactor;
  else
    o << r.linesPerSecond;
  return o.str();
}

std::string defaultName(const SourceConfig& c) {
  std::string k = kindName(c.kind);  // not const: the last return moves it
  switch (c.kind) {
    case Kind::Udp:
      return k + ":" + (c.host.empty() ? "" : hostText(c.host) + ":") + std::to_string(c.port);
    case Kind::Tcp:
    case Kind::Gpsd:
      return k + ":" + hostText(c.host) + ":" + std::to_string(c.port);
    case Kind::Serial:
      return k + ":" + baseName(c.device);
    case Kind::File:
      return k + ":" + baseName(c.path);
  }
  return k;
}

}  // namespace

const char* kindName(Kind k) {
  switch (k) {
    case Kind::Udp:
      return "udp";
    case Kind::Tcp:
      return "tcp";
    case Kind::Serial:
      return "serial";
    case Kind::Gpsd:
      return "gpsd";
    case Kind::File:
      return "file";
  }
  return "?";
}

const char* roleName(Role r) {
  return r == Role::Radar ? "radar" : "nmea";
}

bool InputFilter::accepts(const std::string& talker, const std::string& type) const {
  const auto in = [](const std::vector<std::string>& v, const std::string& s) {
    return std::find(v.begin(), v.end(), s) != v.end();
  };
  if (!acceptTypes.empty() && !in(acceptTypes, type)) return false;
  if (!acceptTalkers.empty() && !in(acceptTalkers, talker)) return false;
  return !in(rejectTypes, type) && !in(rejectTalkers, talker);
}

SourceConfig parseSource(const std::string& spec) {
  const auto sep = spec.find("://");
  if (sep == std::string::npos) fail(spec, "kind", "expected KIND://... (udp, tcp, serial, gpsd, file)");
  const std::string kind = spec.substr(0, sep);
  std::string rest = spec.substr(sep + 3);
  std::string query;
  if (const auto q = rest.find('?'); q != std::string::npos) {
    query = rest.substr(q + 1);
    rest = rest.substr(0, q);
  }
  SourceConfig c;
  std::string host, port;
  if (kind == "udp" || kind == "tcp" || kind == "gpsd") {
    c.kind = kind == "udp" ? Kind::Udp : kind == "tcp" ? Kind::Tcp : Kind::Gpsd;
    splitHostPort(spec, rest, host, port);
    if (port.empty() && c.kind == Kind::Gpsd) port = "2947";
    if (port.empty()) fail(spec, "port", "missing (" + kind + "://HOST:PORT)");
    c.port = static_cast<std::uint16_t>(parseInt(spec, "port", port, 1, 65535));
    if (host.empty() && c.kind != Kind::Udp) fail(spec, "host", "missing (" + kind + "://HOST:PORT)");
    c.host = host;
    c.multicast = c.kind == Kind::Udp && isMulticast(host);
  } else if (kind == "serial") {
    c.kind = Kind::Serial;
    const auto colon = rest.rfind(':');
    if (colon != std::string::npos) {
      c.baud = static_cast<std::int32_t>(parseInt(spec, "baud", rest.substr(colon + 1), 50, 4'000'000));
      rest = rest.substr(0, colon);
    }
    if (rest.empty()) fail(spec, "device", "missing (serial:///dev/ttyUSB0:4800)");
    c.device = rest;
  } else if (kind == "file") {
    c.kind = Kind::File;
    if (rest.empty()) fail(spec, "path", "missing (file:///path/to/recording.nmea)");
    c.path = rest;
  } else {
    fail(spec, "kind", "'" + kind + "' is not one of udp, tcp, serial, gpsd, file");
  }
  bool named = false;
  for (const std::string& kv : split(query, '&')) {
    const auto eq = kv.find('=');
    const std::string key = kv.substr(0, eq);
    const std::string value = eq == std::string::npos ? "" : kv.substr(eq + 1);
    if (key == "name") {
      if (value.empty()) fail(spec, "name", "empty");
      c.name = value;
      named = true;
    } else if (key == "role") {
      if (value != "nmea" && value != "radar") fail(spec, "role", "'" + value + "' is not nmea or radar");
      c.role = value == "radar" ? Role::Radar : Role::Nmea;
    } else if (key == "priority") {
      c.priority = static_cast<int>(parseInt(spec, "priority", value, -1000, 1000));
    } else if (key == "enabled") {
      if (value != "0" && value != "1") fail(spec, "enabled", "'" + value + "' is not 0 or 1");
      c.enabled = value == "1";
    } else if (key == "accept") {
      c.filter.acceptTypes = split(value, ',');
    } else if (key == "reject") {
      c.filter.rejectTypes = split(value, ',');
    } else if (key == "talkers") {
      c.filter.acceptTalkers = split(value, ',');
    } else if (key == "reject-talkers") {
      c.filter.rejectTalkers = split(value, ',');
    } else if (key == "iface" && c.kind == Kind::Udp) {
      if (!c.multicast) fail(spec, "iface", "only for a multicast group");
      c.interfaceName = value;
    } else if (key == "rate" && c.kind == Kind::File) {
      if (value == "realtime") {
        c.rate = FileRate{};
      } else if (!value.empty() && value.front() == 'x') {
        c.rate = FileRate{true, parsePositive(spec, "rate", value.substr(1)), 0.0};
      } else {
        c.rate = FileRate{false, 1.0, parsePositive(spec, "rate", value)};
      }
    } else {
      fail(spec, key.empty() ? "option" : key, "unknown option for " + kind);
    }
  }
  if (!named) c.name = defaultName(c);
  return c;
}

std::string toSpec(const SourceConfig& c) {
  std::string s = std::string(kindName(c.kind)) + "://";
  switch (c.kind) {
    case Kind::Udp:
    case Kind::Tcp:
    case Kind::Gpsd:
      s += hostText(c.host) + ":" + std::to_string(c.port);
      break;
    case Kind::Serial:
      s += c.device + ":" + std::to_string(c.baud);
      break;
    case Kind::File:
      s += c.path;
      break;
  }
  std::vector<std::string> opts;
  if (c.name != defaultName(c)) opts.push_back("name=" + c.name);
  if (c.role != Role::Nmea) opts.push_back(std::string("role=") + roleName(c.role));
  if (c.priority != 0) opts.push_back("priority=" + std::to_string(c.priority));
  if (!c.enabled) opts.emplace_back("enabled=0");
  if (!c.filter.acceptTypes.empty()) opts.push_back("accept=" + join(c.filter.acceptTypes));
  if (!c.filter.rejectTypes.empty()) opts.push_back("reject=" + join(c.filter.rejectTypes));
  if (!c.filter.acceptTalkers.empty()) opts.push_back("talkers=" + join(c.filter.acceptTalkers));
  if (!c.filter.rejectTalkers.empty()) opts.push_back("reject-talkers=" + join(c.filter.rejectTalkers));
  if (c.kind == Kind::Udp && !c.interfaceName.empty()) opts.push_back("iface=" + c.interfaceName);
  if (c.kind == Kind::File && !(c.rate == FileRate{})) opts.push_back("rate=" + rateText(c.rate));
  for (std::size_t i = 0; i < opts.size(); ++i) s += (i == 0 ? "?" : "&") + opts[i];
  return s;
}

bool sentenceId(const std::string& line, std::string& talker, std::string& type) {
  std::size_t start = 0;
  if (!line.empty() && line.front() == '\\') {  // IEC 61162-450 TAG block
    const auto close = line.find('\\', 1);
    if (close == std::string::npos) return false;
    start = close + 1;
  }
  if (start >= line.size() || (line[start] != '$' && line[start] != '!')) return false;
  const auto comma = line.find_first_of(",*", start);
  const std::string address =
      line.substr(start + 1, (comma == std::string::npos ? line.size() : comma) - start - 1);
  if (address.size() < 2) return false;
  if (address.front() == 'P') {
    talker.assign(1, 'P');
    type = address.substr(1);
  } else {
    talker = address.substr(0, 2);
    type = address.substr(2);
  }
  return !type.empty();
}

}  // namespace reckoner::conn
