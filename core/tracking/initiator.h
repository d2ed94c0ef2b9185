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
  friend bool operator==(const AcquisitionZone&, const AcquisitionZone&) = default;
};
/// 0 <= min range < max range (finite) and finite bearings.
[[nodiscard]] bool validZone(const AcquisitionZone& z);

/// True when the plot lies in one of the zones (its true bearing: grid bearing + convergenceRad at
/// own ship); no zones: everywhere.
[[nodiscard]] bool inAcquisitionZones(const std::vector<AcquisitionZone>& zones, const GridPlot& plot,
                                      double convergenceRad);

/// The plot's grid position (x east, y north, m): own ship's estimate carried to the plot time at its
/// estimated velocity, plus the plot's offset.
[[nodiscard]] est::Vec<2> plotGridPosition(const GridPlot& plot, const OwnShipInput& own);

/// True when the plot falls on the land (null: no chart, never).
[[nodiscard]] bool plotOnLand(const radar::LandMask* land, const GridPlot& plot, const OwnShipInput& own);

/// Where the operator cancelled tracks: automatic acquisition keeps away from the vessel each one
/// followed for holdS, around the track's last estimate carried on at its velocity, within a radius
/// that grows with the estimate's uncertainty. Without it a cancelled track is acquired again on the
/// next sweep. Manual acquisition is not held back.
class CancelledTracks {
 public:
  static constexpr double kHoldS = 120.0;
  static constexpr double kBaseRadiusM = 300.0;

  /// The track's target estimate (grid position, velocity, their covariances) at timeUs.
  void add(const est::Vec<2>& positionM, const est::Vec<2>& velocityMps, const est::Mat<2>& positionCov,
           const est::Mat<2>& velocityCov, TimeUs timeUs);
  /// True when a plot at grid position p and time t is near a cancelled track still held; forgets the
  /// ones whose hold is over.
  [[nodiscard]] bool holdsBack(const est::Vec<2>& p, TimeUs t);
  [[nodiscard]] bool empty() const { return held_.empty(); }

 private:
  struct Held {
    est::Vec<2> positionM, velocityMps;
    double sdPositionM, sdVelocityMps;  ///< along the major axes
    TimeUs timeUs;
  };
  std::vector<Held> held_;
};

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
