#include <QTest>

#include "common/angles.h"
#include "estimation/discretize.h"
#include "estimation/models/drkf_ground_velocity.h"
#include "estimation/models/drkf_gyro.h"
#include "estimation/models/drkf_position_fix.h"
#include "estimation/models/drkf_process.h"
#include "estimation/models/drkf_radar_fix.h"
#include "estimation/models/drkf_speedlog.h"
#include "support/compare_near.h"
#include "support/numeric_jacobian.h"

using namespace reckoner;
using namespace reckoner::est;
using namespace reckoner::est::drkf;

Q_DECLARE_METATYPE(reckoner::est::drkf::State)

namespace {
State makeState(double vx, double vy, double cx = 0.3, double cy = -0.2) {
  State x;
  x << 1200.0, cx, vx, 0.1, -800.0, cy, vy, -0.05, 12.0, -7.0, 0.08, 0.012, 0.015;
  return x;
}

template <class Model>
void checkJacobian(const Model& m, const State& x) {
  constexpr int M = Model::kDim;
  const auto numeric =
      numericJacobian<M, kStateDim>([&](const State& s) { return m.h(s); }, x,
                                    [&](const Vec<M>& a, const Vec<M>& b) { return m.residual(a, b); });
  const auto analytic = m.jacobian(x);
  const double scale = std::max(1.0, analytic.cwiseAbs().maxCoeff());
  QVERIFY2(
      (numeric - analytic).cwiseAbs().maxCoeff() < 1e-6 * scale,
      qPrintable(QString("max |numeric - analytic| = %1").arg((numeric - analytic).cwiseAbs().maxCoeff())));
}
}  // namespace

