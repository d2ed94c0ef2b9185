#include "ui/map/range_scale.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "common/units.h"

namespace reckoner::ui {

namespace {
constexpr double kPixelM = 0.28e-3;
}

double displayedRangeNm(const charts::Viewport& v) {
  return metresToNm(0.5 * std::min(v.width(), v.height()) * v.metresPerPixel());
}

double scaleForRange(double rangeNm, int widthPx, int heightPx) {
  const double halfPx = 0.5 * std::max(1, std::min(widthPx, heightPx));
  return nmToMetres(rangeNm) / (halfPx * kPixelM);
}

int standardRangeIndex(double rangeNm) {
  for (int i = 0; i < kRangeScaleCount; ++i)
    if (std::abs(rangeNm / kRangeScales[i].rangeNm - 1.0) <= 0.03) return i;
  return -1;
}

int steppedRangeIndex(double rangeNm, int step) {
  const int exact = standardRangeIndex(rangeNm);
  if (step > 0) {
    for (int i = 0; i < kRangeScaleCount; ++i)
      if (kRangeScales[i].rangeNm > rangeNm && i != exact) return i;
    return kRangeScaleCount - 1;
  }
  for (int i = kRangeScaleCount - 1; i >= 0; --i)
    if (kRangeScales[i].rangeNm < rangeNm && i != exact) return i;
  return 0;
}

double ringIntervalNm(double rangeNm) {
  for (const RangeScale& r : kRangeScales)
    if (r.rangeNm >= rangeNm * 0.97) return r.ringNm;
  return kRangeScales[kRangeScaleCount - 1].ringNm *
         std::ceil(rangeNm / kRangeScales[kRangeScaleCount - 1].rangeNm);
}

}  // namespace reckoner::ui
