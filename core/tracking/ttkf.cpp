#include "tracking/ttkf.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <stdexcept>

#include "common/angles.h"
#include "estimation/chi_square.h"

namespace reckoner::track {
namespace {
constexpr int kN = tk::kStateDim;
constexpr int kV = tk::kOwnDim;       // own position and velocity
constexpr int kR = kN - tk::kOwnDim;  // the rest

double gateOf(double p) {
  if (!(p >= 0.0 && p < 1.0)) throw std::invalid_argument("TTKF: gate probability must lie in [0, 1)");
  return p > 0.0 ? est::chiSquareQuantile(p, 2.0) : 0.0;
}
}  // namespace

namespace {
std::atomic<std::uint64_t> contextGeneration{0};
}

TtkfContext::TtkfContext(const TtkfConfig& c)
    : config(c), process(c.process), radarGate(gateOf(c.gateProbability)), generation_(++contextGeneration) {
  if (!(c.minRangeM >= 0.0) || !(c.initialSpeedSdMps > 0.0))
    throw std::invalid_argument("TTKF: min range must be >= 0 and initial speed sd > 0");
}

const tk::ProcessModel::Discrete& TtkfContext::discrete(TimeUs dt) const {
  struct Entry {
    const TtkfContext* owner = nullptr;
    std::uint64_t generation = 0;
    TimeUs dt = -1;
    tk::ProcessModel::Discrete d;
  };
  // A context may be destroyed and another built at the same address: entries carry the generation
  // of the context that wrote them.
  thread_local std::array<Entry, 4> memo;
  thread_local std::size_t next = 0;
  for (const Entry& e : memo)
    if (e.owner == this && e.generation == generation_ && e.dt == dt) return e.d;
  Entry& e = memo[next];
  next = (next + 1) % memo.size();
  e = {this, generation_, dt, process.discretise(toSeconds(dt))};
  return e.d;
}

GridPlot toGrid(const sensors::RadarPlot& p, const geo::GridInfo& grid) {
  return {p.timeUs, grid.scale * p.rangeM, wrapTwoPi(p.bearingRad - grid.convergenceRad),
          grid.scale * grid.scale * p.rangeVarM2, p.bearingVarRad2};
}

Ttkf::Ttkf(std::shared_ptr<const TtkfContext> ctx, const tk::Belief& initial, TimeUs t0)
    : ctx_(std::move(ctx)), belief_(initial), timeUs_(t0) {
  if (!initial.x.allFinite() || !est::isPositiveDefinite(initial.P))
    throw std::invalid_argument("TTKF: initial state must be finite with a positive definite covariance");
}

Ttkf Ttkf::initiate(std::shared_ptr<const TtkfContext> ctx, const OwnShipInput& own, const GridPlot& plot) {
  const auto& p = ctx->config.process;
  tk::Belief b;
  b.x.setZero();
  b.x.head<kV>() = own.x;
  b.P.setZero();
  b.P.topLeftCorner<kV, kV>() = own.P;
  const double ownA2 = std::max(p.ownAcceleration.sigma * p.ownAcceleration.sigma, 1e-12);
  b.P(tk::kOwnAx, tk::kOwnAx) = b.P(tk::kOwnAy, tk::kOwnAy) = ownA2;
  // Placeholder target (uncorrelated, unit variance) while own ship is carried to the plot time.
  for (int i = tk::kTgtX; i < kN; ++i) b.P(i, i) = 1.0;
  const auto& d = ctx->discrete(std::max<TimeUs>(0, plot.timeUs - own.timeUs));
  est::predictLinear<kN>(b, d.Phi, d.Q);

  // Target = own position + polar offset: covariance of own position plus the converted plot's.
  const double s = std::sin(plot.bearingRad), c = std::cos(plot.bearingRad), r = plot.rangeM;
  est::Mat<2> J;  // d(dx, dy) / d(range, bearing)
  J << s, r * c, c, -r * s;
  const est::Mat<2> Rpolar = est::Vec<2>(plot.rangeVarM2, plot.bearingVarRad2).asDiagonal();
  const est::Mat<2> Rxy = J * Rpolar * J.transpose();
  b.x[tk::kTgtX] = b.x[tk::kOwnX] + r * s;
  b.x[tk::kTgtY] = b.x[tk::kOwnY] + r * c;
  b.x.tail<4>().setZero();
  b.P.bottomRows<6>().setZero();
  b.P.rightCols<6>().setZero();
  // Cross-covariance with everything own-ship: target position inherits own position's.
  b.P.block<2, 6>(tk::kTgtX, 0) = b.P.block<2, 6>(tk::kOwnX, 0);
  b.P.block<6, 2>(0, tk::kTgtX) = b.P.block<6, 2>(0, tk::kOwnX);
  b.P.block<2, 2>(tk::kTgtX, tk::kTgtX) = b.P.block<2, 2>(tk::kOwnX, tk::kOwnX) + Rxy;
  const double v2 = ctx->config.initialSpeedSdMps * ctx->config.initialSpeedSdMps;
  b.P(tk::kTgtVx, tk::kTgtVx) = b.P(tk::kTgtVy, tk::kTgtVy) = v2;
  const double a2 = p.targetAcceleration.sigma * p.targetAcceleration.sigma;
  b.P(tk::kTgtAx, tk::kTgtAx) = b.P(tk::kTgtAy, tk::kTgtAy) = std::max(a2, 1e-12);
  est::symmetrise(b.P);
  return Ttkf(std::move(ctx), b, plot.timeUs);
}

bool Ttkf::predictTo(TimeUs t) {
  if (t < timeUs_) return false;
  if (t == timeUs_) return true;
  const auto& d = ctx_->discrete(t - timeUs_);
  if (!est::predictLinear<kN>(belief_, d.Phi, d.Q)) return false;
  timeUs_ = t;
  return true;
}

est::UpdateReport<4> Ttkf::feedOwnShip(const OwnShipInput& own) {
  est::UpdateReport<4> rep;
  if (!predictTo(own.timeUs)) {
    rep.status =
        own.timeUs < timeUs_ ? est::UpdateStatus::RejectedStale : est::UpdateStatus::RejectedNumerical;
    return rep;
  }
  if (ctx_->config.feed == OwnShipFeed::Measurement)
    return est::update(belief_, tk::OwnShipModel(), own.x, own.P, 0.0);
  return replaceOwnShipMarginal(own);
}

est::UpdateReport<4> Ttkf::replaceOwnShipMarginal(const OwnShipInput& own) {
  // Joint [v; r] with v the own-ship position and velocity. Keep p(r | v), set p(v) = N(z, C):
  //   K = P_rv P_vv^-1,  x_r += K (z - x_v),  P_rr = P_rr - K P_vr + K C K^T,  P_rv = K C,  P_vv = C.
  est::UpdateReport<4> rep;
  rep.dim = kV;
  const est::Vec<kV> y = own.x - belief_.x.head<kV>();
  rep.innovation = y;
  if (!own.x.allFinite() || !own.P.allFinite()) {
    rep.status = est::UpdateStatus::RejectedNonFinite;
    return rep;
  }
  const est::Mat<kV> Pvv = belief_.P.topLeftCorner<kV, kV>();
  const Eigen::Matrix<double, kR, kV> Prv = belief_.P.bottomLeftCorner<kR, kV>();
  rep.S = Pvv + own.P;
  const Eigen::LDLT<est::Mat<kV>> ldlt(Pvv);
  const Eigen::LDLT<est::Mat<kV>> sLdlt(Pvv + own.P);
  if (!est::ldltPositiveDefinite(ldlt) || !est::ldltPositiveDefinite(sLdlt)) {
    rep.status = est::UpdateStatus::RejectedNumerical;
    return rep;
  }
  rep.nis = y.dot(sLdlt.solve(y));
  const Eigen::Matrix<double, kR, kV> K = ldlt.solve(Prv.transpose()).transpose();
  tk::Belief next = belief_;
  next.x.head<kV>() = own.x;
  next.x.tail<kR>() += K * y;
  const Eigen::Matrix<double, kR, kV> KC = K * own.P;
  est::Mat<kR> Prr = belief_.P.bottomRightCorner<kR, kR>() - K * Prv.transpose() + KC * K.transpose();
  est::symmetrise(Prr);
  next.P.topLeftCorner<kV, kV>() = own.P;
  next.P.bottomLeftCorner<kR, kV>() = KC;
  next.P.topRightCorner<kV, kR>() = KC.transpose();
  next.P.bottomRightCorner<kR, kR>() = Prr;
  if (!next.x.allFinite() || !next.P.allFinite()) {
    rep.status = est::UpdateStatus::RejectedNumerical;
    return rep;
  }
  belief_ = next;
  rep.status = est::UpdateStatus::Accepted;
  return rep;
}

est::UpdateReport<2> Ttkf::updateRadar(const GridPlot& plot, RadarDetail* detail) {
  est::UpdateReport<2> rep;
  if (!predictTo(plot.timeUs)) {
    rep.status =
        plot.timeUs < timeUs_ ? est::UpdateStatus::RejectedStale : est::UpdateStatus::RejectedNumerical;
    return rep;
  }
  const tk::RadarModel model(ctx_->config.minRangeM);
  if (model.degenerate(belief_.x)) {
    rep.status = est::UpdateStatus::RejectedDegenerate;
    return rep;
  }
  const est::Mat<2> R = est::Vec<2>(plot.rangeVarM2, plot.bearingVarRad2).asDiagonal();
  if (detail) {
    detail->priorP = belief_.P;
    detail->H = model.jacobian(belief_.x);
  }
  return est::update(belief_, model, est::Vec<2>(plot.rangeM, plot.bearingRad), R, ctx_->radarGate);
}

est::UpdateReport<4> Ttkf::updateTargetState(TimeUs t, const est::Vec<4>& z, const est::Mat<4>& R,
                                             double gate, double adaptNis) {
  est::UpdateReport<4> rep;
  if (!predictTo(t)) {
    rep.status = t < timeUs_ ? est::UpdateStatus::RejectedStale : est::UpdateStatus::RejectedNumerical;
    return rep;
  }
  est::BMatRows<4, kN> H = est::BMatRows<4, kN>::Zero(4, kN);
  constexpr std::array<int, 4> kRows{tk::kTgtX, tk::kTgtY, tk::kTgtVx, tk::kTgtVy};
  est::BVec<4> y(4);
  for (int r = 0; r < 4; ++r) {
    H(r, kRows[static_cast<std::size_t>(r)]) = 1.0;
    y[r] = z[r] - belief_.x[kRows[static_cast<std::size_t>(r)]];
  }
  const est::BMat<4> Rb = R;
  if (adaptNis > 0.0) {
    tk::Belief trial = belief_;
    const auto probe = est::updateJoseph<kN, 4>(trial, y, H, Rb, 0.0);
    if (probe.status == est::UpdateStatus::Accepted && probe.nis > adaptNis) {
      const double scale = std::sqrt(std::min(100.0, probe.nis / 4.0));
      for (int i : {tk::kTgtVx, tk::kTgtVy, tk::kTgtAx, tk::kTgtAy}) {
        belief_.P.row(i) *= scale;
        belief_.P.col(i) *= scale;
      }
    }
  }
  return est::updateJoseph<kN, 4>(belief_, y, H, Rb, gate);
}

void Ttkf::restartTargetAcceleration() {
  const double sigma = ctx_->config.process.targetAcceleration.sigma;
  for (int i : {tk::kTgtAx, tk::kTgtAy}) {
    belief_.x[i] = 0.0;
    belief_.P.row(i).setZero();
    belief_.P.col(i).setZero();
    belief_.P(i, i) = std::max(sigma * sigma, 1e-12);
  }
}

bool Ttkf::correct(const tk::State& dx, const tk::Covariance& dP) {
  tk::Belief b = belief_;
  b.x += dx;
  b.P += dP;
  est::symmetrise(b.P);
  if (!b.x.allFinite() || !b.P.allFinite()) return false;
  belief_ = b;
  return true;
}

}  // namespace reckoner::track
