#include "sim/nmea_export.h"

#include <cmath>
#include <cstdio>

#include "common/angles.h"
#include "common/units.h"
#include "io/iso8601.h"
#include "io/nmea.h"
#include "io/nmea_out.h"

namespace reckoner::sim {
namespace {
using io::nmea::nmeaLatitude;
using io::nmea::nmeaLongitude;

std::string hhmmss(UtcUs t) {
  const std::string iso = io::formatIso8601(t);  // YYYY-MM-DDThh:mm:ss.ffffffZ
  return iso.substr(11, 2) + iso.substr(14, 2) + iso.substr(17, 2) + "." + iso.substr(20, 3);
}

std::string ddmmyy(UtcUs t) {
  return io::nmea::nmeaDate(t);
}
}  // namespace

std::vector<std::string> ownShipSentences(const SimFrame& f, const geo::LocalFrame& frame, UtcUs utc0) {
  std::vector<std::string> out;
  char buf[256];
  // Own-ship samples grouped by epoch (they are stamped with their epoch).
  for (const auto& u : f.updates) {
    const UtcUs t = utc0 + u.timeUs;
    // The ship's clock: HDT, VBW and VHW carry no time, so every epoch opens with a ZDA.
    const std::string iso = io::formatIso8601(t);
    std::snprintf(buf, sizeof buf, "IIZDA,%s,%s,%s,%s,00,00", hhmmss(t).c_str(), iso.substr(8, 2).c_str(),
                  iso.substr(5, 2).c_str(), iso.substr(0, 4).c_str());
    out.push_back(io::nmea::withChecksum(buf));
    for (const auto& m : f.measurements) {
      if (sensors::timeOf(m) != u.timeUs) continue;
      std::visit(
          [&](const auto& v) {
            using T = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<T, sensors::GpsSample>) {
              const geo::GeoPoint ll = frame.toGeodetic(v.position);
              const std::string lat = nmeaLatitude(ll.latDeg), lon = nmeaLongitude(ll.lonDeg);
              const double sog = mpsToKnots(std::hypot(v.velEastMps, v.velNorthMps));
              const double cog = radToDeg(wrapTwoPi(bearingOf(v.velEastMps, v.velNorthMps)));
              std::snprintf(buf, sizeof buf, "GPRMC,%s,A,%s,%s,%.3f,%.2f,%s,,,A", hhmmss(t).c_str(),
                            lat.c_str(), lon.c_str(), sog, cog, ddmmyy(t).c_str());
              out.push_back(io::nmea::withChecksum(buf));
              std::snprintf(buf, sizeof buf, "GPGGA,%s,%s,%s,1,09,1.0,5.0,M,,M,,", hhmmss(t).c_str(),
                            lat.c_str(), lon.c_str());
              out.push_back(io::nmea::withChecksum(buf));
            } else if constexpr (std::is_same_v<T, sensors::LoranSample>) {
              const geo::GeoPoint ll = frame.toGeodetic(v.position);
              std::snprintf(buf, sizeof buf, "LCGLL,%s,%s,%s,A", nmeaLatitude(ll.latDeg).c_str(),
                            nmeaLongitude(ll.lonDeg).c_str(), hhmmss(t).c_str());
              out.push_back(io::nmea::withChecksum(buf));
            } else if constexpr (std::is_same_v<T, sensors::GyroSample>) {
              std::snprintf(buf, sizeof buf, "HEHDT,%.3f,T", radToDeg(v.headingRad));
              out.push_back(io::nmea::withChecksum(buf));
            } else {
              if (v.mode == sensors::SpeedlogMode::GroundLock)
                std::snprintf(buf, sizeof buf, "VWVBW,,,V,%.3f,0.000,A", mpsToKnots(v.speedMps));
              else
                std::snprintf(buf, sizeof buf, "VWVHW,,T,,M,%.3f,N,%.3f,K", mpsToKnots(v.speedMps),
                              3.6 * v.speedMps);
              out.push_back(io::nmea::withChecksum(buf));
            }
          },
          m);
    }
  }
  return out;
}

std::vector<std::string> radarCsvRows(const SimFrame& f, UtcUs utc0) {
  std::vector<std::string> out;
  char buf[128];
  for (std::size_t i = 0; i < f.plots.size(); ++i) {
    const auto& p = f.plots[i];
    std::snprintf(buf, sizeof buf, "%s,%.2f,%.4f,", io::formatIso8601(utc0 + p.timeUs).c_str(), p.rangeM,
                  radToDeg(p.bearingRad));
    out.emplace_back(buf);
    if (f.plotSources[i] >= 0) out.back() += std::to_string(f.plotSources[i]);
  }
  return out;
}

ExportedRun exportRun(const Scenario& s, std::uint64_t seed, UtcUs utc0) {
  ExportedRun out;
  SimulationEngine engine(s, seed);
  const geo::LocalFrame& frame = engine.frame();
  out.radarCsv = "utc,range_m,bearing_deg,target_id\n";
  out.truth.seed = seed;
  while (!engine.finished()) {
    const SimFrame f = engine.step();
    out.truth.rows.push_back(makeRow(f, frame, engine.drkf().config().process));
    appendSweepRows(f, s, frame, out.truth.trackRows, out.truth.targetRows);
    for (const std::string& line : ownShipSentences(f, frame, utc0)) out.nmea += line + "\r\n";
    for (const std::string& row : radarCsvRows(f, utc0)) out.radarCsv += row + '\n';
  }
  out.truth.counters = engine.drkf().counters();
  out.truth.trackCounters = engine.trackers().counters();
  return out;
}

}  // namespace reckoner::sim
