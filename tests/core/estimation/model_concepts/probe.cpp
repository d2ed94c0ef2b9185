// Compiled by expect_compile_error.cmake (ctest model_concepts_*), never linked: a complete measurement
// model passed to est::update and MeasurementStack::add, and the same model with one member left out
// (-DPROBE_WITHOUT_JACOBIAN, -DPROBE_WITHOUT_RESIDUAL), which must not compile, with a message naming
// the concept and the missing member. Likewise a process model without transition() for est::predict.
#include "estimation/ekf.h"
#include "estimation/measurement_stack.h"

namespace probe {
using namespace reckoner::est;

/// z = x[0], of a two-state filter.
struct PositionProbe {
  static constexpr int kDim = 1;
  [[nodiscard]] Vec<1> h(const Vec<2>& x) const { return Vec<1>(x[0]); }
#ifndef PROBE_WITHOUT_JACOBIAN
  [[nodiscard]] MatRC<1, 2> jacobian(const Vec<2>&) const {
    return MatRC<1, 2>(1.0, 0.0);
  }
#endif
#ifndef PROBE_WITHOUT_RESIDUAL
  [[nodiscard]] Vec<1> residual(const Vec<1>& z, const Vec<1>& zhat) const {
    return z - zhat;
  }
#endif
  [[nodiscard]] bool degenerate(const Vec<2>&) const {
    return false;
  }
};

/// x0' = x0 + dt x1, x1' = x1.
struct DriftProbe {
  [[nodiscard]] Vec<2> f(const Vec<2>& x, double dtS) const { return {x[0] + dtS * x[1], x[1]}; }
#ifndef PROBE_WITHOUT_TRANSITION
  [[nodiscard]] Mat<2> transition(const Vec<2>&, double dtS) const {
    Mat<2> F = Mat<2>::Identity();
    F(0, 1) = dtS;
    return F;
  }
#endif
  [[nodiscard]] Mat<2> noise(double dtS) const {
    return Mat<2>::Identity() * dtS;
  }
};

UpdateReport<1> updateWith(Gaussian<2>& g) {
  return update(g, PositionProbe{}, Vec<1>(1.0), Mat<1>(1.0), 0.0);
}

bool stackWith(const Gaussian<2>& g) {
  MeasurementStack<2, 2> stack;
  return stack.add(0, PositionProbe{}, g.x, Vec<1>(1.0), Mat<1>(1.0), 0.0);
}

bool predictWith(Gaussian<2>& g) {
  return predict(g, DriftProbe{}, 1.0);
}

}  // namespace probe
