#include "tracking/initiator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/angles.h"
#include "tracking/sweep_history.h"

namespace reckoner::track {

bool AcquisitionZone::contains(double rangeM, double trueBearingRad) const {
  if (rangeM < minRangeM || rangeM > maxRangeM) return false;
  const double span = wrapTwoPi(toBearingRad - fromBearingRad);
  if (span == 0.0) return true;
  return wrapTwoPi(trueBearingRad - fromBearingRad) <= span;
}

bool validZone(const AcquisitionZone& z) {
  return z.minRangeM >= 0.0 && z.maxRangeM > z.minRangeM && std::isfinite(z.maxRangeM) &&
         std::isfinite(z.fromBearingRad) && std::isfinite(z.toBearingRad);
}

bool inAcquisitionZones(const std::vector<AcquisitionZone>& zones, const GridPlot& plot,
                        double convergenceRad) {
  if (zones.empty()) return true;
  const double trueBearing = plot.bearingRad + convergenceRad;
  for (const auto& z : zones)
    if (z.contains(plot.rangeM, trueBearing)) return true;
  return false;
}

est::Vec<2> plotGridPosition(const GridPlot& plot, const OwnShipInput& own) {
  const double dtS = toSeconds(plot.timeUs - own.timeUs);
  return {own.x[0] + own.x[2] * dtS + plot.rangeM * std::sin(plot.bearingRad),
          own.x[1] + own.x[3] * dtS + plot.rangeM * std::cos(plot.bearingRad)};
}

bool plotOnLand(const radar::LandMask* land, const GridPlot& plot, const OwnShipInput& own) {
  if (!land) return false;
  return land->contains(plotGridPosition(plot, own));
}

void CancelledTracks::add(const est::Vec<2>& positionM, const est::Vec<2>& velocityMps,
                          const est::Mat<2>& positionCov, const est::Mat<2>& velocityCov, TimeUs timeUs) {
  held_.push_back({positionM, velocityMps, std::sqrt(std::max(0.0, est::largestEigenvalue(positionCov))),
                   std::sqrt(std::max(0.0, est::largestEigenvalue(velocityCov))), timeUs});
}

bool CancelledTracks::holdsBack(const est::Vec<2>& p, TimeUs t) {
  std::erase_if(held_, [t](const Held& h) { return toSeconds(t - h.timeUs) > kHoldS; });
  return std::any_of(held_.begin(), held_.end(), [&](const Held& h) {
    const double dt = std::max(0.0, toSeconds(t - h.timeUs));
    const double radius = kBaseRadiusM + 3.0 * (h.sdPositionM + h.sdVelocityMps * dt);
    return (p - (h.positionM + h.velocityMps * dt)).norm() <= radius;
  });
}

std::optional<TrackFilter> TrackFilterFactory::start(TrackerKind kind, const OwnShipInput& own,
                                                     const GridPlot& plot) const {
  try {
    switch (kind) {
      case TrackerKind::Ekf:
      case TrackerKind::EkfInputEstimation:
        return TrackFilter(kind, Ttkf::initiate(ctx, own, plot));
      case TrackerKind::AlphaBetaGamma:
        return TrackFilter(AbgTrackFilter(ctx, abg, own, plot));
      case TrackerKind::Imm:
        return TrackFilter(ImmTrackFilter(ctx, imm, own, plot));
    }
  } catch (const std::invalid_argument&) {
    return std::nullopt;  // degenerate geometry (a plot on own ship)
  }
  return std::nullopt;
}

MofNConfirmation::Verdict MofNConfirmation::verdict(std::uint32_t history, int sweeps) const {
  const int hits = hitsInLast(history, std::min(sweeps, sweeps_));
  if (hits >= hits_) return Verdict::Confirm;
  if (hits + (sweeps_ - sweeps) < hits_) return Verdict::Drop;
  return Verdict::Undecided;
}

}  // namespace reckoner::track
