// Seed 003: the alpha-beta-gamma ARPA tracking filter and its 2drms evaluation.
#include <QTest>

#include <cmath>

#include "estimation/gaussian.h"
#include "sim/seed003.h"
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
      QVERIFY2(std::abs(b - beta) < 1e-9 && std::abs(g - gamma) < 1e-9,
               qPrintable(QString("alpha %1: beta %2 vs %3, gamma %4 vs %5")
                              .arg(alpha)
                              .arg(b)
                              .arg(beta)
                              .arg(g)
                              .arg(gamma)));
    }
  }

  void expandingMemoryStartThenFixed() {
    track::AbgConfig cfg;
    cfg.alpha = 0.5;
    track::AlphaBetaGammaFilter f(cfg);
    const double expected[] = {1.0, 1.0, 10.0 / 12.0, 14.0 / 20.0, 18.0 / 30.0, 22.0 / 42.0, 0.5, 0.5};
    for (int n = 1; n <= 8; ++n) {
      QVERIFY(f.update(fromSeconds(2.0 * n), 10.0 * n, -5.0 * n));
      QVERIFY2(std::abs(f.estimate().alpha - expected[n - 1]) < 1e-12,
               qPrintable(QString("n %1: alpha %2").arg(n).arg(f.estimate().alpha)));
    }
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
    QVERIFY(std::abs(f.estimate().smoothedPos[0] - truth(t)[0]) < 1e-6);
    QVERIFY(std::abs(f.estimate().smoothedVel[1] - (-3.0 - 0.04 * t)) < 1e-6);
    QVERIFY(std::abs(f.estimate().smoothedAcc[0] - 0.02) < 1e-6);
    const auto p = f.predict(fromSeconds(t + 2.5));
    QVERIFY(std::abs(p[1] - truth(t + 2.5)[1]) < 1e-6);
  }

  void smoothingReducesTheErrorOfThePlots() {
    // The paper's findings: with noise the smoothed positions are better than the plots, and the
    // residual (smoothed) errors lower than the prediction errors.
    track::AbgConfig cfg;
    cfg.alpha = 0.5;
    sim::Seed003Setup setup;
    for (const auto c : {sim::Seed003Case::VaryingCourse, sim::Seed003Case::VaryingCourseAndSpeed}) {
      const auto r = sim::runSeed003(c, setup, cfg, 7);
      QVERIFY(std::abs(r.observed2drmsM - 2.0 * std::sqrt(2.0) * setup.plotSdM) < 5.0);
      QVERIFY2(r.smoothed2drmsM < 0.8 * r.observed2drmsM && r.smoothed2drmsM < r.predicted2drmsM,
               qPrintable(QString("%1: %2 %3 %4")
                              .arg(sim::seed003CaseName(c))
                              .arg(r.observed2drmsM)
                              .arg(r.smoothed2drmsM)
                              .arg(r.predicted2drmsM)));
    }
    const auto clean = sim::runSeed003(sim::Seed003Case::NoNoise, setup, cfg, 7);
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
