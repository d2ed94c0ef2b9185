#include "radar/chart_matching.h"

#include <Eigen/Cholesky>
#include <cmath>

#include "estimation/ekf.h"

namespace reckoner::radar {

MatchResult matchEchoes(const std::vector<EchoPoint>& echoes, const SweepPose& pose, const Coastline& coast,
                        const MatchParams& p) {
  MatchResult out;
  out.echoes = static_cast<int>(echoes.size());
  // Each echo's own pose (eq. 2) and bearing from grid north.
  struct Seen {
    est::Vec<2> s;
    double theta, r, beforeEndS;
  };
  std::vector<Seen> seen;
  seen.reserve(echoes.size());
  for (const auto& e : echoes) {
    const double dt = pose.timeOffsetS(e.azimuthRad);
    seen.push_back({pose.positionAt(dt), pose.headingAt(dt) + e.azimuthRad, e.rangeM, pose.periodS - dt});
  }
  est::Vec<3> x = est::Vec<3>::Zero();
  est::Mat<3> A = est::Mat<3>::Zero(), M = est::Mat<3>::Zero();
  std::vector<char> used(echoes.size(), 0);
  for (int it = 0; it < p.maxIterations; ++it) {
    A.setZero();
    M.setZero();
    est::Vec<3> b = est::Vec<3>::Zero();
    int n = 0;
    for (std::size_t i = 0; i < seen.size(); ++i) {
      const Seen& s = seen[i];
      const double th = s.theta + x[2];
      const est::Vec<2> e = s.s + x.head<2>() + s.r * est::Vec<2>(std::sin(th), std::cos(th));
      used[i] = 0;
      const auto k = coast.nearest(e, p.rejectDistanceM);
      if (!k) continue;
      const est::Vec<2>& nrm = k->normal;
      const est::Vec<2> along(std::sin(th), std::cos(th)), across(std::cos(th), -std::sin(th));
      const double sdC = coast.segments()[k->segment].sdM;
      const double var = p.rangeSdM * p.rangeSdM * std::pow(nrm.dot(along), 2) +
                         std::pow(s.r * p.bearingSdRad, 2) * std::pow(nrm.dot(across), 2) + sdC * sdC;
      const est::Vec<3> a(nrm[0], nrm[1], s.r * nrm.dot(across));
      const double d = nrm.dot(k->point - e);
      // Once the picture sits on the chart, an echo far off its contour in its own sd is another
      // object's (a ship alongside, a wrong contour): robust rejection.
      if (it > 0 && d * d > p.outlierSigmas * p.outlierSigmas * var) continue;
      A += a * a.transpose() / var;
      M -= s.beforeEndS * a * a.transpose() / var;
      b += a * d / var;
      used[i] = 1;
      ++n;
    }
    out.used = n;
    out.iterations = it + 1;
    if (n < p.minEchoes) return out;
    const Eigen::LDLT<est::Mat<3>> ldlt(A);
    if (!est::ldltPositiveDefinite(ldlt)) return out;
    const est::Vec<3> dx = ldlt.solve(b);
    if (!dx.allFinite()) return out;
    x += dx;
    // Settled when no echo (at the longest range) moves by more than settleM.
    double maxR = 0.0;
    for (const auto& s : seen) maxR = std::max(maxR, s.r);
    if (dx.head<2>().norm() + maxR * std::abs(dx[2]) < p.settleM) break;
  }
  const Eigen::LDLT<est::Mat<3>> ldlt(A);
  if (!est::ldltPositiveDefinite(ldlt)) return out;
  out.correction = x;
  out.covariance = ldlt.solve(est::Mat<3>::Identity());
  est::symmetrise(out.covariance);
  out.motionSensitivity = ldlt.solve(M);
  out.valid = out.correction.allFinite() && out.covariance.allFinite();
  out.rejected = out.echoes - out.used;
  out.usedMask = used;
  // The matched echoes after the correction, and how well they now sit on the chart.
  double sumSq = 0.0;
  for (std::size_t i = 0; i < seen.size(); ++i) {
    if (!used[i]) continue;
    const Seen& s = seen[i];
    const double th = s.theta + x[2];
    const est::Vec<2> e = s.s + x.head<2>() + s.r * est::Vec<2>(std::sin(th), std::cos(th));
    const auto k = coast.nearest(e, p.rejectDistanceM);
    if (!k) continue;
    const est::Vec<2> along(std::sin(th), std::cos(th)), across(std::cos(th), -std::sin(th));
    const double var = p.rangeSdM * p.rangeSdM * std::pow(k->normal.dot(along), 2) +
                       std::pow(s.r * p.bearingSdRad, 2) * std::pow(k->normal.dot(across), 2) +
                       std::pow(coast.segments()[k->segment].sdM, 2);
    const double d = k->normal.dot(k->point - e);
    if (d * d > p.outlierSigmas * p.outlierSigmas * var) {
      out.usedMask[i] = 0;
      continue;
    }
    sumSq += d * d / var;
    out.echoPoints.push_back(e);
    out.chartPoints.push_back(k->point);
    out.rawEchoPoints.push_back(s.s + s.r * est::Vec<2>(std::sin(s.theta), std::cos(s.theta)));
  }
  out.rmsNormalizedResidual =
      out.echoPoints.empty() ? 0.0 : std::sqrt(sumSq / static_cast<double>(out.echoPoints.size()));
  // A posteriori variance factor (least-squares adjustment), upwards only: when the residuals scatter
  // more than the a-priori errors say (a wrong chart, a water level off the contour), the covariance
  // grows by their chi-square over its degrees of freedom. Smaller residuals do not shrink it: the
  // aggregated echo points' errors are correlated, so their scatter understates the estimate's error.
  const double dof = static_cast<double>(out.echoPoints.size()) - 3.0;
  if (dof > 0.0) out.covariance *= std::max(1.0, sumSq / dof);
  return out;
}

}  // namespace reckoner::radar
