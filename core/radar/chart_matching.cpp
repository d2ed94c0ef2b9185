#include "radar/chart_matching.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <utility>

#include "estimation/ekf.h"

namespace reckoner::radar {
namespace {

/// Echo i as own ship saw it: the pose at the echo's own time in the sweep (eq. 2), its bearing from
/// grid north theta_i = psi_i + v_i and its range r_i.
struct SeenEcho {
  est::Vec<2> fromM;      ///< s_i, grid m
  double gridBearingRad;  ///< theta_i before the heading correction
  double rangeM;          ///< r_i
  double beforeEndS;      ///< how long before the sweep's end it was seen
};

std::vector<SeenEcho> seenEchoes(const std::vector<EchoPoint>& echoes, const SweepPose& pose) {
  std::vector<SeenEcho> seen;
  seen.reserve(echoes.size());
  for (const auto& e : echoes) {
    const double dt = pose.timeOffsetS(e.azimuthRad);
    seen.push_back({pose.positionAt(dt), pose.headingAt(dt) + e.azimuthRad, e.rangeM, pose.periodS - dt});
  }
  return seen;
}

/// One echo against its nearest contour, with the correction x = (ds_x, ds_y, dv) applied.
struct ContourRow {
  est::Vec<2> echoM;   ///< e_i = s_i + ds + r_i (sin, cos)(theta_i + dv) (eq. 3)
  est::Vec<2> chartM;  ///< k_i, the nearest contour point
  est::Vec<3> a;       ///< the row of eq. 4 along the contour's normal: (n_x, n_y, r_i n_i.(cos, -sin))
  double residualM;    ///< n_i' d_i, d_i = k_i - e_i
  double varianceM2;   ///< the echo's error along n_i (eq. 6) plus the contour's own sd^2
  /// An echo this far off its contour in its own sd is another object's (a ship alongside, a wrong
  /// contour): robust rejection.
  [[nodiscard]] bool outlier(const MatchParams& p) const {
    return residualM * residualM > p.outlierSigmas * p.outlierSigmas * varianceM2;
  }
};

std::optional<ContourRow> contourRow(const SeenEcho& s, const est::Vec<3>& x, const Coastline& coast,
                                     const MatchParams& p) {
  const double th = s.gridBearingRad + x[2];
  const est::Vec<2> e = s.fromM + x.head<2>() + s.rangeM * est::Vec<2>(std::sin(th), std::cos(th));
  const auto k = coast.nearest(e, p.rejectDistanceM);
  if (!k) return std::nullopt;
  const est::Vec<2>& nrm = k->normal;
  // Eq. 6: range sd along the beam, range times bearing sd across it.
  const est::Vec<2> along(std::sin(th), std::cos(th)), across(std::cos(th), -std::sin(th));
  const double sdC = coast.segments()[k->segment].sdM;
  const double var = p.rangeSdM * p.rangeSdM * std::pow(nrm.dot(along), 2) +
                     std::pow(s.rangeM * p.bearingSdRad, 2) * std::pow(nrm.dot(across), 2) + sdC * sdC;
  const est::Vec<3> a(nrm[0], nrm[1], s.rangeM * nrm.dot(across));
  return ContourRow{e, k->point, a, nrm.dot(k->point - e), var};
}

/// The weighted normal equations of the stacked rows (eq. 5, one row per echo along its normal).
struct NormalEquations {
  est::Mat<3> information = est::Mat<3>::Zero();  ///< sum_i a_i a_i' / var_i
  est::Mat<3> motion = est::Mat<3>::Zero();       ///< sum_i (-dt_i) a_i a_i' / var_i
  est::Vec<3> rhs = est::Vec<3>::Zero();          ///< sum_i a_i n_i'd_i / var_i
  std::vector<char> used;                         ///< per echo: a row of these equations
  int rows = 0;
};

NormalEquations normalEquations(const std::vector<SeenEcho>& seen, const est::Vec<3>& x,
                                const Coastline& coast, const MatchParams& p, bool rejectOutliers) {
  NormalEquations eq;
  eq.used.assign(seen.size(), 0);
  for (std::size_t i = 0; i < seen.size(); ++i) {
    const auto row = contourRow(seen[i], x, coast, p);
    if (!row || (rejectOutliers && row->outlier(p))) continue;
    const est::Vec<3>& a = row->a;
    const double var = row->varianceM2;
    eq.information += a * a.transpose() / var;
    eq.motion -= seen[i].beforeEndS * a * a.transpose() / var;
    eq.rhs += a * row->residualM / var;
    eq.used[i] = 1;
    ++eq.rows;
  }
  return eq;
}

/// The least-squares fix: solve, move the echoes, find their nearest contour points again, until the
/// correction settles.
struct IteratedFix {
  est::Vec<3> correction = est::Vec<3>::Zero();
  NormalEquations last;  ///< of the last iteration
  int iterations = 0;
  bool failed = false;  ///< too few echoes, or a normal matrix that is not positive definite
};

IteratedFix iterateFix(const std::vector<SeenEcho>& seen, const Coastline& coast, const MatchParams& p) {
  IteratedFix fix;
  double maxR = 0.0;  // settled when no echo (at the longest range) moves by more than settleM
  for (const auto& s : seen) maxR = std::max(maxR, s.rangeM);
  for (int it = 0; it < p.maxIterations; ++it) {
    // Robust rejection once the picture sits on the chart, from the second solve on.
    fix.last = normalEquations(seen, fix.correction, coast, p, it > 0);
    fix.iterations = it + 1;
    fix.failed = true;
    if (fix.last.rows < p.minEchoes) return fix;
    const Eigen::LDLT<est::Mat<3>> ldlt(fix.last.information);
    if (!est::ldltPositiveDefinite(ldlt)) return fix;
    const est::Vec<3> dx = ldlt.solve(fix.last.rhs);
    if (!dx.allFinite()) return fix;
    fix.failed = false;
    fix.correction += dx;
    if (dx.head<2>().norm() + maxR * std::abs(dx[2]) < p.settleM) break;
  }
  return fix;
}

/// The matched echoes after the correction, and how well they now sit on the chart.
struct MatchedEchoes {
  std::vector<char> usedMask;
  std::vector<est::Vec<2>> echoPoints, chartPoints, rawEchoPoints;
  double sumNormalizedSq = 0.0;  ///< sum of d_i^2 / var_i
};

MatchedEchoes matchedEchoes(const std::vector<SeenEcho>& seen, const IteratedFix& fix, const Coastline& coast,
                            const MatchParams& p) {
  MatchedEchoes m;
  m.usedMask = fix.last.used;
  for (std::size_t i = 0; i < seen.size(); ++i) {
    if (!fix.last.used[i]) continue;
    const SeenEcho& s = seen[i];
    const auto row = contourRow(s, fix.correction, coast, p);
    if (!row) continue;
    if (row->outlier(p)) {
      m.usedMask[i] = 0;
      continue;
    }
    m.sumNormalizedSq += row->residualM * row->residualM / row->varianceM2;
    m.echoPoints.push_back(row->echoM);
    m.chartPoints.push_back(row->chartM);
    m.rawEchoPoints.push_back(s.fromM +
                              s.rangeM * est::Vec<2>(std::sin(s.gridBearingRad), std::cos(s.gridBearingRad)));
  }
  return m;
}

}  // namespace

MatchResult matchEchoes(const std::vector<EchoPoint>& echoes, const SweepPose& pose, const Coastline& coast,
                        const MatchParams& p) {
  MatchResult out;
  out.echoes = static_cast<int>(echoes.size());
  const std::vector<SeenEcho> seen = seenEchoes(echoes, pose);  // eq. 2
  const IteratedFix fix = iterateFix(seen, coast, p);           // eqs. 3 to 6
  out.used = fix.last.rows;
  out.iterations = fix.iterations;
  if (fix.failed) return out;
  const Eigen::LDLT<est::Mat<3>> ldlt(fix.last.information);
  if (!est::ldltPositiveDefinite(ldlt)) return out;
  // The fix and its covariance, the inverse normal matrix of the last iteration.
  out.correction = fix.correction;
  out.covariance = ldlt.solve(est::Mat<3>::Identity());
  est::symmetrise(out.covariance);
  out.motionSensitivity = ldlt.solve(fix.last.motion);
  out.valid = out.correction.allFinite() && out.covariance.allFinite();
  out.rejected = out.echoes - out.used;
  MatchedEchoes matched = matchedEchoes(seen, fix, coast, p);
  out.usedMask = std::move(matched.usedMask);
  out.echoPoints = std::move(matched.echoPoints);
  out.chartPoints = std::move(matched.chartPoints);
  out.rawEchoPoints = std::move(matched.rawEchoPoints);
  const double sumSq = matched.sumNormalizedSq;
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
