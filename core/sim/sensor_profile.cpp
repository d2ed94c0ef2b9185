#include "sim/sensor_profile.h"

#include <cmath>

#include "common/units.h"

namespace reckoner::sim {
namespace {
constexpr double kDay = 86400.0;

/// What real ships carry, and a ship's motion (docs/sensor_profiles.md, "realistic").
void realistic(Scenario& s) {
  s.gps.positionVarM2 = 5.0 * 5.0;  // per axis at HDOP 1 (replay scales by HDOP^2 or takes GST)
  // Doppler velocity of the antenna: the receiver's 0.05-0.1 m/s, and the antenna's motion on a mast as
  // the ship rolls and yaws. The icebreaker recording's windowed NIS put its velocity noise at 0.25 m/s
  // (mean NIS per degree of freedom 6 against a configured 0.1 m/s; docs/sensor_profiles.md).
  s.gps.velocityVarM2PerS2 = 0.25 * 0.25;
  s.loran.error = {150.0, 1.0 / 600.0};  // additional secondary factor: hundreds of m, minutes
  s.loran.whiteVarM2 = 20.0 * 20.0;
  // Calibration errors are constant over a passage: a day's correlation lets them settle, not wander.
  s.speedlog.error = {0.1, 1.0 / kDay};  // offset: 0.2 kn is the IMO log standard's limit
  s.speedlog.whiteVarM2PerS2 = 0.06 * 0.06;
  s.speedlog.scaleError = {0.02, 1.0 / kDay};
  s.gyro.sdRad = degToRad(0.3);
  s.gyro.bias = {degToRad(1.0), 1.0 / kDay};
  // A plot extractor's range error with its quantisation (A.823(19): 20 m and 0.02 NM steps, about
  // 23 m together) taken a little wide; the bearing's with the gyro's scatter and calibration.
  s.radar.rangeSdM = 25.0;
  s.radar.bearingSdRad = degToRad(0.5);
  // The current's random walk, 2 sigma^2 / tau, sets how fast dead reckoning forgets it: 0.03 m/s in ten
  // minutes, 0.07 m/s in an hour (docs/sensor_profiles.md).
  s.filter.current = est::GaussMarkov{0.5, 1.0 / (4.0 * kDay)};
  s.filter.acceleration = {0.05, 1.0 / 30.0};
  // A ship's motion (drkf_process.h): speed changes of a fraction of a knot per minute, turns of up to
  // a degree a second lasting a minute; the paper's Cartesian acceleration above is then unused.
  auto& ship = s.filter.shipMotion;
  ship.enabled = true;
  ship.alongAcceleration = {0.005, 1.0 / 60.0};
  ship.turnRate = {degToRad(0.5), 1.0 / 60.0};
  ship.whiteAccelerationQ = 1e-4;
  // The tracker's motion models (issue 16: ARPA-grade on unmanoeuvring targets, the manoeuvre flag
  // for the rest): the IMO scenarios' (resources/scenarios/imo-*.json), a target acceleration of 0.001 m/s^2
  // with a 50 s correlation and own ship's 0.02 m/s^2 with 10 s, under input estimation (ekf-ie, the default
  // scenario's filter), which catches the turns this long memory would lag behind.
  s.tracker.kind = track::TrackerKind::EkfInputEstimation;
  s.tracker.targetAcceleration = {0.001, 1.0 / 50.0};
  s.tracker.ownAcceleration = {0.02, 1.0 / 10.0};
}

/// The IMO performance standards' limits, read as 95% bounds (sd = limit / 1.96, per axis for a
/// horizontal 95% radius: limit / 2.45).
void imo(Scenario& s) {
  realistic(s);  // the process model and the Loran-C correlation are not set by any standard
  s.gps.positionVarM2 = std::pow(13.0 / 2.45, 2);  // MSC.112(73): 13 m (95%)
  s.gps.velocityVarM2PerS2 = std::pow(knotsToMps(0.2) / 1.96, 2);
  s.loran.error = {0.25 * 1852.0 / 2.45, 1.0 / 600.0};  // A.818(19) system: 0.25 NM (95%)
  s.loran.whiteVarM2 = 30.0 * 30.0;
  s.speedlog.error = {knotsToMps(0.2) / 1.96, 1.0 / kDay};  // MSC.96(72): 0.2 kn or 2%
  s.speedlog.scaleError = {0.02 / 1.96, 1.0 / kDay};
  s.speedlog.whiteVarM2PerS2 = std::pow(knotsToMps(0.1), 2);
  s.gyro.bias = {degToRad(0.75) / 1.96, 1.0 / kDay};  // A.424(XI): settle point 0.75 deg
  s.gyro.sdRad = degToRad(0.5);                       // its dynamic errors
}
}  // namespace

const char* nameOf(SensorProfile p) {
  switch (p) {
    case SensorProfile::Paper:
      return "paper";
    case SensorProfile::Imo:
      return "imo";
    case SensorProfile::Realistic:
      return "realistic";
  }
  return "paper";
}

std::optional<SensorProfile> sensorProfileFromName(std::string_view name) {
  for (const auto p : {SensorProfile::Paper, SensorProfile::Imo, SensorProfile::Realistic})
    if (name == nameOf(p)) return p;
  return std::nullopt;
}

void applySensorProfile(Scenario& s, SensorProfile p) {
  switch (p) {
    case SensorProfile::Paper:
      return;  // the scenario's own figures: every built-in scenario has seed 000's
    case SensorProfile::Imo:
      imo(s);
      return;
    case SensorProfile::Realistic:
      realistic(s);
      return;
  }
}

}  // namespace reckoner::sim
