#pragma once
// The initiator: which unassociated plots may start a track (inside an acquisition zone, not on
// charted land), the filter a new track starts with, and M-of-N confirmation of a tentative track
// (seen in M of its first N sweeps; dropped as soon as it can no longer be). docs/ttkf.md has the
// rules and their reasons.
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "radar/land_mask.h"
#include "tracking/track_filter.h"

namespace reckoner::track {

/// A ring sector around own ship: true bearings clockwise from `fromBearingRad` to `toBearingRad`
/// (equal bearings: the whole circle), ranges [minRangeM, maxRangeM].
struct AcquisitionZone {
  double minRangeM = 0.0;
  double maxRangeM = 0.0;
  double fromBearingRad = 0.0;
  double toBearingRad = 0.0;
  [[nodiscard]] bool contains(double rangeM, double trueBearingRad) const;
};

/// True when the plot lies in one of the zones (its true bearing: grid bearing + convergenceRad at
/// own ship); no zones: everywhere.
[[nodiscard]] bool inAcquisitionZones(const std::vector<AcquisitionZone>& zones, const GridPlot& plot,
                                      double convergenceRad);

/// The plot's grid position (x east, y north, m): own ship's estimate carried to the plot time at its
/// estimated velocity, plus the plot's offset.
[[nodiscard]] est::Vec<2> plotGridPosition(const GridPlot& plot, const OwnShipInput& own);

/// True when the plot falls on the land (null: no chart, never).
[[nodiscard]] bool plotOnLand(const radar::LandMask* land, const GridPlot& plot, const OwnShipInput& own);

/// The filter of a new track, of the chosen kind, started on its first plot.
struct TrackFilterFactory {
  std::shared_ptr<const TtkfContext> ctx;
  AbgConfig abg;
  ImmConfig imm;
  /// nullopt for degenerate geometry (a plot on own ship).
  [[nodiscard]] std::optional<TrackFilter> start(TrackerKind kind, const OwnShipInput& own,
                                                 const GridPlot& plot) const;
};

/// M-of-N confirmation of a tentative track from its sweep history (sweep_history.h).
class MofNConfirmation {
 public:
  enum class Verdict : std::uint8_t {
    Undecided,  ///< fewer than M hits so far, M still reachable in the first N sweeps
    Confirm,    ///< M hits in the first N sweeps
    Drop,       ///< M can no longer be reached
  };
  /// 1 <= hits <= sweeps <= 32 (TrackManagerConfig::check).
  MofNConfirmation(int hits, int sweeps) : hits_(hits), sweeps_(sweeps) {}
  /// history: bit k set when seen k sweeps ago; sweeps: completed sweeps since initiation (>= 1).
  [[nodiscard]] Verdict verdict(std::uint32_t history, int sweeps) const;

 private:
  int hits_;    ///< M
  int sweeps_;  ///< N
};

}  // namespace reckoner::track
