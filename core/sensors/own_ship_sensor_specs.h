#pragma once
// What each simulated own-ship sensor is: rate, noise, Gauss-Markov error and on/off schedule.
// The DRKF is tuned with the same numbers (as in seed 000's Table I).
#include <cmath>

#include "common/angles.h"
#include "common/step_schedule.h"
#include "estimation/gauss_markov.h"
#include "sensors/own_ship_samples.h"

namespace reckoner::sensors {

struct GpsSpec {
  bool fitted = true;
  double rateHz = 1.0;
  double positionVarM2 = 1600.0;     ///< Table I R1 = R2
  double velocityVarM2PerS2 = 0.25;  ///< Table I R3 = R4
  StepSchedule<bool> power{true};
};

struct LoranSpec {
  bool fitted = true;
  double rateHz = 1.0;
  est::GaussMarkov error{std::sqrt(500.0), 0.25};  ///< Table I sigma^2 = 500 m^2, beta = 0.25 /s
  double whiteVarM2 = 25.0;                        ///< not in the paper (docs/drkf.md)
  StepSchedule<bool> power{true};
};

struct SpeedlogSpec {
  bool fitted = true;
  double rateHz = 1.0;
  est::GaussMarkov error{std::sqrt(0.5), 0.5};  ///< Table I sigma^2 = 0.5 m^2/s^2, beta = 0.5 /s
  double whiteVarM2PerS2 = 0.01;                ///< not in the paper (docs/drkf.md)
  /// Scale-factor error k, the log reading (1 + k) times the speed: a slow Gauss-Markov fraction (not
  /// in the paper: sigma 0; the IMO log standard allows 2% of the speed or 0.2 kn).
  est::GaussMarkov scaleError{0.0, 1.0};
  StepSchedule<bool> power{true};
  StepSchedule<SpeedlogMode> mode{SpeedlogMode::GroundLock};
};

struct GyroSpec {
  bool fitted = true;
  double rateHz = 1.0;
  double sdRad = degToRad(1.0);  ///< 1 degree (Table I footnote)
  /// Calibration error, rad: a slow Gauss-Markov offset of every reading (not in the paper: sigma 0; a
  /// gyrocompass's settle-point error, a heading device's residual deviation).
  est::GaussMarkov bias{0.0, 1.0};
  StepSchedule<bool> power{true};
};

}  // namespace reckoner::sensors
