#pragma once
// What the EKF algebra requires of the models it is templated on (docs/models.md), as C++20 concepts:
// est::predict takes a ProcessModel, est::update a MeasurementModel, MeasurementStack::add a
// StackableMeasurementModel. A model that lacks a member, or returns the wrong shape, fails at the
// call with the concept and the missing expression named. N is the filter's state dimension (the
// Gaussian<N> the model is applied to); a measurement model declares its own dimension kDim.
// Semantics the compiler cannot check (angle residuals wrapped to (-pi, pi], the Jacobian matching h)
// are the models' tests' job.
#include <concepts>
#include <type_traits>

#include "estimation/gaussian.h"

namespace reckoner::est {

/// An Eigen matrix (or expression) of fixed shape Rows x Cols.
template <class T, int Rows, int Cols>
concept FixedShape = (static_cast<int>(std::remove_cvref_t<T>::RowsAtCompileTime) == Rows) &&
                     (static_cast<int>(std::remove_cvref_t<T>::ColsAtCompileTime) == Cols);

/// A model that declares its measurement dimension: static constexpr int kDim >= 1.
template <class M>
concept HasMeasurementDim = requires {
  { M::kDim } -> std::convertible_to<int>;
}
&&(M::kDim >= 1);

/// A measurement model of a state of dimension N (est::update, ekf.h):
///   h(x)              the predicted measurement, kDim x 1 (angles in [0, 2 pi));
///   jacobian(x)       dh/dx at x, kDim x N;
///   residual(z, zhat) z - zhat with angle components wrapped to (-pi, pi], kDim x 1.
/// All const: models are stateless during an update.
template <class M, int N>
concept MeasurementModel = HasMeasurementDim<M> &&
    requires(const M& model, const Vec<N>& x, const Vec<M::kDim>& z, const Vec<M::kDim>& zhat) {
  { model.h(x) } -> FixedShape<M::kDim, 1>;
  { model.jacobian(x) } -> FixedShape<M::kDim, N>;
  { model.residual(z, zhat) } -> FixedShape<M::kDim, 1>;
};

/// A measurement model a MeasurementStack can carry (MeasurementStack::add, measurement_stack.h): also
///   degenerate(x)     true where the model cannot be linearised (a heading at zero speed, a range
///                     at zero distance); the block is then reported RejectedDegenerate.
template <class M, int N>
concept StackableMeasurementModel = MeasurementModel<M, N> && requires(const M& model, const Vec<N>& x) {
  { model.degenerate(x) } -> std::convertible_to<bool>;
};

/// A nonlinear process model of a state of dimension N (est::predict, ekf.h), over a step of dtS >= 0 s:
///   f(x, dtS)           the mean carried over the step, N x 1;
///   transition(x, dtS)  df/dx at x (Phi), N x N;
///   noise(dtS)          the process noise Q added over the step, N x N.
/// The DRKF and TTKF process models (models/drkf_process.h, ttkf_process.h) are linear and discretised
/// exactly: their filters call predictLinear with the model's discretise(), not est::predict.
template <class P, int N>
concept ProcessModel = requires(const P& model, const Vec<N>& x, double dtS) {
  { model.f(x, dtS) } -> FixedShape<N, 1>;
  { model.transition(x, dtS) } -> FixedShape<N, N>;
  { model.noise(dtS) } -> FixedShape<N, N>;
};

}  // namespace reckoner::est
