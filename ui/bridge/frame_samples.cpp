#include "ui/bridge/frame_samples.h"

#include <cmath>
#include <limits>

namespace reckoner::ui {

OwnSample ownSampleOf(const sim::OwnShipRow& r, const sim::OwnShipDetailRow& d, bool hasTruth) {
  OwnSample s;
  s.tS = toSeconds(r.timeUs);
  s.estPos = {r.estXM, r.estYM};
  s.estVel = {r.estVxMps, r.estVyMps};
  s.sdPos = {r.sdXM, r.sdYM};
  s.sdVel = {r.sdVxMps, r.sdVyMps};
  s.estCurrent = {d.estCurrentXMps, d.estCurrentYMps};
  s.sdCurrent = {d.sdCurrentXMps, d.sdCurrentYMps};
  s.estLoran = {d.estLoranXM, d.estLoranYM};
  s.sdLoran = {d.sdLoranXM, d.sdLoranYM};
  s.estLogBias = d.estLogBiasMps;
  s.sdLogBias = d.sdLogBiasMps;
  s.error95M = d.error95M;
  if (!hasTruth) {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    s.truePos = s.trueVel = s.trueCurrent = s.trueLoran = {nan, nan};
    s.trueLogBias = s.nees = nan;
    return s;
  }
  s.truePos = {r.trueXM, r.trueYM};
  s.trueVel = {r.trueVxMps, r.trueVyMps};
  s.trueCurrent = {d.trueCurrentXMps, d.trueCurrentYMps};
  s.trueLoran = {d.trueLoranXM, d.trueLoranYM};
  s.trueLogBias = d.trueLogBiasMps;
  s.nees = r.nees;
  return s;
}

TrackSample trackSampleOf(const sim::TrackRow& r) {
  TrackSample s;
  s.tS = toSeconds(r.timeUs);
  s.trackId = r.trackId;
  s.targetId = r.targetId;
  s.manoeuvring = r.manoeuvring;
  s.estPos = {r.estXM, r.estYM};
  s.estVel = {r.estVxMps, r.estVyMps};
  s.sdPos = {r.sdXM, r.sdYM};
  s.sdVel = {r.sdVxMps, r.sdVyMps};
  s.hasTruth = r.hasTruth;
  if (r.hasTruth) {
    s.truePos = {r.trueXM, r.trueYM};
    s.trueVel = {r.trueVxMps, r.trueVyMps};
    s.positionVelocityNees4 = r.positionVelocityNees4;
  }
  return s;
}

void FrameFolder::clear() {
  sweepCounter_ = 0;
  plots_.clear();
}

void FrameFolder::fold(const sim::SimFrame& f, const geo::LocalFrame& geo,
                       const est::drkf::ProcessParams& process, const std::vector<sim::TargetSpec>& targets,
                       LiveFrame& pending) {
  pending.ownHistory.push_back(
      ownSampleOf(sim::makeRow(f, geo, process), sim::ownShipDetailRow(f), f.hasTruth));
  pending.error95M = pending.ownHistory.back().error95M;
  for (const auto& sweep : f.sweeps) {
    ++sweepCounter_;
    for (const auto& t : sweep.tracks) {
      sim::TrackRow row = sim::trackRow(sweep, t, targets, geo);
      if (!f.hasTruth) row.hasTruth = false;
      pending.trackHistory.push_back(trackSampleOf(row));
    }
  }
  const std::vector<geo::GridPoint> placed = sim::plotPositionsFromEstimate(f, geo);
  for (std::size_t i = 0; i < placed.size(); ++i)
    plots_.push_back({toSeconds(f.plots[i].timeUs), placed[i].xM, placed[i].yM, sweepCounter_});
  while (!plots_.empty() && plots_.front().sweep < sweepCounter_ - kSweepsShown) plots_.pop_front();
  // Last fixes and the last report per measurement block.
  for (const auto& m : f.measurements) {
    if (const auto* g = std::get_if<sensors::GpsSample>(&m))
      pending.lastFix[0] = {true, toSeconds(g->timeUs), g->position.xM, g->position.yM, false};
    else if (const auto* l = std::get_if<sensors::LoranSample>(&m))
      pending.lastFix[1] = {true, toSeconds(l->timeUs), l->position.xM, l->position.yM, false};
  }
  for (const auto& u : f.updates) {
    for (int b = 0; b < nav::kDrkfBlockCount; ++b) {
      const est::BlockReport* r = u.block(static_cast<nav::DrkfBlock>(b));
      if (!r) continue;
      BlockStatus& s = pending.blocks[static_cast<std::size_t>(b)];
      s = {true, toSeconds(u.timeUs), r->nis, r->dim,
           r->status == est::UpdateStatus::Accepted || r->status == est::UpdateStatus::AcceptedForced};
      if (b == nav::kGpsPosition && pending.lastFix[0].valid) pending.lastFix[0].accepted = s.accepted;
      if (b == nav::kLoranPosition && pending.lastFix[1].valid) pending.lastFix[1].accepted = s.accepted;
    }
  }
  pending.events.insert(pending.events.end(), f.trackEvents.begin(), f.trackEvents.end());
}

}  // namespace reckoner::ui
