#pragma once
// The trial manoeuvre put to the test (docs/trial.md, `reckoner-cli trial --verify`): a run of the
// scenario to the trial time, the trial computed from the estimates there (sim/trial_manoeuvre.h),
// then the order given to the simulated own ship after the delay and the run continued past every
// predicted TCPA, recording the CPA each target really reaches (the truths' closest distance).
#include <cstdint>
#include <optional>
#include <vector>

#include "sim/scenario.h"
#include "sim/trial_manoeuvre.h"

namespace reckoner::studies {

struct TrialCheckTarget {
  sim::TrialTargetResult predicted;
  int targetId = -1;                      ///< the scenario's vessel (-1: clutter, not scored)
  std::optional<double> truePresentCpaM;  ///< the truth's CPA without the manoeuvre, at the trial time
  std::optional<double> realisedCpaM;     ///< with --verify
  std::optional<double> realisedTcpaS;
};

struct TrialCheck {
  sim::TrialResult trial;
  std::vector<TrialCheckTarget> targets;
};

/// Runs the scenario (seed) to atUs, computes the trial and, with carryOut, carries it out. Throws
/// std::invalid_argument for a time outside the run or an order that is not finite and >= 0.
TrialCheck checkTrial(const sim::Scenario& scenario, std::uint64_t seed, TimeUs atUs,
                      const sim::TrialOrder& order, const sim::TrialSettings& settings, bool carryOut);

}  // namespace reckoner::studies
