#include "tracking/track_predictor.h"

#include <algorithm>

#include "tracking/cpa.h"

namespace reckoner::track {
namespace {
const Eigen::Matrix<double, 4, tk::kStateDim>& selector() {
  static const Eigen::Matrix<double, 4, tk::kStateDim> A = relativeSelector();  // rel = A x
  return A;
}
}  // namespace

RelativePrediction RelativePredictor::predict(const TrackFilter& filter) {
  if (const Ttkf* ttkf = filter.ttkf()) return predictTtkf(*ttkf);
  // abg and imm: their own prediction to tRef (never behind it: they sit at their last plot and own
  // ship's last input, both before the pending plots).
  const Eigen::Matrix<double, 4, tk::kStateDim>& A = selector();
  const tk::Belief b = filter.predicted(tRefUs_);
  RelativePrediction p{A * b.x, A * b.P * A.transpose(), 0.0};
  p.P = 0.5 * (p.P + p.P.transpose()).eval();
  return p;
}

RelativePrediction RelativePredictor::predictTtkf(const Ttkf& ttkf) {
  const TimeUs from = ttkf.timeUs();
  const StepCache& s = stepOf(std::max<TimeUs>(0, tRefUs_ - from));
  const tk::Belief& b = ttkf.belief();
  const Eigen::Matrix<double, 4, tk::kStateDim> APhiP = s.APhi.lazyProduct(b.P);
  RelativePrediction p{s.APhi * b.x, APhiP.lazyProduct(s.APhi.transpose()) + s.AQAt, 0.0};
  // The filter may sit later than tRef (a plot just after an own-ship input): carry it back.
  p.lagS = toSeconds(from > tRefUs_ ? from - tRefUs_ : 0);
  p.rel.head<2>() -= p.rel.tail<2>() * p.lagS;
  return p;
}

const RelativePredictor::StepCache& RelativePredictor::stepOf(TimeUs stepUs) {
  const auto it = std::find_if(steps_.begin(), steps_.end(),
                               [stepUs](const StepCache& sc) { return sc.stepUs == stepUs; });
  if (it != steps_.end()) return *it;
  const Eigen::Matrix<double, 4, tk::kStateDim>& A = selector();
  const auto& d = ctx_.discrete(stepUs);
  steps_.push_back({stepUs, A.lazyProduct(d.Phi.dense()), A.lazyProduct(d.Q).lazyProduct(A.transpose())});
  return steps_.back();
}

}  // namespace reckoner::track
