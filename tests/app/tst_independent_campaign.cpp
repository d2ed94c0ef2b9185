// The own-ship filter on data it did not make (issue 16): an independent truth generator
// (support/independent, written apart from core/sim: ships on legs through the water in a current,
// rate-limited turns, a gyro with a calibration error, a log with scale and offset errors, a Loran-C
// with its slow additional-secondary-factor bias, GNSS 3-5 m) writes NMEA; `reckoner-cli replay` reads
// it with its default settings and no per-file tuning; this test scores the output against the
// generator's truth, converted with GeographicLib alone (nothing of Reckoner's code does the scoring).
//
// What must hold, per family (GNSS outage of 10 minutes: with a log, with a log and Loran-C, and with a
// gyro but no log), over the outage's axis errors of every run: 90-99% within 1.96 reported sd, and RMS
// error / RMS sd in [0.6, 1.4] (errors inside the sd, and the sd not absurdly larger); with a log, the
// p95 position error at the end of the outage under 60 m (without one, held to its measured figure).
// docs/consistency.md has the figures.
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <GeographicLib/LocalCartesian.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <vector>

#include "support/campaign_tools.h"
#include "support/compare_near.h"
#include "support/resource_limits.h"

namespace {
namespace test = reckoner::test;

struct Row {
  double latDeg = 0, lonDeg = 0, sdX = 0, sdY = 0;
  bool gpsOn = true;
  double tS = 0;
};

/// Rows keyed by their utc column to the second (the first 19 characters of ISO 8601).
using Rows = std::map<std::string, Row>;

/// Reads a CSV into rows; `take` fills a Row from one of its rows.
template <class F>
Rows readRows(const QString& path, F take) {
  const test::Csv csv = test::readCsv(path);
  Rows rows;
  for (const auto& v : csv.rows) rows[csv.get(v, "utc").substr(0, 19)] = take(csv, v);
  return rows;
}

struct Family {
  std::vector<double> normalised;  ///< axis error / axis sd, over every outage row of every run
  double sumErr2 = 0, sumSd2 = 0;
  std::vector<double> endErrorM;  ///< position error at the end of each run's outage
  int runs = 0;
  std::vector<double> noiseScale;  ///< the adaptive GNSS noise's final scale, both axes of every run

