#pragma once
// Chi-square distribution: CDF, quantile and the two-sided NEES/NIS bounds of a Monte Carlo average.

namespace reckoner::est {

/// Regularised lower incomplete gamma P(a, x) for a > 0, x >= 0.
double regularisedGammaP(double a, double x);

/// CDF of the chi-square distribution with dof > 0 degrees of freedom at x >= 0.
double chiSquareCdf(double x, double dof);

/// Quantile: the x with chiSquareCdf(x, dof) = p, for 0 < p < 1 (relative accuracy ~1e-12).
double chiSquareQuantile(double p, double dof);

struct ChiSquareBounds {
  double lower = 0.0;
  double upper = 0.0;
  [[nodiscard]] bool contains(double v) const { return v >= lower && v <= upper; }
};

/// Two-sided bounds for the average of `runs` independent NEES (or NIS) values of dimension `dim`:
/// runs * average ~ chi2(runs * dim), so the bounds are quantile((1 -/+ confidence) / 2) / runs.
ChiSquareBounds averageNeesBounds(int dim, int runs, double confidence = 0.95);

}  // namespace reckoner::est
