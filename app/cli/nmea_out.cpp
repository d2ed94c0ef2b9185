#include "cli/nmea_out.h"

#include <QCoreApplication>

#include "cli/cli_options.h"
#include "nmea_destination.h"

namespace reckoner::cli {

void addNmeaOut(CLI::App& app, std::optional<std::string>& target) {
  addValue(
      app, "nmea-out", "DEST",
      "NMEA 0183 output of the estimates, tracks and alerts (docs/outputs.md): udp://HOST:PORT (unicast or "
      "broadcast), tcp://:PORT (a server for every client) or a file path",
      [&target](const std::string& t) { target = t; });
}

NmeaSink::NmeaSink(const std::string& spec) : spec_(spec) {
  const conn::DestinationSpec d = conn::parseDestination(spec);
  if (d.kind == conn::DestinationSpec::Kind::TcpServer && !QCoreApplication::instance()) {
    static int argc = 1;
    static char name[] = "reckoner-cli";
    static char* argv[] = {name, nullptr};
    app_ = std::make_unique<QCoreApplication>(argc, argv);
  }
  dest_ = std::make_unique<conn::NmeaDestination>(d);
}

NmeaSink::~NmeaSink() = default;

void NmeaSink::write(const std::vector<std::string>& lines) {
  dest_->write(lines);
  if (app_) QCoreApplication::processEvents();
}

std::string NmeaSink::finish() {
  dest_->flush(2000);
  const conn::DestinationCounters& c = dest_->counters();
  std::string s = std::to_string(c.lines) + " NMEA sentences to " + spec_;
  if (c.datagrams > 0) s += " in " + std::to_string(c.datagrams) + " datagrams";
  if (c.sendErrors > 0) s += ", " + std::to_string(c.sendErrors) + " datagrams refused";
  if (c.clientsAccepted > 0 || c.linesWithoutClient > 0)
    s += ", " + std::to_string(c.clientsAccepted) + " clients (" + std::to_string(c.clientsDropped) +
         " dropped for not reading), " + std::to_string(c.linesWithoutClient) + " with no client connected";
  return s;
}

}  // namespace reckoner::cli