class TestDrkfModels : public QObject {
  Q_OBJECT
 private slots:
  void jacobians_data() {
    QTest::addColumn<State>("x");
    QTest::newRow("ordinary") << makeState(5.0, 4.0);
    QTest::newRow("heading just west of north") << makeState(-0.05, 6.0);
    QTest::newRow("heading exactly north") << makeState(0.0, 6.0);
    QTest::newRow("heading south") << makeState(0.01, -6.0);
    QTest::newRow("slow: 0.03 m/s") << makeState(0.02, 0.0224, 0.0, 0.0);
    QTest::newRow("current cancels water velocity") << makeState(1.0, 1.0, -0.98, -0.99);
    QTest::newRow("large values") << makeState(-15.0, 12.0, 2.5, -1.5);
  }
  void jacobians() {
    QFETCH(State, x);
    checkJacobian(PositionFixModel(PositionFixModel::Source::Gps), x);
    checkJacobian(PositionFixModel(PositionFixModel::Source::LoranC), x);
    checkJacobian(GroundVelocityModel(), x);
    checkJacobian(SpeedlogModel(SpeedlogModel::Mode::GroundLock, 0.0), x);
    checkJacobian(SpeedlogModel(SpeedlogModel::Mode::BottomLock, 0.0), x);
    checkJacobian(GyroHeadingModel(0.0), x);
    // With the calibration states: the log's scale factor, the heading sensor's bias.
    checkJacobian(SpeedlogModel(SpeedlogModel::Mode::GroundLock, 0.0, true), x);
    checkJacobian(SpeedlogModel(SpeedlogModel::Mode::BottomLock, 0.0, true), x);
    checkJacobian(GyroHeadingModel(0.0, true), x);
    // The radar fix, plain and with a sensitivity to the velocity and turn rate it was taken with.
    checkJacobian(RadarFixModel(), x);
    Mat<3> S;
    S << -0.4, 0.1, -150.0, 0.2, -0.7, 320.0, 0.01, -0.02, -1.1;
    checkJacobian(RadarFixModel(S, sweepMotionOf(x) + Vec<3>(0.1, -0.05, 0.002)), x);
    checkJacobian(RadarPositionModel(Mat<2>(S.topLeftCorner<2, 2>()), Vec<2>(0.3, 0.1)), x);
    // Under the ship motion model the fix's turn rate is the state x8.
    checkJacobian(RadarFixModel(S, sweepMotionOf(x, true) + Vec<3>(0.1, -0.05, 0.002), true), x);
    QCOMPARE(sweepMotionOf(x, true)[2], x[kTurnRate]);
  }
  void shipMotionJacobian_data() { jacobians_data(); }
  void shipMotionJacobian() {
    // GIVEN the ship motion model WHEN its continuous Jacobian is compared with central differences of
    // its derivative THEN they agree, above and below the speed at which the along-track term fades.
    QFETCH(State, x);
    ProcessParams p{{0.5, 1.0 / 3600.0}, {0.05, 1.0 / 30.0},    {150.0, 1.0 / 600.0},
                    {0.1, 1.0 / 3600.0}, {0.017, 1.0 / 3600.0}, {0.02, 1.0 / 7200.0}};
    p.ship.enabled = true;
    const ProcessModel m(p);
    const auto numeric =
        numericJacobian<kStateDim, kStateDim>([&](const State& s) { return m.derivative(s); }, x,
                                              [](const State& a, const State& b) { return State(a - b); });
    const Mat<kStateDim> analytic = m.jacobianAt(x);
    const double worst = (numeric - analytic).cwiseAbs().maxCoeff();
    const double speed = std::hypot(x[kVelX], x[kVelY]);
    if (std::abs(speed - p.ship.minSpeedMps) > 1e-3)  // the kink at minSpeed itself has no derivative
      QVERIFY2(worst < 1e-6, qPrintable(QString("max |numeric - analytic| = %1").arg(worst)));
  }
  void shipMotionDiscretisationIsVanLoansOnTheWholeState() {
    // GIVEN the ship model linearised at a turning, accelerating ship WHEN discretised on its coupled
    // states alone THEN Phi and Q equal Van Loan's on all 13 states (the rest are independent).
    ProcessParams p{{0.5, 1.0 / 3600.0}, {0.05, 1.0 / 30.0},    {150.0, 1.0 / 600.0},
                    {0.1, 1.0 / 3600.0}, {0.017, 1.0 / 3600.0}, {0.02, 1.0 / 7200.0}};
    p.ship.enabled = true;
    const ProcessModel m(p);
    State x = makeState(4.0, -3.0);
    x[kAlongAccel] = 0.01;
    x[kTurnRate] = 0.01;
    for (const double dt : {0.1, 1.0, 7.5}) {
      const auto fast = m.discretiseAt(x, dt);
      const auto full = discretiseVanLoan<kStateDim, kShipNoiseDim>(m.jacobianAt(x), m.shipNoiseInput(), dt);
      QVERIFY((fast.Phi - full.Phi).cwiseAbs().maxCoeff() <
              1e-9 * std::max(1.0, full.Phi.cwiseAbs().maxCoeff()));
      QVERIFY((fast.Q - full.Q).cwiseAbs().maxCoeff() < 1e-9 * std::max(1.0, full.Q.cwiseAbs().maxCoeff()));
    }
  }
  void shipMotionTurnsWithoutChangingSpeed() {
    // GIVEN a ship at 5 m/s turning at 1 deg/s with no along-track acceleration WHEN propagated 90 s
    // THEN its speed is kept and its heading has turned 90 deg (the mean's integration is exact enough).
    ProcessParams p{{0.5, 1e-9}, {0.05, 1.0 / 30.0}, {150.0, 1.0 / 600.0},
                    {0.1, 1e-9}, {0.0, 1.0},         {0.0, 1.0}};
    p.ship.enabled = true;
    p.ship.turnRate = {degToRad(0.5), 1e-9};  // a turn rate that does not decay over the test
    const ProcessModel m(p);
    State x = State::Zero();
    x[kVelY] = 5.0;  // north
    x[kTurnRate] = degToRad(1.0);
    const State y = m.propagate(x, 90.0);
    RK_COMPARE_NEAR(std::hypot(y[kVelX], y[kVelY]), 5.0, 1e-6);
    RK_COMPARE_NEAR(angleDiff(bearingOf(y[kVelX], y[kVelY]), degToRad(90.0)), 0.0, 1e-6);
    // the arc: radius 5 / (pi / 180) = 286.5 m, from (0, 0) to (r, r)
    const double r = 5.0 / degToRad(1.0);
    RK_COMPARE_NEAR(y[kPosX], r, 1e-3);
    RK_COMPARE_NEAR(y[kPosY], r, 1e-3);
  }
  void radarFixMovesWithTheAssumedMotion() {
    // GIVEN a fix taken with the filter's own motion, WHEN the state's turn rate differs from the one the
    // picture was placed with, THEN the predicted fix moves by S times the difference.
    const State x = makeState(3.0, 4.0);
    Mat<3> S = Mat<3>::Zero();
    S(2, 2) = -1.0;  // heading at mid-sweep of a 2 s sweep
    S(1, 2) = 500.0;
    const Vec<3> r = sweepMotionOf(x);
    RK_COMPARE_NEAR(r[2], (4.0 * 0.1 - 3.0 * -0.05) / 25.0, 1e-15);
    const Vec<3> same = RadarFixModel(S, r).h(x);
    QVERIFY((same - RadarFixModel().h(x)).norm() < 1e-12);
    const Vec<3> turned = RadarFixModel(S, r - Vec<3>(0.0, 0.0, 0.01)).h(x);
    RK_COMPARE_NEAR(turned[1] - same[1], 5.0, 1e-9);
    RK_COMPARE_NEAR(angleDiff(turned[2], same[2]), -0.01, 1e-12);
  }
  void measurementFunctions() {
    const State x = makeState(3.0, 4.0, 0.0, 1.0);
    QCOMPARE(PositionFixModel(PositionFixModel::Source::Gps).h(x), Vec<2>(1200.0, -800.0));
    QCOMPARE(PositionFixModel(PositionFixModel::Source::LoranC).h(x), Vec<2>(1212.0, -807.0));
    QCOMPARE(GroundVelocityModel().h(x), Vec<2>(3.0, 5.0));
    RK_COMPARE_NEAR(SpeedlogModel(SpeedlogModel::Mode::BottomLock, 0).h(x)[0], 5.0 + 0.08, 1e-12);
    RK_COMPARE_NEAR(SpeedlogModel(SpeedlogModel::Mode::GroundLock, 0).h(x)[0], std::hypot(3.0, 5.0) + 0.08,
                    1e-12);
    // Heading of the water velocity (3, 4): atan2(3, 4) clockwise from north, not of the ground velocity.
    RK_COMPARE_NEAR(GyroHeadingModel(0).h(x)[0], std::atan2(3.0, 4.0), 1e-12);
    // The calibration states: reading (1 + k) |v| + b, heading + bias; unseen unless modelled.
    RK_COMPARE_NEAR(SpeedlogModel(SpeedlogModel::Mode::BottomLock, 0, true).h(x)[0], 1.015 * 5.0 + 0.08,
                    1e-12);
    RK_COMPARE_NEAR(GyroHeadingModel(0, true).h(x)[0], std::atan2(3.0, 4.0) + 0.012, 1e-12);
    QCOMPARE(GyroHeadingModel(0).jacobian(x)(0, kHeadingBias), 0.0);
    QCOMPARE(SpeedlogModel(SpeedlogModel::Mode::GroundLock, 0).jacobian(x)(0, kLogScale), 0.0);
  }
  void gyroResidualWrapsAcrossNorth() {
    const GyroHeadingModel g(0.0);
    const double r = g.residual(Vec<1>(degToRad(1.0)), Vec<1>(degToRad(359.0)))[0];
    RK_COMPARE_NEAR(r, degToRad(2.0), 1e-12);
    const double r2 = g.residual(Vec<1>(degToRad(359.0)), Vec<1>(degToRad(1.0)))[0];
    RK_COMPARE_NEAR(r2, -degToRad(2.0), 1e-12);
    QVERIFY(g.h(makeState(-0.05, 6.0))[0] > degToRad(359.0));  // reported in [0, 2 pi)
  }
  void degenerateAtLowSpeed() {
    const State stopped = makeState(0.0, 0.0, 0.3, 0.3);  // stopped in a 0.42 m/s current
    QVERIFY(GyroHeadingModel(0.5).degenerate(stopped));
    QVERIFY(SpeedlogModel(SpeedlogModel::Mode::BottomLock, 0.5).degenerate(stopped));
    QVERIFY(SpeedlogModel(SpeedlogModel::Mode::GroundLock, 0.5).degenerate(stopped));
    QVERIFY(!SpeedlogModel(SpeedlogModel::Mode::GroundLock, 0.4).degenerate(stopped));
    QVERIFY(SpeedlogModel(SpeedlogModel::Mode::BottomLock, 0.4).degenerate(stopped));
    QVERIFY(!GyroHeadingModel(0.5).degenerate(makeState(3.0, 4.0)));
    QVERIFY(GyroHeadingModel(0.5).degenerate(makeState(std::nan(""), 4.0)));
  }
  void processMatricesFollowEquation4() {
    const ProcessModel m({{0.55, 0.17}, {0.5, 1.0}, {22.4, 0.25}, {0.7, 0.5}});
    const auto& F = m.F();
    QCOMPARE(F(kPosX, kCurX), 1.0);
    QCOMPARE(F(kPosX, kVelX), 1.0);
    QCOMPARE(F(kVelY, kAccY), 1.0);
    QCOMPARE(F(kCurY, kCurY), -0.17);
    QCOMPARE(F(kAccX, kAccX), -1.0);
    QCOMPARE(F(kLoranY, kLoranY), -0.25);
    QCOMPARE(F(kLogBias, kLogBias), -0.5);
    QCOMPARE(F.cwiseAbs().sum(), 2 * (1 + 1 + 0.17 + 1 + 1.0) + 2 * 0.25 + 0.5);
    const auto& G = m.G();
    RK_COMPARE_NEAR(G(kCurX, 0), std::sqrt(2 * 0.55 * 0.55 * 0.17), 1e-15);
    RK_COMPARE_NEAR(G(kLogBias, 6), std::sqrt(2 * 0.7 * 0.7 * 0.5), 1e-15);
    QCOMPARE((G.array() != 0.0).count(), 7);
  }
};

QTEST_APPLESS_MAIN(TestDrkfModels)
#include "tst_drkf_models.moc"
