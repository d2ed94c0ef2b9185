#include <QTest>

#include "common/angles.h"
#include "estimation/discretize.h"
#include "estimation/models/ttkf_process.h"
#include "estimation/models/ttkf_radar.h"
#include "estimation/singer.h"
#include "support/compare_near.h"
#include "support/numeric_jacobian.h"

using namespace reckoner;
using namespace reckoner::est;
using namespace reckoner::est::ttkf;

Q_DECLARE_METATYPE(reckoner::est::ttkf::State)

namespace {
State geometry(double dx, double dy) {
  State x;
  x << 100.0, -50.0, 3.0, 4.0, 0.01, -0.02, 100.0 + dx, -50.0 + dy, -2.0, 1.0, 0.03, 0.0;
  return x;
}
}  // namespace

class TestTtkfModels : public QObject {
  Q_OBJECT
 private slots:
  void singerEqualsVanLoan_data() {
    QTest::addColumn<double>("sigma");
    QTest::addColumn<double>("beta");
    QTest::addColumn<double>("dt");
    QTest::newRow("Table III test 1, one sweep") << std::sqrt(0.005) << 0.1 << 2.0;
    QTest::newRow("Table III tests 2-3, odd beam time") << std::sqrt(0.001) << 0.07 << 1.3771;
    QTest::newRow("tiny beta, 100 s gap") << 0.05 << 1e-4 << 100.0;
    QTest::newRow("fast manoeuvre model, 30 s") << 0.5 << 1.0 << 30.0;
    QTest::newRow("microsecond step") << 0.3 << 0.5 << 1e-6;
    QTest::newRow("zero step") << 0.3 << 0.5 << 0.0;
    // Gaps of a replay: the panels stop at beta T = 20 and one panel takes the polynomial tail (the
    // 4000-year gap of a bit-flipped year overflowed the panel count).
    QTest::newRow("one hour without plots") << 0.5 << 1.0 << 3600.0;
    QTest::newRow("4000-year clock error") << 0.1 << 0.5 << 1.26e11;
  }
  void singerEqualsVanLoan() {
    QFETCH(double, sigma);
    QFETCH(double, beta);
    QFETCH(double, dt);
    const GaussMarkov gm{sigma, beta};
    Mat<3> F;
    F << 0, 1, 0, 0, 0, 1, 0, 0, -beta;
    auto vl = discretiseVanLoan<3, 1>(F, MatRC<3, 1>(0.0, 0.0, gm.alpha()), dt);
    if (beta * dt > 5.0) {
      // Van Loan forms Q as Phi (Phi^-1 Q), with entries ~ e^(beta dt): it loses digits here (and
      // overflows past beta dt ~ 700). Use Singer's closed form as the reference instead.
      const double b = beta, T = dt, q = gm.alpha() * gm.alpha(), e1 = std::exp(-b * T),
                   e2 = std::exp(-2 * b * T);
      vl.Q(0, 0) = q / (2 * std::pow(b, 5)) *
                   (1 - e2 + 2 * b * T + 2 * std::pow(b * T, 3) / 3 - 2 * b * b * T * T - 4 * b * T * e1);
      vl.Q(0, 1) = vl.Q(1, 0) =
          q / (2 * std::pow(b, 4)) * (e2 + 1 - 2 * e1 + 2 * b * T * e1 - 2 * b * T + b * b * T * T);
      vl.Q(0, 2) = vl.Q(2, 0) = q / (2 * std::pow(b, 3)) * (1 - e2 - 2 * b * T * e1);
      vl.Q(1, 1) = q / (2 * std::pow(b, 3)) * (4 * e1 - 3 - e2 + 2 * b * T);
      vl.Q(1, 2) = vl.Q(2, 1) = q / (2 * b * b) * (e2 + 1 - 2 * e1);
      vl.Q(2, 2) = q / (2 * b) * (1 - e2);
      vl.Phi << 1, T, (b * T + e1 - 1) / (b * b), 0, 1, (1 - e1) / b, 0, 0, e1;  // exp overflows in Van Loan
    }
    const auto s = singerDiscretisation(gm, dt);
    QVERIFY2((s.Phi - vl.Phi).cwiseAbs().maxCoeff() <= 1e-12 * std::max(1.0, vl.Phi.cwiseAbs().maxCoeff()),
             qPrintable(QString::number((s.Phi - vl.Phi).cwiseAbs().maxCoeff())));
    const double qScale = std::max(1e-300, vl.Q.cwiseAbs().maxCoeff());
    QVERIFY2((s.Q - vl.Q).cwiseAbs().maxCoeff() <= 1e-9 * qScale,
             qPrintable(QString("rel %1").arg((s.Q - vl.Q).cwiseAbs().maxCoeff() / qScale)));
  }
  void processModelIsBlockSparseAndExact() {
    const ProcessModel m({{0.07, 0.1}, {0.03, 0.07}});
    const auto d = m.discretise(2.0);
    QCOMPARE(d.Phi.nonZeros(), 4 * 6);  // four axes, upper-triangular 3x3 each
    const auto vl = discretiseVanLoan<kStateDim, kNoiseDim>(m.F(), m.G(), 2.0);
    QVERIFY((d.Phi.dense() - vl.Phi).cwiseAbs().maxCoeff() < 1e-12);
    QVERIFY((d.Q - vl.Q).cwiseAbs().maxCoeff() < 1e-9 * vl.Q.cwiseAbs().maxCoeff());
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, ProcessModel({{0.07, 0.0}, {0.03, 0.07}}));
  }
  void radarJacobian_data() {
    QTest::addColumn<State>("x");
    QTest::newRow("ordinary, 3 km") << geometry(2000.0, 2200.0);
    QTest::newRow("target just west of north") << geometry(-0.5, 4000.0);
    QTest::newRow("target due north") << geometry(0.0, 4000.0);
    QTest::newRow("target due south") << geometry(0.0, -4000.0);
    QTest::newRow("near-zero range, 2 m") << geometry(1.2, -1.6);
    QTest::newRow("40 km") << geometry(-30000.0, 26000.0);
  }
  void radarJacobian() {
    QFETCH(State, x);
    const RadarModel m(0.0);
    const auto numeric = numericJacobian<2, kStateDim>(
        [&](const State& s) { return m.h(s); }, x,
        [&](const Vec<2>& a, const Vec<2>& b) { return m.residual(a, b); }, 1e-7);
    const auto analytic = m.jacobian(x);
    const double scale = std::max(1.0, analytic.cwiseAbs().maxCoeff());
    QVERIFY2((numeric - analytic).cwiseAbs().maxCoeff() < 1e-6 * scale,
             qPrintable(QString::number((numeric - analytic).cwiseAbs().maxCoeff())));
    // The own-ship model is the identity on the first four states.
    const OwnShipModel own;
    QVERIFY((own.jacobian(x) - numericJacobian<4, kStateDim>([&](const State& s) { return own.h(s); }, x))
                .norm() < 1e-9);
  }
  void radarMeasurementAndWrap() {
    const RadarModel m(1.0);
    const auto z = m.h(geometry(3000.0, 4000.0));
    RK_COMPARE_NEAR(z[0], 5000.0, 1e-9);
    RK_COMPARE_NEAR(z[1], std::atan2(3000.0, 4000.0), 1e-12);
    // Azimuth residual across north: measured 0.5 deg, predicted 359.5 deg -> +1 deg.
    const auto r = m.residual(Vec<2>(10.0, degToRad(0.5)), Vec<2>(10.0, degToRad(359.5)));
    RK_COMPARE_NEAR(r[1], degToRad(1.0), 1e-12);
    QVERIFY(m.degenerate(geometry(0.3, 0.4)));
    QVERIFY(!m.degenerate(geometry(3.0, 4.0)));
  }
};

QTEST_APPLESS_MAIN(TestTtkfModels)
#include "tst_ttkf_models.moc"
