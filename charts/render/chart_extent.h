#pragma once
// Where the open charts are, for a view that has to find them and keep to scales they support: the
// cells at a point (finest first), the box of their coverage, the view that shows a box, and the
// limits of zooming (docs/charts.md, "Zoom limits"):
//  - in: the best cell at the view's centre shown at most kMaxOverscale times its compilation scale;
//    with no cell there, 1:kLargestScaleWithoutChart; never beyond 1:kLargestScale;
//  - out: the whole world's width (360 degrees of longitude) across the view.
#include <vector>

#include "charts/model/chart_model.h"
#include "charts/render/viewport.h"

namespace reckoner::charts {

/// The overscale a view may reach on the best cell at its centre. At x8 the chart's own drawing
/// precision (some 0.3 to 0.5 mm at its compilation scale, 5 to 8 m on a 1:15 000 harbour cell) is
/// 2.4 to 4 mm on the screen: more zoom shows the generalisation of the data, not more of the sea.
inline constexpr double kMaxOverscale = 8.0;
/// With no chart at the centre: nothing to overscale, but nothing to see beyond own ship's true-scale
/// outline either (120 m is 60 mm at 1:2000); IEC 62388's shortest range, 0.25 NM, needs some 1:5000.
inline constexpr double kLargestScaleWithoutChart = 2000.0;
/// The absolute limit (a berthing cell at 1:4000 overscaled x8).
inline constexpr double kLargestScale = 500.0;

/// The cells whose coverage holds p, the largest compilation scale (smallest 1:N) first.
std::vector<CellPtr> cellsAt(const std::vector<CellPtr>& cells, const LatLon& p);
/// The box holding every cell's coverage (ChartCell::coverageBounds); empty without cells.
Bounds coverageOf(const std::vector<CellPtr>& cells);
/// The smallest 1:N zooming in may reach with the view centred at p (see the header comment).
double largestScaleAt(const std::vector<CellPtr>& cells, const LatLon& p);
/// The largest 1:N zooming out may reach: 360 degrees of longitude across widthPx at latDeg.
double smallestScale(double latDeg, int widthPx, double pixelSizeMm = 0.28);
/// The view of widthPx x heightPx turned by rotationRad, centred on `box`, at the scale that just holds
/// it inside marginPx (not limited: the caller applies its zoom limits). A box reduced to a point
/// gets 1:kLargestScaleWithoutChart.
Viewport fitView(const Bounds& box, int widthPx, int heightPx, double rotationRad, double marginPx,
                 double pixelSizeMm = 0.28);

}  // namespace reckoner::charts
