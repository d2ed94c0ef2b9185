#pragma once
// The hypothesiser and its gate: which plots of an association batch may belong to which track, and
// at what cost. Plots carry no identity; a batch is everything received since the last own-ship input,
// in time order, the first plot's time tRef. Each track comes with its relative state (target minus
// own ship, position and velocity) predicted to tRef (track_predictor.h); the gate carries it to each
// plot's time along the relative velocity and compares it with the plot's offset from own ship:
//   C = Prr + dt (Prv + Prv^T) + dt^2 Pvv + R(plot),  d^2 = e^T C^-1 e  (e = offset - predicted),
// inside the gate when d^2 <= the chi-square gate, at cost d^2 + ln det C (the negative log-likelihood
// up to a constant); a track's miss costs the gate + ln det C at its zero-offset covariance. A uniform
// grid over the plots (geo/grid_index.h) keeps the pairs tried to the plots near each track.
#include <cstddef>
#include <optional>
#include <vector>

#include "common/time.h"
#include "estimation/gaussian.h"
#include "tracking/ttkf.h"

namespace reckoner::track {

/// The plots of one batch as the gate sees them, plot j at index j (time order).
struct PlotBatch {
  /// ownVelocityMps: own ship's estimated velocity (east, north).
  PlotBatch(const std::vector<GridPlot>& plots, const est::Vec<2>& ownVelocityMps);
  [[nodiscard]] std::size_t size() const { return timeUs.size(); }

  est::Vec<2> ownVelocityMps;
  std::vector<TimeUs> timeUs;
  std::vector<est::Vec<2>> offsetM;      ///< from own ship (east, north)
  std::vector<est::Mat<2>> offsetCovM2;  ///< the plot's range and bearing noise, Cartesian
  std::vector<double> sinceRefS;         ///< time from tRef
  std::vector<est::Vec<2>> movingM;      ///< offset + own velocity x sinceRefS: the spatial index's frame
  double spanS = 0.0;                    ///< the last plot's sinceRefS
  double maxRangeVarM2 = 0.0;
  double maxBearingVarRad2 = 0.0;
};

/// A track's relative state [rx ry vx vy] (m, m/s) at tRef with its covariance, and how far the filter
/// sits after tRef (the prediction carried back by lagS).
struct RelativePrediction {
  est::Vec<4> rel;
  est::Mat<4> P;
  double lagS = 0.0;
};

/// A track the gate admitted to a round.
struct GatedTrack {
  std::size_t track = 0;  ///< the caller's index of the track
  TimeUs lastPlotUs = 0;  ///< its last plot: one plot per sweep (Hypothesiser::mayTake)
  est::Vec<4> rel;
  est::Mat<4> P;
  double radiusM = 0.0;   ///< no plot of the batch farther than this (moving frame) can pass the gate
  double missCost = 0.0;  ///< the cost of leaving the track without a plot
};

/// Gated track g (index in the list given) may take plot j at cost.
struct Hypothesis {
  std::size_t track;
  std::size_t plot;
  double cost;
};

/// What the data associator chooses from: per gated track its miss cost, the pairs inside the gate.
struct HypothesisTable {
  std::size_t plots = 0;
  std::vector<double> missCost;
  std::vector<Hypothesis> pairs;
};

class Hypothesiser {
 public:
  /// gate: chi-square threshold on d^2 (2 dof); minGapUs: a track takes no plot within this of its
  /// last one (half a sweep: one plot per sweep).
  Hypothesiser(double gate, TimeUs minGapUs) : gate_(gate), minGapUs_(minGapUs) {}

  /// True when a track last updated at lastPlotUs may take a plot of time plotUs.
  [[nodiscard]] bool mayTake(TimeUs lastPlotUs, TimeUs plotUs) const {
    return plotUs - lastPlotUs > minGapUs_;
  }
  /// The track's gate radius and miss cost; nullopt when its predicted covariance is not positive
  /// definite or the radius is not finite (the track sits this round out).
  [[nodiscard]] std::optional<GatedTrack> admit(std::size_t track, TimeUs lastPlotUs,
                                                const RelativePrediction& p, const PlotBatch& batch) const;
  /// The cost of plot j for track g, nullopt outside the gate.
  [[nodiscard]] std::optional<double> cost(const GatedTrack& g, const PlotBatch& batch, std::size_t j) const;
  /// Every pair inside the gate among plots not yet taken (taken[j] != 0), tracks in the order given,
  /// plots as the spatial index returns them.
  [[nodiscard]] HypothesisTable hypothesise(const std::vector<GatedTrack>& tracks, const PlotBatch& batch,
                                            const std::vector<char>& taken) const;

 private:
  double gate_;
  TimeUs minGapUs_;
};

}  // namespace reckoner::track
