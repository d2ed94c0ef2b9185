#include "navigation/drkf.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <variant>
#include <vector>

#include "common/angles.h"
#include "estimation/chi_square.h"
#include "estimation/model_concepts.h"
#include "estimation/models/drkf_ground_velocity.h"
#include "estimation/models/drkf_gyro.h"
#include "estimation/models/drkf_position_fix.h"
#include "estimation/models/drkf_radar_fix.h"
#include "estimation/models/drkf_speedlog.h"

namespace reckoner::nav {
namespace {
using namespace est::drkf;
// The grid convergence changes by ~0.005 deg per 500 m; recompute it only after moving that far.
constexpr double kGridRefreshM = 500.0;
// Longest single prediction step: beta dt at most kMaxBetaDt keeps Van Loan's exponential accurate
// (cancellation ~ 1e-16 exp(2 beta dt) ~ 3e-13), and never more than a minute.
constexpr double kMaxBetaDt = 4.0;
constexpr double kMaxPredictStepS = 60.0;

template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;  // C++20 deduces it; clang before 17 (clang-tidy) needs it said

/// The smallest delta >= 0 such that the block's NIS against S + delta I is at most its dimension:
/// how much variance must be added to the states a fix observes one-to-one (position, velocity) for
/// the fix to be consistent. Used only when the gate re-opens after a persistent rejection.
template <est::MeasurementModel<kStateDim> Model>
double consistencyInflation(const Covariance& P, const Model& model, const State& x,
                            const est::Vec<Model::kDim>& z, const est::Mat<Model::kDim>& R) {
  constexpr int M = Model::kDim;
  const est::Vec<M> y = model.residual(z, model.h(x));
  const est::MatRC<M, kStateDim> H = model.jacobian(x);
  const est::Mat<M> S = H * P * H.transpose() + R;
  auto nis = [&](double delta) {
    const est::Mat<M> Sd = S + delta * est::Mat<M>::Identity();
    return y.dot(Sd.ldlt().solve(y));
  };
  if (!y.allFinite() || !(nis(0.0) > M)) return 0.0;
  double lo = 0.0, hi = y.squaredNorm() / M;  // nis(hi) <= |y|^2 / hi = M
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (nis(mid) > M ? lo : hi) = mid;
  }
  return hi;
}
}  // namespace

const char* blockName(DrkfBlock b) {
  switch (b) {
    case kGpsPosition:
      return "gps_position";
    case kGpsVelocity:
      return "gps_velocity";
    case kLoranPosition:
      return "loran_c";
    case kSpeedlog:
      return "speedlog";
    case kGyro:
      return "gyro";
    case kDrkfBlockCount:
      break;
  }
  return "unknown";
}

void addToNisWindows(const DrkfUpdateReport& r, DrkfNisWindows& windows) {
  for (int i = 0; i < r.blockCount; ++i) {
    const est::BlockReport& b = r.blocks[static_cast<std::size_t>(i)];
    if (est::isApplied(b.status) || b.status == est::UpdateStatus::RejectedGate)
      windows[static_cast<std::size_t>(b.tag)].add(b.nis, b.dim);
  }
}

const est::BlockReport* DrkfUpdateReport::block(DrkfBlock b) const {
  for (int i = 0; i < blockCount; ++i)
    if (blocks[static_cast<std::size_t>(i)].tag == b) return &blocks[static_cast<std::size_t>(i)];
  return nullptr;
}

Covariance initialCovariance(const ProcessParams& p, double positionSdM, double velocitySdMps) {
  State sd;
  sd[kPosX] = sd[kPosY] = positionSdM;
  sd[kVelX] = sd[kVelY] = velocitySdMps;
  // A Gauss-Markov state with sigma 0 is known to be 0; a tiny floor keeps P positive definite.
  constexpr double kFloor = 1e-6;
  sd[kCurX] = sd[kCurY] = std::max(p.current.sigma, kFloor);
  sd[kAccX] = sd[kAccY] = std::max(p.acceleration.sigma, kFloor);
  if (p.ship.enabled) {
    sd[kAlongAccel] = std::max(p.ship.alongAcceleration.sigma, kFloor);
    sd[kTurnRate] = std::max(p.ship.turnRate.sigma, kFloor);
  }
  sd[kLoranX] = sd[kLoranY] = std::max(p.loranError.sigma, kFloor);
  sd[kLogBias] = std::max(p.speedlogError.sigma, kFloor);
  sd[kHeadingBias] = std::max(p.headingBias.sigma, kFloor);
  sd[kLogScale] = std::max(p.logScale.sigma, kFloor);
  return sd.cwiseAbs2().asDiagonal();
}

