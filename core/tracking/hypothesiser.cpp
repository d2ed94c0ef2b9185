#include "tracking/hypothesiser.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include "common/angles.h"
#include "geo/grid_index.h"

namespace reckoner::track {
namespace {

/// Cartesian covariance of a polar plot offset (range r, bearing b clockwise from north).
est::Mat<2> polarToCartesianCov(double r, double b, double varR, double varB) {
  const double s = std::sin(b), c = std::cos(b);
  est::Mat<2> J;
  J << s, r * c, c, -r * s;
  return J * est::Vec<2>(varR, varB).asDiagonal() * J.transpose();
}

/// d^T C^-1 d and log det C for a 2x2 covariance; nullopt if C is not positive definite.
std::optional<std::pair<double, double>> mahalanobis2(const est::Vec<2>& d, const est::Mat<2>& C) {
  const double det = C(0, 0) * C(1, 1) - C(0, 1) * C(1, 0);
  if (!(C(0, 0) > 0.0) || !(det > 0.0) || !std::isfinite(det)) return std::nullopt;
  const double q = (C(1, 1) * d[0] * d[0] - 2.0 * C(0, 1) * d[0] * d[1] + C(0, 0) * d[1] * d[1]) / det;
  return std::make_pair(q, std::log(det));
}

/// The spatial index of a batch: a uniform grid over the plots' positions in the moving frame, with
/// the median gate radius of the round's tracks as its cell.
class PlotIndex {
 public:
  PlotIndex(const std::vector<GatedTrack>& tracks, const PlotBatch& batch)
      : plots_(batch.size()), cellM_(medianCell(tracks)), grid_(cellM_, boxesOf(batch)) {}

  /// The plots in the cells within radiusM of the track's position (all plots when that is fewer).
  void near(const GatedTrack& g, std::vector<std::size_t>& out) const {
    out.clear();
    const double cells = std::ceil(g.radiusM / cellM_);
    if ((2 * cells + 1) * (2 * cells + 1) > static_cast<double>(plots_)) {
      for (std::size_t j = 0; j < plots_; ++j) out.push_back(j);
      return;
    }
    const auto n = static_cast<std::int64_t>(cells);
    const auto cx = grid_.cellOf(g.rel[0]);
    const auto cy = grid_.cellOf(g.rel[1]);
    for (std::int64_t ix = cx - n; ix <= cx + n; ++ix)
      for (std::int64_t iy = cy - n; iy <= cy + n; ++iy)
        for (const std::uint32_t j : grid_.cell(ix, iy)) out.push_back(j);
  }

