#pragma once
// Manoeuvre detection at radar rates (issue 6): own ship straight; a target straight, then (optionally)
// turning by a given angle at a given rate, or changing speed; radar plots every sweep with range and
// bearing noise. The seed 001 input-estimation EKF and the IMM run on the same plots; the trial
// reports when each first flags a manoeuvre after it begins, and how often each flags one on a straight
// run (false alarms, counted as rising edges of the flag).
#include <cstdint>
#include <optional>

#include "tracking/imm.h"
#include "tracking/input_estimation.h"

namespace reckoner::sim {

struct ManoeuvreTrial {
  double sweepS = 2.0;
  double durationS = 600.0;
  double rangeSdM = 20.0;
  double bearingSdRad = 0.005235987755982988;  ///< 0.3 deg
  double ownCourseRad = 0.0, ownSpeedMps = 12.0 * 1852.0 / 3600.0;
  double targetBearingRad = 0.7853981633974483, targetRangeM = 3.0 * 1852.0;  ///< at t = 0
  double targetCourseRad = 4.71238898038469, targetSpeedMps = 12.0 * 1852.0 / 3600.0;
  double manoeuvreStartS = 300.0;
  double turnRad = 0.0;                           ///< course change (clockwise positive); 0: none
  double turnRateRadPerS = 0.017453292519943295;  ///< 1 deg/s
  double speedChangeMps = 0.0;                    ///< speed change; 0: none
  double accelerationMps2 = 0.1;
};

struct ManoeuvreOutcome {
  std::optional<double> ieDelayS, immDelayS;  ///< first flag at or after the manoeuvre's start
  int ieFalseAlarms = 0, immFalseAlarms = 0;  ///< rising edges before the manoeuvre's start
  double straightS = 0.0;                     ///< time before the manoeuvre (or the whole run)
};

ManoeuvreOutcome runManoeuvreTrial(const ManoeuvreTrial& trial, const track::InputEstimationConfig& ie,
                                   const track::ImmConfig& imm, std::uint64_t seed);

}  // namespace reckoner::sim
