// Round graticule intervals and the lines of a view (graticule.h).
#include "charts/world/graticule.h"

#include <cmath>
#include <cstdint>

namespace reckoner::charts::world {

const std::vector<int>& graticuleStepsSeconds() {
  static const std::vector<int> steps{1,     2,     5,     10,    15,     20,    30,   60,
                                      120,   300,   600,   900,   1200,   1800,  3600, 7200,
                                      18000, 36000, 54000, 72000, 108000, 162000};
  return steps;
}

int graticuleStepSeconds(double pxPerDegree, double minSpacingPx) {
  for (const int s : graticuleStepsSeconds())
    if (s / 3600.0 * pxPerDegree >= minSpacingPx) return s;
  return graticuleStepsSeconds().back();
}

std::vector<double> graticuleValues(double loDeg, double hiDeg, int stepSeconds, int maxLines) {
  std::vector<double> out;
  if (!(loDeg <= hiDeg) || stepSeconds <= 0 || maxLines <= 0) return out;
  // Whole multiples of the step in integer arc-seconds: no drift over many lines.
  auto first = static_cast<std::int64_t>(std::ceil(loDeg * 3600.0 / stepSeconds - 1e-9));
  auto last = static_cast<std::int64_t>(std::floor(hiDeg * 3600.0 / stepSeconds + 1e-9));
  if (last - first + 1 > maxLines) {
    const std::int64_t middle = (first + last) / 2;
    first = middle - maxLines / 2;
    last = first + maxLines - 1;
  }
  for (std::int64_t k = first; k <= last; ++k) out.push_back(static_cast<double>(k * stepSeconds) / 3600.0);
  return out;
}

}  // namespace reckoner::charts::world
