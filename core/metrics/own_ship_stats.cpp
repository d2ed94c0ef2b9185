#include "metrics/own_ship_stats.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "navigation/drkf.h"
#include "sim/simulation_engine.h"

namespace reckoner::metrics {
namespace {

struct Accumulator {
  int steps = 0;
  double sumPos2 = 0, sumVel2 = 0, sumNees = 0, maxPos = 0;
  int within3Sd = 0;
  void add(const sim::OwnShipRow& r) {
    ++steps;
    const double ep = r.positionErrorM(), ev = r.velocityErrorMps();
    sumPos2 += ep * ep;
    sumVel2 += ev * ev;
    sumNees += r.nees;
    maxPos = std::max(maxPos, ep);
    within3Sd += r.positionWithin(3.0) ? 1 : 0;
  }
  void fill(PhaseStats& s) const {
    s.steps = steps;
    if (steps == 0) return;
    s.rmsePositionM = std::sqrt(sumPos2 / steps);
    s.rmseVelocityMps = std::sqrt(sumVel2 / steps);
    s.meanNees = sumNees / steps;
    s.maxPositionErrorM = maxPos;
    s.fractionWithin3Sd = static_cast<double>(within3Sd) / steps;
  }
};

}  // namespace

std::vector<PhaseStats> summarisePhases(const std::vector<Phase>& phases,
                                        std::span<const sim::OwnShipRow> rows) {
  std::vector<PhaseStats> out;
  for (const Phase& p : phases) {
    PhaseStats s;
    s.phase = p;
    Accumulator acc;
    const sim::OwnShipRow* first = nullptr;
    const sim::OwnShipRow* last = nullptr;
    for (const auto& r : rows) {
      if (!p.contains(r.timeUs)) continue;
      acc.add(r);
      if (!first) first = &r;
      last = &r;
    }
    acc.fill(s);
    if (first) {
      s.sdPositionStartM = first->sdPositionM();
      s.sdPositionEndM = last->sdPositionM();
    }
    out.push_back(std::move(s));
  }
  return out;
}

MonteCarloSummary summariseMonteCarlo(const sim::Scenario& scenario, std::span<const sim::RunResult> runs,
                                      double confidence) {
  if (runs.empty()) throw std::invalid_argument("Monte Carlo summary: no runs");
  const std::size_t steps = runs.front().rows.size();
  for (const auto& r : runs)
    if (r.rows.size() != steps) throw std::invalid_argument("Monte Carlo summary: runs differ in length");

  MonteCarloSummary m;
  m.runs = static_cast<int>(runs.size());
  m.confidence = confidence;
  m.neesDof = nav::neesDof(sim::drkfConfigFor(scenario).process);
  m.bounds = est::averageNeesBounds(m.neesDof, m.runs, confidence);
  const double n = static_cast<double>(runs.size());
  auto& s = m.series;
  for (std::size_t k = 0; k < steps; ++k) {
    double pos2 = 0, vel2 = 0, nees = 0, sd2 = 0;
    for (const auto& r : runs) {
      const auto& row = r.rows[k];
      pos2 += row.positionErrorM() * row.positionErrorM();
      vel2 += row.velocityErrorMps() * row.velocityErrorMps();
      nees += row.nees;
      sd2 += row.sdXM * row.sdXM + row.sdYM * row.sdYM;
    }
    s.timeS.push_back(toSeconds(runs.front().rows[k].timeUs));
    s.rmsePositionM.push_back(std::sqrt(pos2 / n));
    s.rmseVelocityMps.push_back(std::sqrt(vel2 / n));
    s.meanNees.push_back(nees / n);
    s.rmsSdPositionM.push_back(std::sqrt(sd2 / n));
  }

  m.allPhasesInside = true;
  for (const Phase& p : derivePhases(scenario)) {
    MonteCarloPhase mp;
    mp.stats.phase = p;
    Accumulator acc;
    int inside = 0;
    int count = 0;
    double neesSum = 0.0;
    for (std::size_t k = 0; k < steps; ++k) {
      const TimeUs t = runs.front().rows[k].timeUs;
      if (!p.contains(t)) continue;
      for (const auto& r : runs) acc.add(r.rows[k]);
      ++count;
      neesSum += s.meanNees[k];
      inside += m.bounds.contains(s.meanNees[k]) ? 1 : 0;
      mp.maxMeanNees = std::max(mp.maxMeanNees, s.meanNees[k]);
      if (count == 1) mp.stats.sdPositionStartM = s.rmsSdPositionM[k];
      mp.stats.sdPositionEndM = s.rmsSdPositionM[k];
    }
    acc.fill(mp.stats);
    mp.stats.steps = count;
    if (count > 0) {
      mp.stats.meanNees = neesSum / count;
      mp.fractionStepsInside = static_cast<double>(inside) / count;
    }
    mp.inside = count > 0 && m.bounds.contains(mp.stats.meanNees);
    m.allPhasesInside = m.allPhasesInside && mp.inside;
    m.phases.push_back(std::move(mp));
  }
  return m;
}

}  // namespace reckoner::metrics
