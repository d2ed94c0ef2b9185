// reckoner-bench: AIS (issue 19). The decoder (io/ais.h) on a realistic mix of sentences, and the target
// table (tracking/ais_targets.h) taking a position report from each of 2000 targets and computing their
// CPA/TCPA. Items are messages (decoder) and targets (table). docs/performance.md, "AIS (issue 19)".
#include <benchmark/benchmark.h>

#include <QImage>
#include <QPainter>
#include <chrono>
#include <string>
#include <vector>

#include "common/angles.h"
#include "common/percentile.h"

#include "geo/local_frame.h"
#include "io/ais.h"
#include "support/ais_corpus.h"
#include "tracking/ais_targets.h"
#include "ui/map/ecdis_ais.h"

namespace {
using namespace reckoner;
namespace ta = reckoner::test::ais;

/// 1000 messages in the proportions a coastal receiver hears (position reports dominate): 70% class A
/// position reports (types 1-3, 300 ships), 10% class B (18), 5% type 5 in two fragments, 5% type 24
/// (parts A and B), 5% base stations (4), 3% aids to navigation (21), 2% long range (27).
std::vector<std::string> mix() {
  std::vector<std::string> lines;
  int seq = 0;
  for (int i = 0; i < 1000; ++i) {
    const int k = i % 100;
    const long long mmsi = 200000000 + (i * 7919) % 300;
    if (k < 70) {
      lines.push_back(
          ta::sentence(ta::classA(1 + i % 3, mmsi, i % 16 == 1 ? 1 : 0, (i % 41) - 20, i % 300,
                                  -73000000 + i * 97, 24000000 + i * 53, (i * 37) % 3600, (i * 7) % 360)));
    } else if (k < 80) {
      lines.push_back(ta::sentence(ta::classB(18)));
    } else if (k < 85) {
      for (const auto& f : ta::fragments(ta::staticVoyage(), seq++ % 10)) lines.push_back(f);
    } else if (k < 90) {
      lines.push_back(ta::sentence(ta::staticReport(k % 2)));
    } else if (k < 95) {
      lines.push_back(ta::sentence(ta::baseStation()));
    } else if (k < 98) {
      lines.push_back(ta::sentence(ta::aidToNavigation("BUOY 7", "")));
    } else {
      lines.push_back(ta::sentence(ta::longRange(-4400, 2400, 12, 200)));
    }
  }
  return lines;
}

void BM_AisDecodeMix(benchmark::State& state) {
  const std::vector<std::string> lines = mix();
  std::int64_t messages = 0;
  for (auto _ : state) {
    io::AisDecoder d;
    for (const std::string& l : lines) {
      auto m = d.feed(l);
      benchmark::DoNotOptimize(m);
    }
    messages += static_cast<std::int64_t>(d.counters().decoded);
  }
  state.SetItemsProcessed(messages);
}
BENCHMARK(BM_AisDecodeMix)->Unit(benchmark::kMicrosecond);

/// 2000 class A targets within 20 NM of own ship; each iteration feeds one position report from each and
/// updates the table with own ship (lost rule, range, bearing, CPA/TCPA, dangerous flag).
void BM_AisTableUpdate2000(benchmark::State& state) {
  const geo::LocalFrame frame(50.0, -3.0);
  track::AisTableLimits limits;
  limits.maxSleeping = 2000;
  track::AisTargetTable table(limits);
  std::vector<io::AisMessage> reports;
  for (int i = 0; i < 2000; ++i) {
    io::AisMessage m;
    m.type = 1;
    m.mmsi = 200000000u + static_cast<std::uint32_t>(i);
    const int row = i / 50, column = i % 50;  // a 50-wide grid
    const geo::GeoPoint p = frame.toGeodetic({(column - 25) * 1400.0, (row - 20) * 900.0});
    m.latDeg = p.latDeg;
    m.lonDeg = p.lonDeg;
    m.sogKn = 5.0 + i % 20;
    m.cogDeg = (i * 37) % 360;
    m.headingDeg = (i * 37) % 360;
    m.navStatus = 0;
    reports.push_back(m);
  }
  const track::AisOwnShip own{frame.origin(), 2.0, 5.0};
  TimeUs now = 0;
  for (auto _ : state) {
    now += kMicrosPerSecond;
    for (const io::AisMessage& m : reports) table.feed(m, now);
    table.update(now, frame, own);
    benchmark::DoNotOptimize(table.size());
  }
  state.SetItemsProcessed(state.iterations() * 2000);
  const track::AisTableCounts c = table.counts();
  state.counters["targets"] = static_cast<double>(c.targets);
  state.counters["dangerous"] = static_cast<double>(c.dangerous);
}
BENCHMARK(BM_AisTableUpdate2000)->Unit(benchmark::kMillisecond);

/// 2000 AIS symbols (a fifth activated with vectors, a few selected, dangerous and lost, a quarter with
/// dimensions, some drawn to scale) painted into a 1920 x 1080 QImage; the frame times' p50 and p99 as
/// counters (ms).
void BM_AisPaint2000(benchmark::State& state) {
  std::vector<ui::AisSymbol> symbols;
  for (int i = 0; i < 2000; ++i) {
    ui::AisSymbol s;
    s.mmsi = 200000000u + static_cast<std::uint32_t>(i);
    const int row = i / 50, column = i % 50;  // a 50-wide grid
    s.xM = column * 380.0 + 200.0;
    s.yM = row * 260.0 + 200.0;
    s.headingGridRad = degToRad(i * 37 % 360);
    s.cogGridRad = s.headingGridRad;
    s.sogMps = 2.0 + i % 8;
    s.turn = i % 7 == 0 ? 1 : 0;
    if (i % 4 == 0) {
      s.toBowM = 60.0 + i % 200;
      s.toSternM = 20.0;
      s.toPortM = s.toStarboardM = 8.0;
    }
    s.activated = i % 5 == 0;
    s.selected = i == 10;
    s.dangerous = i % 97 == 0;
    s.lost = i % 101 == 0;
    symbols.push_back(s);
  }
  ui::AisPaintGeometry g;
  const double ppm = 1920.0 / 19500.0;  // the 2000 targets fill the image
  g.toWidget = [ppm](double x, double y) { return QPointF(x * ppm, 1080.0 - y * ppm); };
  g.pixelsPerMetre = ppm;
  QImage img(1920, 1080, QImage::Format_ARGB32_Premultiplied);
  std::vector<double> framesMs;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    img.fill(Qt::white);
    QPainter p(&img);
    ui::paintAisTargets(p, symbols, g);
    p.end();
    framesMs.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  state.SetItemsProcessed(state.iterations() * 2000);
  state.counters["p50_ms"] = percentileNearestRank(framesMs, 0.50);
  state.counters["p99_ms"] = percentileNearestRank(framesMs, 0.99);
}
BENCHMARK(BM_AisPaint2000)->Unit(benchmark::kMillisecond);

}  // namespace