  [[nodiscard]] double within(double k) const {
    const auto n =
        std::count_if(normalised.begin(), normalised.end(), [k](double z) { return std::abs(z) <= k; });
    return normalised.empty() ? 0.0 : static_cast<double>(n) / static_cast<double>(normalised.size());
  }
  [[nodiscard]] double ratio() const { return std::sqrt(sumErr2 / sumSd2); }
  [[nodiscard]] double p95End() const { return test::percentile95(endErrorM); }
};

/// Generates one run, replays it, and adds its outage rows to the family.
enum class Kind { DeadReckoning, LoranC, NoLog, PositionOnly };

/// Each family's output folder, label, generator options and seed offset.
struct KindInfo {
  const char* dir;
  const char* label;
  QStringList generator;
  int seedOffset;
};
KindInfo infoOf(Kind kind) {
  switch (kind) {
    case Kind::LoranC:
      return {"loran", "Loran-C on", {"--loran"}, 100};
    case Kind::NoLog:
      return {"nolog", "gyro, no log", {"--no-log"}, 200};
    case Kind::PositionOnly:
      return {"posonly", "position only", {"--no-log", "--no-gyro"}, 400};
    case Kind::DeadReckoning:
      break;
  }
  return {"dr", "dead reckoning", {}, 0};
}

/// What else a run is given: generator and replay options, and which rows are scored (the outage, or
/// the rows with GNSS on from 600 s, after the filter has settled).
struct Extra {
  QStringList generator, replay;
  bool scoreGnssOn = false;
  QString tag;
};

void score(const QTemporaryDir& dir, int seed, Kind kind, Family& fam, const Extra& extra = {}) {
  const KindInfo info = infoOf(kind);
  const QString out = dir.filePath(QString("%1%2-%3").arg(info.dir, extra.tag).arg(seed));
  QString err;
  QStringList genArgs{"ownship", "--seed", QString::number(seed), "--out", out};
  genArgs << info.generator << extra.generator;
  QVERIFY2(test::runTool(test::toolPath(RECKONER_INDEP_SIM, "RECKONER_INDEP_SIM"), genArgs, err),
           qPrintable(err));
  QStringList replayArgs{"replay", "--nmea", out + "/ownship.nmea", "--out", out + "/replay", "--quiet"};
  replayArgs << extra.replay;
  QVERIFY2(test::runTool(test::toolPath(RECKONER_CLI, "RECKONER_CLI_UNDER_TEST"), replayArgs, err),
           qPrintable(err));
  if (extra.replay.contains("--adaptive-gnss")) {  // the estimated scale on the receiver's R
    QFile f(out + "/replay/summary.json");
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QJsonArray s = QJsonDocument::fromJson(f.readAll())
                             .object()["own_ship_filter"]
                             .toObject()["gnss_noise_scale"]
                             .toArray();
    for (const auto& v : s) fam.noiseScale.push_back(v.toDouble());
  }
  Rows truth, est;
  try {
    truth = readRows(out + "/truth.csv", [](const test::Csv& c, const auto& v) {
      Row r;
      r.tS = c.number(v, "t_s");
      r.latDeg = c.number(v, "lat_deg");
      r.lonDeg = c.number(v, "lon_deg");
      r.gpsOn = c.get(v, "gps_on") == "1";
      return r;
    });
    est = readRows(out + "/replay/ownship.csv", [](const test::Csv& c, const auto& v) {
      Row r;
      r.latDeg = c.number(v, "est_lat_deg");
      r.lonDeg = c.number(v, "est_lon_deg");
      r.sdX = c.number(v, "sd_x_m");
      r.sdY = c.number(v, "sd_y_m");
      return r;
    });
  } catch (const std::exception& e) {
    QFAIL(qPrintable(out + ": " + e.what()));
  }
  QVERIFY2(truth.size() > 1000, qPrintable(out + "/truth.csv: too few rows"));
  QVERIFY2(est.size() > 1000, qPrintable(out + "/replay/ownship.csv: too few rows"));
  // The outage: truth rows with gps_on 0. Errors east/north at the truth point (the replay's grid
  // axes differ from east/north by the grid convergence, well under a degree within the 20 km here).
  double lastOutageT = -1, endErr = NAN;
  int rows = 0;
  for (const auto& [utc, t] : truth) {
    if (t.gpsOn != extra.scoreGnssOn || (extra.scoreGnssOn && t.tS < 600.0)) continue;
    const auto e = est.find(utc);
    QVERIFY2(e != est.end(), qPrintable(out + ": no estimate at " + QString::fromStdString(utc)));
    const GeographicLib::LocalCartesian enu(t.latDeg, t.lonDeg, 0.0);
    double x = 0, y = 0, z = 0;
    enu.Forward(e->second.latDeg, e->second.lonDeg, 0.0, x, y, z);
    fam.normalised.push_back(x / e->second.sdX);
    fam.normalised.push_back(y / e->second.sdY);
    fam.sumErr2 += x * x + y * y;
    fam.sumSd2 += e->second.sdX * e->second.sdX + e->second.sdY * e->second.sdY;
    if (t.tS > lastOutageT) {
      lastOutageT = t.tS;
      endErr = std::hypot(x, y);
    }
    ++rows;
  }
  QVERIFY2(rows >= 500, qPrintable(out + ": the outage has too few rows"));
  fam.endErrorM.push_back(endErr);
  ++fam.runs;
}

}  // namespace

/// The position-only family's p95 at the end of the outage when its test was written (2026-12-02).
constexpr double kPositionOnlyP95M = 3423.0;

class TstIndependentCampaign : public QObject {
  Q_OBJECT

  void campaign(Kind kind) {
    reckoner::test::limitThisProcess(1200, std::size_t{4} << 30);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    Family fam;
    constexpr int kRuns = 24;
    const KindInfo info = infoOf(kind);
    for (int seed = 1; seed <= kRuns; ++seed) {
      score(dir, seed + info.seedOffset, kind, fam);
      if (QTest::currentTestFailed()) return;
    }
    const double w = fam.within(1.96), r = fam.ratio(), p95 = fam.p95End();
    qInfo(
        "%s: %d runs, %zu axis errors in the outage: %.1f%% within 1.96 sd, RMS error / RMS sd %.2f, "
        "p95 error at the end of the outage %.1f m",
        info.label, fam.runs, fam.normalised.size(), 100.0 * w, r, p95);
    QVERIFY2(w >= 0.90 && w <= 0.99, qPrintable(QString("within 1.96 sd: %1%").arg(100.0 * w, 0, 'f', 1)));
    if (kind == Kind::PositionOnly) {
      // Nothing but the last fixes: the ship model's turn rate lets it turn anywhere in ten minutes, so
      // the sd is larger than the error of ships that mostly held their legs; the real recordings'
      // band [0.3, 2] (tst_real_recordings), and the p95 held to its measured figure plus 15%.
      QVERIFY2(r >= 0.3 && r <= 2.0, qPrintable(QString("RMS error / RMS sd %1").arg(r, 0, 'f', 2)));
      QVERIFY2(p95 < kPositionOnlyP95M * 1.15,
               qPrintable(QString("p95 end-of-outage error %1 m (recorded %2 m)")
                              .arg(p95, 0, 'f', 1)
                              .arg(kPositionOnlyP95M)));
      return;
    }
    QVERIFY2(r >= 0.6 && r <= 1.4, qPrintable(QString("RMS error / RMS sd %1").arg(r, 0, 'f', 2)));
    if (kind == Kind::NoLog) {
      // No speed sensor: ten minutes at an unknown speed (the generator changes it by up to 3 kn a leg)
      // cannot meet 60 m; the figure is held to what was measured (2026-12-02, docs/consistency.md) plus
      // 15%, so that a change that makes it worse fails.
      QVERIFY2(p95 < 800.0,
               qPrintable(QString("p95 end-of-outage error %1 m (recorded 702 m)").arg(p95, 0, 'f', 1)));
      return;
    }
    // Issue 16: the p95 position error at the end of ten minutes of pure dead reckoning under 60 m (at
    // 6-14 kn, in a current known before the outage). With Loran-C the same bound holds (it only adds
    // information); docs/consistency.md has the figures.
    QVERIFY2(p95 < 60.0,
             qPrintable(QString("p95 end-of-outage error %1 m (limit 60 m)").arg(p95, 0, 'f', 1)));
  }

