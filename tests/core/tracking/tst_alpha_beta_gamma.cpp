// Seed 003: the alpha-beta-gamma ARPA tracking filter and its 2drms evaluation.
#include <QTest>

#include <cmath>

#include <Eigen/QR>
#include <vector>

#include "common/rng.h"
#include "estimation/gaussian.h"
#include "studies/seed003.h"
#include "support/compare_near.h"
#include "tracking/alpha_beta_gamma.h"

using namespace reckoner;

class TestAlphaBetaGamma : public QObject {
  Q_OBJECT
 private slots:
  void gainRelationIsTheSteadyStateKalmanGain() {
    // GIVEN the white-jerk (Wiener-process acceleration) model at several noise ratios WHEN the Riccati
    // equation is iterated to its steady state THEN its gains K = [alpha, beta/T, 2 gamma/T^2] satisfy
    // the relation the filter uses.
    for (const double ratio : {0.001, 0.1, 10.0}) {
      const double T = 2.5, q = 1.0, r = 1.0 / ratio;
      est::Mat<3> F;
      F << 1, T, T * T / 2, 0, 1, T, 0, 0, 1;
      const est::Vec<3> G(T * T / 2, T, 1);
      const est::Mat<3> Q = q * G * G.transpose();
      est::Mat<3> P = est::Mat<3>::Identity() * 1e4;
      est::Vec<3> K = est::Vec<3>::Zero();
      for (int i = 0; i < 20000; ++i) {
        const est::Mat<3> Pp = F * P * F.transpose() + Q;
        K = Pp.col(0) / (Pp(0, 0) + r);
        P = Pp - K * Pp.row(0);
      }
      const double alpha = K[0], beta = K[1] * T, gamma = K[2] * T * T / 2.0;
      const auto [b, g] = track::abgGainsFromAlpha(alpha);
      const test::NearContext at(QString("alpha %1").arg(alpha));
      RK_COMPARE_NEAR(b, beta, 1e-9);
      RK_COMPARE_NEAR(g, gamma, 1e-9);
    }
  }

  void expandingMemoryStartIsTheLeastSquaresFitThenFixed() {
    // GIVEN noisy plots of an accelerating target every 2 s WHEN the filter starts THEN from the
    // third plot on, while the growing-memory alpha exceeds the chosen one, its smoothed position,
    // velocity and acceleration are those of the least-squares quadratic through all plots so far (to
    // 1e-6), its alpha is above the paper's lower bound 2(2n-1)/(n(n+1)), and afterwards alpha is the
    // chosen one with beta and gamma from the steady-state relation.
    track::AbgConfig cfg;
    cfg.alpha = 0.3;
    track::AlphaBetaGammaFilter f(cfg);
    Rng rng(5, 0);
    std::vector<double> ts, zs;
    bool fixedSeen = false;
    for (int n = 1; n <= 40; ++n) {
      const double t = 2.0 * n, z = 3.0 * t + 0.01 * t * t + rng.normal(0.0, 20.0);
      ts.push_back(t);
      zs.push_back(z);
      QVERIFY(f.update(fromSeconds(t), z, 0.0));
      const auto& e = f.estimate();
      if (n < 3) continue;
      const double bound = 2.0 * (2.0 * n - 1.0) / (n * (n + 1.0));
      if (e.alpha > cfg.alpha) {
        QVERIFY(!fixedSeen);
        QVERIFY2(e.alpha > bound,
                 qPrintable(QString("n %1: alpha %2 bound %3").arg(n).arg(e.alpha).arg(bound)));
        // Least squares in time relative to the latest plot: z = p + v s + a s^2 / 2.
        Eigen::MatrixXd A(n, 3);
        Eigen::VectorXd b(n);
        for (int k = 0; k < n; ++k) {
          const double s = ts[static_cast<std::size_t>(k)] - t;
          A(k, 0) = 1.0;
          A(k, 1) = s;
          A(k, 2) = 0.5 * s * s;
          b(k) = zs[static_cast<std::size_t>(k)];
        }
        const Eigen::Vector3d ls = A.colPivHouseholderQr().solve(b);
        const test::NearContext at(QString("n %1").arg(n));
        RK_COMPARE_NEAR(e.smoothedPos[0], ls[0], 1e-6);
        RK_COMPARE_NEAR(e.smoothedVel[0], ls[1], 1e-6);
        RK_COMPARE_NEAR(e.smoothedAcc[0], ls[2], 1e-6);
      } else {
        fixedSeen = true;
        QCOMPARE(e.alpha, cfg.alpha);
        QCOMPARE(e.beta, track::abgGainsFromAlpha(cfg.alpha)[0]);
      }
    }
    QVERIFY(fixedSeen);
  }

