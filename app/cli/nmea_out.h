#pragma once
// --nmea-out DEST of run, replay and live: the NMEA 0183 output (docs/outputs.md, "NMEA 0183
// output") to udp://HOST:PORT, tcp://:PORT or a file.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

class QCoreApplication;

namespace reckoner::conn {
class NmeaDestination;
}

namespace reckoner::cli {

void addNmeaOut(CLI::App& app, std::optional<std::string>& target);

/// The destination, opened (and its spec checked) before the command's work starts.
class NmeaSink {
 public:
  explicit NmeaSink(const std::string& spec);
  ~NmeaSink();
  void write(const std::vector<std::string>& lines);
  /// Flushes (TCP: waits a moment for the clients' queues) and returns a one-line account.
  std::string finish();

 private:
  std::string spec_;
  std::unique_ptr<QCoreApplication> app_;  ///< for a TCP server when the program has no event loop
  std::unique_ptr<conn::NmeaDestination> dest_;
};

}  // namespace reckoner::cli
