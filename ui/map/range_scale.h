#pragma once
// The radar ranges an ECDIS offers (IEC 62388's 0.25 to 24 NM), each with its range-ring interval, and
// the arithmetic between a range and a chart scale: the range is the distance from the view's centre
// to its nearest edge.
#include "charts/render/viewport.h"

namespace reckoner::ui {

struct RangeScale {
  double rangeNm;
  double ringNm;  ///< range-ring interval
};
inline constexpr RangeScale kRangeScales[] = {{0.25, 0.05}, {0.5, 0.1}, {0.75, 0.25}, {1.5, 0.25},
                                              {3.0, 0.5},   {6.0, 1.0}, {12.0, 2.0},  {24.0, 4.0}};
inline constexpr int kRangeScaleCount = static_cast<int>(std::size(kRangeScales));

/// The range (NM) the view shows: from its centre to the nearest edge, at the centre's latitude.
double displayedRangeNm(const charts::Viewport& v);
/// The scale denominator at which rangeNm reaches the nearest edge of a widthPx x heightPx view (at
/// S-52's 0.28 mm pixel).
double scaleForRange(double rangeNm, int widthPx, int heightPx);
/// The standard range within 3% of rangeNm, or -1.
int standardRangeIndex(double rangeNm);
/// The next standard range above (step > 0) or below (step < 0) rangeNm (clamped at the ends).
int steppedRangeIndex(double rangeNm, int step);
/// The ring interval for a displayed range: that of the smallest standard range at or above it (the
/// largest range's beyond 24 NM), so 3 to 6 rings fill the range.
double ringIntervalNm(double rangeNm);

}  // namespace reckoner::ui
