#include <QTest>

#include "support/drkf_fixtures.h"

#include <Eigen/Eigenvalues>

#include "common/rng.h"
#include "estimation/ekf.h"
#include "estimation/measurement_stack.h"
#include "estimation/sparse_transition.h"
#include "support/compare_near.h"

using namespace reckoner;
using namespace reckoner::est;

namespace {
/// z = x[i] (one row), for stack tests.
template <int N>
struct PickModel {
  static constexpr int kDim = 1;
  int i = 0;
  bool degen = false;
  Vec<1> h(const Vec<N>& x) const { return Vec<1>(x[i]); }
  MatRC<1, N> jacobian(const Vec<N>&) const {
    MatRC<1, N> H = MatRC<1, N>::Zero();
    H(0, i) = 1.0;
    return H;
  }
  Vec<1> residual(const Vec<1>& z, const Vec<1>& zh) const { return z - zh; }
  bool degenerate(const Vec<N>&) const { return degen; }
};
static_assert(StackableMeasurementModel<PickModel<3>, 3>);
static_assert(!MeasurementModel<PickModel<3>, 2>);  // its Jacobian has three columns

double minEigen(const Mat<3>& P) {
  return Eigen::SelfAdjointEigenSolver<Mat<3>>(P).eigenvalues().minCoeff();
}
}  // namespace

