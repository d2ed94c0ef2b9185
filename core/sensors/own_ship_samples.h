#pragma once
// Own-ship sensor measurements as value types, with units on every field. Positions are in the local
// grid frame (file and device readers convert latitude/longitude with geo::LocalFrame); velocities and
// headings are referenced to TRUE north as the instruments report them (the filter converts to grid).
#include <cstdint>
#include <string_view>
#include <variant>

#include "common/time.h"
#include "geo/local_frame.h"

namespace reckoner::sensors {

enum class SensorId : std::uint8_t { Gps, LoranC, Speedlog, Gyro };
inline constexpr int kOwnShipSensorCount = 4;

/// Speedlog reference, seed 000's names: ground-lock measures speed over ground, bottom-lock speed
/// through the water.
enum class SpeedlogMode : std::uint8_t { GroundLock, BottomLock };

constexpr std::string_view modeName(SpeedlogMode m) {
  return m == SpeedlogMode::GroundLock ? "ground_lock" : "bottom_lock";
}

struct GpsSample {
  TimeUs timeUs = 0;
  geo::GridPoint position;     ///< grid metres
  double positionVarM2 = 0.0;  ///< variance of each position coordinate, m^2
  bool hasVelocity = false;
  double velEastMps = 0.0;          ///< velocity over ground, true east, m/s
  double velNorthMps = 0.0;         ///< velocity over ground, true north, m/s
  double velocityVarM2PerS2 = 0.0;  ///< variance of each velocity component, m^2/s^2
};

struct LoranSample {
  TimeUs timeUs = 0;
  geo::GridPoint position;     ///< grid metres (includes the Loran-C Gauss-Markov error)
  double positionVarM2 = 0.0;  ///< white-noise variance of each coordinate, m^2
};

struct SpeedlogSample {
  TimeUs timeUs = 0;
  double speedMps = 0.0;  ///< true-length speed, m/s (over ground or through water, per mode)
  SpeedlogMode mode = SpeedlogMode::GroundLock;
  double varM2PerS2 = 0.0;  ///< white-noise variance, m^2/s^2
};

struct GyroSample {
  TimeUs timeUs = 0;
  double headingRad = 0.0;  ///< true heading, clockwise from true north, [0, 2 pi)
  double varRad2 = 0.0;     ///< white-noise variance, rad^2
};

using OwnShipSample = std::variant<GpsSample, LoranSample, SpeedlogSample, GyroSample>;

inline TimeUs timeOf(const OwnShipSample& s) {
  return std::visit([](const auto& v) { return v.timeUs; }, s);
}
inline SensorId sensorOf(const OwnShipSample& s) {
  return static_cast<SensorId>(s.index());
}

/// One epoch's GPS, gyro and speedlog samples (the last of each kind; null when absent), for filters
/// that pair the gyro and the log into a dead-reckoning velocity (seed 002).
struct EpochSamples {
  const GpsSample* gps = nullptr;
  const GyroSample* gyro = nullptr;
  const SpeedlogSample* speedlog = nullptr;
};
template <class Range>
EpochSamples epochSamples(const Range& samples) {
  EpochSamples e;
  for (const auto& s : samples) {
    if (const auto* g = std::get_if<GpsSample>(&s)) e.gps = g;
    if (const auto* g = std::get_if<GyroSample>(&s)) e.gyro = g;
    if (const auto* l = std::get_if<SpeedlogSample>(&s)) e.speedlog = l;
  }
  return e;
}

}  // namespace reckoner::sensors
