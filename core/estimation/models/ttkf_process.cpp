#include "estimation/models/ttkf_process.h"

#include <array>
#include <stdexcept>

#include "estimation/singer.h"

namespace reckoner::est::ttkf {
namespace {
struct Axis {
  int p, v, a;
  bool target;
};
constexpr std::array<Axis, 4> kAxes{{{kOwnX, kOwnVx, kOwnAx, false},
                                     {kOwnY, kOwnVy, kOwnAy, false},
                                     {kTgtX, kTgtVx, kTgtAx, true},
                                     {kTgtY, kTgtVy, kTgtAy, true}}};
}  // namespace

ProcessModel::ProcessModel(const ProcessParams& p) : params_(p) {
  if (!p.ownAcceleration.valid() || !p.targetAcceleration.valid())
    throw std::invalid_argument("TTKF process model: accelerations need sigma >= 0 and beta > 0");
}

ProcessModel::Discrete ProcessModel::discretise(double dtS) const {
  const SingerAxis own = singerDiscretisation(params_.ownAcceleration, dtS);
  const SingerAxis tgt = singerDiscretisation(params_.targetAcceleration, dtS);
  Mat<kStateDim> Phi = Mat<kStateDim>::Zero();
  Covariance Q = Covariance::Zero();
  for (const Axis& ax : kAxes) {
    const SingerAxis& s = ax.target ? tgt : own;
    const std::array<int, 3> idx{ax.p, ax.v, ax.a};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        Phi(idx[i], idx[j]) = s.Phi(i, j);
        Q(idx[i], idx[j]) = s.Q(i, j);
      }
    }
  }
  return {SparseTransition<kStateDim>(Phi), Q};
}

Mat<kStateDim> ProcessModel::F() const {
  Mat<kStateDim> F = Mat<kStateDim>::Zero();
  for (const Axis& ax : kAxes) {
    F(ax.p, ax.v) = 1.0;
    F(ax.v, ax.a) = 1.0;
    F(ax.a, ax.a) = -(ax.target ? params_.targetAcceleration : params_.ownAcceleration).betaPerS;
  }
  return F;
}

MatRC<kStateDim, kNoiseDim> ProcessModel::G() const {
  MatRC<kStateDim, kNoiseDim> G = MatRC<kStateDim, kNoiseDim>::Zero();
  for (int k = 0; k < 4; ++k)
    G(kAxes[static_cast<std::size_t>(k)].a, k) =
        (kAxes[static_cast<std::size_t>(k)].target ? params_.targetAcceleration : params_.ownAcceleration)
            .alpha();
  return G;
}

}  // namespace reckoner::est::ttkf
