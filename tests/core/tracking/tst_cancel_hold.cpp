// The operator's cancellation and acquisition switch on the default scenario: a cancelled track's
// vessel is not acquired again for the hold (2 min) and is acquired again soon after it; with automatic
// acquisition off nothing is acquired until it is switched on again.
#include <QTest>

#include <algorithm>

#include "files/scenario_json.h"
#include "resources/embedded.h"
#include "sim/simulation_engine.h"
#include "support/compare_near.h"

using namespace reckoner;

namespace {

sim::Scenario builtinDefault() {
  const auto* f = resources::findScenario("default");
  if (!f) qFatal("no built-in default scenario");
  return files::parseScenario(f->text, "builtin:default");
}

/// Steps until the simulated time reaches tS; returns the first time (s) a track of `targetId` is seen
/// (any status), or a negative value.
double runWatching(sim::SimulationEngine& e, double tS, int targetId) {
  double seen = -1.0;
  while (toSeconds(e.timeUs()) < tS - 1e-9) {
    const sim::SimFrame f = e.step();
    const bool present = std::any_of(f.tracks.begin(), f.tracks.end(),
                                     [&](const sim::TrackSnapshot& t) { return t.targetId == targetId; });
    if (present && seen < 0.0) seen = toSeconds(f.timeUs);
  }
  return seen;
}

std::optional<int> trackOf(const sim::SimulationEngine& e, int targetId) {
  for (const auto& t : e.trackers().tracks())
    if (t.status == track::TrackStatus::Confirmed && t.tag() == targetId) return t.id;
  return std::nullopt;
}

}  // namespace

class TestCancelHold : public QObject {
  Q_OBJECT
 private slots:
  void aCancelledTracksVesselIsHeldBackForTwoMinutes() {
    const sim::Scenario s = builtinDefault();
    sim::SimulationEngine e(s, s.seed);
    runWatching(e, 300.0, -2);
    const auto id = trackOf(e, 1);
    QVERIFY(id);
    QVERIFY(e.cancelTrack(*id));
    const double cancelledS = toSeconds(e.timeUs());
    // THEN no track follows vessel 1 during the hold
    QCOMPARE(runWatching(e, cancelledS + track::CancelledTracks::kHoldS - 1.0, 1), -1.0);
    // AND soon after it, one does again (the hold, not the tracker, kept it away)
    const double again = runWatching(e, cancelledS + track::CancelledTracks::kHoldS + 30.0, 1);
    QVERIFY2(again > 0.0, "vessel 1 never acquired again");
    qInfo("vessel 1 acquired again %.0f s after the cancellation", again - cancelledS);
    RK_COMPARE_NEAR(again - cancelledS, track::CancelledTracks::kHoldS + 5.0, 5.0);
    // AND the other vessels kept their tracks
    QVERIFY(trackOf(e, 2));
    QVERIFY(trackOf(e, 3));
  }

  void withAutomaticAcquisitionOffNothingIsAcquired() {
    const sim::Scenario s = builtinDefault();
    sim::SimulationEngine e(s, s.seed);
    runWatching(e, 300.0, -2);
    e.setAutoAcquire(false);
    e.cancelAllTracks();
    const double offS = toSeconds(e.timeUs());
    bool any = false;
    while (toSeconds(e.timeUs()) < offS + 300.0) any = any || !e.step().tracks.empty();
    QVERIFY(!any);
    // WHEN switched on again THEN the vessels are acquired (those cancelled once the hold is over)
    e.setAutoAcquire(true);
    runWatching(e, offS + 400.0, -2);
    QVERIFY(trackOf(e, 1));
  }
};

QTEST_GUILESS_MAIN(TestCancelHold)
#include "tst_cancel_hold.moc"
