#pragma once
// When own ship is dead reckoning, and for how long it stays within a position-error limit. One rule for
// the window (the DR banner, docs/gui.md) and the headless runs: the engine keeps a monitor and puts
// its status into every SimFrame (sim::SimFrame::deadReckoning), runScenario its intervals into the
// RunResult.
#include <array>
#include <optional>
#include <vector>

#include "common/time.h"
#include "navigation/dr_horizon.h"
#include "navigation/drkf.h"

namespace reckoner::nav {

/// What counts as a recent position fix. A GPS or Loran-C position counts while the latest update of
/// its block was applied (accepted, or accepted forced) and is at most fixRecentS old; a radar fix
/// (seed 004) while the latest applied one is at most radarFixRecentS old.
struct DeadReckoningRule {
  double fixRecentS = 3.0;
  double radarFixRecentS = 8.0;
};

/// The rule for a radar sweeping every sweepPeriodS (> 0) and matched to the chart every everySweeps
/// sweeps (values below 1 count as 1): a radar fix counts for four matching intervals.
DeadReckoningRule deadReckoningRule(double sweepPeriodS, int everySweeps);

struct DeadReckoningStatus {
  bool active = false;  ///< no recent position fix at the last evaluation
  TimeUs sinceUs = 0;   ///< the first evaluation of the current stretch without one (while active)
};

/// One stretch of dead reckoning: from the first evaluation without a recent fix to the first one with a
/// fix again (none while it lasts).
struct DeadReckoningInterval {
  TimeUs startUs = 0;
  std::optional<TimeUs> endUs;
};

/// Feed it each DRKF epoch's report and each applied radar fix in time order, then evaluate() at the
/// end of each output cycle. Plain values only; per-step code, never throws.
class DeadReckoningMonitor {
 public:
  explicit DeadReckoningMonitor(DeadReckoningRule rule = {}) : rule_(rule) {}

  /// The outcome of the epoch's GPS and Loran-C position blocks (an epoch without them changes nothing).
  void addEpoch(const DrkfUpdateReport& report);
  /// A radar fix the DRKF applied at t.
  void addRadarFix(TimeUs t);
  /// Decides at t (not before anything fed so far) and opens or closes an interval.
  const DeadReckoningStatus& evaluate(TimeUs t);

  [[nodiscard]] const DeadReckoningStatus& status() const { return status_; }
  [[nodiscard]] const std::vector<DeadReckoningInterval>& intervals() const { return intervals_; }
  [[nodiscard]] const DeadReckoningRule& rule() const { return rule_; }

 private:
  struct LastPosition {
    bool seen = false;
    TimeUs timeUs = 0;
    bool applied = false;
  };
  [[nodiscard]] bool fixRecent(TimeUs t) const;

  DeadReckoningRule rule_;
  std::array<LastPosition, 2> positions_{};  ///< GPS, Loran-C
  std::optional<TimeUs> lastRadarFixUs_;
  DeadReckoningStatus status_;
  std::vector<DeadReckoningInterval> intervals_;
};

/// The time left until the 95% position error passes a limit while dead reckoning (the window's "limit
/// in ..."): timeToPositionLimitS, at most kMaxS. The propagation is costly and the window asks up to
/// 30 times a second, so an answer is counted down while the aids and the limit stay the same and the
/// questions come less than 5 s of filter time apart; it is computed again otherwise.
class DeadReckoningHorizon {
 public:
  static constexpr double kMaxS = 4.0 * 3600.0;  ///< the window shows "> 4 h" from here on
  static constexpr double kRecomputeAfterS = 5.0;

  /// nullopt while not dead reckoning (and the last answer is forgotten); else seconds in [0, kMaxS].
  /// t is the filter's time.
  std::optional<double> update(bool deadReckoning, TimeUs t, const Drkf& filter,
                               const DeadReckoningAids& aids, double limitM);

 private:
  std::optional<double> horizonS_;
  double askedAtS_ = -1e9;
  DeadReckoningAids aids_;
  double limitM_ = 0.0;
};

}  // namespace reckoner::nav
