#pragma once
// The soak's scenario (docs/robustness.md, "Soak"): own ship following a square route round and round
// for the whole run, vessels crossing the radar picture and a ring of AIS traffic beyond it, entering
// and leaving all the time (appear_s, leave_s: each one leaving is replaced at once, so the counts stay
// as planned), sea clutter, and a GPS and a gyro drop-out every hour.
// Built from the busy AIS harbour's sensors, filter and tracker (resources/scenarios/ais-harbour.json).
#include <cstdint>

#include "sim/scenario.h"

namespace reckoner::soak {

struct SoakPlan {
  double hours = 24.0;
  int radarTargets = 40;        ///< vessels inside the radar circle at every moment
  int aisTargets = 200;         ///< AIS stations in the ring beyond it at every moment
  double radarCircleNm = 12.0;  ///< radar vessels cross this circle round the route's centre
  double radarRangeNm = 16.5;   ///< the circle and own ship's greatest distance from the centre
  double aisRingInnerNm = 22.0, aisRingOuterNm = 36.0;  ///< closest approach to the centre of AIS vessels
  double radarAisShare = 0.3;                           ///< share of the radar vessels carrying AIS
  double clutterPerKm2 = 0.3;                           ///< within 3 NM
  double squareSideNm = 6.0;  ///< the route: a square round the origin, sailed at routeSpeedKn
  double routeSpeedKn = 10.0;
  double gpsOutageS = 300.0;   ///< every hour from 20 min past
  double gyroOutageS = 120.0;  ///< every hour from 40 min past
};

/// The scenario of a plan; the vessels are drawn with seed.
sim::Scenario soakScenario(const SoakPlan& plan, std::uint64_t seed);

}  // namespace reckoner::soak
