#pragma once
// TTKF process model, seed 000 eqs. 8b-8c: own vessel and target each move with a Gauss-Markov
// acceleration per axis (four independent unit white noises). Discretised exactly per axis
// (estimation/singer.h), which eq. 8c approximates to first order, as eq. 5 does for the DRKF.
#include "estimation/gauss_markov.h"
#include "estimation/models/ttkf_state.h"
#include "estimation/sparse_transition.h"

namespace reckoner::est::ttkf {

inline constexpr int kNoiseDim = 4;

struct ProcessParams {
  GaussMarkov ownAcceleration;     ///< Table III "Ves" sigma (m/s^2) and beta
  GaussMarkov targetAcceleration;  ///< Table III "Tgt" sigma (m/s^2) and beta
};

class ProcessModel {
 public:
  /// Throws std::invalid_argument for invalid Gauss-Markov parameters.
  explicit ProcessModel(const ProcessParams& p);

  struct Discrete {
    SparseTransition<kStateDim> Phi;
    Covariance Q;
  };
  /// Exact Phi and Q over dtS >= 0.
  [[nodiscard]] Discrete discretise(double dtS) const;

  /// Continuous F and G (for tests against Van Loan).
  [[nodiscard]] Mat<kStateDim> F() const;
  [[nodiscard]] MatRC<kStateDim, kNoiseDim> G() const;
  [[nodiscard]] const ProcessParams& params() const { return params_; }

 private:
  ProcessParams params_;
};

}  // namespace reckoner::est::ttkf
