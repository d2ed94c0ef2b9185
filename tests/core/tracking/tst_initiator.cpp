// The initiator on its own: M-of-N confirmation on hand-made hit/miss sequences, acquisition zones,
// plot positions and the filter a new track starts with.
#include <QTest>

#include <string>

#include "common/angles.h"
#include "support/compare_near.h"
#include "tracking/initiator.h"
#include "tracking/sweep_history.h"

using namespace reckoner;
using namespace reckoner::track;
using Verdict = MofNConfirmation::Verdict;

namespace {
/// The verdict after each sweep of a sequence, oldest first: 'x' seen, '.' missed. "U", "C", "D" per
/// sweep, as far as the track lives (a confirmed or dropped track is no longer judged).
std::string verdicts(const MofNConfirmation& rule, const std::string& seen) {
  std::uint32_t history = 0;
  int sweeps = 0;
  std::string out;
  for (const char c : seen) {
    history = recordSweep(history, c == 'x');
    ++sweeps;
    const Verdict v = rule.verdict(history, sweeps);
    out += v == Verdict::Confirm ? 'C' : v == Verdict::Drop ? 'D' : 'U';
    if (v != Verdict::Undecided) break;
  }
  return out;
}

OwnShipInput ownAt(TimeUs t, double x, double y, double vx, double vy) {
  OwnShipInput o;
  o.timeUs = t;
  o.x << x, y, vx, vy;
  o.P = est::Vec<4>(1.0, 1.0, 0.01, 0.01).asDiagonal();
  return o;
}
}  // namespace

class TestInitiator : public QObject {
  Q_OBJECT
 private slots:
  void threeOfFiveConfirmsOnTheThirdHit() {
    const MofNConfirmation rule(3, 5);
    QCOMPARE(verdicts(rule, "xxx"), std::string("UUC"));
    QCOMPARE(verdicts(rule, "x.x.x"), std::string("UUUUC"));
    QCOMPARE(verdicts(rule, ".xx.x"), std::string("UUUUC"));
  }
  void threeOfFiveDropsAsSoonAsThreeAreOutOfReach() {
    const MofNConfirmation rule(3, 5);
    // One hit and three misses: with one sweep left at most 2 of 5.
    QCOMPARE(verdicts(rule, "x...x"), std::string("UUUD"));
    QCOMPARE(verdicts(rule, "xx..."), std::string("UUUUD"));
    QCOMPARE(verdicts(rule, "..."), std::string("UUD"));
  }
  void oneOfOneDecidesAtOnce() {
    const MofNConfirmation rule(1, 1);
    QCOMPARE(verdicts(rule, "x"), std::string("C"));
    QCOMPARE(verdicts(rule, "."), std::string("D"));
  }
  void nOfNNeedsEverySweep() {
    const MofNConfirmation rule(4, 4);
    QCOMPARE(verdicts(rule, "xxxx"), std::string("UUUC"));
    QCOMPARE(verdicts(rule, "xx.x"), std::string("UUD"));
  }
  void thirtyTwoSweepsUseTheWholeHistory() {
    const MofNConfirmation rule(32, 32);
    QCOMPARE(verdicts(rule, std::string(32, 'x')), std::string(31, 'U') + "C");
  }

  void zoneContainsItsSectorAcrossNorth() {
    const AcquisitionZone z{500.0, 5000.0, degToRad(350.0), degToRad(10.0)};
    QVERIFY(z.contains(1000.0, degToRad(355.0)));
    QVERIFY(z.contains(1000.0, degToRad(5.0)));
    QVERIFY(!z.contains(1000.0, degToRad(20.0)));
    QVERIFY(!z.contains(400.0, degToRad(0.0)));
    QVERIFY(!z.contains(5001.0, degToRad(0.0)));
    const AcquisitionZone ring{0.0, 100.0, 1.0, 1.0};  // equal bearings: the whole circle
    QVERIFY(ring.contains(50.0, degToRad(200.0)));
  }
  void zonesJudgeTheTrueBearing() {
    const std::vector<AcquisitionZone> zones{{0.0, 5000.0, degToRad(80.0), degToRad(100.0)}};
    const GridPlot plot{0, 1000.0, degToRad(75.0), 100.0, 1e-4};  // grid bearing 75 degrees
    QVERIFY(!inAcquisitionZones(zones, plot, 0.0));
    QVERIFY(inAcquisitionZones(zones, plot, degToRad(10.0)));  // true bearing 85 degrees
    QVERIFY(inAcquisitionZones({}, plot, 0.0));                // no zones: everywhere
  }
  void plotPositionCarriesOwnShipToThePlotTime() {
    const OwnShipInput own = ownAt(0, 100.0, 200.0, 1.0, 2.0);
    const GridPlot plot{2'000'000, 10.0, kPi / 2.0, 100.0, 1e-4};  // 2 s later, 10 m east
    const est::Vec<2> at = plotGridPosition(plot, own);
    RK_COMPARE_NEAR(at[0], 100.0 + 2.0 + 10.0, 1e-9);
    RK_COMPARE_NEAR(at[1], 200.0 + 4.0, 1e-9);
    QVERIFY(!plotOnLand(nullptr, plot, own));
  }
  void factoryStartsTheChosenKind() {
    TtkfConfig fc;
    fc.process = {{0.02, 0.1}, {0.05, 0.05}};
    const TrackFilterFactory factory{std::make_shared<const TtkfContext>(fc), AbgConfig{0.1, true},
                                     ImmConfig{}};
    const OwnShipInput own = ownAt(0, 0.0, 0.0, 0.0, 5.0);
    const GridPlot plot{0, 2000.0, degToRad(30.0), 100.0, 1e-4};
    for (const TrackerKind k :
         {TrackerKind::Ekf, TrackerKind::EkfInputEstimation, TrackerKind::AlphaBetaGamma, TrackerKind::Imm}) {
      const auto f = factory.start(k, own, plot);
      QVERIFY(f.has_value());
      QCOMPARE(f->kind(), k);
      // The new track's target sits on the plot.
      RK_COMPARE_NEAR(f->belief().x[est::ttkf::kTgtX], 2000.0 * std::sin(degToRad(30.0)), 1e-6);
      RK_COMPARE_NEAR(f->belief().x[est::ttkf::kTgtY], 2000.0 * std::cos(degToRad(30.0)), 1e-6);
    }
  }
};

QTEST_APPLESS_MAIN(TestInitiator)
#include "tst_initiator.moc"
