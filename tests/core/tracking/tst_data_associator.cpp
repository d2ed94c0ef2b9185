// The data associator on its own: global nearest neighbour on hand-made cost and gate tables.
#include <QTest>

#include <stdexcept>

#include "tracking/data_associator.h"

using namespace reckoner::track;

namespace {
HypothesisTable table(std::size_t plots, std::vector<double> miss, std::vector<Hypothesis> pairs) {
  HypothesisTable t;
  t.plots = plots;
  t.missCost = std::move(miss);
  t.pairs = std::move(pairs);
  return t;
}
}  // namespace

class TestDataAssociator : public QObject {
  Q_OBJECT
 private slots:
  void theTotalCostIsMinimisedNotEachTracksOwn() {
    // Track 0 is nearest to plot 0, but giving plot 0 to track 1 and plot 1 to track 0 costs 4, not 11.
    const auto a =
        associateNearest(table(2, {20.0, 20.0}, {{0, 0, 1.0}, {0, 1, 2.0}, {1, 0, 2.0}, {1, 1, 10.0}}));
    QCOMPARE(a.trackOfPlot, (std::vector<int>{1, 0}));
    QCOMPARE(a.largestCluster, std::size_t{4});
  }
  void aMissCheaperThanThePairLeavesBothFree() {
    const auto a = associateNearest(table(1, {1.0}, {{0, 0, 5.0}}));
    QCOMPARE(a.trackOfPlot, (std::vector<int>{-1}));
  }
  void aPairOutsideTheGateIsNeverTaken() {
    // Track 1 has no pair with plot 1 (outside its gate) however dear its miss.
    const auto a = associateNearest(table(2, {100.0, 100.0}, {{0, 0, 1.0}, {1, 0, 2.0}}));
    QCOMPARE(a.trackOfPlot, (std::vector<int>{0, -1}));
  }
  void theCheaperPairLosesWhenItsTrackCanAffordToMiss() {
    // Both tracks want plot 0; track 1's miss is cheap, track 0's dear: track 0 takes it.
    const auto a = associateNearest(table(1, {50.0, 3.0}, {{0, 0, 4.0}, {1, 0, 1.0}}));
    QCOMPARE(a.trackOfPlot, (std::vector<int>{0}));
  }
  void separateClustersAreSolvedApart() {
    // Tracks 0, 1 with plots 0, 1; track 2 alone with plot 3; plot 2 with nobody.
    const auto a =
        associateNearest(table(4, {20.0, 20.0, 20.0}, {{0, 0, 1.0}, {1, 0, 1.5}, {1, 1, 1.0}, {2, 3, 0.5}}));
    QCOMPARE(a.trackOfPlot, (std::vector<int>{0, 1, -1, 2}));
    QCOMPARE(a.largestCluster, std::size_t{4});
  }
  void noTracksLeaveEveryPlotFree() {
    const auto a = associateNearest(table(3, {}, {}));
    QCOMPARE(a.trackOfPlot, (std::vector<int>{-1, -1, -1}));
    QCOMPARE(a.largestCluster, std::size_t{0});
  }
  void aPairOutsideTheTableThrows() {
    QVERIFY_THROWS_EXCEPTION(std::out_of_range, (void)associateNearest(table(1, {1.0}, {{0, 1, 1.0}})));
    QVERIFY_THROWS_EXCEPTION(std::out_of_range, (void)associateNearest(table(1, {1.0}, {{1, 0, 1.0}})));
  }
};

QTEST_APPLESS_MAIN(TestDataAssociator)
#include "tst_data_associator.moc"
