#include "navigation/look_ahead.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "common/angles.h"
#include "common/rng.h"

namespace reckoner::nav {
namespace {

/// The symmetric square root of a covariance, its negative eigenvalues (rounding) taken as 0.
est::Mat<4> sqrtPsd(const est::Mat<4>& m) {
  const Eigen::SelfAdjointEigenSolver<est::Mat<4>> eig(0.5 * (m + m.transpose()));
  const est::Vec<4> d = eig.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  return eig.eigenvectors() * d.asDiagonal() * eig.eigenvectors().transpose();
}

/// The standard normal quantile: a coarse start refined by Newton on erfc (used once per table).
double normalQuantile(double u) {
  const double q = std::min(u, 1.0 - u);
  double x = std::sqrt(-2.0 * std::log(q));
  x -= (2.515517 + 0.802853 * x + 0.010328 * x * x) /
       (1.0 + 1.432788 * x + 0.189269 * x * x + 0.001308 * x * x * x);
  for (int i = 0; i < 6; ++i) {  // solve Phi(-x) = q
    const double f = 0.5 * std::erfc(x / std::sqrt(2.0)) - q;
    x += f / (std::exp(-0.5 * x * x) / std::sqrt(2.0 * kPi));
  }
  return u < 0.5 ? -x : x;
}

/// Radical inverse of i in a prime base (the Halton sequence).
double radicalInverse(std::uint64_t i, std::uint64_t base) {
  double f = 1.0, r = 0.0;
  for (; i > 0; i /= base) {
    f /= static_cast<double>(base);
    r += f * static_cast<double>(i % base);
  }
  return r;
}

/// The fixed standard normal draws, per path 4 for the fan and 2 for the wander: a Halton sequence
/// in six prime bases, shifted by a fixed random offset per dimension (Cranley-Patterson), through the
/// normal quantile. Low-discrepancy draws estimate a probability of a few percent several times more
/// accurately than as many pseudo-random ones.
const std::vector<est::Vec<6>>& draws(int n) {
  static thread_local std::vector<est::Vec<6>> cache;
  if (static_cast<int>(cache.size()) != n) {
    constexpr std::array<std::uint64_t, 6> kBases{2, 3, 5, 7, 11, 13};
    Rng rng(0x10CA4EADull, 0);
    std::array<double, 6> shift{};
    for (double& s : shift) s = rng.uniform();
    cache.resize(static_cast<std::size_t>(n));
    for (std::size_t i = 0; i < cache.size(); ++i) {
      for (std::size_t k = 0; k < 6; ++k) {
        double u = radicalInverse(i + 1, kBases[k]) + shift[k];
        u -= std::floor(u);
        u = std::clamp(u, 1e-12, 1.0 - 1e-12);
        cache[i][static_cast<int>(k)] = normalQuantile(u);
      }
    }
  }
  return cache;
}

}  // namespace

std::vector<std::string> LookAheadSettings::problems() const {
  std::vector<std::string> out;
  if (!(horizonS > 0.0 && horizonS <= 3600.0)) out.emplace_back("look-ahead time must be in (0, 3600] s");
  if (!(stepS > 0.0 && stepS <= horizonS))
    out.emplace_back("look-ahead step must be in (0, look-ahead time] s");
  if (samples < 10 || samples > 100000) out.emplace_back("look-ahead samples must be in [10, 100000]");
  if (!(courseKeepingM2S3 >= 0.0 && courseKeepingM2S3 < 1.0))
    out.emplace_back("look-ahead course keeping acceleration must be in [0, 1) m^2/s^3");
  return out;
}

LookAheadPrediction predictLookAhead(const Drkf& filter, const LookAheadSettings& s) {
  if (const auto p = s.problems(); !p.empty()) throw std::invalid_argument(p.front());
  LookAheadPrediction out;
  out.t0Us = filter.timeUs();
  const est::Vec<4> g0 = groundStateOf(filter.belief());
  const est::Mat<4> c0 = groundCovarianceOf(filter.belief());
  if (!g0.allFinite() || !c0.allFinite()) return out;
  const est::Mat<4> fan = sqrtPsd(c0);
  const auto steps = static_cast<int>(std::ceil(s.horizonS / s.stepS - 1e-9));
  std::vector<double> wander;
  for (int k = 0; k <= steps; ++k) {
    const double t = std::min(s.horizonS, k * s.stepS);
    out.timesS.push_back(t);
    out.mean.push_back({g0[0] + g0[2] * t, g0[1] + g0[3] * t});
    est::MatRC<2, 4> a = est::MatRC<2, 4>::Zero();
    a(0, 0) = a(1, 1) = 1.0;
    a(0, 2) = a(1, 3) = t;
    const double w2 = s.courseKeepingM2S3 * t * t * t / 3.0;
    out.covariance.push_back(a * c0 * a.transpose() + w2 * est::Mat<2>::Identity());
    wander.push_back(std::sqrt(w2));
  }
  const std::vector<est::Vec<6>>& z = draws(s.samples);
  out.paths.resize(static_cast<std::size_t>(s.samples));
  for (std::size_t i = 0; i < out.paths.size(); ++i) {
    const est::Vec<4> d = fan * z[i].head<4>();
    auto& path = out.paths[i];
    path.reserve(out.timesS.size());
    for (std::size_t k = 0; k < out.timesS.size(); ++k) {
      const double t = out.timesS[k];
      path.push_back({out.mean[k].xM + d[0] + d[2] * t + wander[k] * z[i][4],
                      out.mean[k].yM + d[1] + d[3] * t + wander[k] * z[i][5]});
    }
  }
  out.valid = true;
  return out;
}

}  // namespace reckoner::nav
