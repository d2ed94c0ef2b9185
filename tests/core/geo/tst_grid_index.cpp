#include <QTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <vector>

#include "common/percentile.h"
#include "common/rng.h"
#include "geo/grid_index.h"

using namespace reckoner;

namespace {
/// Brute force: the items whose box touches cell (ix, iy).
std::vector<std::uint32_t> touching(const std::vector<geo::GridBox>& boxes, double c, std::int64_t ix,
                                    std::int64_t iy) {
  std::vector<std::uint32_t> out;
  const auto cellOf = [c](double v) { return static_cast<std::int64_t>(std::floor(v / c)); };
  for (std::uint32_t i = 0; i < boxes.size(); ++i) {
    const auto& b = boxes[i];
    if (cellOf(b.x0) <= ix && ix <= cellOf(b.x1) && cellOf(b.y0) <= iy && iy <= cellOf(b.y1))
      out.push_back(i);
  }
  return out;
}
}  // namespace

class TestGridIndex : public QObject {
  Q_OBJECT
 private slots:
  void everyCellHoldsExactlyTheBoxesTouchingIt_data() {
    QTest::addColumn<double>("spreadM");
    QTest::newRow("dense (compact items)") << 2000.0;
    QTest::newRow("sparse (items spread over 200 km)") << 200000.0;
  }
  void everyCellHoldsExactlyTheBoxesTouchingIt() {
    QFETCH(double, spreadM);
    Rng rng(7, 0);
    std::vector<geo::GridBox> boxes;
    for (int i = 0; i < 300; ++i) {
      const double x = (rng.uniform() - 0.5) * spreadM, y = (rng.uniform() - 0.5) * spreadM;
      const double w = i % 3 == 0 ? 0.0 : rng.uniform() * 250.0, h = i % 3 == 0 ? 0.0 : rng.uniform() * 250.0;
      boxes.push_back({x, y, x + w, y + h});
    }
    const double c = 100.0;
    const geo::GridIndex index(c, boxes);
    std::set<std::pair<std::int64_t, std::int64_t>> cells;
    for (const auto& b : boxes)
      for (std::int64_t ix = index.cellOf(b.x0) - 1; ix <= index.cellOf(b.x1) + 1; ++ix)
        for (std::int64_t iy = index.cellOf(b.y0) - 1; iy <= index.cellOf(b.y1) + 1; ++iy)
          cells.insert({ix, iy});
    for (const auto& [ix, iy] : cells) {
      const auto got = index.cell(ix, iy);
      const std::vector<std::uint32_t> v(got.begin(), got.end());
      QCOMPARE(v, touching(boxes, c, ix, iy));  // ascending, no duplicates
    }
    QVERIFY(index.cell(index.maxX() + 1, index.minY()).empty());
    QVERIFY(index.cell(index.minX() - 1, index.minY()).empty());
  }
  void unusableBoxesAreLeftOut() {
    const double inf = std::numeric_limits<double>::infinity();
    const geo::GridIndex index(50.0, {{0.0, 0.0, 10.0, 10.0},
                                      {std::nan(""), 0.0, 1.0, 1.0},
                                      {0.0, 0.0, inf, 1.0},
                                      {1e300, 1e300, 1e300, 1e300},
                                      {5.0, 5.0, 1.0, 1.0}});  // x1 < x0
    QCOMPARE(index.minX(), std::int64_t(0));
    QCOMPARE(index.maxX(), std::int64_t(0));
    const auto c = index.cell(0, 0);
    QCOMPARE(std::vector<std::uint32_t>(c.begin(), c.end()), std::vector<std::uint32_t>{0});
    QVERIFY(geo::GridIndex(10.0, {}).empty());
    QVERIFY(!geo::GridIndex(10.0, {}).inside(0, 0));
  }
  void badCellSizeIsRejected() {
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, geo::GridIndex(0.0, {}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, geo::GridIndex(std::nan(""), {}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, geo::GridIndex(1e-9, {{-1e8, 0.0, 1e8, 0.0}}));
  }
  void percentileIsTheNearestRank() {
    // 20 samples 1..20: the 95th percentile is the 19th smallest (ceil(0.95 * 20) = 19).
    std::vector<double> v;
    for (int i = 20; i >= 1; --i) v.push_back(i);
    QCOMPARE(percentile95(v), 19.0);
    QCOMPARE(percentileNearestRank(v, 0.5), 10.0);
    QCOMPARE(percentileNearestRank(v, 1.0), 20.0);
    QCOMPARE(percentileNearestRank(v, 0.01), 1.0);
    QCOMPARE(percentile95({7.0}), 7.0);
    QVERIFY(std::isnan(percentile95({})));
    QCOMPARE(percentile95({}, 3.0), 3.0);
    // 21 samples: ceil(19.95) = 20th smallest.
    v.push_back(21.0);
    QCOMPARE(percentile95(v), 20.0);
  }
};

QTEST_APPLESS_MAIN(TestGridIndex)
#include "tst_grid_index.moc"
