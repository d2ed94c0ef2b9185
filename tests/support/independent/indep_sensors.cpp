// Own-ship sensors of the independent generator: GNSS (ZDA, RMC, GGA, GST), gyro (HDT), speed log
// through the water (VHW) and Loran-C (GLL), written as NMEA 0183 text, one epoch per truth row.
#include "indep_sim.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace reckoner_indep {

namespace {
// Talkers: GP (GNSS receiver), HE (north-seeking gyro), VW (water-referenced log), LC (Loran-C).
std::string zda(const UtcClock& clock, std::int64_t tUs) {
  return nmeaSentence("GPZDA," + clock.nmeaTime(tUs) + "," + clock.zdaDate(tUs) + ",00,00");
}
}  // namespace

void writeOwnShipNmea(const std::string& path, const UtcClock& clock, const std::vector<TruthRow>& truth,
                      const SensorModel& model, std::uint64_t seed) {
  Rng gnssRng = makeRng(seed, Stream::Gnss);
  Rng gyroRng = makeRng(seed, Stream::Gyro);
  Rng logRng = makeRng(seed, Stream::Log);
  Rng loranRng = makeRng(seed, Stream::Loran);
  GaussMarkov gnssEast(model.gnssCorrelatedSdM, model.gnssCorrelationS, gnssRng);
  GaussMarkov gnssNorth(model.gnssCorrelatedSdM, model.gnssCorrelationS, gnssRng);
  GaussMarkov loranEast(model.loranCorrelatedSdM, model.loranCorrelationS, loranRng);
  GaussMarkov loranNorth(model.loranCorrelatedSdM, model.loranCorrelationS, loranRng);

  std::string text;
  text.reserve(truth.size() * 420);
  std::int64_t previousUs = truth.empty() ? 0 : truth.front().tUs;
  for (const TruthRow& row : truth) {
    const double dtS = static_cast<double>(row.tUs - previousUs) * 1e-6;
    previousUs = row.tUs;
    const std::string time = clock.nmeaTime(row.tUs);

    // Every process advances and every draw is made each epoch, in or out of the outage, so the
    // errors at a given second do not depend on the outage settings.
    if (dtS > 0.0) {
      gnssEast.step(dtS, gnssRng);
      gnssNorth.step(dtS, gnssRng);
      loranEast.step(dtS, loranRng);
      loranNorth.step(dtS, loranRng);
    }
    const Enu gnssErrorM(gnssEast.value() + gnssRng.normal(model.gnssWhiteSdM),
                         gnssNorth.value() + gnssRng.normal(model.gnssWhiteSdM));
    const Enu velocityErrorMps(gnssRng.normal(model.gnssVelocitySdKn * kMpsPerKnot),
                               gnssRng.normal(model.gnssVelocitySdKn * kMpsPerKnot));
    const double altitudeM = 12.0 + gnssRng.normal(1.5 * model.gnssWhiteSdM);
    const Enu loranErrorM(loranEast.value() + loranRng.normal(model.loranWhiteSdM),
                          loranNorth.value() + loranRng.normal(model.loranWhiteSdM));
    const double gyroDeg =
        wrapDeg360(row.headingDeg + model.gyroBiasDeg + gyroRng.normal(model.gyroNoiseSdDeg));
    const double logKn = std::max(0.0, (1.0 + model.logScale) * row.stwMps / kMpsPerKnot + model.logOffsetKn +
                                           logRng.normal(model.logNoiseSdKn));

    // The receiver's ZDA leads its burst, as many receivers write it; it keeps coming in an outage
    // (the receiver's clock runs on), which also gives the untimed HDT and VHW their epoch.
    text += zda(clock, row.tUs);
    if (row.gpsOn) {
      const LatLon fix = offsetEnu(row.pos, gnssErrorM);
      const Enu velocityMps = enuFromPolar(row.sogMps, row.cogDeg) + velocityErrorMps;
      const std::string lat = nmeaLat(fix.latDeg), lon = nmeaLon(fix.lonDeg);
      text += nmeaSentence(
          joinFields({"GPRMC", time, "A", lat, lon, fmt("%.3f", velocityMps.norm() / kMpsPerKnot),
                      fmt("%.2f", azimuthDegOf(velocityMps)), clock.nmeaDateDdmmyy(row.tUs), "", "", "A"}));
      text += nmeaSentence(joinFields(
          {"GPGGA", time, lat, lon, "1", "10", "1.0", fmt("%.1f", altitudeM), "M", "-23.4", "M", "", ""}));
      // GST: rms, semi-major sd, semi-minor sd, orientation, lat sd, lon sd, altitude sd (metres).
      const double reportedSdM = model.gnssWhiteSdM / model.gstUnderstates;
      const std::string sd = fmt("%.2f", reportedSdM);
      text += nmeaSentence(
          joinFields({"GPGST", time, "1.0", sd, sd, "0.0", sd, sd, fmt("%.2f", 1.5 * reportedSdM)}));
    }
    if (model.loran) {
      const LatLon fix = offsetEnu(row.pos, loranErrorM);
      text += nmeaSentence("LCGLL," + nmeaLat(fix.latDeg) + "," + nmeaLon(fix.lonDeg) + "," + time + ",A,A");
    }
    if (model.gyro) text += nmeaSentence("HEHDT," + fmt("%.2f", gyroDeg) + ",T");
    if (model.log)  // heading fields empty: the log does not know the heading
      text += nmeaSentence("VWVHW,,T,,M," + fmt("%.3f", logKn) + ",N," + fmt("%.3f", logKn * 1.852) + ",K");
  }
  writeTextFile(path, text);
}

std::string sensorModelJson(const SensorModel& m) {
  char buf[2048];
  std::snprintf(
      buf, sizeof buf,
      "{\n"
      "    \"gnss\": {\"white_sd_m_per_axis\": %.6f, \"gst_lat_lon_sd_m\": %.2f, "
      "\"correlated_sd_m_per_axis\": %.3f, \"correlation_time_s\": %.1f, "
      "\"total_sd_m_per_axis\": %.6f, \"velocity_sd_kn_per_axis\": %.3f, "
      "\"outage_start_s\": %.3f, \"outage_length_s\": %.3f},\n"
      "    \"gyro\": {\"enabled\": %s, \"bias_deg\": %.6f, \"noise_sd_deg\": %.3f},\n"
      "    \"log\": {\"enabled\": %s, \"scale\": %.8f, \"scale_percent\": %.6f, \"offset_kn\": %.6f, "
      "\"noise_sd_kn\": %.3f},\n"
      "    \"loran\": {\"enabled\": %s, \"correlated_sd_m_per_axis\": %.1f, \"correlation_time_s\": %.1f, "
      "\"white_sd_m_per_axis\": %.1f}\n"
      "  }",
      m.gnssWhiteSdM, m.gnssWhiteSdM / m.gstUnderstates, m.gnssCorrelatedSdM, m.gnssCorrelationS,
      std::sqrt(m.gnssWhiteSdM * m.gnssWhiteSdM + m.gnssCorrelatedSdM * m.gnssCorrelatedSdM),
      m.gnssVelocitySdKn, m.outageStartS, m.outageLengthS, m.gyro ? "true" : "false", m.gyroBiasDeg,
      m.gyroNoiseSdDeg, m.log ? "true" : "false", m.logScale, 100.0 * m.logScale, m.logOffsetKn,
      m.logNoiseSdKn, m.loran ? "true" : "false", m.loranCorrelatedSdM, m.loranCorrelationS, m.loranWhiteSdM);
  return buf;
}

}  // namespace reckoner_indep
