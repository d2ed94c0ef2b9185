#pragma once
// The chart contours a radar sees, for seed 004's matching (docs/radar_matching.md): the edges of land
// areas (LNDARE), the coastline (COALNE) and shoreline constructions (SLCONS: quays, piers, sea walls),
// in the grid frame, within a radius of a point. Each carries the sd of an echo about it: constructions
// 2 m (concrete where the chart says), the natural coast 5 m (its echo moves with the water level and
// the slope of the shore).
#include <vector>

#include "charts/model/chart_model.h"
#include "geo/local_frame.h"
#include "radar/coastline.h"
#include "radar/land_mask.h"

namespace reckoner::charts {

struct RadarContourParams {
  double constructionSdM = 2.0;
  double naturalSdM = 5.0;
};

/// Contours of the cells within radiusM of `centre` (grid), converted with `frame`.
radar::Coastline radarContours(const std::vector<CellPtr>& cells, const geo::LocalFrame& frame,
                               const geo::GridPoint& centre, double radiusM,
                               const RadarContourParams& params = {});

/// The land areas (LNDARE rings) of the cells within radiusM of `centre` (grid), for chart-aided ARPA.
radar::LandMask landMask(const std::vector<CellPtr>& cells, const geo::LocalFrame& frame,
                         const geo::GridPoint& centre, double radiusM);

}  // namespace reckoner::charts