  void constantAccelerationIsFollowedWithoutLag() {
    // The filter models acceleration: a noise-free constant-acceleration target is tracked exactly once
    // the start has died out (an alpha-beta filter would lag).
    track::AbgConfig cfg;
    cfg.alpha = 0.4;
    track::AlphaBetaGammaFilter f(cfg);
    const auto truth = [](double t) {
      return std::array<double, 2>{100.0 + 5.0 * t + 0.01 * t * t, -3.0 * t - 0.02 * t * t};
    };
    for (int n = 0; n < 400; ++n) {
      const double t = 2.5 * n;
      f.update(fromSeconds(t), truth(t)[0], truth(t)[1]);
    }
    const double t = 2.5 * 399;
    RK_COMPARE_NEAR(f.estimate().smoothedPos[0], truth(t)[0], 1e-6);
    RK_COMPARE_NEAR(f.estimate().smoothedVel[1], -3.0 - 0.04 * t, 1e-6);
    RK_COMPARE_NEAR(f.estimate().smoothedAcc[0], 0.02, 1e-6);
    const auto p = f.predict(fromSeconds(t + 2.5));
    RK_COMPARE_NEAR(p[1], truth(t + 2.5)[1], 1e-6);
  }

  void smoothingReducesTheErrorOfThePlots() {
    // The paper's findings: with noise the smoothed positions are better than the plots, and the
    // residual (smoothed) errors lower than the prediction errors.
    track::AbgConfig cfg;
    cfg.alpha = 0.5;
    studies::Seed003Setup setup;
    for (const auto c : {studies::Seed003Case::VaryingCourse, studies::Seed003Case::VaryingCourseAndSpeed}) {
      const auto r = studies::runSeed003(c, setup, cfg, 7);
      RK_COMPARE_NEAR(r.observed2drmsM, 2.0 * std::sqrt(2.0) * setup.plotSdM, 5.0);
      QVERIFY2(r.smoothed2drmsM < 0.8 * r.observed2drmsM && r.smoothed2drmsM < r.predicted2drmsM,
               qPrintable(QString("%1: %2 %3 %4")
                              .arg(studies::seed003CaseName(c))
                              .arg(r.observed2drmsM)
                              .arg(r.smoothed2drmsM)
                              .arg(r.predicted2drmsM)));
    }
    const auto clean = studies::runSeed003(studies::Seed003Case::NoNoise, setup, cfg, 7);
    QVERIFY(clean.observed2drmsM == 0.0 && clean.smoothed2drmsM < 0.5);
  }

  void badInputIsRefused() {
    track::AbgConfig cfg;
    cfg.alpha = 0.7;  // beyond the paper's 0.6
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, track::AlphaBetaGammaFilter{cfg});
    cfg.alpha = 0.5;
    track::AlphaBetaGammaFilter f(cfg);
    QVERIFY(f.update(fromSeconds(1.0), 0.0, 0.0));
    QVERIFY(!f.update(fromSeconds(1.0), 1.0, 1.0));  // not after the last plot
    QVERIFY(!f.update(fromSeconds(2.0), std::nan(""), 1.0));
    QCOMPARE(f.plots(), 1);
  }
};

QTEST_APPLESS_MAIN(TestAlphaBetaGamma)
#include "tst_alpha_beta_gamma.moc"
