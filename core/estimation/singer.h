#pragma once
// Exact discretisation of one axis of a body with Gauss-Markov acceleration (Singer's model; seed 000
// eq. 8c per axis): p' = v, v' = a, a' = -beta a + alpha w, alpha = sqrt(2 sigma^2 beta).
//   Phi = [1, T, phi_p(T); 0, 1, phi_v(T); 0, 0, e^-bT],  phi_v(s) = (1 - e^-bs)/b,
//   phi_p(s) = (bs - 1 + e^-bs)/b^2,  Q_ij = alpha^2 integral_0^T phi_i(s) phi_j(s) ds, phi_a(s) = e^-bs.
// Radar plots arrive at times set by the beam, so T varies continuously and a Van Loan cache would miss;
// this costs a few dozen exponentials. Phi uses cancellation-free forms; Q is integrated by 8-point
// Gauss-Legendre on panels of b T <= 1 (exact to rounding there; tested against Van Loan).
#include "estimation/gauss_markov.h"
#include "estimation/gaussian.h"

namespace reckoner::est {

struct SingerAxis {
  Mat<3> Phi;
  Mat<3> Q;
};

/// Discretisation over dtS >= 0 for acceleration model acc (sigma m/s^2, beta 1/s > 0).
SingerAxis singerDiscretisation(const GaussMarkov& acc, double dtS);

/// The transition alone (cheap: three exponentials).
Mat<3> singerTransition(const GaussMarkov& acc, double dtS);

}  // namespace reckoner::est
