#pragma once
// Shared by the connections tests: free loopback ports, sentences with their checksums, and a hub
// drained into a vector while the test waits on a condition.
#include <QTcpServer>
#include <QUdpSocket>

#include <chrono>
#include <string>
#include <vector>

#include "connection_hub.h"
#include "io/nmea.h"

namespace conn = reckoner::conn;

namespace conn_test {

inline conn::UtcUs nowUtcUs() {
  return std::chrono::duration_cast<std::chrono::microseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

/// A free UDP port on loopback (bound, read back, released).
inline quint16 freeUdpPort() {
  QUdpSocket s;
  s.bind(QHostAddress::LocalHost, 0);
  return s.localPort();
}
inline quint16 freeTcpPort() {
  QTcpServer s;
  s.listen(QHostAddress::LocalHost, 0);
  return s.serverPort();
}

inline std::string sentence(const std::string& body) {
  return reckoner::io::nmea::withChecksum(body);
}

/// Headings of their own (not from any recording), each different for n <= 3600.
inline std::vector<std::string> sentences(int n) {
  std::vector<std::string> out;
  for (int i = 0; i < n; ++i) {
    std::string body("HEHDT,");
    body += std::to_string(i / 10) + "." + std::to_string(i % 10) + ",T";
    out.push_back(sentence(body));
  }
  return out;
}

struct Drain {
  conn::ConnectionHub& hub;
  std::vector<conn::ReceivedLine> got;
  std::size_t operator()() {
    for (auto& l : hub.take()) got.push_back(std::move(l));
    return got.size();
  }
  [[nodiscard]] std::vector<std::string> lines() const {
    std::vector<std::string> out;
    for (const auto& l : got) out.push_back(l.line);
    return out;
  }
};

inline conn::SourceStatus statusOf(const conn::ConnectionHub& hub, const std::string& name) {
  for (const auto& s : hub.status())
    if (s.name == name) return s;
  return {};
}

inline conn::HubOptions fastRetry() {
  conn::HubOptions o;
  o.retryInitialMs = 50;
  o.retryMaxMs = 400;
  return o;
}

}  // namespace conn_test
