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

struct ProcessParams {
  GaussMarkov current;                ///< sigma m/s, Table I sigma_c^2, beta_c
  GaussMarkov acceleration;           ///< sigma m/s^2, Table I footnote sigma_a = 0.5, beta_a = 1
  GaussMarkov loranError;             ///< sigma m, Table I L-C sigma^2, beta_L-C = 0.25
  GaussMarkov speedlogError;          ///< sigma m/s, Table I S-L sigma^2, beta_S-L = 0.5
  GaussMarkov headingBias{0.0, 1.0};  ///< sigma rad; not in the paper (0: no heading bias state)
  GaussMarkov logScale{0.0, 1.0};     ///< sigma (fraction of the speed); not in the paper (0: none)
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
  /// The transition matrix as printed in eq. 5 (first-order in the Gauss-Markov decays), kept to
  /// document and test how far it is from the exact one; the filter uses discretise().
  [[nodiscard]] Mat<kStateDim> printedTransition(double dtS) const;
  [[nodiscard]] const ProcessParams& params() const { return params_; }

 private:
  ProcessParams params_;
  Mat<kStateDim> F_;
  MatRC<kStateDim, kNoiseDim> G_;
};

}  // namespace reckoner::est::drkf
