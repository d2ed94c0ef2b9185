#include <QTest>

#include <Eigen/Eigenvalues>
#include <unsupported/Eigen/MatrixFunctions>

#include "common/rng.h"
#include "estimation/discretize.h"
#include "estimation/gauss_markov.h"
#include "estimation/models/drkf_process.h"
#include "support/compare_near.h"

using namespace reckoner;
using namespace reckoner::est;

class TestGaussMarkov : public QObject {
  Q_OBJECT
 private slots:
  void scalarVanLoanEqualsPaperClosedForm() {
    // Seed 000 eqs. 2a and 2b.
    for (double beta : {0.05, 0.17, 1.0, 4.0}) {
      for (double dt : {0.01, 0.1, 1.0, 2.0, 30.0}) {
        const GaussMarkov gm{0.7, beta};
        const auto d = discretiseVanLoan<1, 1>(Mat<1>(-beta), MatRC<1, 1>(gm.alpha()), dt);
        RK_COMPARE_NEAR(d.Phi(0, 0), gm.phi(dt), 1e-13);
        RK_COMPARE_NEAR(d.Q(0, 0), gm.discreteVariance(dt), 1e-12 * std::max(1.0, d.Q(0, 0)));
      }
    }
  }
  void integratedGaussMarkovEqualsClosedForm() {
    // v' = a, a' = -beta a + alpha w: the velocity/acceleration block of the DRKF.
    const double sigma = 0.5, beta = 1.3, dt = 1.7;
    const GaussMarkov gm{sigma, beta};
    Mat<2> F;
    F << 0, 1, 0, -beta;
    MatRC<2, 1> G(0.0, gm.alpha());
    const auto d = discretiseVanLoan<2, 1>(F, G, dt);
    const double e1 = std::exp(-beta * dt), e2 = std::exp(-2 * beta * dt), a2 = gm.alpha() * gm.alpha();
    RK_COMPARE_NEAR(d.Phi(0, 1), (1 - e1) / beta, 1e-13);
    RK_COMPARE_NEAR(d.Q(1, 1), sigma * sigma * (1 - e2), 1e-13);
    RK_COMPARE_NEAR(d.Q(0, 1), a2 / beta * ((1 - e1) / beta - (1 - e2) / (2 * beta)), 1e-12);
    RK_COMPARE_NEAR(d.Q(0, 0), a2 / (beta * beta) * (dt - 2 * (1 - e1) / beta + (1 - e2) / (2 * beta)),
                    1e-12);
  }
  void vanLoanAgreesWithMonteCarlo() {
    // GIVEN the DRKF's per-axis block [position, current, velocity, acceleration] WHEN the continuous
    // system is simulated finely from zero over one step THEN the sample covariance matches Q.
    const GaussMarkov cur{0.55, 0.17}, acc{0.5, 1.0};
    Mat<4> F = Mat<4>::Zero();
    F(0, 1) = F(0, 2) = 1;
    F(1, 1) = -cur.betaPerS;
    F(2, 3) = 1;
    F(3, 3) = -acc.betaPerS;
    MatRC<4, 2> G = MatRC<4, 2>::Zero();
    G(1, 0) = cur.alpha();
    G(3, 1) = acc.alpha();
    const double dt = 1.0;
    const auto d = discretiseVanLoan<4, 2>(F, G, dt);

    // Euler-Maruyama integration of dx = F x dt + G dW, independent of Van Loan (bias O(h) ~ 0.3%).
    constexpr int kSamples = 20000, kSub = 400;
    const double h = dt / kSub, sqrtH = std::sqrt(h);
    Rng rng(11, 1);
    Mat<4> C = Mat<4>::Zero();
    for (int s = 0; s < kSamples; ++s) {
      Vec<4> x = Vec<4>::Zero();
      for (int k = 0; k < kSub; ++k) {
        const Vec<2> w(rng.normal(), rng.normal());
        x += (F * x) * h + G * (sqrtH * w);
      }
      C += x * x.transpose();
    }
    C /= kSamples;
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j <= i; ++j) {
        // Standard error of a sample covariance: sqrt((Qii Qjj + Qij^2) / n); allow 4 of them.
        const double se = std::sqrt((d.Q(i, i) * d.Q(j, j) + d.Q(i, j) * d.Q(i, j)) / kSamples);
        const test::NearContext at(QString("Q(%1,%2)").arg(i).arg(j));
        RK_COMPARE_NEAR(C(i, j), d.Q(i, j), 4 * se);  // Monte Carlo against Van Loan
      }
    }
  }
  void drkfTransitionIsTheMatrixExponential() {
    // With the calibration states (heading bias, log scale) modelled too.
    const drkf::ProcessModel m(
        {{0.55, 0.17}, {0.5, 1.0}, {22.4, 0.25}, {0.7, 0.5}, {0.017, 1.0 / 3600.0}, {0.02, 1.0 / 7200.0}});
    for (double dt : {0.1, 1.0, 2.0}) {  // the filter never discretises beyond 4 / beta_max in one step
      const auto d = m.discretise(dt);
      const Mat<drkf::kStateDim> expFdt = (m.F() * dt).exp();
      QVERIFY((d.Phi - expFdt).norm() < 1e-12);
      QVERIFY((d.Q - d.Q.transpose()).norm() == 0.0);
      QVERIFY(Eigen::SelfAdjointEigenSolver<Mat<drkf::kStateDim>>(d.Q).eigenvalues().minCoeff() >
              -1e-12 * std::max(1.0, d.Q.norm()));
      // A calibration state is its own first-order Gauss-Markov process (eq. 2b).
      const double q =
          drkf::ProcessParams{{}, {}, {}, {}, {0.017, 1.0 / 3600.0}, {}}.headingBias.discreteVariance(dt);
      RK_COMPARE_NEAR(d.Q(drkf::kHeadingBias, drkf::kHeadingBias), q, 1e-12 * q + 1e-18);
      RK_COMPARE_NEAR(d.Phi(drkf::kLogScale, drkf::kLogScale), std::exp(-dt / 7200.0), 1e-14);
    }
  }
  void printedTransitionIsFirstOrder() {
    // Eq. 5 treats the Gauss-Markov processes as constant over the step: right to first order in dt,
    // visibly wrong at dt = 1 s with beta_a = 1 (docs/drkf.md).
    using namespace drkf;
    const ProcessModel m({{0.55, 0.17}, {0.5, 1.0}, {22.4, 0.25}, {0.7, 0.5}});
    const double small = 1e-3;
    QVERIFY((m.printedTransition(small) - m.discretise(small).Phi).cwiseAbs().maxCoeff() < 1e-6);
    const auto exact = m.discretise(1.0).Phi;
    const auto printed = m.printedTransition(1.0);
    RK_COMPARE_NEAR(exact(kPosX, kAccX), 1.0 - (1.0 - std::exp(-1.0)), 1e-12);  // dt/b - (1-e^-b dt)/b^2
    RK_COMPARE_NEAR(printed(kPosX, kAccX), 0.5, 1e-15);
    RK_COMPARE_NEAR(exact(kVelX, kAccX), 1.0 - std::exp(-1.0), 1e-12);
    RK_COMPARE_NEAR(printed(kVelX, kAccX), 1.0, 1e-15);
  }
  void invalidParametersThrow() {
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             drkf::ProcessModel({{0.5, 0.0}, {0.5, 1.0}, {1, 1}, {1, 1}}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             drkf::ProcessModel({{-0.5, 1.0}, {0.5, 1.0}, {1, 1}, {1, 1}}));
    QVERIFY(!GaussMarkov({std::nan(""), 1.0}).valid());
  }
};

QTEST_APPLESS_MAIN(TestGaussMarkov)
#include "tst_gauss_markov.moc"
