#include "navigation/dead_reckoning_monitor.h"

#include <algorithm>

namespace reckoner::nav {

DeadReckoningRule deadReckoningRule(double sweepPeriodS, int everySweeps) {
  DeadReckoningRule rule;
  rule.radarFixRecentS = 4.0 * sweepPeriodS * std::max(1, everySweeps);
  return rule;
}

void DeadReckoningMonitor::addEpoch(const DrkfUpdateReport& report) {
  constexpr std::array<DrkfBlock, 2> kPositionBlocks{kGpsPosition, kLoranPosition};
  for (std::size_t i = 0; i < kPositionBlocks.size(); ++i) {
    const est::BlockReport* b = report.block(kPositionBlocks[i]);
    if (b) positions_[i] = {true, report.timeUs, est::isApplied(b->status)};
  }
}

void DeadReckoningMonitor::addRadarFix(TimeUs t) {
  lastRadarFixUs_ = t;
}

// The ages are compared in seconds (doubles), as the window always did.
bool DeadReckoningMonitor::fixRecent(TimeUs t) const {
  const double tS = toSeconds(t);
  for (const LastPosition& p : positions_)
    if (p.seen && p.applied && tS - toSeconds(p.timeUs) <= rule_.fixRecentS) return true;
  return lastRadarFixUs_ && tS - toSeconds(*lastRadarFixUs_) <= rule_.radarFixRecentS;
}

const DeadReckoningStatus& DeadReckoningMonitor::evaluate(TimeUs t) {
  const bool dr = !fixRecent(t);
  if (dr && !status_.active) {
    status_ = {true, t};
    intervals_.push_back({t, std::nullopt});
  } else if (!dr && status_.active) {
    status_ = {false, 0};
    intervals_.back().endUs = t;
  }
  return status_;
}

std::optional<double> DeadReckoningHorizon::update(bool deadReckoning, TimeUs t, const Drkf& filter,
                                                   const DeadReckoningAids& aids, double limitM) {
  const double tS = toSeconds(t);
  if (!deadReckoning) {
    horizonS_.reset();
    askedAtS_ = -1e9;
    return horizonS_;
  }
  if (horizonS_ && tS - askedAtS_ < kRecomputeAfterS && aids == aids_ && limitM == limitM_) {
    horizonS_ = std::max(0.0, *horizonS_ - (tS - askedAtS_));
    askedAtS_ = tS;
    return horizonS_;
  }
  horizonS_ = timeToPositionLimitS(filter, aids, limitM, kMaxS).value_or(kMaxS);
  askedAtS_ = tS;
  aids_ = aids;
  limitM_ = limitM;
  return horizonS_;
}

}  // namespace reckoner::nav
