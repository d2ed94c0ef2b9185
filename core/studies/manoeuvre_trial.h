#pragma once
// Manoeuvre detection and tracking at radar rates (issue 6): own ship straight; a target straight,
// then (optionally) turning by a given angle at a given rate, or changing speed; radar plots every
// sweep with range and bearing noise. Four trackers run on the same plots: the EKF without input
// estimation, the EKF with seed 001's input estimation, seed 003's alpha-beta-gamma filter and the
// IMM. Each run reports, per tracker, when its manoeuvre flag first rises after the manoeuvre begins,
// its false alarms before (rising edges), and its position, course and speed errors at every sweep;
// and the posterior Cramer-Rao bound of the position along the true trajectory.
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "common/angles.h"
#include "common/units.h"
#include "studies/seed001.h"
#include "tracking/alpha_beta_gamma.h"
#include "tracking/imm.h"
#include "tracking/input_estimation.h"

namespace reckoner::studies {

struct ManoeuvreTrial {
  double sweepS = 2.0;
  double durationS = 600.0;
  double rangeSdM = 20.0;
  double bearingSdRad = 0.005235987755982988;  ///< 0.3 deg
  double ownCourseRad = 0.0, ownSpeedMps = knotsToMps(12.0);
  double targetBearingRad = 0.7853981633974483, targetRangeM = 3.0 * 1852.0;  ///< at t = 0
  double targetCourseRad = 1.5 * kPi, targetSpeedMps = knotsToMps(12.0);
  double manoeuvreStartS = 300.0;
  double turnRad = 0.0;                    ///< course change (clockwise positive); 0: none
  double turnRateRadPerS = degToRad(1.0);  ///< 1 deg/s
  double speedChangeMps = 0.0;             ///< speed change; 0: none
  double accelerationMps2 = 0.1;
  /// White acceleration (m^2/s^3) of the model the PCRB assumes: the EKF's by default (a bound for
  /// targets that manoeuvre as the model says); 0 for the bound of a truly straight target.
  double boundProcessNoiseQ = 1e-4;
  [[nodiscard]] bool manoeuvres() const { return turnRad != 0.0 || speedChangeMps != 0.0; }
  /// When the manoeuvre is complete (its start plus the turn or speed change at its rate).
  [[nodiscard]] double manoeuvreEndS() const;
};

enum TrackerKind : int { kEkf = 0, kEkfIe, kAbg, kImm, kTrackerKinds };
const char* trackerName(TrackerKind k);

struct TrackerConfigs {
  track::InputEstimationConfig ie;  ///< also the plain EKF's (with its false-alarm probability ~0)
  track::ImmConfig imm;
  track::AbgConfig abg;
};
/// The radar-rate settings used by the trial and the report (docs/manoeuvres.md).
TrackerConfigs radarRateTrackers(const ManoeuvreTrial& trial);

struct TrackerSeries {
  std::optional<double> delayS;  ///< first flag at or after the manoeuvre's start (none for abg)
  int falseAlarms = 0;           ///< rising edges before the manoeuvre's start
  std::vector<double> posErrM, courseErrRad, speedErrMps;  ///< per sweep (NaN before initialisation)
};

struct ManoeuvreRun {
  std::vector<double> tS;        ///< sweep times
  std::vector<double> pcrbPosM;  ///< sqrt of the trace of the position PCRB, per sweep
  std::array<TrackerSeries, kTrackerKinds> trackers;
  double straightS = 0.0;  ///< time before the manoeuvre (or the whole run)
};

ManoeuvreRun runManoeuvreTrial(const ManoeuvreTrial& trial, const TrackerConfigs& configs,
                               std::uint64_t seed);

/// The four trackers at seed 001's sonar rates: the paper's EKF settings (s = 2, Pfa 0.01, 1 deg and
/// 20 m), the IMM with the sonar's noise, abg at alpha 0.6.
TrackerConfigs sonarTrackers();

/// One echo's errors for one tracker (the estimate against the truth at the echo's reflection time,
/// range from the observer at the stamp).
struct Seed001TrackerSample {
  int index = 0;
  double tS = 0.0;
  double rangeErrorPct = 0.0, courseErrorDeg = 0.0, speedErrorMps = 0.0;
  bool manoeuvring = false;
  double positionErrorM = 0.0;
  double pcrbPositionM = 0.0;  ///< sqrt of the trace of the position PCRB at this echo
};
struct Seed001TrackerRun {
  std::array<std::vector<Seed001TrackerSample>, kTrackerKinds> trackers;
};

/// Seed 001's scenario (sonar pings) through the four trackers, one run. The PCRB assumes the EKF's
/// white acceleration (q = configs.ie.processNoiseQ).
Seed001TrackerRun runSeed001Trackers(const Seed001Scenario& s, const TrackerConfigs& configs,
                                     std::uint64_t seed);

}  // namespace reckoner::studies
