#pragma once
// The dead-reckoning Kalman filter of seed 000 section 2.0 (its 11 states, and two calibration states). It
// predicts to each measurement epoch's own timestamp, stacks whatever measurements that epoch has (8 rows
// with everything on, 2 in dead reckoning), gates each sensor on its own NIS and applies the rest in one
// Joseph-form update. Measurements referenced to true north are converted to the grid frame here
// (docs/drkf.md).
#include <array>
#include <span>

#include "estimation/divergence_guard.h"
#include "estimation/measurement_stack.h"
#include "estimation/models/drkf_process.h"
#include "estimation/nis_window.h"
#include "estimation/sparse_transition.h"
#include "geo/local_frame.h"
#include "sensors/own_ship_samples.h"

namespace reckoner::nav {

namespace drkf = est::drkf;

struct DrkfConfig {
  drkf::ProcessParams process;
  double gateProbability = 0.9999;  ///< per-sensor chi-square gate probability; 0 disables gating
  /// A position or GPS velocity fix rejected continuously this long is applied ungated once (re-anchors a
  /// filter that has diverged). Never for gyro and speedlog: their models may simply not hold (a ship
  /// stopped in a current has a heading but no velocity through the water).
  double gateReopenS = 10.0;
  double minSpeedMps = 0.5;  ///< gyro and speedlog below this speed are not linearisable
  /// ... nor below this many standard deviations of the speed (largest axis of the velocity covariance):
  /// atan2 and |v| are only near-linear when the velocity is known to be clearly non-zero.
  double minSpeedSigmas = 3.0;
  /// Adaptive GNSS position noise (docs/drkf.md, "Adaptive GNSS noise"): each axis's R is the
  /// receiver's (GST or HDOP) times a scale estimated by a variational-Bayes inverse-gamma recursion
  /// with forgetting over about adaptiveWindow fixes. Off: R as the receiver says.
  bool adaptiveGnssNoise = false;
  double adaptiveWindow = 60.0;
  /// The divergence guard (estimation/divergence_guard.h, docs/consistency.md "Divergence guards"):
  /// a filter whose covariance loses positive definiteness, or whose NIS stays far above its band,
  /// restarts at the next GNSS fix.
  est::DivergenceGuardConfig guard;
};

/// The adaptive GNSS noise's state: per grid axis, the inverse-gamma (alpha, beta) of the scale on R.
struct GnssNoiseScale {
  std::array<double, 2> alpha{5.0, 5.0}, beta{5.0, 5.0};  ///< prior: scale 1, worth ten fixes
  [[nodiscard]] double scale(int axis) const {
    return beta[static_cast<std::size_t>(axis)] / alpha[static_cast<std::size_t>(axis)];
  }
};

/// The DRKF's measurement blocks (each with its own gate).
enum DrkfBlock : int { kGpsPosition = 0, kGpsVelocity, kLoranPosition, kSpeedlog, kGyro, kDrkfBlockCount };
/// Most blocks one epoch can carry (more samples at one timestamp are counted and skipped).
inline constexpr int kMaxBlocksPerEpoch = 8;
const char* blockName(DrkfBlock b);

struct DrkfUpdateReport {
  TimeUs timeUs = 0;
  int dim = 0;  ///< rows applied
  /// The joint update of the blocks that passed their gates (innovation in grid units, radians for
  /// the heading; BlockReport::row locates a block in it).
  est::UpdateReport<8> joint;
  std::array<est::BlockReport, kMaxBlocksPerEpoch> blocks{};
  int blockCount = 0;
  /// The filter restarted at this epoch's GNSS fix, and why it had diverged (None: no restart). The
  /// fix's blocks then read AcceptedForced with no NIS: they made the new state.
  est::DivergenceReason reset = est::DivergenceReason::None;
  /// After this epoch the filter is marked diverged, waiting for a GNSS fix to restart (None: healthy).
  est::DivergenceReason diverged = est::DivergenceReason::None;

