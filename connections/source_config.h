#pragma once
// What a connection is (docs/connections.md, "Source specs"): its kind and where, its input filter and
// its priority, and the one-line spec that names it on a command line and in the settings.
#include <cstdint>
#include <string>
#include <vector>

namespace reckoner::conn {

enum class Kind : std::uint8_t { Udp, Tcp, Serial, Gpsd, File };
/// What the lines are: NMEA 0183 / AIS sentences, or radar plot CSV rows (docs/outputs.md).
enum class Role : std::uint8_t { Nmea, Radar };

const char* kindName(Kind k);
const char* roleName(Role r);

/// Sentences a source lets through: empty accept lists accept everything; a reject list wins over an
/// accept list. Sentence types are the three (or more) letters after the talker ("RMC", "VDM");
/// talkers the two letters after '$' or '!' ("GP", "AI"), "P" for proprietary sentences ($PGRME:
/// talker "P", type "GRME"). Lines that are no sentence (radar CSV rows) are never filtered.
struct InputFilter {
  std::vector<std::string> acceptTypes, rejectTypes, acceptTalkers, rejectTalkers;
  [[nodiscard]] bool empty() const {
    return acceptTypes.empty() && rejectTypes.empty() && acceptTalkers.empty() && rejectTalkers.empty();
  }
  /// Whether the sentence with this talker and type passes.
  [[nodiscard]] bool accepts(const std::string& talker, const std::string& type) const;
  bool operator==(const InputFilter&) const = default;
};

/// How a file is played: at the pace of its sentences' own UTC times (speedFactor 1 = real time,
/// N = N times faster), or at a fixed number of lines per second.
struct FileRate {
  bool ownTime = true;
  double speedFactor = 1.0;     ///< with ownTime, > 0
  double linesPerSecond = 0.0;  ///< without ownTime, > 0
  bool operator==(const FileRate&) const = default;
};

struct SourceConfig {
  std::string name;  ///< unique in a hub; defaults to the spec's kind and address
  Kind kind = Kind::Udp;
  Role role = Role::Nmea;
  std::string host;  ///< udp: the address to bind (empty: any) or the multicast group; tcp, gpsd: the peer
  std::uint16_t port = 0;     ///< udp, tcp, gpsd
  bool multicast = false;     ///< udp: host is a multicast group (224.0.0.0/4 or ff00::/8) to join
  std::string interfaceName;  ///< udp multicast: the interface to join on (empty: the system's choice)
  std::string device;         ///< serial: /dev/ttyUSB0
  std::int32_t baud = 4800;   ///< serial: 4800 (IEC 61162-1), 38400 (AIS, -2 high speed), ...
  std::string path;           ///< file
  FileRate rate;              ///< file
  bool enabled = true;
  InputFilter filter;
  int priority = 0;  ///< the source priority of issue 9 (higher wins where sources overlap)
  bool operator==(const SourceConfig&) const = default;
};

/// Parses a spec:
///   udp://:10110  udp://127.0.0.1:10110  udp://239.192.0.1:60001 (multicast)  tcp://HOST:PORT
///   serial:///dev/ttyUSB0:4800  gpsd://HOST:2947  gpsd://HOST (2947)  file:///path?rate=x10
/// with options after '?' joined by '&': name=, role=nmea|radar, priority=N, enabled=0|1,
/// accept=RMC,GGA  reject=GSV  talkers=GP,GN  reject-talkers=AI, iface=lo (multicast), and for files
/// rate=realtime|xN|N (N lines per second). Throws std::invalid_argument naming the spec and the field.
SourceConfig parseSource(const std::string& spec);
/// The spec that parseSource() reads back to the same config.
std::string toSpec(const SourceConfig& c);

/// The talker and type of a sentence line ("$GPRMC,..." -> "GP", "RMC"; after an IEC 61162-450 TAG
/// block "\...\"); false for a line that is no sentence.
bool sentenceId(const std::string& line, std::string& talker, std::string& type);

}  // namespace reckoner::conn
