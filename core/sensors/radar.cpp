#include "sensors/radar.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/angles.h"

namespace reckoner::sensors {
namespace {
double quantise(double v, double q) {
  return q > 0.0 ? q * std::round(v / q) : v;
}
}  // namespace

double RadarSpec::plotRangeVarM2() const {
  return rangeSdM * rangeSdM + rangeQuantumM * rangeQuantumM / 12.0;
}

double RadarSpec::plotBearingVarRad2() const {
  return bearingSdRad * bearingSdRad + bearingBacklashRad * bearingBacklashRad / 3.0 +
         bearingQuantumRad * bearingQuantumRad / 12.0 + gyroScatterSdRad * gyroScatterSdRad;
}

std::string RadarSpec::check() const {
  const auto bad = [](double v) { return !std::isfinite(v) || v < 0.0; };
  if (!(sweepPeriodS > 0.0) || !std::isfinite(sweepPeriodS)) return "sweep_period_s must be positive";
  if (!(rangeSdM > 0.0) || !(bearingSdRad > 0.0)) return "range_sd_m and bearing_sd_deg must be positive";
  if (bad(bearingBacklashRad) || bad(rangeQuantumM) || bad(bearingQuantumRad) || bad(gyroScatterSdRad))
    return "error terms must not be negative";
  if (!std::isfinite(gyroCalibrationRad)) return "gyro_calibration_deg must be finite";
  if (!(maxRangeM > 0.0) || bad(minRangeM) || minRangeM >= maxRangeM)
    return "need 0 <= min_range_nm < max_range_nm";
  if (!(detectionProbability >= 0.0 && detectionProbability <= 1.0))
    return "detection_probability must lie in [0, 1]";
  if (bad(clutterPerKm2) || bad(clutterMaxRangeM)) return "clutter fields must not be negative";
  return {};
}

int poisson(Rng& rng, double mean) {
  if (!(mean > 0.0)) return 0;
  int n = 0;
  // Sum of Poisson variates with means <= 50 (their sum is Poisson); each by Knuth's product method.
  while (mean > 0.0) {
    const double m = std::min(mean, 50.0);
    mean -= m;
    const double limit = std::exp(-m);
    double prod = rng.uniform();
    while (prod > limit) {
      ++n;
      prod *= rng.uniform();
    }
  }
  return n;
}

TimeUs RadarSimulator::beamTime(TimeUs sweepStartUs, double trueBearingRad) const {
  return sweepStartUs + fromSeconds(wrapTwoPi(trueBearingRad) / kTwoPi * spec_.sweepPeriodS);
}

RadarPlot RadarSimulator::finish(TimeUs t, double rangeM, double bearingRad) const {
  RadarPlot p;
  p.timeUs = t;
  p.rangeM = std::max(0.0, quantise(rangeM, spec_.rangeQuantumM));
  p.bearingRad = wrapTwoPi(quantise(wrapTwoPi(bearingRad), spec_.bearingQuantumRad));
  p.rangeVarM2 = spec_.plotRangeVarM2();
  p.bearingVarRad2 = spec_.plotBearingVarRad2();
  return p;
}

std::vector<RadarPlot> RadarSimulator::beginSweep(TimeUs sweepStartUs) {
  sweepGyroErrorRad_ = spec_.gyroCalibrationRad + spec_.gyroScatterSdRad * clutterRng_.normal();
  std::vector<RadarPlot> out;
  const double rMax =
      spec_.clutterMaxRangeM > 0.0 ? std::min(spec_.clutterMaxRangeM, spec_.maxRangeM) : spec_.maxRangeM;
  const double rMin = spec_.minRangeM;
  if (spec_.clutterPerKm2 <= 0.0 || rMax <= rMin) return out;
  const double areaKm2 = kPi * (rMax * rMax - rMin * rMin) * 1e-6;
  const int n = poisson(clutterRng_, spec_.clutterPerKm2 * areaKm2);
  out.reserve(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const double r = std::sqrt(rMin * rMin + clutterRng_.uniform() * (rMax * rMax - rMin * rMin));
    const double b = kTwoPi * clutterRng_.uniform();
    out.push_back(finish(beamTime(sweepStartUs, b), r, b));
  }
  std::sort(out.begin(), out.end(),
            [](const RadarPlot& a, const RadarPlot& b) { return a.timeUs < b.timeUs; });
  return out;
}

std::optional<RadarPlot> RadarSimulator::measure(TimeUs t, double dxGridM, double dyGridM,
                                                 const geo::GridInfo& grid) {
  const double rangeTrue = std::hypot(dxGridM, dyGridM) / grid.scale;
  // Drawn whatever happens, so one target's fate never shifts another's noise.
  const double u = rng_.uniform();
  const double nr = rng_.normal(), nb = rng_.normal(), ub = rng_.uniform();
  if (rangeTrue > spec_.maxRangeM || rangeTrue < spec_.minRangeM || u >= spec_.detectionProbability)
    return std::nullopt;
  const double bearing = bearingOf(dxGridM, dyGridM) + grid.convergenceRad + spec_.bearingSdRad * nb +
                         spec_.bearingBacklashRad * (2.0 * ub - 1.0) + sweepGyroErrorRad_;
  return finish(t, rangeTrue + spec_.rangeSdM * nr, bearing);
}

}  // namespace reckoner::sensors
