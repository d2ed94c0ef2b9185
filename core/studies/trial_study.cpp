#include "studies/trial_study.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/angles.h"
#include "sim/simulation_engine.h"
#include "tracking/cpa.h"

namespace reckoner::studies {

TrialCheck checkTrial(const sim::Scenario& scenario, std::uint64_t seed, TimeUs atUs,
                      const sim::TrialOrder& order, const sim::TrialSettings& settings, bool carryOut) {
  if (atUs <= 0 || atUs >= scenario.durationUs)
    throw std::invalid_argument("trial: --at must lie inside the run (0, duration)");
  if (!std::isfinite(order.courseRad) || !(order.speedMps >= 0.0) || !(order.delayS >= 0.0) ||
      !std::isfinite(order.speedMps) || !std::isfinite(order.delayS))
    throw std::invalid_argument("trial: course, speed and delay must be finite, speed and delay >= 0");
  sim::SimulationEngine engine(scenario, seed);
  sim::SimFrame f;
  while (engine.timeUs() < atUs && !engine.finished()) f = engine.step();
  TrialCheck out;
  out.trial = sim::trialManoeuvre(
      f.timeUs, sim::trialOwnShipOf(f, scenario.ownShip, engine.frame()),
      sim::trialTargetsOf(f, scenario.tracker.aisAssociation.errors, engine.frame()), order, settings);
  std::vector<std::size_t> index;  // scenario index of each trial target, or npos
  for (const auto& t : out.trial.targets) {
    TrialCheckTarget c;
    c.predicted = t;
    for (const auto& tr : f.tracks)
      if (t.trackId != 0 && tr.trackId == t.trackId) c.targetId = tr.targetId;
    for (std::size_t i = 0; i < scenario.targets.size(); ++i)
      if (c.targetId < 0 && t.trackId == 0 && scenario.targets[i].ais &&
          scenario.targets[i].ais->mmsi == t.mmsi)
        c.targetId = scenario.targets[i].id;
    std::size_t k = static_cast<std::size_t>(-1);
    for (std::size_t i = 0; i < scenario.targets.size(); ++i)
      if (scenario.targets[i].id == c.targetId) k = i;
    index.push_back(k);
    if (k < f.targets.size()) {
      const auto& o = f.truth;
      const auto& g = f.targets[k];
      est::Vec<4> rel;
      rel << g.position.xM - o.position.xM, g.position.yM - o.position.yM, g.groundVxMps() - o.groundVxMps(),
          g.groundVyMps() - o.groundVyMps();
      c.truePresentCpaM = track::cpaOf(rel, est::Mat<4>::Identity()).cpaM;
    }
    out.targets.push_back(c);
  }
  if (!carryOut) return out;

  // The order at the trial time plus the delay, then on past the last predicted TCPA.
  double lastTcpa = 0.0;
  for (const auto& t : out.trial.targets) lastTcpa = std::max(lastTcpa, t.tcpaS);
  const TimeUs orderUs = f.timeUs + fromSeconds(order.delayS);
  const TimeUs endUs = f.timeUs + fromSeconds(std::min(lastTcpa + 300.0, 6.0 * 3600.0));
  engine.extendTo(endUs);
  const double convergence = engine.frame().gridInfo(f.truth.position).convergenceRad;
  bool ordered = false;
  std::vector<double> best(out.targets.size(), std::numeric_limits<double>::infinity());
  std::vector<double> bestT(out.targets.size(), 0.0);
  while (!engine.finished() && engine.timeUs() < endUs) {
    if (!ordered && engine.timeUs() + 1 >= orderUs) {
      engine.orderOwnShip({wrapTwoPi(order.courseRad - convergence), order.speedMps, 0.0, 0.0});
      ordered = true;
    }
    const sim::SimFrame g = engine.step();
    for (std::size_t j = 0; j < index.size(); ++j) {
      if (index[j] >= g.targets.size()) continue;
      const auto& p = g.targets[index[j]].position;
      const double d = std::hypot(p.xM - g.truth.position.xM, p.yM - g.truth.position.yM);
      if (d < best[j]) {
        best[j] = d;
        bestT[j] = toSeconds(g.timeUs - f.timeUs);
      }
    }
  }
  for (std::size_t j = 0; j < index.size(); ++j) {
    if (index[j] == static_cast<std::size_t>(-1)) continue;
    out.targets[j].realisedCpaM = best[j];
    out.targets[j].realisedTcpaS = bestT[j];
  }
  return out;
}

}  // namespace reckoner::studies