 private:
  static double medianCell(const std::vector<GatedTrack>& tracks) {
    std::vector<double> radii;
    radii.reserve(tracks.size());
    for (const auto& g : tracks) radii.push_back(g.radiusM);
    std::nth_element(radii.begin(), radii.begin() + static_cast<std::ptrdiff_t>(radii.size() / 2),
                     radii.end());
    return std::clamp(radii[radii.size() / 2], 50.0, 20000.0);
  }
  static std::vector<geo::GridBox> boxesOf(const PlotBatch& batch) {
    std::vector<geo::GridBox> points;
    points.reserve(batch.size());
    for (const auto& m : batch.movingM) points.push_back({m[0], m[1], m[0], m[1]});
    return points;
  }
  std::size_t plots_;
  double cellM_;
  geo::GridIndex grid_;
};

}  // namespace

PlotBatch::PlotBatch(const std::vector<GridPlot>& plots, const est::Vec<2>& ownVelocity)
    : ownVelocityMps(ownVelocity),
      timeUs(plots.size()),
      offsetM(plots.size()),
      offsetCovM2(plots.size()),
      sinceRefS(plots.size()),
      movingM(plots.size()) {
  if (plots.empty()) return;
  const TimeUs tRef = plots.front().timeUs;
  for (std::size_t j = 0; j < plots.size(); ++j) {
    const GridPlot& p = plots[j];
    timeUs[j] = p.timeUs;
    offsetM[j] = {p.rangeM * std::sin(p.bearingRad), p.rangeM * std::cos(p.bearingRad)};
    offsetCovM2[j] = polarToCartesianCov(p.rangeM, p.bearingRad, p.rangeVarM2, p.bearingVarRad2);
    sinceRefS[j] = toSeconds(p.timeUs - tRef);
    movingM[j] = offsetM[j] + ownVelocityMps * sinceRefS[j];
    spanS = std::max(spanS, sinceRefS[j]);
    maxRangeVarM2 = std::max(maxRangeVarM2, p.rangeVarM2);
    maxBearingVarRad2 = std::max(maxBearingVarRad2, p.bearingVarRad2);
  }
}

std::optional<GatedTrack> Hypothesiser::admit(std::size_t track, TimeUs lastPlotUs,
                                              const RelativePrediction& p, const PlotBatch& batch) const {
  GatedTrack g{track, lastPlotUs, p.rel, p.P, 0.0, 0.0};
  // The widest the gate can be over the batch: the position spread with the noisiest plot's noise at
  // the track's range and bearing, plus how far the target may move (speed and its spread) meanwhile.
  const double range = g.rel.head<2>().norm();
  const double bearing = bearingOf(g.rel[0], g.rel[1]);
  const est::Mat<2> Rt = polarToCartesianCov(range, bearing, batch.maxRangeVarM2, batch.maxBearingVarRad2);
  const est::Mat<2> Crr = g.P.topLeftCorner<2, 2>() + Rt;
  const double lmaxR = est::largestEigenvalue(Crr);
  const est::Mat<2> Pvv = g.P.bottomRightCorner<2, 2>();
  const double lmaxV = est::largestEigenvalue(Pvv);
  const double speed = (g.rel.tail<2>() + batch.ownVelocityMps).norm();
  g.radiusM = std::sqrt(gate_ * lmaxR) + (speed + std::sqrt(gate_ * lmaxV)) * (batch.spanS + p.lagS);
  const auto m = mahalanobis2(est::Vec<2>::Zero(), Crr);
  if (!m || !std::isfinite(g.radiusM)) return std::nullopt;
  g.missCost = gate_ + m->second;
  return g;
}

std::optional<double> Hypothesiser::cost(const GatedTrack& g, const PlotBatch& batch, std::size_t j) const {
  const double d = batch.sinceRefS[j];
  const est::Vec<2> pred = g.rel.head<2>() + g.rel.tail<2>() * d;
  const est::Mat<2> Prv = g.P.block<2, 2>(0, 2);
  est::Mat<2> C = g.P.topLeftCorner<2, 2>() + d * (Prv + Prv.transpose()) +
                  d * d * g.P.bottomRightCorner<2, 2>() + batch.offsetCovM2[j];
  const auto m = mahalanobis2(batch.offsetM[j] - pred, C);
  if (!m || !(m->first <= gate_)) return std::nullopt;
  return m->first + m->second;
}

HypothesisTable Hypothesiser::hypothesise(const std::vector<GatedTrack>& tracks, const PlotBatch& batch,
                                          const std::vector<char>& taken) const {
  HypothesisTable table;
  table.plots = batch.size();
  table.missCost.reserve(tracks.size());
  for (const auto& g : tracks) table.missCost.push_back(g.missCost);
  if (tracks.empty()) return table;
  const PlotIndex index(tracks, batch);
  std::vector<std::size_t> near;
  for (std::size_t gi = 0; gi < tracks.size(); ++gi) {
    const GatedTrack& g = tracks[gi];
    index.near(g, near);
    for (const std::size_t j : near) {
      if (taken[j] || !mayTake(g.lastPlotUs, batch.timeUs[j])) continue;
      if (const auto c = cost(g, batch, j)) table.pairs.push_back({gi, j, *c});
    }
  }
  return table;
}

}  // namespace reckoner::track
