#pragma once
// Seed 002's two own-ship filters beside the DRKF on the same simulated sensors (docs/seed002.md):
// the geodetic Kalman filter (navigation/geodetic_kf.h) and the least-squares navigator
// (navigation/lsq_fusion.h). Each cycle gives, per filter, the row ownship.csv would hold, with the
// NEES of position and velocity over ground (4 dof, grid frame) for all three alike.
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "estimation/chi_square.h"
#include "navigation/geodetic_kf.h"
#include "navigation/lsq_fusion.h"
#include "sim/scenario_run.h"

namespace reckoner::studies {

enum class OwnShipFilter : std::uint8_t { Drkf, Geodetic, Lsq };
inline constexpr int kOwnShipFilterCount = 3;
const char* ownShipFilterName(OwnShipFilter f);  ///< "drkf", "geodetic", "lsq"
std::optional<OwnShipFilter> ownShipFilterFromName(std::string_view name);

/// Seed 002's two filters fed from the simulation's frames (the same samples as the DRKF).
class Seed002Filters {
 public:
  /// Both start from the DRKF's initial estimate, with the process noise described below.
  Seed002Filters(const sim::Scenario& scenario, const est::drkf::Belief& drkfStart,
                 const geo::LocalFrame& frame);
  /// The frame's samples, epoch by epoch; both filters are then at the frame's time.
  void feed(const sim::SimFrame& frame);
  /// [x, y, vx, vy] over ground in the grid frame with covariance (Drkf: not handled here).
  [[nodiscard]] est::Gaussian<4> ground(OwnShipFilter f) const;
  [[nodiscard]] int geodeticRowsApplied() const { return geodeticRows_; }

 private:
  const geo::LocalFrame& frame_;
  nav::GeodeticKf geodetic_;
  nav::LsqNavigator lsq_;
  TimeUs timeUs_ = 0;
  int geodeticRows_ = 0;
};

struct OwnShipFilterRun {
  std::array<std::vector<sim::OwnShipRow>, kOwnShipFilterCount> rows;  ///< nees: 4 dof, position and velocity
  sim::RunResult drkf;  ///< the DRKF run as sim::runScenario gives it (tracks included)
};

/// The scenario with one seed; the seed 002 filters start from the DRKF's initial estimate and take
/// their process noise from the scenario's filter model: white acceleration of density
/// q = 2 e^-1 sigma^2 / beta, which gives the Gauss-Markov acceleration's velocity change over its
/// correlation time 1 / beta (docs/seed002.md).
OwnShipFilterRun runOwnShipFilters(const sim::Scenario& scenario, std::uint64_t seed);
/// Seeds baseSeed, baseSeed + 1, ... on `threads` threads, in seed order.
std::vector<OwnShipFilterRun> runOwnShipFiltersMonteCarlo(const sim::Scenario& scenario, int runs,
                                                          int threads, std::uint64_t baseSeed);

/// Per filter and phase (0: GPS on, 1: GPS off), over the rows from `fromUs` on.
struct OwnShipPhaseStats {
  long rows = 0;
  double positionRmseM = 0.0, velocityRmseMps = 0.0;
  double meanNees = 0.0;     ///< of the run-averaged 4-dof NEES at each time
  double shareInBand = 0.0;  ///< share of times whose run-averaged NEES lies in the band
  double p95PositionErrorM = 0.0;
};
using OwnShipFilterStats = std::array<std::array<OwnShipPhaseStats, 2>, kOwnShipFilterCount>;
OwnShipFilterStats summariseOwnShipFilters(const std::vector<OwnShipFilterRun>& runs, TimeUs fromUs,
                                           const est::ChiSquareBounds& band);

}  // namespace reckoner::studies
