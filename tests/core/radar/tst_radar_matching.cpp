// Seed 004: radar image simulation, echo extraction and matching to chart contours (synthetic coast).
#include <QTest>

#include <cmath>

#include "common/angles.h"
#include "common/rng.h"
#include "estimation/chi_square.h"
#include "estimation/ekf.h"
#include "radar/chart_matching.h"
#include "radar/coastline.h"
#include "radar/land_mask.h"
#include "radar/radar_image.h"
#include "support/compare_near.h"
#include "support/radar_fixtures.h"
#include "tracking/track_manager.h"

using namespace reckoner;
using radar::CoastSegment;

namespace {
/// A closed polygon as contour segments (sd 5 m).
void addRing(std::vector<CoastSegment>& out, const std::vector<est::Vec<2>>& pts, double sd = 5.0) {
  for (std::size_t i = 0; i < pts.size(); ++i) out.push_back({pts[i], pts[(i + 1) % pts.size()], sd});
}
radar::Coastline harbour() {
  return test::syntheticHarbour();
}
radar::SweepPose truePose() {
  return test::harbourPose();
}
}  // namespace

class TestRadarMatching : public QObject {
  Q_OBJECT
 private slots:
  void nearestPointAndRayCasting() {
    std::vector<CoastSegment> s;
    addRing(s, {{-100, -100}, {100, -100}, {100, 100}, {-100, 100}});
    const radar::Coastline c(s, 30.0);
    const auto n = c.nearest({90.0, 10.0}, 50.0);
    QVERIFY(n);
    RK_COMPARE_NEAR(n->distanceM, 10.0, 1e-9);
    QVERIFY((n->point - est::Vec<2>(100.0, 10.0)).norm() < 1e-9);
    RK_COMPARE_NEAR(std::abs(n->normal[0]), 1.0, 1e-12);
    QVERIFY(!c.nearest({0.0, 0.0}, 50.0));  // 100 m from every side
    // From inside, a ray due east meets x = 100; one at 45 deg meets the corner region at 141 m.
    RK_COMPARE_NEAR(*c.firstHit({0.0, 0.0}, degToRad(90.0), 500.0), 100.0, 1e-9);
    RK_COMPARE_NEAR(*c.firstHit({0.0, 0.0}, degToRad(45.0), 500.0), 100.0 * std::sqrt(2.0), 1e-6);
    QVERIFY(!c.firstHit({0.0, 0.0}, degToRad(90.0), 50.0));                            // beyond the range
    RK_COMPARE_NEAR(*c.firstHit({-300.0, 0.0}, degToRad(90.0), 1000.0), 200.0, 1e-9);  // from outside
    QVERIFY(!c.firstHit({-300.0, 0.0}, degToRad(270.0), 1000.0));                      // away from it
  }

  void landMaskIsEvenOdd() {
    // An island with a lake: inside the island is land, the lake and the sea are not; points on the
    // cells' boundaries and beyond the mask's extent are handled.
    const radar::LandMask m(
        {{{0, 0}, {1000, 0}, {1000, 800}, {0, 800}}, {{300, 300}, {600, 300}, {600, 500}, {300, 500}}},
        200.0);
    QVERIFY(m.contains({100.0, 100.0}));
    QVERIFY(m.contains({800.0, 600.0}));
    QVERIFY(m.contains({400.0, 200.0}));    // on a cell boundary in y
    QVERIFY(!m.contains({450.0, 400.0}));   // the lake
    QVERIFY(!m.contains({-50.0, 400.0}));   // west of it
    QVERIFY(!m.contains({1500.0, 400.0}));  // east of the mask
    QVERIFY(!m.contains({500.0, 900.0}));   // north
    QVERIFY(!m.contains({std::nan(""), 0.0}));
  }

