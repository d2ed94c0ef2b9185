#pragma once
// reckoner-bench's live feed: a second of mixed own-ship NMEA and AIS, as bench_live_feed.cpp and
// bench_live_window.cpp send it over loopback UDP; and the process's resident memory.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <QElapsedTimer>

#include <atomic>
#include <chrono>
#include <functional>
#include <thread>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/angles.h"
#include "common/units.h"
#include "io/nmea.h"
#include "support/ais_corpus.h"

namespace reckoner::bench {

inline double residentMb() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

/// One second of the stream: own ship (RMC, GGA, VTG and ten HDT: a ship steaming east at 10 kn off
/// 47 N 122 W) and AIS lines from the project's corpus up to `perSecond` sentences; aisMessages
/// counts the AIS messages in it (the corpus's type 5 is two fragments, kept together). `extra` lines
/// (AIS of one's own) go after own ship, before the corpus (counted by the caller).
inline void secondOfStream(int s, int perSecond, std::vector<std::string>& out, int& aisMessages,
                           const std::vector<std::string>& extra = {}) {
  out.clear();
  const int hh = (s / 3600) % 24, mm = (s / 60) % 60, ss = s % 60;
  // a minute of longitude is cos(latitude) nautical miles
  const double lonMin = 30.0 + knotsToMps(10.0) * s / (kMetresPerNauticalMile * std::cos(degToRad(47.5)));
  const int lonDeg = 122 - static_cast<int>(lonMin / 60.0);
  const double lonM = std::fmod(lonMin, 60.0);
  char b[160];
  std::snprintf(b, sizeof b, "GPRMC,%02d%02d%02d.00,A,4730.0000,N,%03d%07.4f,W,10.0,90.0,011226,,,A", hh, mm,
                ss, lonDeg, 60.0 - lonM);
  out.push_back(io::nmea::withChecksum(b));
  std::snprintf(b, sizeof b, "GPGGA,%02d%02d%02d.00,4730.0000,N,%03d%07.4f,W,1,09,0.9,10.0,M,-20.0,M,,", hh,
                mm, ss, lonDeg, 60.0 - lonM);
  out.push_back(io::nmea::withChecksum(b));
  out.push_back(io::nmea::withChecksum("GPVTG,90.0,T,,M,10.0,N,18.5,K,A"));
  for (int i = 0; i < 10; ++i) out.push_back(io::nmea::withChecksum("HEHDT,90.0,T"));
  out.insert(out.end(), extra.begin(), extra.end());
  static const std::vector<std::string> corpus = test::ais::corpus();
  int messages = 0;
  std::size_t k = 0;
  while (static_cast<int>(out.size()) < perSecond - 1) {
    const std::string& l = corpus[k % corpus.size()];
    out.push_back(l);
    // a first fragment of two ("!AIVDM,2,1,") is completed by the next line of the corpus
    if (l.compare(0, 11, "!AIVDM,2,1,") == 0) {
      out.push_back(corpus[(k + 1) % corpus.size()]);
      ++k;
    }
    ++messages;
    ++k;
  }
  aisMessages += messages;
}

/// A loopback address with a free UDP port (bound, read back, released).
inline sockaddr_in freeLoopbackPort() {
  sockaddr_in to{};
  to.sin_family = AF_INET;
  to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  const int probe = ::socket(AF_INET, SOCK_DGRAM, 0);
  sockaddr_in any = to;
  socklen_t len = sizeof any;
  if (probe < 0 || ::bind(probe, reinterpret_cast<sockaddr*>(&any), sizeof any) != 0 ||
      ::getsockname(probe, reinterpret_cast<sockaddr*>(&any), &len) != 0) {
    if (probe >= 0) ::close(probe);
    throw std::runtime_error("no free UDP port on 127.0.0.1");
  }
  to.sin_port = any.sin_port;
  ::close(probe);
  return to;
}

/// Sends `seconds` of the stream (secondOfStream, with extra(s) after own ship) to `to`, a datagram a
/// sentence, spread over each second and none before its time; counts what it sent and the AIS messages
/// of the corpus in it.
inline void sendStream(const sockaddr_in& to, int seconds, int perSecond,
                       const std::function<std::vector<std::string>(int)>& extra, std::atomic<long>& sent,
                       int& aisSent) {
  const int fd = ::socket(AF_INET, SOCK_DGRAM, 0);
  std::vector<std::string> lines;
  QElapsedTimer clock;
  clock.start();
  for (int s = 0; s < seconds; ++s) {
    secondOfStream(s, perSecond, lines, aisSent, extra ? extra(s) : std::vector<std::string>{});
    for (std::size_t i = 0; i < lines.size(); ++i) {
      const qint64 due = s * 1000LL + static_cast<qint64>(i * 1000 / lines.size());
      while (clock.elapsed() < due) std::this_thread::sleep_for(std::chrono::microseconds(500));
      const std::string d = lines[i] + "\r\n";
      ::sendto(fd, d.data(), d.size(), 0, reinterpret_cast<const sockaddr*>(&to), sizeof to);
      sent.fetch_add(1, std::memory_order_relaxed);
    }
  }
  ::close(fd);
}

}  // namespace reckoner::bench
