#pragma once
// Scoring of track management against the truth (docs/outputs.md, "Tracking summary"):
//  - a target is held in a sweep by a confirmed track whose plots came mostly from it;
//  - continuity: share of the sweeps, from the target's first hold on and while it is within radar
//    range, in which it is held;
//  - a break: the track holding a target changes to another track (a gap with the same track
//    returning is no break);
//  - a swap: a confirmed track's target changes from one real target to another; it counts as far
//    when the two targets are more than swapDistanceM apart at that sweep;
//  - a false track: a confirmed track whose plots came mostly from clutter.
#include <span>
#include <vector>

#include "sim/scenario_run.h"

namespace reckoner::metrics {

struct TargetTrackStats {
  int targetId = 0;
  int sweepsTracked = 0;  ///< in range, from the first hold on
  int sweepsHeld = 0;
  double continuity = 0.0;
  int breaks = 0;
  int tracks = 0;  ///< distinct tracks that held it
  TimeUs firstHeldUs = -1;
  int rows = 0;  ///< confirmed rows used for the errors below
  double rmsePositionM = 0.0;
  double rmseVelocityMps = 0.0;
  double meanNees = 0.0;
};

struct TrackingStats {
  std::vector<TargetTrackStats> targets;  ///< by target id
  int targetsNeverHeld = 0;               ///< in range at some sweep but never held
  double continuity = 0.0;                ///< pooled over targets
  int breaks = 0;
  int swaps = 0;
  int farSwaps = 0;
  int falseTracks = 0;
  int falseTrackSweeps = 0;
  int confirmedTracks = 0;
};

TrackingStats summariseTracking(std::span<const sim::TrackRow> tracks,
                                std::span<const sim::TargetSweepRow> targets, double swapDistanceM = 500.0);

}  // namespace reckoner::metrics
