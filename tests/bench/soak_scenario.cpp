#include "soak_scenario.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "common/angles.h"
#include "common/rng.h"
#include "common/units.h"
#include "geo/local_frame.h"
#include "support/drkf_fixtures.h"

namespace reckoner::soak {
namespace {

/// Vessels crossing a circle round the origin in straight lines: each passes at a distance in
/// [closestM, farthestM] of the centre at a speed in [minMps, maxMps].
struct Crossing {
  double radiusM = 0.0, closestM = 0.0, farthestM = 0.0, minMps = 0.0, maxMps = 0.0;
};

/// prefix and number (snprintf: GCC 12's -Wrestrict misfires on "S" + std::to_string(n) here).
std::string label(const char* prefix, int n) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%s%d", prefix, n);
  return buf;
}

struct Pass {
  geo::GridPoint start;
  double vx = 0.0, vy = 0.0;
  double lifetimeS = 0.0;  ///< until it leaves the circle
};

/// A pass, begun the fraction `done` of the way along its chord.
Pass drawPass(Rng& rng, const Crossing& c, double done) {
  const double theta = 2.0 * kPi * rng.uniform();
  const double d = (c.closestM + (c.farthestM - c.closestM) * rng.uniform()) * (rng.uniform() < 0.5 ? -1 : 1);
  const double speed = c.minMps + (c.maxMps - c.minMps) * rng.uniform();
  const double half = std::sqrt(c.radiusM * c.radiusM - d * d);
  const double ex = std::sin(theta), ey = std::cos(theta);   // along the pass
  const double nx = std::cos(theta), ny = -std::sin(theta);  // across it
  const double along = -half + 2.0 * half * done;
  Pass p;
  p.start = {d * nx + along * ex, d * ny + along * ey};
  p.vx = speed * ex;
  p.vy = speed * ey;
  p.lifetimeS = 2.0 * half * (1.0 - done) / speed;
  return p;
}

class Traffic {
 public:
  Traffic(sim::Scenario& s, std::uint64_t seed) : s_(s), rng_(seed, 7) {}

  /// `count` vessels of crossing c present at every moment: `count` lanes, each starting with a vessel
  /// part way along its pass, and each vessel that leaves the circle followed at once by a new one
  /// entering it. The load is the same in every hour of the run, so the memory of hour 2 and of hour 24
  /// are comparable (with arrivals drawn at random the count wanders by its square root, and the
  /// memory in use with it).
  void populate(const Crossing& c, int count, double aisShare) {
    const double durationS = toSeconds(s_.durationUs);
    for (int lane = 0; lane < count; ++lane) {
      Pass p = drawPass(rng_, c, rng_.uniform());
      for (double t = 0.0;;) {
        add(p, t, durationS, aisShare);
        t += p.lifetimeS;
        if (t >= durationS) break;
        p = drawPass(rng_, c, 0.0);
      }
    }
  }

 private:
  void add(const Pass& p, double appearS, double durationS, double aisShare) {
    sim::TargetSpec t;
    t.id = static_cast<int>(s_.targets.size()) + 1;
    t.name = label("S", t.id);
    t.appearUs = fromSeconds(appearS);
    if (appearS + p.lifetimeS < durationS) t.leaveUs = fromSeconds(appearS + p.lifetimeS);
    t.motion.initialPosition = p.start;
    t.motion.initialVelocityMps = {p.vx, p.vy};
    t.motion.randomAcceleration = est::GaussMarkov{0.005, 0.02};  // as the AIS harbour's vessels
    if (rng_.uniform() < aisShare) {
      const bool classA = rng_.uniform() < 0.8;
      auto ais = sensors::AisTransmitterSpec::defaults(classA ? sensors::AisStationClass::A
                                                              : sensors::AisStationClass::B);
      ais.mmsi = 232000000u + static_cast<std::uint32_t>(t.id);
      ais.shipName = label("SOAK ", t.id);
      ais.toBowM = 60;
      ais.toSternM = 20;
      ais.toPortM = 6;
      ais.toStarboardM = 6;
      t.ais = ais;
    }
    s_.targets.push_back(std::move(t));
  }

