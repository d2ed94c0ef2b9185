// `ownship`: a manoeuvring own ship in a current, and its sensors.
//
// Motion through the water: legs of 3-10 min at a commanded heading and speed through the water;
// at each new leg the heading command changes by up to 90 deg (random sign) and the speed command by
// up to +-3 kn (held to [speed-min, speed-max]). Heading and speed follow their commands with a
// rate- and acceleration-limited second-order law (turn rate <= 1 deg/s reached with a turn-rate
// acceleration of 0.1 deg/s^2; |acceleration| <= 0.05 m/s^2 reached with a jerk of 0.01 m/s^3), so
// rates ramp and the ship arrives on its new heading or speed without overshoot. The limits on turn
// rate and acceleration are hard; the ramps' limits hold except for the arrival step (see follow()). Heading
// is the direction of the water velocity (no leeway). Velocity over ground = water velocity + current.
#include "indep_sim.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace reckoner_indep {

namespace {
constexpr std::int64_t kStepUs = 100000;  // 10 Hz integration
constexpr double kTurnRateMaxDegS = 1.0, kTurnAccelDegS2 = 0.1;
constexpr double kAccelMaxMps2 = 0.05, kJerkMps3 = 0.01;
constexpr double kCurrentPeriodS = 7200.0, kCurrentSpeedVariation = 0.03, kCurrentSetVariationDeg = 2.0;

// One step of a second-order follower: `rate` moves by at most accelMax * dt towards the largest
// rate (<= rateMax) from which the remaining `error` can still be closed in steps of accelMax * dt
// (the discrete braking curve r^2 / 2a + r dt / 2 = |error|); the step that would reach or pass the
// target lands on it with rate 0 (a last rate step of at most ~2 accelMax * dt). Returns the change
// of the followed value over the step. Never overshoots.
double follow(double error, double& rate, double rateMax, double accelMax, double dtS) {
  const double half = 0.5 * accelMax * dtS;
  const double braking = -half + std::sqrt(half * half + 2.0 * accelMax * std::fabs(error));
  rate +=
      std::clamp(std::copysign(std::min(rateMax, braking), error) - rate, -accelMax * dtS, accelMax * dtS);
  const double step = rate * dtS;
  if (error == 0.0 ? rate == 0.0 : step / error >= 1.0) {  // arrived (or already there)
    rate = 0.0;
    return error;
  }
  return step;
}

struct Current {
  double speedMps, setDeg, speedPhase, setPhase, speedVariation, setVariationDeg;
  Enu at(double tS) const {
    const double w = 2.0 * kPi * tS / kCurrentPeriodS;
    return enuFromPolar(speedMps * (1.0 + speedVariation * std::sin(w + speedPhase)),
                        setDeg + setVariationDeg * std::sin(w + setPhase));
  }
};

struct Leg {
  double startS, headingCmdDeg, speedCmdKn;
};

/// params.json: the run's start, current, motion limits, sensors and legs.
void writeOwnShipParams(const OwnShipOptions& o, const UtcClock& clock, const LatLon& start,
                        const Current& current, const SensorModel& model, const std::vector<Leg>& legs) {
  std::string legText;
  for (const Leg& leg : legs) {
    char buf[160];
    std::snprintf(buf, sizeof buf,
                  "%s\n    {\"start_s\": %.1f, \"heading_cmd_deg\": %.4f, \"stw_cmd_kn\": %.4f}",
                  legText.empty() ? "" : ",", leg.startS, leg.headingCmdDeg, leg.speedCmdKn);
    legText += buf;
  }
  char head[1600];
  std::snprintf(
      head, sizeof head,
      "{\n  \"generator\": \"reckoner-indep-sim ownship\",\n  \"seed\": %llu,\n"
      "  \"start_utc\": \"%s\",\n  \"duration_s\": %.3f,\n"
      "  \"start_lat_deg\": %.9f,\n  \"start_lon_deg\": %.9f,\n"
      "  \"speed_min_kn\": %.3f,\n  \"speed_max_kn\": %.3f,\n"
      "  \"current\": {\"speed_mps\": %.6f, \"set_deg\": %.6f, \"max_mps\": %.3f, "
      "\"speed_variation_fraction\": %.3f, \"set_variation_deg\": %.3f, \"variation_period_s\": %.1f},\n"
      "  \"motion\": {\"turn_rate_max_deg_s\": %.2f, \"turn_accel_deg_s2\": %.2f, "
      "\"accel_max_mps2\": %.3f, \"jerk_mps3\": %.3f, \"integration_hz\": 10},\n",
      static_cast<unsigned long long>(o.seed), clock.iso(0, 3).c_str(), o.durationS, start.latDeg,
      start.lonDeg, o.speedMinKn, o.speedMaxKn, current.speedMps, current.setDeg, o.currentMaxMps,
      current.speedVariation, current.setVariationDeg, kCurrentPeriodS, kTurnRateMaxDegS, kTurnAccelDegS2,
      kAccelMaxMps2, kJerkMps3);
  writeTextFile(o.outDir + "/params.json", std::string(head) + "  \"sensors\": " + sensorModelJson(model) +
                                               ",\n  \"legs\": [" + legText + "\n  ]\n}\n");
}
}  // namespace

