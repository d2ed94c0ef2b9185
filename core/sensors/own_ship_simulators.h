#pragma once
// Own-ship sensor simulators. Each draws from its own random stream. Gauss-Markov errors evolve in
// continuous time whether the sensor is on or not (the truth does not stop when a receiver is off), and
// are exposed so tests and NEES can compare the filter's error states with them.
#include <cmath>

#include "common/rng.h"
#include "geo/local_frame.h"
#include "sensors/own_ship_sensor_specs.h"

namespace reckoner::sensors {

/// A scalar Gauss-Markov process advanced exactly between arbitrary times (seed 000 eq. 3).
class GaussMarkovSignal {
 public:
  GaussMarkovSignal(const est::GaussMarkov& gm, Rng& rng, TimeUs t0)
      : gm_(gm), timeUs_(t0), value_(rng.normal(0.0, gm.sigma)) {}
  void advanceTo(TimeUs t, Rng& rng) {
    if (t <= timeUs_) return;
    const double dt = toSeconds(t - timeUs_);
    value_ = gm_.phi(dt) * value_ + std::sqrt(gm_.discreteVariance(dt)) * rng.normal();
    timeUs_ = t;
  }
  [[nodiscard]] double value() const { return value_; }

 private:
  est::GaussMarkov gm_;
  TimeUs timeUs_;
  double value_;
};

class GpsSimulator {
 public:
  GpsSimulator(const GpsSpec& spec, Rng rng) : spec_(spec), rng_(rng) {}
  /// groundVel is the true velocity over ground in grid m/s; grid gives convergence and scale there.
  GpsSample measure(TimeUs t, const geo::GridPoint& truePos, double groundVxGrid, double groundVyGrid,
                    const geo::GridInfo& grid);

 private:
  GpsSpec spec_;
  Rng rng_;
};

class LoranSimulator {
 public:
  LoranSimulator(const LoranSpec& spec, Rng rng, TimeUs t0)
      : spec_(spec), rng_(rng), ex_(spec.error, rng_, t0), ey_(spec.error, rng_, t0) {}
  void advanceTo(TimeUs t) {
    ex_.advanceTo(t, rng_);
    ey_.advanceTo(t, rng_);
  }
  /// Advances the error to t and measures.
  LoranSample measure(TimeUs t, const geo::GridPoint& truePos);
  [[nodiscard]] double errorXM() const { return ex_.value(); }
  [[nodiscard]] double errorYM() const { return ey_.value(); }

 private:
  LoranSpec spec_;
  Rng rng_;
  GaussMarkovSignal ex_, ey_;
};

class SpeedlogSimulator {
 public:
  /// scaleRng draws the scale-factor error (its own stream, so the paper's draws do not change).
  SpeedlogSimulator(const SpeedlogSpec& spec, Rng rng, TimeUs t0, Rng scaleRng)
      : spec_(spec),
        rng_(rng),
        error_(spec.error, rng_, t0),
        scaleRng_(scaleRng),
        scale_(spec.scaleError, scaleRng_, t0) {}
  void advanceTo(TimeUs t) {
    error_.advanceTo(t, rng_);
    scale_.advanceTo(t, scaleRng_);
  }
  /// Speeds are true grid speeds (m/s of grid length); the sample reports true length. The mode is
  /// the one in force (the scenario's schedule, or the operator's switch).
  SpeedlogSample measure(TimeUs t, double speedOverGroundGrid, double speedThroughWaterGrid,
                         SpeedlogMode mode, const geo::GridInfo& grid);
  [[nodiscard]] double errorMps() const { return error_.value(); }
  [[nodiscard]] double scaleError() const { return scale_.value(); }

 private:
  SpeedlogSpec spec_;
  Rng rng_;
  GaussMarkovSignal error_;
  Rng scaleRng_;
  GaussMarkovSignal scale_;
};

class GyroSimulator {
 public:
  /// biasRng draws the calibration error (its own stream).
  GyroSimulator(const GyroSpec& spec, Rng rng, TimeUs t0, Rng biasRng)
      : spec_(spec), rng_(rng), biasRng_(biasRng), bias_(spec.bias, biasRng_, t0) {}
  void advanceTo(TimeUs t) { bias_.advanceTo(t, biasRng_); }
  /// Advances the bias to t and measures.
  GyroSample measure(TimeUs t, double headingGridRad, const geo::GridInfo& grid);
  [[nodiscard]] double biasRad() const { return bias_.value(); }

 private:
  GyroSpec spec_;
  Rng rng_;
  Rng biasRng_;
  GaussMarkovSignal bias_;
};

}  // namespace reckoner::sensors