  void plotsOnChartedLandAreNotAcquired() {
    // GIVEN a track bank with the chart's land WHEN an unassociated plot falls on land and another on
    // the water THEN only the one on the water starts a track, and the other is counted.
    track::TrackManagerConfig c;
    track::TrackManager bank(c);
    bank.setLandMask(std::make_shared<const radar::LandMask>(
        std::vector<std::vector<est::Vec<2>>>{{{1000, 1000}, {3000, 1000}, {3000, 3000}, {1000, 3000}}}));
    track::OwnShipInput own;
    own.x << 0, 0, 0, 0;
    own.P = est::Mat<4>::Identity();
    bank.feedOwnShip(own);
    const auto plot = [](TimeUs t, double x, double y) {
      return track::GridPlot{t, std::hypot(x, y), wrapTwoPi(std::atan2(x, y)), 100.0, 7.6e-5};
    };
    bank.addPlot(plot(100'000, 2000, 2000));   // land
    bank.addPlot(plot(200'000, -2000, 2000));  // water
    own.timeUs = 1'000'000;
    bank.feedOwnShip(own);
    QCOMPARE(bank.tracks().size(), std::size_t(1));
    QCOMPARE(bank.counters().plotsOnLand, 1L);
    const auto b = bank.beliefAt(bank.tracks().front(), 1'000'000);
    QVERIFY(b.x[est::ttkf::kTgtX] < 0.0);
  }

  void echoesAreTheFrontContour() {
    // GIVEN a noise-free image of the harbour WHEN echoes are extracted THEN there are about 200 and
    // every one lies within a few metres of a contour (the front, not the land behind it).
    radar::RadarImageParams p;
    p.noiseProbability = 0.0;
    p.clutterProbability = 0.0;
    p.rangeSdM = 0.0;
    p.bearingSdRad = 0.0;
    Rng rng(1, 0);
    const radar::Coastline c = harbour();
    const radar::SweepPose pose = truePose();
    const auto img = radar::simulateRadarImage(c, {}, pose, p, rng);
    const auto echoes = radar::extractEchoes(img, p.azStepRad(), {});
    qInfo("%zu echo points", echoes.size());
    QVERIFY(echoes.size() >= 150 && echoes.size() <= 260);
    double worst = 0.0;
    for (const auto& e : echoes) {
      const double dt = pose.timeOffsetS(e.azimuthRad);
      const double th = pose.headingAt(dt) + e.azimuthRad;
      const est::Vec<2> w = pose.positionAt(dt) + e.rangeM * est::Vec<2>(std::sin(th), std::cos(th));
      const auto n = c.nearest(w, 1000.0);
      QVERIFY(n);
      worst = std::max(worst, n->distanceM);
    }
    qInfo("largest distance of a noise-free echo from the contour: %.1f m", worst);
    QVERIFY(worst < 10.0);  // a range bin (5.9 m) and the half-power beam's spread on a sloping shore
  }

  void matchingRecoversPositionAndHeadingConsistently() {
    // GIVEN 50 noisy sweeps (range 10 m, bearing 0.5 deg, receiver noise and sea clutter) WHEN each is
    // matched from a pose 40 m and 1 deg off THEN the corrected pose is within 10 m and 0.15 deg of the
    // truth, and the reported covariance is honest or conservative: the mean NEES (3 dof) is under the
    // 99% band's upper end of 50 runs. It is conservative, and asserted above 0.15 (sd at most about
    // 4.5 times too large): the a-priori echo errors (MatchParams' defaults) are a single pulse's, and
    // at 4096 azimuths the half-power rule takes the median of 13 beams.
    const radar::Coastline c = harbour();
    radar::RadarImageParams p;
    radar::MatchParams mp;
    const radar::SweepPose truth = truePose();
    double nees = 0.0, worstPos = 0.0, worstHdg = 0.0;
    const int runs = 50;
    for (int run = 0; run < runs; ++run) {
      Rng rng(7, static_cast<std::uint64_t>(run));
      const auto img = radar::simulateRadarImage(c, {}, truth, p, rng);
      const auto echoes = radar::extractEchoes(img, p.azStepRad(), {});
      radar::SweepPose guess = truth;
      guess.position += est::Vec<2>(30.0, -25.0);
      guess.headingRad -= degToRad(1.0);
      const auto m = radar::matchEchoes(echoes, guess, c, mp);
      QVERIFY(m.valid);
      const est::Vec<3> err(guess.position[0] + m.correction[0] - truth.position[0],
                            guess.position[1] + m.correction[1] - truth.position[1],
                            angleDiff(guess.headingRad + m.correction[2], truth.headingRad));
      nees += est::nees<3>(err, m.covariance);
      worstPos = std::max(worstPos, err.head<2>().norm());
      worstHdg = std::max(worstHdg, std::abs(err[2]));
      if (run == 0)
        qInfo(
            "run 0: %d echoes, %d used, %d iterations, sd %.1f m %.1f m %.3f deg, rms normalised residual "
            "%.2f",
            m.echoes, m.used, m.iterations, std::sqrt(m.covariance(0, 0)), std::sqrt(m.covariance(1, 1)),
            radToDeg(std::sqrt(m.covariance(2, 2))), m.rmsNormalizedResidual);
    }
    const auto band = est::averageNeesBounds(3, runs, 0.99);
    qInfo("worst position error %.2f m, heading %.3f deg; mean NEES %.2f in [%.2f, %.2f]", worstPos,
          radToDeg(worstHdg), nees / runs, band.lower, band.upper);
    QVERIFY(worstPos < 10.0);
    QVERIFY(radToDeg(worstHdg) < 0.15);
    QVERIFY(nees / runs < band.upper && nees / runs > 0.15);
  }

  void motionSensitivityExplainsAWrongTurnRate() {
    // GIVEN a noise-free picture taken while turning at 1.3 deg/s, WHEN it is matched from a pose that is
    // right at the sweep's end but placed the echoes with no turn and a velocity 0.6 m/s off, THEN the
    // end-of-sweep correction is off by what the matcher's motion sensitivity S predicts for that motion
    // error (to a tenth of it), which is what the DRKF's fix model relies on.
    const radar::Coastline c = harbour();
    radar::RadarImageParams p;
    p.rangeSdM = 0.0;
    p.bearingSdRad = 0.0;
    p.noiseProbability = 0.0;
    p.clutterProbability = 0.0;
    radar::SweepPose truth = truePose();
    truth.turnRateRadPerS = degToRad(1.3);
    const double T = truth.periodS;
    Rng rng(5, 0);
    const auto img = radar::simulateRadarImage(c, {}, truth, p, rng);
    const auto echoes = radar::extractEchoes(img, p.azStepRad(), {});
    bool allValid = true;
    const auto match = [&](const radar::SweepPose& guess) -> est::Vec<3> {
      const auto m = radar::matchEchoes(echoes, guess, c, {});
      allValid = allValid && m.valid;
      // Error of the corrected pose at the sweep's end.
      return est::Vec<3>(guess.positionAt(T)[0] + m.correction[0] - truth.positionAt(T)[0],
                         guess.positionAt(T)[1] + m.correction[1] - truth.positionAt(T)[1],
                         angleDiff(guess.headingAt(T) + m.correction[2], truth.headingAt(T)));
    };
    const est::Vec<3> base = match(truth);
    radar::SweepPose guess = truth;
    guess.velocity += est::Vec<2>(0.5, -0.3);
    guess.turnRateRadPerS = 0.0;
    guess.position = truth.positionAt(T) - guess.velocity * T;
    guess.headingRad = truth.headingAt(T);
    const auto m = radar::matchEchoes(echoes, guess, c, {});
    const est::Vec<3> err = match(guess);
    QVERIFY(allValid);
    const est::Vec<3> delta(truth.velocity[0] - guess.velocity[0], truth.velocity[1] - guess.velocity[1],
                            truth.turnRateRadPerS - guess.turnRateRadPerS);
    const est::Vec<3> predicted = m.motionSensitivity * delta;
    qInfo("end-of-sweep error %.2f m %.2f m %.4f deg; predicted by S %.2f m %.2f m %.4f deg",
          err[0] - base[0], err[1] - base[1], radToDeg(err[2] - base[2]), predicted[0], predicted[1],
          radToDeg(predicted[2]));
    QCOMPARE_GT(std::abs(radToDeg(predicted[2])), 1.0);  // the effect is large: about T/2 times 1.3 deg/s
    const est::Vec<3> miss = err - base - predicted;
    QVERIFY(miss.head<2>().norm() < 0.1 * predicted.head<2>().norm() + 0.5);
    RK_COMPARE_NEAR(miss[2], 0.0, 0.1 * std::abs(predicted[2]));
  }

  void shipsAndClutterAreRejected() {
    // GIVEN 20 vessels within 150 m of the shore (and 10 in open water) WHEN the image is matched
    // THEN at least 95% of the echo points from vessels are rejected as not the chart's, and the pose
    // is still recovered.
    const radar::Coastline c = harbour();
    const radar::SweepPose truth = truePose();
    std::vector<radar::RadarTarget> ships;
    Rng place(3, 0);
    for (int k = 0; k < 30; ++k) {
      const double a = degToRad(-110.0 + 220.0 * place.uniform());
      const double r0 = test::harbourShoreRangeM(a);
      const double r = k < 20 ? r0 - 60.0 - 90.0 * place.uniform() : 600.0 + 800.0 * place.uniform();
      ships.push_back({est::Vec<2>(r * std::sin(a), r * std::cos(a)), 25.0});
    }
    radar::RadarImageParams p;
    Rng rng(11, 0);
    const auto img = radar::simulateRadarImage(c, ships, truth, p, rng);
    const auto echoes = radar::extractEchoes(img, p.azStepRad(), {});
    const auto m = radar::matchEchoes(echoes, truth, c, {});
    QVERIFY(m.valid);
    int fromShips = 0, shipsUsed = 0;
    for (std::size_t i = 0; i < echoes.size(); ++i) {
      const double dt = truth.timeOffsetS(echoes[i].azimuthRad);
      const double th = truth.headingAt(dt) + echoes[i].azimuthRad;
      const est::Vec<2> w = truth.positionAt(dt) + echoes[i].rangeM * est::Vec<2>(std::sin(th), std::cos(th));
      bool ship = false;
      for (const auto& s : ships) ship = ship || (w - s.position).norm() < s.radiusM + 25.0;
      if (!ship) continue;
      ++fromShips;
      shipsUsed += m.usedMask[i] ? 1 : 0;
    }
    qInfo("%d echo points from vessels, %d of them used (%.1f%% rejected); correction %.1f m %.3f deg",
          fromShips, shipsUsed, 100.0 * (fromShips - shipsUsed) / std::max(1, fromShips),
          m.correction.head<2>().norm(), radToDeg(m.correction[2]));
    QVERIFY(fromShips >= 20);
    QVERIFY(shipsUsed <= 0.05 * fromShips);
    QVERIFY(m.correction.head<2>().norm() < 10.0);
  }
};

QTEST_APPLESS_MAIN(TestRadarMatching)
#include "tst_radar_matching.moc"
