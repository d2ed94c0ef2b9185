#pragma once
// The updater of a track with its associated plot: the filter's own radar update (track_filter.h),
// then what the track keeps besides: seed 001's input estimation around the TTKF for ekf-ie tracks
// (docs/manoeuvres.md), the IMM's manoeuvre flag for imm tracks, and the track's record (last plot,
// belief right after it, the tags of the plots used).
#include "tracking/track.h"

namespace reckoner::track {

struct PlotUpdate {
  bool applied = false;            ///< the filter accepted the plot
  bool manoeuvreDeclared = false;  ///< the manoeuvre flag rose (a Manoeuvre event at the plot's time)
};

class TrackUpdater {
 public:
  /// inputThreshold: the chi-square threshold (2 dof) on input estimation's statistic d.
  explicit TrackUpdater(double inputThreshold = 0.0) : inputThreshold_(inputThreshold) {}
  /// Updates the track with the plot; tag: its true target in simulation (-1: unknown). A plot the
  /// filter rejects leaves the track's record unchanged (lastRadar holds the report).
  PlotUpdate apply(Track& t, const GridPlot& plot, int tag) const;

 private:
  /// Seed 001's input estimation after an accepted TTKF update; true when a manoeuvre was declared.
  bool estimateInput(Track& t, Ttkf& filter, TimeUs time, const Ttkf::RadarDetail& detail) const;
  double inputThreshold_;
};

}  // namespace reckoner::track
