#pragma once
// The predictor of an association round: each track's relative state (target minus own ship,
// position and velocity) at the batch's reference time tRef, as the hypothesiser's gate needs it
// (hypothesiser.h). TTKF tracks (ekf, ekf-ie): only the relative block is predicted,
//   rel = (A Phi) x,  P = (A Phi) P (A Phi)^T + A Q A^T   (A: cpa.h's relativeSelector),
// with one discretisation per distinct time step (most tracks share the last own-ship time), far
// cheaper than predicting all 12 states; abg and imm tracks: their own 12-state prediction to tRef.
#include <vector>

#include "tracking/hypothesiser.h"
#include "tracking/track_filter.h"

namespace reckoner::track {

class RelativePredictor {
 public:
  RelativePredictor(const TtkfContext& ctx, TimeUs tRefUs) : ctx_(ctx), tRefUs_(tRefUs) {}
  /// The filter's relative state at tRef (not changing the filter).
  [[nodiscard]] RelativePrediction predict(const TrackFilter& filter);

 private:
  /// A Phi and A Q A^T over one time step.
  struct StepCache {
    TimeUs stepUs;
    Eigen::Matrix<double, 4, tk::kStateDim> APhi;
    est::Mat<4> AQAt;
  };
  [[nodiscard]] RelativePrediction predictTtkf(const Ttkf& ttkf);
  [[nodiscard]] const StepCache& stepOf(TimeUs stepUs);
  const TtkfContext& ctx_;
  TimeUs tRefUs_;
  std::vector<StepCache> steps_;
};

}  // namespace reckoner::track
