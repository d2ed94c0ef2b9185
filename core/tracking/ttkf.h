#pragma once
// The 12-state target-tracking Kalman filter of seed 000 section 2.2: own vessel and one target.
// The DRKF's own-ship position and velocity feed it (figure 3) in one of two ways:
//  - Marginal (default): the own-ship marginal is replaced by the DRKF's, keeping the conditional of
//    everything else given it (Jeffrey's rule for Gaussians). The DRKF's information is used once.
//  - Measurement (seed 000): the DRKF output is a measurement z1..z4 with the DRKF covariance as R.
//    Its errors are correlated in time, so the same information is counted again every cycle and the
//    covariance becomes optimistic, as the paper itself notes (docs/ttkf.md has the figures).
#include <memory>

#include "estimation/measurement_stack.h"
#include "estimation/models/ttkf_process.h"
#include "estimation/models/ttkf_radar.h"
#include "geo/local_frame.h"
#include "sensors/radar.h"

namespace reckoner::track {

namespace tk = est::ttkf;

enum class OwnShipFeed : std::uint8_t { Marginal, Measurement };

struct TtkfConfig {
  tk::ProcessParams process;
  double gateProbability = 0.9999;  ///< radar chi-square gate (2 dof); 0 disables
  OwnShipFeed feed = OwnShipFeed::Marginal;
  double minRangeM = 1.0;           ///< below: range/bearing geometry degenerate
  double initialSpeedSdMps = 10.0;  ///< target velocity uncertainty at initiation (~20 kn)
};

/// What all TTKFs of a bank share: the configuration, the process model and the gate.
class TtkfContext {
 public:
  /// Throws std::invalid_argument for an invalid configuration.
  explicit TtkfContext(const TtkfConfig& config);
  const TtkfConfig config;
  const tk::ProcessModel process;
  const double radarGate;

  /// process.discretise(dt), memoised: a bank predicts many filters over the same step (every track
  /// not updated since the last own-ship input moves one DRKF period). The memo is per thread.
  [[nodiscard]] const tk::ProcessModel::Discrete& discrete(TimeUs dt) const;

 private:
  std::uint64_t generation_;
};

/// A radar plot in the grid frame: range in grid metres, bearing clockwise from grid north.
struct GridPlot {
  TimeUs timeUs = 0;
  double rangeM = 0.0;
  double bearingRad = 0.0;
  double rangeVarM2 = 0.0;
  double bearingVarRad2 = 0.0;
};
/// Converts a true-north radar plot with the convergence and scale at own ship.
GridPlot toGrid(const sensors::RadarPlot& p, const geo::GridInfo& grid);

/// The DRKF's own-ship output: position and velocity over ground and their covariance, at a time.
struct OwnShipInput {
  TimeUs timeUs = 0;
  est::Vec<4> x;
  est::Mat<4> P;
  double convergenceRad = 0.0;  ///< grid convergence at own ship (true bearing = grid + this)
};

class Ttkf {
 public:
  /// Single-plot initiation: own ship from `own` (predicted to the plot time by the TTKF's own model),
  /// target at the plot's position (converted covariance, correlated with own ship), velocity unknown
  /// (0 with initialSpeedSdMps), acceleration at its stationary distribution.
  static Ttkf initiate(std::shared_ptr<const TtkfContext> ctx, const OwnShipInput& own, const GridPlot& plot);

  /// Throws std::invalid_argument for a non-finite or non-positive-definite initial belief.
  Ttkf(std::shared_ptr<const TtkfContext> ctx, const tk::Belief& initial, TimeUs t0);

  /// Predicts to t; false (unchanged) if t is earlier than the filter time or the result not finite.
  bool predictTo(TimeUs t);
  /// Predicts to own.timeUs and feeds the DRKF output (see OwnShipFeed). The report's innovation is
  /// DRKF minus TTKF own ship, its S their summed covariances.
  est::UpdateReport<4> feedOwnShip(const OwnShipInput& own);
  /// What input estimation needs of a radar update besides its report.
  struct RadarDetail {
    tk::Covariance priorP;           ///< predicted covariance at the plot's time
    est::MatRC<2, tk::kStateDim> H;  ///< the measurement Jacobian there
  };
  /// Predicts to the plot's time and applies range and azimuth (gated). detail, if given, receives
  /// the prior covariance and the Jacobian.
  est::UpdateReport<2> updateRadar(const GridPlot& plot, RadarDetail* detail = nullptr);
  /// Predicts to t and applies a direct measurement z of the target's position and ground velocity
  /// [x, y, vx, vy] (grid) with covariance R (an AIS report, ais_fusion.h), gated at `gate` (0: none).
  /// adaptNis > 0: when the NIS exceeds it (a manoeuvre the model did not expect), the target's velocity
  /// and acceleration covariance is first scaled up by NIS / 4 (at most 100), then the update is made.
  est::UpdateReport<4> updateTargetState(TimeUs t, const est::Vec<4>& z, const est::Mat<4>& R, double gate,
                                         double adaptNis = 0.0);
  /// The context (process model) from now on: a track fused with AIS runs a quieter target model.
  void setContext(std::shared_ptr<const TtkfContext> ctx) { ctx_ = std::move(ctx); }
  [[nodiscard]] const std::shared_ptr<const TtkfContext>& context() const { return ctx_; }
  /// Restarts the target's acceleration estimate: 0 with the context's stationary variance, no
  /// correlation with the rest (on association with AIS: the radar-only estimate of the acceleration
  /// is the noisiest part of the state, and the quieter model would keep its error for long).
  void restartTargetAcceleration();
  /// Adds a correction to the belief (input estimation: x += M u, P += M L M'); false and unchanged
  /// when the result is not finite.
  bool correct(const tk::State& dx, const tk::Covariance& dP);
  /// The transition over dt (dense), from the shared context.
  [[nodiscard]] const tk::Covariance& transition(TimeUs dt) const { return ctx_->discrete(dt).Phi.dense(); }

  [[nodiscard]] const tk::Belief& belief() const { return belief_; }
  [[nodiscard]] TimeUs timeUs() const { return timeUs_; }

 private:
  est::UpdateReport<4> replaceOwnShipMarginal(const OwnShipInput& own);
  std::shared_ptr<const TtkfContext> ctx_;
  tk::Belief belief_;
  TimeUs timeUs_;
};

}  // namespace reckoner::track
