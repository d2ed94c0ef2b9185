#pragma once
// DRKF process model, seed 000 eqs. 4b-6: per axis, position integrates current + water velocity, the
// water velocity integrates a Gauss-Markov acceleration, and the current, Loran-C errors and speedlog
// error are Gauss-Markov. Seven independent unit white noises drive the system (eq. 6's I_7); two more
// drive the heading-sensor bias and the log's scale-factor error (Gauss-Markov, zero in the paper).
#include "estimation/discretize.h"
#include "estimation/gauss_markov.h"
#include "estimation/models/drkf_state.h"

namespace reckoner::est::drkf {

inline constexpr int kNoiseDim = 9;
/// The ship motion model's noise inputs: current (2), along-track acceleration, turn rate, white
/// acceleration of the water velocity (2), Loran-C (2), log offset, heading bias, log scale.
inline constexpr int kShipNoiseDim = 11;

/// A ship's motion model for the velocity through the water (docs/drkf.md, "Ship motion"): in place of
/// the paper's Cartesian Gauss-Markov acceleration, an acceleration along the track and a turn rate,
///   dv/dt = a v / max(|v|, minSpeed) + omega (v_y, -v_x) + w,
/// a (x4) and omega (x8) Gauss-Markov, w a small white acceleration (either axis) for what neither
/// covers (leeway, starting from rest). A ship turns and changes speed the way ships do: bounded rates,
/// correlated over a manoeuvre, so dead reckoning on a heading alone keeps its speed.
struct ShipMotionParams {
  bool enabled = false;
  GaussMarkov alongAcceleration{0.01, 1.0 / 60.0};  ///< m/s^2
  GaussMarkov turnRate{0.0087, 1.0 / 60.0};         ///< rad/s (0.5 deg/s)
  double whiteAccelerationQ = 1e-4;                 ///< m^2/s^3 per axis
  double minSpeedMps = 0.5;  ///< below: the along-track acceleration fades with the speed
};

struct ProcessParams {
  GaussMarkov current;                ///< sigma m/s, Table I sigma_c^2, beta_c
  GaussMarkov acceleration;           ///< sigma m/s^2, Table I footnote sigma_a = 0.5, beta_a = 1
  GaussMarkov loranError;             ///< sigma m, Table I L-C sigma^2, beta_L-C = 0.25
  GaussMarkov speedlogError;          ///< sigma m/s, Table I S-L sigma^2, beta_S-L = 0.5
  GaussMarkov headingBias{0.0, 1.0};  ///< sigma rad; not in the paper (0: no heading bias state)
  GaussMarkov logScale{0.0, 1.0};     ///< sigma (fraction of the speed); not in the paper (0: none)
  ShipMotionParams ship{};            ///< off: the paper's acceleration (x4, x8 Cartesian)
};

class ProcessModel {
 public:
  /// Throws std::invalid_argument if any Gauss-Markov parameter is invalid (sigma < 0, beta <= 0).
  explicit ProcessModel(const ProcessParams& params);

  /// Continuous system matrix F of eq. 4c.
  [[nodiscard]] const Mat<kStateDim>& F() const { return F_; }
  /// Input matrix G of eq. 4d (seven noise columns; the printed G has an empty eighth column), and the
  /// calibration states' two.
  [[nodiscard]] const MatRC<kStateDim, kNoiseDim>& G() const { return G_; }
  /// Exact Phi = exp(F dt) and Q of eq. 6 by Van Loan's method. dtS >= 0.
  [[nodiscard]] Discretised<kStateDim> discretise(double dtS) const;
  // ---- The ship motion model (params().ship.enabled): a nonlinear process, linearised per step ----
  /// dx/dt at x.
  [[nodiscard]] State derivative(const State& x) const;
  /// d(dx/dt)/dx at x.
  [[nodiscard]] Mat<kStateDim> jacobianAt(const State& x) const;
  /// The mean carried over dtS (classical Runge-Kutta, in steps of at most 0.25 s).
  [[nodiscard]] State propagate(const State& x, double dtS) const;
  /// Phi and Q of the system linearised at x (Van Loan on the coupled states), for a step of dtS.
  [[nodiscard]] Discretised<kStateDim> discretiseAt(const State& x, double dtS) const;
  /// The ship model's noise input matrix (kShipNoiseDim unit white noises).
  [[nodiscard]] const MatRC<kStateDim, kShipNoiseDim>& shipNoiseInput() const { return shipG_; }
  /// The transition matrix as printed in eq. 5 (first-order in the Gauss-Markov decays), kept to
  /// document and test how far it is from the exact one; the filter uses discretise().
  [[nodiscard]] Mat<kStateDim> printedTransition(double dtS) const;
  [[nodiscard]] const ProcessParams& params() const { return params_; }

 private:
  ProcessParams params_;
  Mat<kStateDim> F_;
  MatRC<kStateDim, kNoiseDim> G_;
  Mat<kStateDim> shipF_;                   ///< the ship model's linear part (velocity rows aside)
  MatRC<kStateDim, kShipNoiseDim> shipG_;  ///< and its noise inputs
};

}  // namespace reckoner::est::drkf