std::array<bool, kStateDim> neesStates(const ProcessParams& p) {
  std::array<bool, kStateDim> keep{};
  keep.fill(true);
  const auto drop = [&](const est::GaussMarkov& gm, std::initializer_list<int> states) {
    if (gm.sigma > 0.0) return;
    for (int i : states) keep[static_cast<std::size_t>(i)] = false;
  };
  drop(p.current, {kCurX, kCurY});
  if (p.ship.enabled) {
    drop(p.ship.alongAcceleration, {kAlongAccel});
    drop(p.ship.turnRate, {kTurnRate});
  } else {
    drop(p.acceleration, {kAccX, kAccY});
  }
  drop(p.loranError, {kLoranX, kLoranY});
  drop(p.speedlogError, {kLogBias});
  drop(p.headingBias, {kHeadingBias});
  drop(p.logScale, {kLogScale});
  return keep;
}

int neesDof(const ProcessParams& p) {
  const auto keep = neesStates(p);
  return static_cast<int>(std::count(keep.begin(), keep.end(), true));
}

double drkfNees(const State& err, const Covariance& P, const ProcessParams& p) {
  const auto keep = neesStates(p);
  const int n = static_cast<int>(std::count(keep.begin(), keep.end(), true));
  if (n == kStateDim) return est::nees<kStateDim>(err, P);
  std::vector<int> idx;
  for (int i = 0; i < kStateDim; ++i)
    if (keep[static_cast<std::size_t>(i)]) idx.push_back(i);
  Eigen::VectorXd e(n);
  Eigen::MatrixXd S(n, n);
  for (int a = 0; a < n; ++a) {
    e[a] = err[idx[static_cast<std::size_t>(a)]];
    for (int b = 0; b < n; ++b)
      S(a, b) = P(idx[static_cast<std::size_t>(a)], idx[static_cast<std::size_t>(b)]);
  }
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(S);
  if (!est::ldltPositiveDefinite(ldlt)) return std::numeric_limits<double>::quiet_NaN();
  return e.dot(ldlt.solve(e));
}

Drkf::Drkf(const DrkfConfig& config, const geo::LocalFrame& frame, const Belief& initial, TimeUs t0)
    : config_(config),
      frame_(frame),
      process_(config.process),
      belief_(initial),
      timeUs_(t0),
      initialP_(initial.P),
      modelled_(neesStates(config.process)),
      guard_(config.guard) {
  if (!initial.x.allFinite() || !est::isPositiveDefinite(initial.P)) {
    throw std::invalid_argument("DRKF: initial state must be finite with a positive definite covariance");
  }
  if (!(config.gateProbability >= 0.0 && config.gateProbability < 1.0))
    throw std::invalid_argument("DRKF: gate probability must lie in [0, 1)");
  if (config.gateProbability > 0.0) {
    gates_[1] = est::chiSquareQuantile(config.gateProbability, 1.0);
    gates_[2] = est::chiSquareQuantile(config.gateProbability, 2.0);
    gates_[3] = est::chiSquareQuantile(config.gateProbability, 3.0);
  }
  rejectedSinceUs_.fill(-1);
  const auto& p = config.process;
  // The calibration states count only when modelled (their default beta would shorten the paper's steps).
  const double accelBeta = p.ship.enabled
                               ? std::max(p.ship.alongAcceleration.betaPerS, p.ship.turnRate.betaPerS)
                               : p.acceleration.betaPerS;
  const double betaMax =
      std::max({p.current.betaPerS, accelBeta, p.loranError.betaPerS, p.speedlogError.betaPerS,
                p.headingBias.sigma > 0.0 ? p.headingBias.betaPerS : 0.0,
                p.logScale.sigma > 0.0 ? p.logScale.betaPerS : 0.0});
  maxStepUs_ = std::max<TimeUs>(1, fromSeconds(std::min(kMaxPredictStepS, kMaxBetaDt / betaMax)));
}

