#include "tracking/track_updater.h"

#include <Eigen/Cholesky>

namespace reckoner::track {
namespace tk = est::ttkf;
namespace {

/// Sets the track's manoeuvre flag; true on its rising edge.
bool setManoeuvring(Track& t, bool flag) {
  const bool rising = flag && !t.manoeuvring;
  t.manoeuvring = flag;
  return rising;
}

}  // namespace

PlotUpdate TrackUpdater::apply(Track& t, const GridPlot& plot, int tag) const {
  PlotUpdate out;
  const bool ie = t.filter.kind() == TrackerKind::EkfInputEstimation;
  Ttkf::RadarDetail detail;
  t.lastRadar = t.filter.updateRadar(plot, ie ? &detail : nullptr);
  if (!t.lastRadar.applied()) return out;
  out.applied = true;
  if (ie)
    out.manoeuvreDeclared = estimateInput(t, *t.filter.ttkf(), plot.timeUs, detail);
  else if (t.filter.kind() == TrackerKind::Imm)
    out.manoeuvreDeclared = setManoeuvring(t, t.filter.modelManoeuvring());
  ++t.radarUpdates;
  t.seenThisSweep = true;
  t.lastPlotUs = plot.timeUs;
  t.lastUpdate = t.filter.belief();
  t.recentTags[static_cast<std::size_t>(t.tagCount % static_cast<int>(t.recentTags.size()))] = tag;
  ++t.tagCount;
  return out;
}

bool TrackUpdater::estimateInput(Track& t, Ttkf& filter, TimeUs time, const Ttkf::RadarDetail& detail) const {
  // Seed 001's input estimation around the TTKF (docs/manoeuvres.md): one window entry per radar
  // update. Between radar updates the own-ship feed also updates the filter; its effect on the
  // target's response to the input is neglected (it conditions the own-ship states).
  const TimeUs dtUs = time - t.lastRadarUs;
  const double dt = toSeconds(dtUs);
  t.lastRadarUs = time;
  if (dtUs <= 0) return false;
  InputWindow<tk::kStateDim>::Entry e;
  e.Phi = filter.transition(dtUs);
  e.G.setZero();
  e.G(tk::kTgtX, 0) = e.G(tk::kTgtY, 1) = 0.5 * dt * dt;  // a constant acceleration over dt
  e.G(tk::kTgtVx, 0) = e.G(tk::kTgtVy, 1) = dt;
  e.H = detail.H;
  e.S = t.lastRadar.S;
  e.innovation = t.lastRadar.innovation;
  const Eigen::LDLT<est::Mat<2>> ldlt(e.S);
  e.W = ldlt.solve(e.H * detail.priorP).transpose();  // K = P H^T S^-1 (S and P symmetric)
  t.inputWindow.push(e);
  const auto est = t.inputWindow.estimate();
  if (!est.tested) return false;
  if (est.d < inputThreshold_) {
    t.manoeuvring = false;  // the input is no longer significant: the manoeuvre has ended
    return false;
  }
  if (!filter.correct(est.M * est.u, est.M * est.L * est.M.transpose())) return false;
  t.inputWindow.clear();  // the stored innovations belong to the uncorrected estimate
  return setManoeuvring(t, true);
}

}  // namespace reckoner::track