 private slots:
  void deadReckoningOutages() { campaign(Kind::DeadReckoning); }
  void loranCOutages() { campaign(Kind::LoranC); }
  /// GNSS and gyro only (the icebreaker's outfit): the ship motion model's dead reckoning on a heading.
  void gyroWithoutLogOutages() { campaign(Kind::NoLog); }
  /// GNSS only: the replay dead-reckons on the ship model through the outage (time-only epochs).
  void positionOnlyOutages() { campaign(Kind::PositionOnly); }

  /// A receiver whose GST claims a third of its noise: with GNSS on, the filter believes it and its sd
  /// is several times too small; `--adaptive-gnss on` estimates the scale on R (about 9) and recovers
  /// the consistency the same filter has with an honest GST; with an honest GST it changes little.
  void adaptiveGnssNoiseRecoversAnUnderstatedGst() {
    reckoner::test::limitThisProcess(1200, std::size_t{4} << 30);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    constexpr int kRuns = 8;
    const QStringList understated{"--gst-understates", "3"};
    Family plain, adaptive, honest, honestAdaptive;
    for (int seed = 301; seed < 301 + kRuns; ++seed) {
      score(dir, seed, Kind::DeadReckoning, plain, {understated, {}, true, "u"});
      score(dir, seed, Kind::DeadReckoning, adaptive, {understated, {"--adaptive-gnss", "on"}, true, "ua"});
      score(dir, seed, Kind::DeadReckoning, honest, {{}, {}, true, "h"});
      score(dir, seed, Kind::DeadReckoning, honestAdaptive, {{}, {"--adaptive-gnss", "on"}, true, "ha"});
      if (QTest::currentTestFailed()) return;
    }
    std::vector<double> scale = adaptive.noiseScale;
    std::sort(scale.begin(), scale.end());
    QVERIFY(scale.size() == 2 * static_cast<std::size_t>(kRuns));
    qInfo(
        "GNSS on, GST understating 3x: RMS error / RMS sd %.2f (%.1f%% within 1.96 sd); adaptive %.2f "
        "(%.1f%%), "
        "scale on R %.2f to %.2f (9 expected); honest GST %.2f (%.1f%%), adaptive %.2f (%.1f%%)",
        plain.ratio(), 100.0 * plain.within(1.96), adaptive.ratio(), 100.0 * adaptive.within(1.96),
        scale.front(), scale.back(), honest.ratio(), 100.0 * honest.within(1.96), honestAdaptive.ratio(),
        100.0 * honestAdaptive.within(1.96));
    QVERIFY2(plain.ratio() > 3.0, "the understated GST did not make the filter over-confident");
    QVERIFY2(scale.front() > 6.0 && scale.back() < 13.0, "the estimated scale is not about 9");
    // Adaptive on an understated GST is as consistent as the plain filter on an honest one (15%),
    RK_COMPARE_NEAR(adaptive.ratio(), honest.ratio(), 0.15 * honest.ratio());
    // and the adaptive estimate changes an honest receiver's consistency by at most 10%.
    RK_COMPARE_NEAR(honestAdaptive.ratio(), honest.ratio(), 0.1 * honest.ratio());
  }
};

QTEST_GUILESS_MAIN(TstIndependentCampaign)
#include "tst_independent_campaign.moc"