const Drkf::Transition& Drkf::discretisation(TimeUs dtUs) {
  for (const auto& c : cache_)
    if (c.dtUs == dtUs) return c.d;
  CacheEntry& slot = cache_[cacheNext_];
  cacheNext_ = (cacheNext_ + 1) % cache_.size();
  slot.dtUs = dtUs;
  const auto d = process_.discretise(toSeconds(dtUs));
  // exp(F dt) is exactly zero outside the per-axis blocks; drop round-off so the sparsity is kept.
  est::Mat<kStateDim> Phi = d.Phi;
  Phi = (Phi.array().abs() < 1e-300).select(0.0, Phi);
  slot.d = {est::SparseTransition<kStateDim>(Phi), d.Q};
  return slot.d;
}

const geo::GridInfo& Drkf::gridAt(double xM, double yM) {
  if (!(std::abs(xM - gridPoint_.xM) <= kGridRefreshM && std::abs(yM - gridPoint_.yM) <= kGridRefreshM)) {
    gridPoint_ = {xM, yM};
    grid_ = frame_.gridInfo(gridPoint_);
  }
  return grid_;
}

void Drkf::setBelief(const Belief& b, TimeUs t) {
  if (!b.x.allFinite() || !b.P.allFinite()) throw std::invalid_argument("DRKF: belief must be finite");
  belief_ = b;
  timeUs_ = t;
}

bool Drkf::predictShipMotion(TimeUs dtUs) {
  // Linearised afresh every step of at most kShipStepS (longer steps for long gaps, where the restart
  // logic of a replay takes over anyway): the mean by Runge-Kutta, the covariance by Van Loan at the
  // step's start.
  constexpr double kShipStepS = 1.0;
  constexpr int kMaxSteps = 600;
  const double dtS = toSeconds(dtUs);
  const int n = std::clamp(static_cast<int>(std::ceil(dtS / kShipStepS)), 1, kMaxSteps);
  const double h = dtS / n;
  Belief b = belief_;
  for (int i = 0; i < n; ++i) {
    const auto d = process_.discretiseAt(b.x, h);
    const State x = process_.propagate(b.x, h);
    Covariance P = d.Phi.lazyProduct(b.P).lazyProduct(d.Phi.transpose()) + d.Q;
    est::symmetrise(P);
    if (!x.allFinite() || !P.allFinite()) return false;
    b.x = x;
    b.P = P;
  }
  belief_ = b;
  return true;
}

bool Drkf::predictTo(TimeUs t) {
  if (t < timeUs_) return false;
  if (t == timeUs_) return true;
  const TimeUs dtUs = t - timeUs_;
  bool ok = false;
  if (process_.params().ship.enabled) {
    ok = predictShipMotion(dtUs);
  } else if (dtUs <= maxStepUs_) {
    const auto& d = discretisation(dtUs);
    ok = est::predictLinear(belief_, d.Phi, d.Q);
  } else {
    // Van Loan's exponential holds exp(+beta dt) beside exp(-beta dt): past beta dt of a few units
    // its Q is lost to cancellation (a 200 s gap at beta 1 /s gave a covariance that is not positive
    // definite). A long interval is n steps of at most maxStepUs_ and a remainder, composed exactly
    // by binary powering (O(log n) products, so a gap of days costs microseconds).
    const TimeUs n = dtUs / maxStepUs_, rest = dtUs % maxStepUs_;
    const Transition& step = discretisation(maxStepUs_);
    est::Mat<kStateDim> Phi = est::Mat<kStateDim>::Identity(), Q = est::Mat<kStateDim>::Zero();
    est::Mat<kStateDim> basePhi = step.Phi.dense(), baseQ = step.Q;
    for (TimeUs k = n; k > 0; k >>= 1) {
      if (k & 1) {  // append the current power of the step (powers of one step commute)
        Q = basePhi * Q * basePhi.transpose() + baseQ;
        Phi = basePhi * Phi;
      }
      if (k > 1) {
        baseQ = basePhi * baseQ * basePhi.transpose() + baseQ;
        basePhi = basePhi * basePhi;
      }
    }
    if (rest > 0) {
      const Transition& r = discretisation(rest);
      Q = r.Phi.dense() * Q * r.Phi.dense().transpose() + r.Q;
      Phi = r.Phi.dense() * Phi;
    }
    est::symmetrise(Q);
    ok = est::predictLinear(belief_, Phi, Q);
  }
  if (!ok) {
    ++counters_.predictFailures;
    return false;
  }
  timeUs_ = t;
  return true;
}

