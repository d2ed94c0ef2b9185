#include "metrics/track_stats.h"

#include <cmath>
#include <map>
#include <set>

namespace reckoner::metrics {
namespace {

/// The truth rows of one sweep, by target id.
using SweepTruth = std::map<int, const sim::TargetSweepRow*>;
/// The confirmed tracks of one sweep labelled with each target, by target id.
using HeldBy = std::map<int, std::vector<int>>;

/// What is summed over the run for one target.
struct TargetAccumulator {
  TargetTrackStats s;
  int lastHolder = -1;
  bool everInRange = false;
  std::set<int> holders;
  double se2 = 0, sv2 = 0, nees = 0;
  int neesRows = 0;
};

/// The track holding a target in a sweep: the one that held it last sweep if it still does, else the
/// first labelled with it; -1 when none.
int holderOf(const HeldBy& heldBy, int targetId, int lastHolder) {
  const auto h = heldBy.find(targetId);
  int holder = -1;
  if (h != heldBy.end()) {
    holder = h->second.front();
    for (int tr : h->second)
      if (tr == lastHolder) holder = tr;
  }
  return holder;
}

/// Scores track rows and truth rows sweep by sweep (both in time order) and gives the totals.
class TrackingScorer {
 public:
  explicit TrackingScorer(double swapDistanceM) : swapDistanceM_(swapDistanceM) {}

  /// One confirmed track row of a sweep: false tracks, swaps, the errors against its target.
  void scoreTrackRow(const sim::TrackRow& r, const SweepTruth& where, HeldBy& heldBy) {
    confirmed_.insert(r.trackId);
    if (r.targetId < 0) {
      falseIds_.insert(r.trackId);
      ++out_.falseTrackSweeps;
    } else {
      heldBy[r.targetId].push_back(r.trackId);
    }
    if (const auto it = lastTagOfTrack_.find(r.trackId);
        it != lastTagOfTrack_.end() && it->second >= 0 && r.targetId >= 0 && it->second != r.targetId) {
      ++out_.swaps;
      const auto a = where.find(it->second), b = where.find(r.targetId);
      if (a != where.end() && b != where.end() &&
          std::hypot(a->second->xM - b->second->xM, a->second->yM - b->second->yM) > swapDistanceM_)
        ++out_.farSwaps;
    }
    lastTagOfTrack_[r.trackId] = r.targetId;
    if (r.hasTruth && r.targetId >= 0) {
      TargetAccumulator& a = acc_[r.targetId];
      a.se2 += std::pow(r.positionErrorM(), 2);
      a.sv2 += std::pow(r.velocityErrorMps(), 2);
      ++a.s.rows;
      if (std::isfinite(r.nees)) {
        a.nees += r.nees;
        ++a.neesRows;
      }
    }
  }

  /// One target's truth row of the sweep at t: whether it was tracked and held, and by which track.
  void scoreTargetSweep(int id, const sim::TargetSweepRow& row, const HeldBy& heldBy, TimeUs t) {
    TargetAccumulator& a = acc_[id];
    a.s.targetId = id;
    a.everInRange = a.everInRange || row.inRange;
    const int holder = holderOf(heldBy, id, a.lastHolder);
    if (holder >= 0 && a.s.firstHeldUs < 0) a.s.firstHeldUs = t;
    if (a.s.firstHeldUs >= 0 && (row.inRange || holder >= 0)) {
      ++a.s.sweepsTracked;
      if (holder >= 0) ++a.s.sweepsHeld;
    }
    if (holder >= 0) {
      if (a.lastHolder >= 0 && holder != a.lastHolder) ++a.s.breaks;
      a.lastHolder = holder;
      a.holders.insert(holder);
    }
  }

  /// Each target's continuity, RMSE and mean NEES, and the pooled totals.
  TrackingStats finish() {
    long held = 0, tracked = 0;
    for (auto& [id, a] : acc_) {
      a.s.tracks = static_cast<int>(a.holders.size());
      a.s.continuity = a.s.sweepsTracked > 0 ? static_cast<double>(a.s.sweepsHeld) / a.s.sweepsTracked : 0.0;
      if (a.s.rows > 0) {
        a.s.rmsePositionM = std::sqrt(a.se2 / a.s.rows);
        a.s.rmseVelocityMps = std::sqrt(a.sv2 / a.s.rows);
      }
      a.s.meanNees = a.neesRows > 0 ? a.nees / a.neesRows : std::nan("");
      if (a.everInRange && a.s.firstHeldUs < 0) ++out_.targetsNeverHeld;
      held += a.s.sweepsHeld;
      tracked += a.s.sweepsTracked;
      out_.breaks += a.s.breaks;
      out_.targets.push_back(a.s);
    }
    out_.continuity = tracked > 0 ? static_cast<double>(held) / static_cast<double>(tracked) : 0.0;
    out_.falseTracks = static_cast<int>(falseIds_.size());
    out_.confirmedTracks = static_cast<int>(confirmed_.size());
    return out_;
  }

 private:
  double swapDistanceM_;
  TrackingStats out_;
  std::map<int, TargetAccumulator> acc_;
  std::map<int, int> lastTagOfTrack_;
  std::set<int> confirmed_, falseIds_;
};

}  // namespace

TrackingStats summariseTracking(std::span<const sim::TrackRow> tracks,
                                std::span<const sim::TargetSweepRow> targets, double swapDistanceM) {
  TrackingScorer scorer(swapDistanceM);
  std::size_t ti = 0, gi = 0;
  while (ti < tracks.size() || gi < targets.size()) {
    const TimeUs t = gi < targets.size() && (ti >= tracks.size() || targets[gi].timeUs <= tracks[ti].timeUs)
                         ? targets[gi].timeUs
                         : tracks[ti].timeUs;
    SweepTruth where;
    for (; gi < targets.size() && targets[gi].timeUs == t; ++gi) where[targets[gi].targetId] = &targets[gi];
    HeldBy heldBy;
    for (; ti < tracks.size() && tracks[ti].timeUs == t; ++ti)
      if (tracks[ti].status == track::TrackStatus::Confirmed) scorer.scoreTrackRow(tracks[ti], where, heldBy);
    for (const auto& [id, row] : where) scorer.scoreTargetSweep(id, *row, heldBy, t);
  }
  return scorer.finish();
}

}  // namespace reckoner::metrics