  sim::Scenario& s_;
  Rng rng_;
};

/// The square round the origin, `laps` times, clockwise from its north-west corner.
geo::Route squareRoute(const SoakPlan& plan, const geo::LocalFrame& frame, int laps) {
  geo::Route r;
  r.name = "soak square";
  r.defaultTurnRadiusNm = 0.5;
  const double h = nmToMetres(plan.squareSideNm) / 2.0;
  const geo::GridPoint corners[4] = {{-h, h}, {h, h}, {h, -h}, {-h, -h}};
  for (int k = 0; k <= 4 * laps; ++k) {
    geo::Waypoint w;
    w.id = k + 1;
    w.name = label("WP", k + 1);
    w.position = frame.toGeodetic(corners[k % 4]);
    w.leg.plannedSpeedKn = plan.routeSpeedKn;
    w.leg.portXtlNm = w.leg.starboardXtlNm = 0.1;
    r.waypoints.push_back(w);
  }
  return r;
}

void hourlyOutages(sim::Scenario& s, const SoakPlan& plan) {
  for (double h = 0.0; h < plan.hours; h += 1.0) {
    const double base = h * 3600.0;
    if (base + 1200.0 < toSeconds(s.durationUs)) {
      s.gps.power.addChange(fromSeconds(base + 1200.0), false);
      s.gps.power.addChange(fromSeconds(base + 1200.0 + plan.gpsOutageS), true);
    }
    if (base + 2400.0 < toSeconds(s.durationUs)) {
      s.gyro.power.addChange(fromSeconds(base + 2400.0), false);
      s.gyro.power.addChange(fromSeconds(base + 2400.0 + plan.gyroOutageS), true);
    }
  }
}

}  // namespace

sim::Scenario soakScenario(const SoakPlan& plan, std::uint64_t seed) {
  sim::Scenario s = test::builtinScenario("ais-harbour");
  s.name = "soak";
  s.description = "reckoner-soak (docs/robustness.md, \"Soak\")";
  s.origin = {45.0, -30.0};  // open water: no chart is needed
  s.durationUs = fromSeconds(plan.hours * 3600.0);
  s.seed = seed;
  s.targets.clear();
  const geo::LocalFrame frame(s.origin.latDeg, s.origin.lonDeg);

  // Own ship on the route from its first corner, under track control.
  const double laps = std::ceil(plan.hours * plan.routeSpeedKn / (4.0 * plan.squareSideNm)) + 1.0;
  const double h = nmToMetres(plan.squareSideNm) / 2.0;
  s.ownShip = {};
  s.ownShip.initialPosition = {-h, h};
  s.ownShip.initialVelocityMps = {knotsToMps(plan.routeSpeedKn), 0.0};
  s.ownShip.maxAccelerationMps2 = 0.05;
  s.ownShip.maxTurnRateRadPerS = degToRad(0.5);
  s.voyage.route = squareRoute(plan, frame, static_cast<int>(laps));
  s.voyage.followRoute = true;

  hourlyOutages(s, plan);
  s.radar.maxRangeM = nmToMetres(plan.radarRangeNm);
  s.radar.clutterPerKm2 = plan.clutterPerKm2;
  s.radar.clutterMaxRangeM = nmToMetres(3.0);

  Traffic traffic(s, seed);
  const double r = nmToMetres(plan.radarCircleNm);
  traffic.populate({r, 0.0, 0.85 * r, knotsToMps(5.0), knotsToMps(20.0)}, plan.radarTargets,
                   plan.radarAisShare);
  traffic.populate({nmToMetres(plan.aisRingOuterNm), nmToMetres(plan.aisRingInnerNm),
                    0.95 * nmToMetres(plan.aisRingOuterNm), knotsToMps(5.0), knotsToMps(20.0)},
                   plan.aisTargets, 1.0);
  return s;
}

}  // namespace reckoner::soak
