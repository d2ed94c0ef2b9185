#include "metrics/track_stats.h"

#include <cmath>
#include <map>
#include <set>

namespace reckoner::metrics {

TrackingStats summariseTracking(std::span<const sim::TrackRow> tracks,
                                std::span<const sim::TargetSweepRow> targets, double swapDistanceM) {
  TrackingStats out;
  struct Acc {
    TargetTrackStats s;
    int lastHolder = -1;
    bool everInRange = false;
    std::set<int> holders;
    double se2 = 0, sv2 = 0, nees = 0;
    int neesRows = 0;
  };
  std::map<int, Acc> acc;
  std::map<int, int> lastTagOfTrack;
  std::set<int> confirmed, falseIds;
  std::size_t ti = 0, gi = 0;
  while (ti < tracks.size() || gi < targets.size()) {
    const TimeUs t = gi < targets.size() && (ti >= tracks.size() || targets[gi].timeUs <= tracks[ti].timeUs)
                         ? targets[gi].timeUs
                         : tracks[ti].timeUs;
    std::map<int, const sim::TargetSweepRow*> where;
    for (; gi < targets.size() && targets[gi].timeUs == t; ++gi) where[targets[gi].targetId] = &targets[gi];
    std::map<int, std::vector<int>> heldBy;  // target -> confirmed tracks labelled with it
    for (; ti < tracks.size() && tracks[ti].timeUs == t; ++ti) {
      const sim::TrackRow& r = tracks[ti];
      if (r.status != track::TrackStatus::Confirmed) continue;
      confirmed.insert(r.trackId);
      if (r.targetId < 0) {
        falseIds.insert(r.trackId);
        ++out.falseTrackSweeps;
      } else {
        heldBy[r.targetId].push_back(r.trackId);
      }
      if (const auto it = lastTagOfTrack.find(r.trackId);
          it != lastTagOfTrack.end() && it->second >= 0 && r.targetId >= 0 && it->second != r.targetId) {
        ++out.swaps;
        const auto a = where.find(it->second), b = where.find(r.targetId);
        if (a != where.end() && b != where.end() &&
            std::hypot(a->second->xM - b->second->xM, a->second->yM - b->second->yM) > swapDistanceM)
          ++out.farSwaps;
      }
      lastTagOfTrack[r.trackId] = r.targetId;
      if (r.hasTruth && r.targetId >= 0) {
        Acc& a = acc[r.targetId];
        a.se2 += std::pow(r.positionErrorM(), 2);
        a.sv2 += std::pow(r.velocityErrorMps(), 2);
        ++a.s.rows;
        if (std::isfinite(r.nees)) {
          a.nees += r.nees;
          ++a.neesRows;
        }
      }
    }
    for (const auto& [id, row] : where) {
      Acc& a = acc[id];
      a.s.targetId = id;
      a.everInRange = a.everInRange || row->inRange;
      const auto h = heldBy.find(id);
      int holder = -1;
      if (h != heldBy.end()) {
        holder = h->second.front();
        for (int tr : h->second)
          if (tr == a.lastHolder) holder = tr;
      }
      if (holder >= 0 && a.s.firstHeldUs < 0) a.s.firstHeldUs = t;
      if (a.s.firstHeldUs >= 0 && (row->inRange || holder >= 0)) {
        ++a.s.sweepsTracked;
        if (holder >= 0) ++a.s.sweepsHeld;
      }
      if (holder >= 0) {
        if (a.lastHolder >= 0 && holder != a.lastHolder) ++a.s.breaks;
        a.lastHolder = holder;
        a.holders.insert(holder);
      }
    }
  }
  long held = 0, tracked = 0;
  for (auto& [id, a] : acc) {
    a.s.tracks = static_cast<int>(a.holders.size());
    a.s.continuity = a.s.sweepsTracked > 0 ? static_cast<double>(a.s.sweepsHeld) / a.s.sweepsTracked : 0.0;
    if (a.s.rows > 0) {
      a.s.rmsePositionM = std::sqrt(a.se2 / a.s.rows);
      a.s.rmseVelocityMps = std::sqrt(a.sv2 / a.s.rows);
    }
    a.s.meanNees = a.neesRows > 0 ? a.nees / a.neesRows : std::nan("");
    if (a.everInRange && a.s.firstHeldUs < 0) ++out.targetsNeverHeld;
    held += a.s.sweepsHeld;
    tracked += a.s.sweepsTracked;
    out.breaks += a.s.breaks;
    out.targets.push_back(a.s);
  }
  out.continuity = tracked > 0 ? static_cast<double>(held) / static_cast<double>(tracked) : 0.0;
  out.falseTracks = static_cast<int>(falseIds.size());
  out.confirmedTracks = static_cast<int>(confirmed.size());
  return out;
}

}  // namespace reckoner::metrics