  /// The report of a block, or nullptr when this epoch had none.
  [[nodiscard]] const est::BlockReport* block(DrkfBlock b) const;
};

/// The online consistency windows of every DRKF block (est::NisWindow), indexed by DrkfBlock.
using DrkfNisWindows = std::array<est::NisWindow, kDrkfBlockCount>;
/// Adds an epoch's blocks to their windows: the applied and the gated (a sensor refused by its gate is
/// the clearest case of noise larger than configured).
void addToNisWindows(const DrkfUpdateReport& r, DrkfNisWindows& windows);

/// Totals per block since construction.
struct DrkfCounters {
  std::array<std::array<long, 8>, kDrkfBlockCount> byStatus{};  ///< [block][UpdateStatus]
  long predictFailures = 0;
  long staleSamples = 0;         ///< stamped other than their epoch, or older than the filter
  long overflowSamples = 0;      ///< beyond an epoch's capacity (kMaxBlocksPerEpoch blocks, 8 rows)
  est::DivergenceCounts resets;  ///< restarts by the divergence guard, by what tripped it
};

/// Initial uncertainty: position and velocity from the caller, every Gauss-Markov state at its
/// stationary standard deviation.
drkf::Covariance initialCovariance(const drkf::ProcessParams& p, double positionSdM, double velocitySdMps);

/// The states a DRKF NEES measures: all but the Gauss-Markov states whose sigma is 0. The model says
/// those are exactly zero; their variance is initialCovariance()'s 1e-12 floor, against which any
/// rounding in their estimate would dominate the NEES (or make P look singular: NaN). Indexed by
/// drkf::StateIndex.
std::array<bool, drkf::kStateDim> neesStates(const drkf::ProcessParams& p);
/// How many states neesStates() keeps: the dimension of the DRKF's NEES (11 with every sensor error
/// modelled, the chi-square degrees of freedom of its bounds).
int neesDof(const drkf::ProcessParams& p);
/// NEES (x_true - x)^T P^-1 (x_true - x) over neesStates(p), by LDLT; NaN when P restricted to them is
/// not positive definite. err is x_true - x.
double drkfNees(const drkf::State& err, const drkf::Covariance& P, const drkf::ProcessParams& p);

/// Position and velocity over ground [x, y, vx, vy] of a DRKF belief, and their covariance (what a
/// TTKF consumes and what the display shows).
est::Vec<4> groundStateOf(const drkf::Belief& b);
est::Mat<4> groundCovarianceOf(const drkf::Belief& b);

class Drkf {
 public:
  /// Throws std::invalid_argument for an invalid configuration or a non-finite/non-PD initial belief.
  Drkf(const DrkfConfig& config, const geo::LocalFrame& frame, const drkf::Belief& initial, TimeUs t0);

  /// Predicts to t; returns false (state unchanged) if t is earlier than the filter time or the
  /// prediction is not finite.
  bool predictTo(TimeUs t);

  /// Predicts to t and applies every sample (all stamped t; others are counted stale and skipped).
  /// Then the divergence guard judges the result; a filter it marked diverged is restarted instead at
  /// the first epoch with a usable GNSS fix (restartAt).
  DrkfUpdateReport update(TimeUs t, std::span<const sensors::OwnShipSample> samples);
  /// A radar fix at t (seed 004): position (grid m) and heading (grid, the direction of the velocity
  /// through the water) with their joint covariance, and how the fix moves with the filter's velocity
  /// and turn rate it was taken with (`sensitivity` to `assumedMotion`, drkf_radar_fix.h; zero for a
  /// plain fix). Predicts to t, gates at the filter's probability (3 dof) and applies it; below the
  /// linearisable speed only the position is used.
  est::UpdateReport<3> updateRadarFix(TimeUs t, const est::Vec<3>& z, const est::Mat<3>& R,
                                      const est::Mat<3>& sensitivity = est::Mat<3>::Zero(),
                                      const est::Vec<3>& assumedMotion = est::Vec<3>::Zero());

  [[nodiscard]] const drkf::Belief& belief() const { return belief_; }
  [[nodiscard]] TimeUs timeUs() const { return timeUs_; }
  /// Replaces the belief (gate and counter state kept): the coupled filter of the comparison runs
  /// its own-ship updates through this filter on the marginal of its joint state. Throws
  /// std::invalid_argument for a non-finite belief.
  void setBelief(const drkf::Belief& b, TimeUs t);
  [[nodiscard]] const DrkfCounters& counters() const { return counters_; }
  /// The divergence guard: diverged() while waiting to restart, its margins for the figures.
  [[nodiscard]] const est::DivergenceGuard& guard() const { return guard_; }
  /// The adaptive GNSS noise's current scale per axis (1, 1 when not adaptive).
  [[nodiscard]] const GnssNoiseScale& gnssNoiseScale() const { return gnssScale_; }
  [[nodiscard]] const DrkfConfig& config() const { return config_; }
  [[nodiscard]] const geo::LocalFrame& frame() const { return frame_; }

