#pragma once
// The route check of an ECDIS (MSC.232(82) 11.3.5): each leg of a route against the open charts, inside
// its cross-track corridor (the leg's port and starboard limits). What it reports is what
// chart_hazards.h calls a hazard: crossing the safety contour (areas shallower than it, unsurveyed
// areas), land, isolated dangers above the safety depth, prohibited and restricted areas, and areas for
// which special conditions exist. One finding per leg and feature, at the feature's point in the
// corridor nearest where the leg first meets it, in order along the leg (docs/routes.md).
//
// The corridor of a leg is the union of quadrilaterals along it, one per piece of at most 500 m, each
// with corners set off the leg square to it by the limits on the ellipsoid (so great circles and long
// rhumb lines are followed and the limits are true metres) and straight in Mercator between them.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "charts/pick/pick_report.h"
#include "charts/route/chart_hazards.h"
#include "geo/route.h"

namespace reckoner::charts {

struct RouteFinding {
  std::size_t leg = 0;  ///< the leg arriving at waypoint index `leg` (1: from the first waypoint)
  HazardKind kind = HazardKind::Danger;
  LatLon position;
  std::string cell;         ///< the cell's name
  std::string objectClass;  ///< e.g. "WRECKS"
  std::string lnam;         ///< the feature's long name, unique in its cell
  std::optional<double> depthM;
  std::uint32_t hazard = 0;  ///< index into ChartHazards::hazards()
};

/// The corridor pieces of one leg (Mercator polygons: the start on the track first, then the start's
/// starboard corner, the end's starboard and port corners, the start's port corner).
std::vector<std::vector<MercatorPoint>> legCorridor(const geo::Route& route, std::size_t to);

/// The findings of one leg, appended to `out`.
void checkLeg(const geo::Route& route, std::size_t to, const ChartHazards& hazards,
              std::vector<RouteFinding>& out);
/// The findings of every leg, leg by leg.
std::vector<RouteFinding> checkRoute(const geo::Route& route, const ChartHazards& hazards);

/// The pick report of a finding's feature.
PickedFeature findingReport(const ChartHazards& hazards, const RouteFinding& finding,
                            const S57Catalogue& catalogue = S57Catalogue::installed());

}  // namespace reckoner::charts
