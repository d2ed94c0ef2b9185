#pragma once
// True own-ship motion in the grid frame: position, velocity through the water (scheduled as in seed 000
// Table II, plus an optional Gauss-Markov acceleration), and a Gauss-Markov ocean current. The random
// parts are propagated with the exact discretisation of the filter's own model, so a scenario without a
// schedule is a matched-model test.
#include <array>

#include "common/rng.h"
#include "estimation/gaussian.h"
#include "sim/scenario.h"

namespace reckoner::sim {

struct OwnShipTruth {
  TimeUs timeUs = 0;
  geo::GridPoint position;
  double waterVxMps = 0.0, waterVyMps = 0.0;  ///< velocity through water, grid
  double currentXMps = 0.0, currentYMps = 0.0;
  double accelXMps2 = 0.0, accelYMps2 = 0.0;  ///< d(water velocity)/dt
  double headingRad = 0.0;                    ///< grid heading; kept while stopped

  [[nodiscard]] double groundVxMps() const { return waterVxMps + currentXMps; }
  [[nodiscard]] double groundVyMps() const { return waterVyMps + currentYMps; }
};

class OwnShipTruthModel {
 public:
  /// Throws std::invalid_argument for invalid Gauss-Markov parameters.
  OwnShipTruthModel(const OwnShipSpec& spec, const est::GaussMarkov& current, Rng rng);

  /// Advances to t (>= current time) in substeps of at most 0.1 s, splitting at schedule events.
  void advanceTo(TimeUs t);
  [[nodiscard]] const OwnShipTruth& state() const { return truth_; }

  static constexpr TimeUs kMaxSubstepUs = 100'000;

 private:
  struct AxisDiscretisation {
    TimeUs dtUs = -1;
    est::Mat<4> Phi;
    est::Mat<4> sqrtQ;  // any S with S S^T = Q
  };
  const AxisDiscretisation& discretisation(TimeUs dtUs);
  void substep(TimeUs dtUs);
  void applyEvent(const KinematicEvent& e);
  void refreshOutputs();

  OwnShipSpec spec_;
  est::GaussMarkov current_;
  est::GaussMarkov randomAccel_;
  Rng rng_;
  std::size_t nextEvent_ = 0;
  // Scheduled motion.
  std::array<double, 2> commanded_{};
  std::array<double, 2> scheduledVel_{};
  std::array<double, 2> rampAccel_{};  // acceleration of the last substep's speed ramp
  double turnRateRadPerS_ = 0.0;
  std::array<double, 2> scheduledDisplacement_{};
  // Random part per axis: [displacement from current and random velocity, current, random velocity,
  // random acceleration] (the DRKF's per-axis block).
  std::array<est::Vec<4>, 2> random_{};
  std::array<AxisDiscretisation, 4> cache_{};
  std::size_t cacheNext_ = 0;
  OwnShipTruth truth_;
};

}  // namespace reckoner::sim