 private:
  struct Transition {
    est::SparseTransition<drkf::kStateDim> Phi;
    drkf::Covariance Q;
  };
  const Transition& discretisation(TimeUs dtUs);
  /// predictTo's step under a ship's motion model (drkf_process.h): nonlinear, linearised per second.
  bool predictShipMotion(TimeUs dtUs);
  // ---- One epoch (update): the stacked measurement of seed 000 eq. 7, gated per block and applied in
  // one Joseph-form update, then the outcomes committed to the counters and the gates' clocks ----
  using Stack = est::MeasurementStack<drkf::kStateDim, 8, kMaxBlocksPerEpoch>;
  struct Epoch {
    Stack stack;                                       ///< one block per sensor sample
    const sensors::GpsSample* gnssFix = nullptr;       ///< the fix the adaptive GNSS noise learns from
    const sensors::GyroSample* headingOnly = nullptr;  ///< applied alone after the stack
  };
  /// The epoch's samples stamped t as blocks (others counted stale), linearised at the prior.
  Epoch assembleEpoch(TimeUs t, std::span<const sensors::OwnShipSample> samples, const geo::GridInfo& g);
  /// Under a ship's motion model, the epoch's first heading when it has no log (else nullptr).
  [[nodiscard]] const sensors::GyroSample* headingOnlySample(
      TimeUs t, std::span<const sensors::OwnShipSample> samples) const;
  /// One sample's block(s), converted from true north to the grid.
  void addSample(Epoch& epoch, TimeUs t, const sensors::OwnShipSample& sample, const geo::GridInfo& g);
  void addGpsFix(Epoch& epoch, TimeUs t, const sensors::GpsSample& s, const geo::GridInfo& g);
  /// A block with its gate; a position or velocity fix whose gate has re-opened first inflates the
  /// prior to be consistent with it (the only change of the state before the update).
  template <est::StackableMeasurementModel<drkf::kStateDim> Model>
  void addBlock(Stack& stack, TimeUs t, DrkfBlock b, const Model& model, const est::Vec<Model::kDim>& z,
                const est::Mat<Model::kDim>& R);
  /// Counts each block's outcome and starts or stops its gate's re-opening clock.
  void commitOutcomes(const DrkfUpdateReport& report, TimeUs t);
  /// One epoch: predict, the stacked update, the heading alone, the adaptive noise, the counts.
  DrkfUpdateReport updateEpoch(TimeUs t, std::span<const sensors::OwnShipSample> samples);

  // ---- The divergence guard (drkf_guard.cpp) ----
  /// The epoch's first GNSS fix stamped t with a finite position and a positive variance, or null.
  [[nodiscard]] static const sensors::GpsSample* usableFix(TimeUs t,
                                                           std::span<const sensors::OwnShipSample> samples);
  /// The belief a restart at this fix starts from: the initial covariance, position (and velocity when
  /// the fix has one) from the fix, at least as uncertain as the fix, every other state at its prior.
  [[nodiscard]] drkf::Belief beliefAtFix(const sensors::GpsSample& fix) const;
  /// Restarts at the fix (which the restart consumes) and applies the epoch's other samples.
  DrkfUpdateReport restartAt(TimeUs t, const sensors::GpsSample& fix,
                             std::span<const sensors::OwnShipSample> samples);
  /// The guard's verdict on the epoch just made: its blocks' NIS and the covariance.
  void watch(DrkfUpdateReport& report);

  // ---- A heading with no log in its epoch under a ship's motion model (drkf_heading.cpp) ----
  struct HeadingFix {
    double zRad;      ///< measured heading, grid, [0, 2 pi)
    double varRad2;   ///< its variance
    bool withBias;    ///< the heading-bias state is modelled
    double speedMps;  ///< the estimated speed through the water, >= minSpeedMps
  };
  /// Applied after the stack with a gain that leaves the speed alone.
  est::BlockReport headingOnlyUpdate(TimeUs t, const sensors::GyroSample& s, const geo::GridInfo& g);
  /// The velocity's direction too uncertain to linearise atan2: turned to the measured heading.
  est::BlockReport reanchorHeading(const HeadingFix& fix, est::BlockReport rep);
  /// The gated Joseph-form update with the speed-preserving gain.
  est::BlockReport speedPreservingHeadingUpdate(const HeadingFix& fix, est::BlockReport rep);
  /// The adaptive GNSS noise's recursion after an applied GNSS position fix.
  void adaptGnssNoise(const sensors::GpsSample& s);
  const geo::GridInfo& gridAt(double xM, double yM);
  double gateFor(DrkfBlock b, int dim, TimeUs t) const;
  /// Smallest speed at which the heading / speed magnitude of the velocity block (i0, i1) summed with
  /// (j0, j1) when given (ground velocity) is treated as linearisable.
  [[nodiscard]] double linearisableSpeed(bool overGround) const;

  DrkfConfig config_;
  geo::LocalFrame frame_;
  drkf::ProcessModel process_;
  drkf::Belief belief_;
  TimeUs timeUs_;
  std::array<double, 4> gates_{};  // chi-square gate for 1, 2, 3 rows (index = dim)
  std::array<TimeUs, kDrkfBlockCount> rejectedSinceUs_{};
  struct CacheEntry {
    TimeUs dtUs = -1;
    Transition d;
  };
  std::array<CacheEntry, 4> cache_{};
  TimeUs maxStepUs_ = 1;  ///< longest single prediction step (predictTo composes longer ones)
  std::size_t cacheNext_ = 0;
  geo::GridPoint gridPoint_{std::numeric_limits<double>::quiet_NaN(), 0.0};
  geo::GridInfo grid_;
  DrkfCounters counters_;
  GnssNoiseScale gnssScale_;
  drkf::Covariance initialP_;                     ///< the covariance the filter started with
  std::array<bool, drkf::kStateDim> modelled_{};  ///< the states the guard judges (neesStates)
  est::DivergenceGuard guard_;
};

}  // namespace reckoner::nav