double Drkf::gateFor(DrkfBlock b, int dim, TimeUs t) const {
  const double gate = gates_[static_cast<std::size_t>(dim)];
  if (gate <= 0.0) return 0.0;
  const bool linearFix = b == kGpsPosition || b == kGpsVelocity || b == kLoranPosition;
  const TimeUs since = rejectedSinceUs_[b];
  if (linearFix && since >= 0 && toSeconds(t - since) >= config_.gateReopenS) return 0.0;
  return gate;
}

double Drkf::linearisableSpeed(bool overGround) const {
  const Covariance& P = belief_.P;
  double a = P(kVelX, kVelX), b = P(kVelX, kVelY), c = P(kVelY, kVelY);
  if (overGround) {  // covariance of (x2 + x3, x6 + x7)
    a += P(kCurX, kCurX) + 2.0 * P(kCurX, kVelX);
    c += P(kCurY, kCurY) + 2.0 * P(kCurY, kVelY);
    b += P(kCurX, kCurY) + P(kCurX, kVelY) + P(kVelX, kCurY);
  }
  const double lambdaMax = est::largestEigenvalue2x2(a, b, c);
  return std::max(config_.minSpeedMps, config_.minSpeedSigmas * std::sqrt(std::max(0.0, lambdaMax)));
}

DrkfUpdateReport Drkf::update(TimeUs t, std::span<const sensors::OwnShipSample> samples) {
  // The guard looks at the covariance before the epoch too (as the last prediction or update left it),
  // so that a covariance broken since the last epoch restarts at this epoch's own fix.
  if (!guard_.diverged()) guard_.checkCovariance<kStateDim>(belief_.P, &modelled_);
  if (guard_.diverged() && t >= timeUs_)
    if (const sensors::GpsSample* fix = usableFix(t, samples)) return restartAt(t, *fix, samples);
  DrkfUpdateReport report = updateEpoch(t, samples);
  watch(report);
  return report;
}

DrkfUpdateReport Drkf::updateEpoch(TimeUs t, std::span<const sensors::OwnShipSample> samples) {
  DrkfUpdateReport report;
  report.timeUs = t;
  if (!predictTo(t)) {
    report.joint.status =
        t < timeUs_ ? est::UpdateStatus::RejectedStale : est::UpdateStatus::RejectedNumerical;
    counters_.staleSamples += t < timeUs_ ? static_cast<long>(samples.size()) : 0;
    return report;
  }
  const geo::GridInfo& g = gridAt(belief_.x[kPosX], belief_.x[kPosY]);
  Epoch epoch = assembleEpoch(t, samples, g);
  // Each block gated on its own NIS, the rest applied in one Joseph-form update (measurement_stack.h).
  report.joint = epoch.stack.apply(belief_);
  report.dim = report.joint.applied() ? report.joint.dim : 0;
  report.blockCount = epoch.stack.blockCount();
  for (int i = 0; i < report.blockCount; ++i)
    report.blocks[static_cast<std::size_t>(i)] = epoch.stack.block(i);
  if (epoch.headingOnly != nullptr && report.blockCount < kMaxBlocksPerEpoch) {
    report.blocks[static_cast<std::size_t>(report.blockCount++)] =
        headingOnlyUpdate(t, *epoch.headingOnly, g);
    if (est::isApplied(report.blocks[static_cast<std::size_t>(report.blockCount - 1)].status)) ++report.dim;
  }
  if (epoch.gnssFix != nullptr) {
    const est::BlockReport* b = report.block(kGpsPosition);
    if (b && est::isApplied(b->status)) adaptGnssNoise(*epoch.gnssFix);
  }
  commitOutcomes(report, t);
  return report;
}

Drkf::Epoch Drkf::assembleEpoch(TimeUs t, std::span<const sensors::OwnShipSample> samples,
                                const geo::GridInfo& g) {
  Epoch epoch;
  epoch.headingOnly = headingOnlySample(t, samples);
  for (const auto& sample : samples) {
    if (sensors::timeOf(sample) != t) {
      ++counters_.staleSamples;
      continue;
    }
    if (epoch.headingOnly != nullptr && std::get_if<sensors::GyroSample>(&sample) == epoch.headingOnly)
      continue;
    addSample(epoch, t, sample, g);
  }
  return epoch;
}

