#include "tracking/data_associator.h"

#include "tracking/assignment.h"

namespace reckoner::track {

PlotAssignment associateNearest(const HypothesisTable& table) {
  GnnProblem problem(table.missCost.size(), table.plots, table.missCost);
  for (const Hypothesis& h : table.pairs) problem.addPair(h.track, h.plot, h.cost);
  const std::vector<int> plotOfTrack = problem.solve();
  PlotAssignment out;
  out.largestCluster = problem.largestCluster();
  out.trackOfPlot.assign(table.plots, -1);
  for (std::size_t i = 0; i < plotOfTrack.size(); ++i)
    if (plotOfTrack[i] >= 0) out.trackOfPlot[static_cast<std::size_t>(plotOfTrack[i])] = static_cast<int>(i);
  return out;
}

}  // namespace reckoner::track
