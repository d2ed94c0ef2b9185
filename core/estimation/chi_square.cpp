#include "estimation/chi_square.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace reckoner::est {
namespace {

// log Gamma(a), a > 0, through lgamma_r: std::lgamma writes the global signgam, a data race when two
// threads set up filters at once (the workers run theirs off the GUI thread; concurrency-mt-unsafe).
double logGamma(double a) {
  int sign = 0;
  return ::lgamma_r(a, &sign);
}

// Series P(a, x) = e^-x x^a / Gamma(a + 1) * sum_n x^n / ((a + 1) ... (a + n)); converges for x < a + 1.
double gammaPSeries(double a, double x) {
  double term = 1.0 / a;
  double sum = term;
  for (int n = 1; n < 10000; ++n) {
    term *= x / (a + n);
    sum += term;
    if (std::abs(term) < std::abs(sum) * 1e-16) break;
  }
  return sum * std::exp(-x + a * std::log(x) - logGamma(a));
}

// Continued fraction for Q(a, x) = 1 - P(a, x), modified Lentz; converges for x >= a + 1.
double gammaQContinuedFraction(double a, double x) {
  constexpr double tiny = 1e-300;
  double b = x + 1.0 - a;
  double c = 1.0 / tiny;
  double d = 1.0 / b;
  double h = d;
  for (int i = 1; i < 10000; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-16) break;
  }
  return std::exp(-x + a * std::log(x) - logGamma(a)) * h;
}

}  // namespace

double regularisedGammaP(double a, double x) {
  if (!(a > 0.0) || !(x >= 0.0)) return std::numeric_limits<double>::quiet_NaN();
  if (x == 0.0) return 0.0;
  if (std::isinf(x)) return 1.0;
  return x < a + 1.0 ? gammaPSeries(a, x) : 1.0 - gammaQContinuedFraction(a, x);
}

double chiSquareCdf(double x, double dof) {
  return regularisedGammaP(0.5 * dof, 0.5 * x);
}

double chiSquareQuantile(double p, double dof) {
  if (!(p > 0.0 && p < 1.0) || !(dof > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  // Bracket, then Newton steps kept inside the bracket (bisection when Newton leaves it).
  double lo = 0.0;
  double hi = dof + 10.0 * std::sqrt(2.0 * dof) + 10.0;
  while (chiSquareCdf(hi, dof) < p) hi *= 2.0;
  double x = dof;  // the mean; a fine start for all but tiny dof
  if (x <= lo || x >= hi) x = 0.5 * (lo + hi);
  const double a = 0.5 * dof;
  const double logNorm = -a * std::log(2.0) - logGamma(a);
  for (int it = 0; it < 200; ++it) {
    const double f = chiSquareCdf(x, dof) - p;
    if (f > 0.0)
      hi = x;
    else
      lo = x;
    const double pdf = std::exp(logNorm + (a - 1.0) * std::log(x) - 0.5 * x);
    // Bisect geometrically once the bracket is positive: small-dof quantiles can be ~1e-24.
    const double mid = lo > 0.0 ? std::sqrt(lo * hi) : 0.5 * hi;
    double next = (pdf > 0.0 && std::isfinite(pdf)) ? x - f / pdf : mid;
    if (!(next > lo && next < hi)) next = mid;
    if (std::abs(next - x) <= 1e-15 * x) return next;
    x = next;
  }
  return x;
}

ChiSquareBounds averageNeesBounds(int dim, int runs, double confidence) {
  if (dim <= 0 || runs <= 0 || !(confidence > 0.0 && confidence < 1.0)) {
    throw std::invalid_argument("averageNeesBounds: need dim > 0, runs > 0 and 0 < confidence < 1");
  }
  const double dof = static_cast<double>(dim) * runs;
  const double tail = 0.5 * (1.0 - confidence);
  return {chiSquareQuantile(tail, dof) / runs, chiSquareQuantile(1.0 - tail, dof) / runs};
}

}  // namespace reckoner::est
