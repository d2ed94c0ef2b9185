#include "support/radar_fixtures.h"

#include <cmath>

#include "common/angles.h"

namespace reckoner::test {
namespace {
void addRing(std::vector<radar::CoastSegment>& out, const std::vector<est::Vec<2>>& pts) {
  for (std::size_t i = 0; i < pts.size(); ++i) out.push_back({pts[i], pts[(i + 1) % pts.size()], 5.0});
}
}  // namespace

double harbourShoreRangeM(double a) {
  return 2200.0 + 500.0 * std::sin(3.0 * a) + 250.0 * std::cos(7.0 * a);
}

radar::Coastline syntheticHarbour() {
  std::vector<radar::CoastSegment> s;
  std::vector<est::Vec<2>> shore;
  for (int k = 0; k <= 60; ++k) {
    const double a = degToRad(-120.0 + 4.0 * k);
    const double r = harbourShoreRangeM(a);
    shore.push_back({r * std::sin(a), r * std::cos(a)});
  }
  for (std::size_t i = 0; i + 1 < shore.size(); ++i) s.push_back({shore[i], shore[i + 1], 5.0});
  addRing(s, {{-900, -1200}, {-600, -1100}, {-500, -1400}, {-850, -1500}});
  addRing(s, {{1100, -900}, {1400, -800}, {1500, -1150}, {1150, -1250}, {1000, -1050}});
  return radar::Coastline(s);
}

radar::SweepPose harbourPose() {
  radar::SweepPose p;
  p.periodS = 2.5;
  p.position = {30.0, -50.0};
  p.velocity = {1.5, 4.5};
  p.headingRad = degToRad(18.0);
  p.turnRateRadPerS = degToRad(0.3);
  return p;
}

}  // namespace reckoner::test