const sensors::GyroSample* Drkf::headingOnlySample(TimeUs t,
                                                   std::span<const sensors::OwnShipSample> samples) const {
  if (!config_.process.ship.enabled) return nullptr;
  const sensors::GyroSample* heading = nullptr;
  for (const auto& sample : samples) {
    if (sensors::timeOf(sample) != t) continue;
    if (std::holds_alternative<sensors::SpeedlogSample>(sample)) return nullptr;  // a log in the epoch
    if (const auto* h = std::get_if<sensors::GyroSample>(&sample); h && !heading) heading = h;
  }
  return heading;
}

void Drkf::addSample(Epoch& epoch, TimeUs t, const sensors::OwnShipSample& sample, const geo::GridInfo& g) {
  std::visit(
      Overloaded{
          [&](const sensors::GpsSample& s) { addGpsFix(epoch, t, s, g); },
          [&](const sensors::LoranSample& s) {  // eq. 7a rows 5-6
            addBlock(epoch.stack, t, kLoranPosition, PositionFixModel(PositionFixModel::Source::LoranC),
                     est::Vec<2>(s.position.xM, s.position.yM), est::Mat<2>::Identity() * s.positionVarM2);
          },
          [&](const sensors::SpeedlogSample& s) {  // eqs. 7c, 7d
            const auto mode = s.mode == sensors::SpeedlogMode::GroundLock ? SpeedlogModel::Mode::GroundLock
                                                                          : SpeedlogModel::Mode::BottomLock;
            const double minSpeed = linearisableSpeed(mode == SpeedlogModel::Mode::GroundLock);
            addBlock(epoch.stack, t, kSpeedlog,
                     SpeedlogModel(mode, minSpeed, config_.process.logScale.sigma > 0.0),
                     est::Vec<1>(g.scale * s.speedMps), est::Mat<1>(g.scale * g.scale * s.varM2PerS2));
          },
          [&](const sensors::GyroSample& s) {  // eq. 7b row 8, of the water velocity (drkf_gyro.h)
            addBlock(epoch.stack, t, kGyro,
                     GyroHeadingModel(linearisableSpeed(false), config_.process.headingBias.sigma > 0.0),
                     est::Vec<1>(wrapTwoPi(s.headingRad - g.convergenceRad)), est::Mat<1>(s.varRad2));
          },
      },
      sample);
}

void Drkf::addGpsFix(Epoch& epoch, TimeUs t, const sensors::GpsSample& s, const geo::GridInfo& g) {
  est::Mat<2> R = est::Mat<2>::Identity() * s.positionVarM2;
  if (config_.adaptiveGnssNoise) {
    R(0, 0) *= gnssScale_.scale(0);
    R(1, 1) *= gnssScale_.scale(1);
    epoch.gnssFix = &s;
  }
  // eq. 7a rows 1-2.
  addBlock(epoch.stack, t, kGpsPosition, PositionFixModel(PositionFixModel::Source::Gps),
           est::Vec<2>(s.position.xM, s.position.yM), R);
  if (s.hasVelocity) {
    // eq. 7b rows 3-4. True east/north to grid: rotate by -convergence, scale by the point scale.
    const double cg = std::cos(g.convergenceRad), sg = std::sin(g.convergenceRad);
    const est::Vec<2> v(g.scale * (s.velEastMps * cg - s.velNorthMps * sg),
                        g.scale * (s.velEastMps * sg + s.velNorthMps * cg));
    addBlock(epoch.stack, t, kGpsVelocity, GroundVelocityModel(), v,
             est::Mat<2>::Identity() * (g.scale * g.scale * s.velocityVarM2PerS2));
  }
}

template <est::StackableMeasurementModel<kStateDim> Model>
void Drkf::addBlock(Stack& stack, TimeUs t, DrkfBlock b, const Model& model, const est::Vec<Model::kDim>& z,
                    const est::Mat<Model::kDim>& R) {
  constexpr int M = Model::kDim;
  const double gate = gateFor(b, M, t);
  const bool forced = gate <= 0.0 && gates_[M] > 0.0;
  if (forced) {
    // Re-anchor: make the prior as uncertain as the fix says it is before applying it ungated.
    const double delta = consistencyInflation(belief_.P, model, belief_.x, z, R);
    const auto [i, j] = b == kGpsVelocity ? std::pair{kVelX, kVelY} : std::pair{kPosX, kPosY};
    belief_.P(i, i) += delta;
    belief_.P(j, j) += delta;
  }
  if (!stack.add(b, model, belief_.x, z, R, gate, forced)) ++counters_.overflowSamples;
}

