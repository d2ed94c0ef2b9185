#pragma once
// What both workers (SimulationWorker, LiveWorker) fold into a LiveFrame from each engine frame
// (sim::SimFrame): the own-ship sample, the track samples of the sweeps that ended, the radar plots of
// the last few sweeps placed from the estimate, the latest GPS and Loran-C fixes, the last report of
// each DRKF block and the track events. Conversions only: every figure is the engine's or its rows'.
// A frame without truth (a live run's) gives samples whose truth and NEES are NaN.
#include <deque>

#include "geo/local_frame.h"
#include "sim/run_rows.h"
#include "ui/bridge/live_frame.h"

namespace reckoner::ui {

/// Radar plots shown: those of this many latest sweeps.
inline constexpr int kSweepsShown = 6;

OwnSample ownSampleOf(const sim::OwnShipRow& r, const sim::OwnShipDetailRow& d, bool hasTruth = true);
TrackSample trackSampleOf(const sim::TrackRow& r);

class FrameFolder {
 public:
  /// Folds f into pending (ownHistory, trackHistory, lastFix, blocks, events, error95M) and keeps its
  /// plots; `targets`: the scenario's (empty for a live run), for the truth of the tracks' rows.
  void fold(const sim::SimFrame& f, const geo::LocalFrame& geo, const est::drkf::ProcessParams& process,
            const std::vector<sim::TargetSpec>& targets, LiveFrame& pending);
  /// The plots of the last kSweepsShown sweeps.
  [[nodiscard]] const std::deque<ShownPlot>& plots() const { return plots_; }
  void clear();

 private:
  int sweepCounter_ = 0;
  std::deque<ShownPlot> plots_;
};

}  // namespace reckoner::ui
