#include "studies/radar_fix_study.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/angles.h"
#include "common/percentile.h"
#include "estimation/chi_square.h"
#include "estimation/models/drkf_radar_fix.h"
#include "sim/scenario_run.h"
#include "sim/simulation_engine.h"

// The studies drive the engine and score its runs: the engine's names unqualified here.
using namespace reckoner::sim;

namespace reckoner::studies {

namespace {
struct RunOut {
  std::vector<double> posErr, hdgErr, fixPosErr, fixHdgErr;
  double nees = 0.0, fixNees = 0.0, fixPosNees = 0.0, fixHdgNees = 0.0;
  long pictures = 0, applied = 0, echoes = 0, used = 0, fixes = 0;
  long vessel = 0, clutter = 0, spuriousUsed = 0;

  void add(const RunOut& o) {
    for (auto [to, from] : {std::pair{&posErr, &o.posErr}, std::pair{&hdgErr, &o.hdgErr},
                            std::pair{&fixPosErr, &o.fixPosErr}, std::pair{&fixHdgErr, &o.fixHdgErr}})
      to->insert(to->end(), from->begin(), from->end());
    for (auto [to, from] : {std::pair{&nees, o.nees}, std::pair{&fixNees, o.fixNees},
                            std::pair{&fixPosNees, o.fixPosNees}, std::pair{&fixHdgNees, o.fixHdgNees}})
      *to += from;
    for (auto [to, from] :
         {std::pair{&pictures, o.pictures}, std::pair{&applied, o.applied}, std::pair{&echoes, o.echoes},
          std::pair{&used, o.used}, std::pair{&fixes, o.fixes}, std::pair{&vessel, o.vessel},
          std::pair{&clutter, o.clutter}, std::pair{&spuriousUsed, o.spuriousUsed}})
      *to += from;
  }
};

double p95(std::vector<double> v) {
  return percentile95(std::move(v));
}

void scoreFix(const RadarFixReport& r, const SimFrame& f, RunOut& o) {
  const est::Vec<3> err = radarFixError(r, f);
  o.fixPosErr.push_back(err.head<2>().norm());
  o.fixHdgErr.push_back(std::abs(err[2]));
  o.fixNees += est::nees<3>(err, r.covariance);
  o.fixPosNees += est::nees<2>(est::Vec<2>(err.head<2>()), est::Mat<2>(r.covariance.topLeftCorner<2, 2>()));
  o.fixHdgNees += err[2] * err[2] / r.covariance(2, 2);
  ++o.fixes;
}
}  // namespace

RadarFixStudy runRadarFixStudy(const Scenario& scenario, std::shared_ptr<const radar::Coastline> coast,
                               std::shared_ptr<const radar::LandMask> land, bool matching, int runs,
                               int threads, std::uint64_t seed) {
  Scenario sc = scenario;
  sc.radarMatching.active = StepSchedule<bool>(matching);
  const est::drkf::ProcessParams process = drkfConfigFor(sc).process;
  std::vector<RunOut> outs(static_cast<std::size_t>(std::max(0, runs)));
  parallelRuns(runs, threads, [&](int i) {
    SimulationEngine e(sc, seed + static_cast<std::uint64_t>(i));
    e.setCoastline(coast);
    e.setLandMask(land);
    RunOut& o = outs[static_cast<std::size_t>(i)];
    while (!e.finished()) {
      const SimFrame f = e.step();
      for (const auto& r : f.radarFixes) {
        ++o.pictures;
        o.applied += r.update.applied() ? 1 : 0;
        o.echoes += r.echoes;
        o.used += r.used;
        o.vessel += r.vesselEchoes;
        o.clutter += r.clutterEchoes;
        o.spuriousUsed += r.spuriousUsed;
        // Fixes are taken at sweep starts; the frame's truth is at its end, so only fixes at it.
        if (r.informative && r.timeUs == f.timeUs) scoreFix(r, f, o);
      }
      if (f.sensors.isOn(sensors::SensorId::Gps) || f.timeUs < fromSeconds(60.0)) continue;
      const auto& x = f.estimate.x;
      o.posErr.push_back(
          std::hypot(x[est::drkf::kPosX] - f.truth.position.xM, x[est::drkf::kPosY] - f.truth.position.yM));
      o.hdgErr.push_back(
          std::abs(angleDiff(bearingOf(x[est::drkf::kVelX], x[est::drkf::kVelY]), f.truth.headingRad)));
      o.nees += nav::drkfNees(f.trueState - f.estimate.x, f.estimate.P, process);
    }
  });
  RadarFixStudy s;
  s.runs = runs;
  RunOut all;
  for (const auto& o : outs) all.add(o);
  s.rows = static_cast<long>(all.posErr.size());
  const double rows = static_cast<double>(std::max(1L, s.rows));
  double sq = 0.0;
  for (const double e : all.posErr) sq += e * e;
  s.positionP95M = p95(all.posErr);
  s.positionRmsM = std::sqrt(sq / rows);
  s.headingP95Deg = radToDeg(p95(all.hdgErr));
  s.meanNees = all.nees / rows;
  s.pictures = all.pictures;
  s.applied = all.applied;
  const double pictures = static_cast<double>(std::max(1L, all.pictures));
  s.echoesPerPicture = static_cast<double>(all.echoes) / pictures;
  s.matchedPerPicture = static_cast<double>(all.used) / pictures;
  s.fixes = all.fixes;
  s.vesselEchoes = all.vessel;
  s.clutterEchoes = all.clutter;
  s.spuriousUsed = all.spuriousUsed;
  const double fixes = static_cast<double>(std::max(1L, all.fixes));
  s.fixPositionP95M = p95(all.fixPosErr);
  s.fixHeadingP95Deg = radToDeg(p95(all.fixHdgErr));
  s.fixNees = all.fixNees / fixes;
  s.fixPositionNees = all.fixPosNees / fixes;
  s.fixHeadingNees = all.fixHdgNees / fixes;
  return s;
}

}  // namespace reckoner::studies
