#pragma once
// A synthetic harbour for the radar matching tests and benchmark: a wavy shore 1.5-3 km away on three
// sides of the origin and two islands to the south (grid metres).
#include "radar/coastline.h"
#include "radar/radar_image.h"

namespace reckoner::test {

radar::Coastline syntheticHarbour();
/// Shore range at grid azimuth a (rad) of syntheticHarbour's wavy shore.
double harbourShoreRangeM(double azimuthRad);
/// Own ship in the harbour: 30 m east, 50 m south of the origin, heading 018 at 4.7 m/s, turning
/// 0.3 deg/s; a 2.5 s sweep.
radar::SweepPose harbourPose();

}  // namespace reckoner::test
