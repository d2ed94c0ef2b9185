#pragma once
// True motion of a vessel (own ship or a radar target) in the grid frame: position, velocity through the
// water (scheduled as in seed 000 Tables II and III, plus an optional Gauss-Markov acceleration), and a
// Gauss-Markov ocean current (zero for targets, whose motion is specified over ground). The random parts
// are propagated with the exact discretisation of the filters' own models, so a scenario without a
// schedule is a matched-model test.
#include <array>
#include <optional>

#include "common/rng.h"
#include "estimation/gaussian.h"
#include "sim/scenario.h"

namespace reckoner::sim {

struct VesselTruth {
  TimeUs timeUs = 0;
  geo::GridPoint position;
  double waterVxMps = 0.0, waterVyMps = 0.0;  ///< velocity through water, grid
  double currentXMps = 0.0, currentYMps = 0.0;
  double accelXMps2 = 0.0, accelYMps2 = 0.0;  ///< d(water velocity)/dt
  double headingRad = 0.0;                    ///< grid heading; kept while stopped

  [[nodiscard]] double groundVxMps() const { return waterVxMps + currentXMps; }
  [[nodiscard]] double groundVyMps() const { return waterVyMps + currentYMps; }
};

class VesselMotionModel {
 public:
  /// Throws std::invalid_argument for invalid Gauss-Markov parameters. The motion starts at startUs
  /// (a target that appears during the run) from the spec's initial position and velocity.
  VesselMotionModel(const VesselMotionSpec& spec, const est::GaussMarkov& current, Rng rng,
                    TimeUs startUs = 0);

  /// Advances to t (>= the last time asked for). The random sample path is drawn on a fixed grid
  /// (multiples of kGridUs, plus the scenario's own event times), so it does not depend on when the
  /// truth is looked at; between grid points the state is propagated without noise (the missing
  /// noise over < 0.1 s is ~1e-5 m for the accelerations used here).
  void advanceTo(TimeUs t);
  [[nodiscard]] const VesselTruth& state() const { return truth_; }
  /// The helm order in force at the last time asked for, if any.
  [[nodiscard]] const std::optional<HelmOrder>& order() const { return order_; }

  /// An operator's event (time after every committed one): drops the scheduled events at or after its
  /// time and appends it. Returns false if the time is too early. (The model keeps only the events
  /// still to come and the last few spent; the engine's scenario is the record of what happened.)
  bool overrideFrom(const KinematicEvent& e);

  /// The vessel runs aground at its position at the last time asked for: from then on it stays there,
  /// at rest over ground (its water velocity the current's opposite), whatever its schedule says.
  void runAground();
  [[nodiscard]] bool aground() const { return aground_.has_value(); }

  static constexpr TimeUs kGridUs = 100'000;
  /// Spent events are dropped once this many have piled up.
  static constexpr std::size_t kSpentEventsKept = 256;

 private:
  /// Everything that evolves, so that a copy can be propagated to an off-grid time.
  struct Motion {
    TimeUs timeUs = 0;
    std::size_t nextEvent = 0;
    std::array<double, 2> commanded{};
    std::array<double, 2> scheduledVel{};
    std::array<double, 2> rampAccel{};  // acceleration of the last substep's speed ramp
    double turnRateRadPerS = 0.0;
    std::optional<HelmOrder> order;
    std::array<double, 2> scheduledDisplacement{};
    // Random part per axis: [displacement from current and random velocity, current, random
    // velocity, random acceleration] (the DRKF's per-axis block).
    std::array<est::Vec<4>, 2> random{};
    // Random ship motion (spec.randomShipMotion): its velocity through the water on top of the
    // schedule, along-track acceleration and turn rate.
    std::array<double, 2> shipVel{};
    double shipAlong = 0.0, shipTurn = 0.0;
    double headingRad = 0.0;
  };
  void shipSubstep(Motion& m, double dt, bool noisy);
  struct AxisDiscretisation {
    TimeUs dtUs = -1;
    est::Mat<4> Phi;
    est::Mat<4> sqrtQ;  // any S with S S^T = Q
  };
  const AxisDiscretisation& discretisation(TimeUs dtUs);
  [[nodiscard]] est::Mat<4> transition(TimeUs dtUs) const;
  void substep(Motion& m, TimeUs dtUs, bool noisy);
  void applyDueEvents(Motion& m) const;
  void refreshOutputs(const Motion& m);

  VesselMotionSpec spec_;
  est::GaussMarkov current_;
  est::GaussMarkov randomAccel_;
  Rng rng_;
  Motion committed_;
  std::array<AxisDiscretisation, 4> cache_{};
  std::size_t cacheNext_ = 0;
  VesselTruth truth_;
  std::optional<HelmOrder> order_;
  std::optional<geo::GridPoint> aground_;
};

}  // namespace reckoner::sim
