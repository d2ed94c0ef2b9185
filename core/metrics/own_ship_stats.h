#pragma once
// Error statistics of own-ship runs: per phase for one run, per time and per phase over Monte Carlo runs,
// with the two-sided chi-square bounds of the average NEES.
#include <span>
#include <vector>

#include "estimation/chi_square.h"
#include "metrics/phases.h"
#include "sim/scenario_run.h"

namespace reckoner::metrics {

struct PhaseStats {
  Phase phase;
  int steps = 0;
  double rmsePositionM = 0.0;    ///< sqrt(mean(ex^2 + ey^2))
  double rmseVelocityMps = 0.0;  ///< over ground
  double meanNees = 0.0;
  double maxPositionErrorM = 0.0;
  double fractionWithin3Sd = 0.0;  ///< steps with both position errors within 3 sd of their axis
  double sdPositionStartM = 0.0;   ///< sqrt(sd_x^2 + sd_y^2) at the first and last step of the phase
  double sdPositionEndM = 0.0;
};

/// Statistics of one run's rows in each phase.
std::vector<PhaseStats> summarisePhases(const std::vector<Phase>& phases,
                                        std::span<const sim::OwnShipRow> rows);

struct MonteCarloSeries {
  std::vector<double> timeS;
  std::vector<double> rmsePositionM;
  std::vector<double> rmseVelocityMps;
  std::vector<double> meanNees;
  std::vector<double> rmsSdPositionM;  ///< sqrt(mean(sd_x^2 + sd_y^2)): what the filter claims
};

struct MonteCarloPhase {
  PhaseStats stats;                  ///< pooled over all runs (meanNees is the time average of the MC mean)
  double fractionStepsInside = 0.0;  ///< share of time steps whose MC-average NEES lies inside the bounds
  double maxMeanNees = 0.0;
  bool inside = false;  ///< time-averaged MC NEES inside the bounds
};

struct MonteCarloSummary {
  int runs = 0;
  double confidence = 0.95;
  int neesDof = 11;             ///< dimension of the DRKF NEES (nav::neesDof of the scenario)
  est::ChiSquareBounds bounds;  ///< for the average of `runs` NEES values of dimension neesDof
  MonteCarloSeries series;
  std::vector<MonteCarloPhase> phases;
  bool allPhasesInside = false;
};

/// Throws std::invalid_argument if the runs are empty or not on one time grid.
MonteCarloSummary summariseMonteCarlo(const sim::Scenario& scenario, std::span<const sim::RunResult> runs,
                                      double confidence = 0.95);

}  // namespace reckoner::metrics