int runOwnShip(const OwnShipOptions& o) {
  ensureDirectory(o.outDir);
  Rng params = makeRng(o.seed, Stream::Params);
  Rng plan = makeRng(o.seed, Stream::Plan);

  // ---- Per-run parameters ----
  const LatLon start{47.6 + params.uniform(-0.1, 0.1), -122.4 + params.uniform(-0.1, 0.1)};
  SensorModel model;
  model.gnssWhiteSdM = params.uniform(3.0, 5.0);
  model.gyroBiasDeg = params.sign() * params.uniform(0.5, 1.0);
  model.logScale = params.sign() * params.uniform(0.01, 0.03);
  model.logOffsetKn = params.uniform(-0.2, 0.2);
  model.outageStartS = o.outageStartS;
  model.outageLengthS = o.outageLengthS;
  model.gyro = o.gyro;
  model.log = o.log;
  model.gstUnderstates = o.gstUnderstates;
  model.loran = o.loran;
  Current current{params.uniform(0.0, o.currentMaxMps),
                  params.uniform(0.0, 360.0),
                  params.uniform(0.0, 2.0 * kPi),
                  params.uniform(0.0, 2.0 * kPi),
                  o.steadyCurrent ? 0.0 : kCurrentSpeedVariation,
                  o.steadyCurrent ? 0.0 : kCurrentSetVariationDeg};

  // ---- Truth: integrate at 10 Hz, keep 1 Hz rows ----
  double headingDeg = plan.uniform(0.0, 360.0), turnRateDegS = 0.0;
  double stwMps = plan.uniform(o.speedMinKn, o.speedMaxKn) * kMpsPerKnot, accelMps2 = 0.0;
  std::vector<Leg> legs{{0.0, headingDeg, stwMps / kMpsPerKnot}};
  double nextLegS = plan.uniform(180.0, 600.0);

  const UtcClock clock{unixSecondsFromCivil(2026, 6, 15, 10, 0, 0)};
  const std::int64_t endUs = static_cast<std::int64_t>(std::floor(o.durationS)) * 1000000;
  std::vector<TruthRow> rows;
  LatLon pos = start;
  auto groundVelocity = [&](double tS) { return Enu(enuFromPolar(stwMps, headingDeg) + current.at(tS)); };
  for (std::int64_t tUs = 0;; tUs += kStepUs) {
    const double tS = static_cast<double>(tUs) * 1e-6;
    if (tUs % 1000000 == 0) {
      const Enu vg = groundVelocity(tS);
      const bool gpsOn = !(tS >= o.outageStartS && tS < o.outageStartS + o.outageLengthS);
      rows.push_back(TruthRow{tUs, pos, vg.norm(), azimuthDegOf(vg), wrapDeg360(headingDeg), stwMps,
                              current.at(tS), gpsOn});
    }
    if (tUs >= endUs) break;
    if (tS >= nextLegS) {  // a new leg: new commands
      const Leg& last = legs.back();
      const double turnDeg = plan.sign() * plan.uniform(0.0, 90.0);
      const double speedKn =
          std::clamp(last.speedCmdKn + plan.uniform(-3.0, 3.0), o.speedMinKn, o.speedMaxKn);
      legs.push_back(Leg{tS, wrapDeg360(last.headingCmdDeg + turnDeg), speedKn});
      nextLegS = tS + plan.uniform(180.0, 600.0);
    }
    // Trapezoidal step of the position along the rhumb line of the mean ground velocity.
    const double dtS = static_cast<double>(kStepUs) * 1e-6;
    const Enu v0 = groundVelocity(tS);
    headingDeg = wrapDeg360(headingDeg + follow(wrapDeg180(legs.back().headingCmdDeg - headingDeg),
                                                turnRateDegS, kTurnRateMaxDegS, kTurnAccelDegS2, dtS));
    stwMps += follow(legs.back().speedCmdKn * kMpsPerKnot - stwMps, accelMps2, kAccelMaxMps2, kJerkMps3, dtS);
    const Enu vMean = 0.5 * (v0 + groundVelocity(tS + dtS));
    pos = rhumbDirect(pos, azimuthDegOf(vMean), vMean.norm() * dtS);
  }

  // ---- Files ----
  writeTruthCsv(o.outDir + "/truth.csv", clock, rows);
  writeOwnShipNmea(o.outDir + "/ownship.nmea", clock, rows, model, o.seed);

  writeOwnShipParams(o, clock, start, current, model, legs);
  return 0;
}

}  // namespace reckoner_indep
