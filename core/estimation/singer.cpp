#include "estimation/singer.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace reckoner::est {
namespace {

// (x + e^-x - 1) for x >= 0 without cancellation: series below 0.1 (error < x^10 / 10!).
double xPlusExpm1(double x) {
  if (x >= 0.1) return x + std::expm1(-x);
  double term = x * x / 2.0, sum = 0.0;
  for (int n = 2; n < 12; ++n) {
    sum += term;
    term *= -x / (n + 1);
  }
  return sum;
}

// 8-point Gauss-Legendre on [-1, 1].
constexpr std::array<double, 4> kNodes{0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                       0.9602898564975363};
constexpr std::array<double, 4> kWeights{0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                         0.1012285362903763};

}  // namespace

Mat<3> singerTransition(const GaussMarkov& acc, double dtS) {
  const double b = acc.betaPerS, T = std::max(0.0, dtS);
  Mat<3> Phi = Mat<3>::Identity();
  Phi(0, 1) = T;
  Phi(0, 2) = xPlusExpm1(b * T) / (b * b);
  Phi(1, 2) = -std::expm1(-b * T) / b;
  Phi(2, 2) = std::exp(-b * T);
  return Phi;
}

SingerAxis singerDiscretisation(const GaussMarkov& acc, double dtS) {
  const double b = acc.betaPerS, T = std::max(0.0, dtS);
  SingerAxis d;
  d.Phi = singerTransition(acc, T);

  // Q = alpha^2 * integral of phi phi^T over [0, T], by panels of at most b T = 1 up to b T =
  // kTailBT; beyond it phi is a polynomial of degree 1 in s (its exponentials are below 2e-9), which
  // one 8-point panel integrates exactly, so a gap of any length costs at most kTailBT + 1 panels.
  constexpr double kTailBT = 20.0;
  const double head = std::min(T, kTailBT / b);
  const int panels = std::max(1, static_cast<int>(std::ceil(b * head)));
  Mat<3> integral = Mat<3>::Zero();
  const auto panel = [&](double mid, double h) {
    for (std::size_t i = 0; i < kNodes.size(); ++i) {
      for (const double sign : {-1.0, 1.0}) {
        const double s = mid + sign * kNodes[i] * 0.5 * h;
        const Vec<3> phi(xPlusExpm1(b * s) / (b * b), -std::expm1(-b * s) / b, std::exp(-b * s));
        integral += (kWeights[i] * 0.5 * h) * (phi * phi.transpose());
      }
    }
  };
  const double h = head / panels;
  for (int k = 0; k < panels; ++k) panel((k + 0.5) * h, h);
  if (T > head) panel(0.5 * (head + T), T - head);
  const double alpha2 = 2.0 * acc.sigma * acc.sigma * b;
  d.Q = alpha2 * integral;
  symmetrise(d.Q);
  return d;
}

}  // namespace reckoner::est