class TestEkf : public QObject {
  Q_OBJECT
 private slots:
  void largestEigenvalueOf2x2MatchesEigen() {
    // GIVEN random symmetric positive semi-definite 2 x 2 matrices (and a diagonal and a degenerate one)
    // WHEN the closed form is compared with Eigen's solver THEN they agree to 1e-12 relative.
    Rng rng(7, 7);
    std::vector<Mat<2>> cases{Mat<2>::Identity(), (Mat<2>() << 4.0, 0.0, 0.0, 1.0).finished(),
                              (Mat<2>() << 1.0, 1.0, 1.0, 1.0).finished()};
    for (int k = 0; k < 100; ++k) {
      Mat<2> A;
      A << rng.normal(), rng.normal(), rng.normal(), rng.normal();
      cases.push_back(A * A.transpose());
    }
    for (const Mat<2>& P : cases) {
      const double expected = Eigen::SelfAdjointEigenSolver<Mat<2>>(P).eigenvalues().maxCoeff();
      RK_COMPARE_NEAR(largestEigenvalue(P), expected, 1e-12 * std::max(1.0, expected));
    }
  }
  void scalarUpdateMatchesClosedForm() {
    // Second state uncorrelated and unmeasured: the first behaves as a scalar filter.
    Gaussian<2> g;
    g.x << 2.0, -1.0;
    g.P << 4.0, 0.0, 0.0, 9.0;
    const auto rep = update(g, PickModel<2>{0}, Vec<1>(5.0), Mat<1>(1.0), 0.0);
    QVERIFY(rep.applied());
    RK_COMPARE_NEAR(g.x[0], 2.0 + 4.0 / 5.0 * 3.0, 1e-12);
    RK_COMPARE_NEAR(g.P(0, 0), 4.0 * 1.0 / 5.0, 1e-12);
    QCOMPARE(g.x[1], -1.0);
    QCOMPARE(g.P(1, 1), 9.0);
    RK_COMPARE_NEAR(rep.nis, 9.0 / 5.0, 1e-12);
    QCOMPARE(rep.dim, 1);
    RK_COMPARE_NEAR(rep.S(0, 0), 5.0, 1e-12);
  }
  void josephKeepsCovariancePositiveWhenIllConditioned() {
    // Near-perfect measurements of a strongly correlated state: the simple P - K H P form loses
    // positive definiteness here; the Joseph form must not.
    Gaussian<3> g;
    g.x.setZero();
    g.P << 1e6, 999999.0, 0.0, 999999.0, 1e6, 0.0, 0.0, 0.0, 1.0;
    Rng rng(5, 5);
    for (int k = 0; k < 200; ++k) {
      const auto rep = update(g, PickModel<3>{k % 2}, Vec<1>(rng.normal(0.0, 1e-6)), Mat<1>(1e-12), 0.0);
      QVERIFY(rep.applied());
      QVERIFY((g.P - g.P.transpose()).norm() == 0.0);
      QVERIFY2(minEigen(g.P) > -1e-18, qPrintable(QString::number(minEigen(g.P))));
    }
  }
  void nonFiniteInputLeavesStateUnchanged() {
    Gaussian<2> g;
    g.x << 1.0, 2.0;
    const Gaussian<2> before = g;
    auto rep = update(g, PickModel<2>{0}, Vec<1>(std::nan("")), Mat<1>(1.0), 0.0);
    QCOMPARE(rep.status, UpdateStatus::RejectedNonFinite);
    rep = update(g, PickModel<2>{0}, Vec<1>(1.0), Mat<1>(std::numeric_limits<double>::infinity()), 0.0);
    QCOMPARE(rep.status, UpdateStatus::RejectedNonFinite);
    QVERIFY(g.x == before.x && g.P == before.P);
  }
  void nonPositiveInnovationCovarianceIsRejected() {
    Gaussian<2> g;
    const Gaussian<2> before = g;
    const auto rep = update(g, PickModel<2>{0}, Vec<1>(1.0), Mat<1>(-5.0), 0.0);
    QCOMPARE(rep.status, UpdateStatus::RejectedNumerical);
    QVERIFY(g.x == before.x && g.P == before.P);
  }
  void gateRejectsOutlierAndReportsNis() {
    Gaussian<2> g;
    const Gaussian<2> before = g;
    const auto rep = update(g, PickModel<2>{1}, Vec<1>(10.0), Mat<1>(1.0), 9.0);
    QCOMPARE(rep.status, UpdateStatus::RejectedGate);
    RK_COMPARE_NEAR(rep.nis, 50.0, 1e-12);  // 10^2 / (1 + 1)
    QCOMPARE(rep.gate, 9.0);
    QVERIFY(g.x == before.x && g.P == before.P);
  }
  void neesUsesTheFullCovariance() {
    Mat<2> P;
    P << 4.0, 1.0, 1.0, 2.0;
    const Vec<2> e(1.0, -1.0);
    RK_COMPARE_NEAR(nees<2>(e, P), e.dot(P.inverse() * e), 1e-12);
    QVERIFY(std::isnan(nees<2>(e, Mat<2>::Zero())));
  }
  void predictRejectsNonFinite() {
    Gaussian<2> g;
    const Gaussian<2> before = g;
    Mat<2> Phi = Mat<2>::Identity();
    Phi(0, 1) = std::numeric_limits<double>::infinity();
    QVERIFY(!predictLinear<2>(g, Phi, Mat<2>::Zero()));
    QVERIFY(g.x == before.x && g.P == before.P);
  }
  void nonlinearPredictUsesTheModelsJacobian() {
    // A 2-state model x0' = x0 + dt sin(x1), x1' = x1: f for the mean, its Jacobian for the covariance.
    struct Pendulumish {
      Vec<2> f(const Vec<2>& x, double dt) const { return {x[0] + dt * std::sin(x[1]), x[1]}; }
      Mat<2> transition(const Vec<2>& x, double dt) const {
        Mat<2> F;
        F << 1.0, dt * std::cos(x[1]), 0.0, 1.0;
        return F;
      }
      Mat<2> noise(double dt) const { return Mat<2>::Identity() * 0.01 * dt; }
    };
    static_assert(ProcessModel<Pendulumish, 2>);
    Gaussian<2> g;
    g.x << 1.0, 0.5;
    g.P << 0.2, 0.05, 0.05, 0.1;
    const Pendulumish m;
    const Mat<2> F = m.transition(g.x, 2.0);
    const Mat<2> expectedP = F * g.P * F.transpose() + m.noise(2.0);
    QVERIFY(predict(g, m, 2.0));
    RK_COMPARE_NEAR(g.x[0], 1.0 + 2.0 * std::sin(0.5), 1e-15);
    QVERIFY((g.P - expectedP).norm() < 1e-15);
  }
  void sparseTransitionMatchesDense() {
    Rng rng(9, 9);
    Mat<6> Phi = Mat<6>::Zero();
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        if ((i + 2 * j) % 3 != 0) Phi(i, j) = rng.normal();
    Mat<6> L;
    for (int i = 0; i < 36; ++i) L(i) = rng.normal();
    Gaussian<6> dense, sparse;
    dense.P = sparse.P = L * L.transpose() + Mat<6>::Identity();
    for (int i = 0; i < 6; ++i) dense.x[i] = sparse.x[i] = rng.normal();
    const Mat<6> Q = Mat<6>::Identity() * 0.3;
    const SparseTransition<6> sp(Phi);
    QVERIFY(sp.nonZeros() < 36);
    QVERIFY(predictLinear<6>(dense, Phi, Q));
    QVERIFY(predictLinear<6>(sparse, sp, Q));
    QVERIFY((dense.x - sparse.x).norm() < 1e-12);
    QVERIFY((dense.P - sparse.P).norm() < 1e-10 * dense.P.norm());
  }
  void stackOfIndependentBlocksEqualsSequentialUpdates() {
    Gaussian<3> batch;
    batch.x << 1.0, 2.0, 3.0;
    batch.P << 2.0, 0.5, 0.1, 0.5, 3.0, 0.2, 0.1, 0.2, 1.5;
    Gaussian<3> seq = batch;
    MeasurementStack<3, 4> stack;
    QVERIFY(stack.add(0, PickModel<3>{0}, batch.x, Vec<1>(1.5), Mat<1>(0.5), 0.0));
    QVERIFY(stack.add(1, PickModel<3>{2}, batch.x, Vec<1>(2.0), Mat<1>(0.2), 0.0));
    const auto rep = stack.apply(batch);
    QVERIFY(rep.applied());
    QCOMPARE(rep.dim, 2);
    update(seq, PickModel<3>{0}, Vec<1>(1.5), Mat<1>(0.5), 0.0);
    update(seq, PickModel<3>{2}, Vec<1>(2.0), Mat<1>(0.2), 0.0);
    QVERIFY((batch.x - seq.x).norm() < 1e-12);
    QVERIFY((batch.P - seq.P).norm() < 1e-12);
  }
  void stackDropsOnlyTheBlockThatFailsItsGate() {
    Gaussian<3> g;
    g.x.setZero();
    Gaussian<3> onlyGood = g;
    MeasurementStack<3, 4> stack;
    stack.add(10, PickModel<3>{0}, g.x, Vec<1>(0.5), Mat<1>(1.0), 6.63);   // NIS 0.125
    stack.add(11, PickModel<3>{1}, g.x, Vec<1>(40.0), Mat<1>(1.0), 6.63);  // NIS 800: outlier
    PickModel<3> degenerate{2};
    degenerate.degen = true;
    stack.add(12, degenerate, g.x, Vec<1>(0.0), Mat<1>(1.0), 6.63);
    stack.add(13, PickModel<3>{2}, g.x, Vec<1>(std::nan("")), Mat<1>(1.0), 6.63);
    const auto rep = stack.apply(g);
    QCOMPARE(rep.dim, 1);
    QCOMPARE(stack.block(0).status, UpdateStatus::Accepted);
    QCOMPARE(stack.block(1).status, UpdateStatus::RejectedGate);
    RK_COMPARE_NEAR(stack.block(1).nis, 800.0, 1e-9);
    QCOMPARE(stack.block(2).status, UpdateStatus::RejectedDegenerate);
    QCOMPARE(stack.block(3).status, UpdateStatus::RejectedNonFinite);
    update(onlyGood, PickModel<3>{0}, Vec<1>(0.5), Mat<1>(1.0), 0.0);
    QVERIFY((g.x - onlyGood.x).norm() < 1e-12 && (g.P - onlyGood.P).norm() < 1e-12);
  }
  void stackReportsForcedBlocks() {
    Gaussian<2> g;
    MeasurementStack<2, 2> stack;
    stack.add(0, PickModel<2>{0}, g.x, Vec<1>(100.0), Mat<1>(1.0), 0.0, true);
    stack.apply(g);
    QCOMPARE(stack.block(0).status, UpdateStatus::AcceptedForced);
  }
  void stackRefusesOverflow() {
    Gaussian<2> g;
    MeasurementStack<2, 1, 1> stack;
    QVERIFY(stack.add(0, PickModel<2>{0}, g.x, Vec<1>(1.0), Mat<1>(1.0), 0.0));
    QVERIFY(!stack.add(1, PickModel<2>{1}, g.x, Vec<1>(1.0), Mat<1>(1.0), 0.0));
    QCOMPARE(stack.blockCount(), 1);
  }
};

QTEST_APPLESS_MAIN(TestEkf)
#include "tst_ekf.moc"