void Drkf::commitOutcomes(const DrkfUpdateReport& report, TimeUs t) {
  for (int i = 0; i < report.blockCount; ++i) {
    const est::BlockReport& b = report.blocks[static_cast<std::size_t>(i)];
    ++counters_.byStatus[static_cast<std::size_t>(b.tag)][static_cast<std::size_t>(b.status)];
    TimeUs& since = rejectedSinceUs_[static_cast<std::size_t>(b.tag)];
    if (b.status == est::UpdateStatus::RejectedGate) {
      if (since < 0) since = t;
    } else if (est::isApplied(b.status)) {
      since = -1;
    }
  }
}

void Drkf::adaptGnssNoise(const sensors::GpsSample& s) {
  // Variational Bayes for an unknown scale lambda on a known R0 (Sarkka and Nummenmaa 2009, one
  // iteration): with the posterior x+, P+ of this update and a forgetting factor rho,
  //   alpha <- rho alpha + 1/2,   beta <- rho beta + ((z - x+)^2 + P+) / (2 R0),   lambda = beta / alpha,
  // per grid axis. lambda is clamped to [0.25, 100] so that one odd stretch cannot make R absurd.
  const double rho = 1.0 - 1.0 / std::max(2.0, config_.adaptiveWindow);
  const double z[2] = {s.position.xM, s.position.yM};
  const int pos[2] = {kPosX, kPosY};
  for (int a = 0; a < 2; ++a) {
    const auto i = static_cast<std::size_t>(a);
    const double e = z[a] - belief_.x[pos[a]];
    const double term = (e * e + belief_.P(pos[a], pos[a])) / (2.0 * s.positionVarM2);
    if (!std::isfinite(term)) continue;
    gnssScale_.alpha[i] = rho * gnssScale_.alpha[i] + 0.5;
    gnssScale_.beta[i] = rho * gnssScale_.beta[i] + term;
    const double lambda = std::clamp(gnssScale_.scale(a), 0.25, 100.0);
    gnssScale_.beta[i] = lambda * gnssScale_.alpha[i];
  }
}

est::UpdateReport<3> Drkf::updateRadarFix(TimeUs t, const est::Vec<3>& z, const est::Mat<3>& R,
                                          const est::Mat<3>& sensitivity, const est::Vec<3>& assumedMotion) {
  est::UpdateReport<3> rep;
  if (!predictTo(t)) {
    rep.status = t < timeUs_ ? est::UpdateStatus::RejectedStale : est::UpdateStatus::RejectedNumerical;
    return rep;
  }
  const State& x = belief_.x;
  if (std::hypot(x[kVelX], x[kVelY]) >= linearisableSpeed(false)) {
    rep = est::update(belief_,
                      est::drkf::RadarFixModel(sensitivity, assumedMotion, config_.process.ship.enabled), z,
                      R, gates_[3]);
  } else {
    const auto r2 = est::update(belief_,
                                est::drkf::RadarPositionModel(est::Mat<2>(sensitivity.topLeftCorner<2, 2>()),
                                                              est::Vec<2>(assumedMotion.head<2>())),
                                est::Vec<2>(z.head<2>()), est::Mat<2>(R.topLeftCorner<2, 2>()), gates_[2]);
    rep.dim = r2.dim;
    rep.status = r2.status;
    rep.nis = r2.nis;
    rep.gate = r2.gate;
  }
  // The guard judges a radar fix as it does an epoch (a filter it marks diverged restarts at a GNSS fix).
  if (rep.applied() || rep.status == est::UpdateStatus::RejectedGate) guard_.addNis(rep.nis, rep.dim);
  guard_.checkCovariance<kStateDim>(belief_.P, &modelled_);
  return rep;
}

est::Vec<4> groundStateOf(const Belief& b) {
  const State& x = b.x;
  return {x[kPosX], x[kPosY], groundVx(x), groundVy(x)};
}

est::Mat<4> groundCovarianceOf(const Belief& b) {
  est::MatRC<4, kStateDim> J = est::MatRC<4, kStateDim>::Zero();
  J(0, kPosX) = 1.0;
  J(1, kPosY) = 1.0;
  J(2, kCurX) = J(2, kVelX) = 1.0;
  J(3, kCurY) = J(3, kVelY) = 1.0;
  est::Mat<4> C = J * b.P * J.transpose();
  est::symmetrise(C);
  return C;
}

}  // namespace reckoner::nav
