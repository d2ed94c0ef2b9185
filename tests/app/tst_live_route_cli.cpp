// Route monitoring in a live run (docs/routes.md, "Live"; issue 21): `reckoner-cli live --route` on the
// research icebreaker's real Seapath recording (../shared/data/nmea, 12 min at 8-11 kn), with a GPX
// route written here by hand from the recording's own first and last GGA fixes (not by the project's
// writer), sends the autopilot's XTE, RMB and APB with every own-ship epoch to --nmea-out. Checked
// against this file's own reading of the recording: every sentence's checksum, one RMB per own-ship
// epoch sent, the destination's id and position, the first range to it against the haversine distance between
// the two fixes (within 1%), ranges falling along the run, the arrival flagged at the end; XTE's
// distance and side equal to RMB's; a route file that cannot be read refused naming it.
#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>
#include <optional>

#include "app/cli_process.h"
#include "common/units.h"
#include "support/compare_near.h"

using reckoner::test::runCli;

namespace {

const QString kSeapath =
    QStringLiteral(RECKONER_SHARED_DIR "/data/nmea/openrvdas-NBP1406_seap-2014-08-01.nmea");
constexpr double kEarthRadiusM = 6371008.8;  // mean radius: haversine, an oracle good to 0.5%

struct Fix {
  double latDeg = 0.0, lonDeg = 0.0;
};

/// ddmm.mmmm with its hemisphere as degrees.
double nmeaDegrees(const QString& value, const QString& hemisphere, int degreeDigits) {
  const double deg = value.left(degreeDigits).toDouble() + value.mid(degreeDigits).toDouble() / 60.0;
  return hemisphere == QLatin1String("S") || hemisphere == QLatin1String("W") ? -deg : deg;
}

/// The recording's GGA fixes with a position (quality > 0), in order.
std::vector<Fix> ggaFixes(const QString& path) {
  QFile f(path);
  std::vector<Fix> out;
  if (!f.open(QIODevice::ReadOnly)) return out;
  while (!f.atEnd()) {
    const QString line = QString::fromLatin1(f.readLine()).trimmed();
    if (line.mid(3, 4) != QLatin1String("GGA,")) continue;
    const QStringList p = line.left(line.indexOf('*')).split(',');
    if (p.size() < 7 || p[6].toInt() == 0 || p[2].isEmpty()) continue;
    out.push_back({nmeaDegrees(p[2], p[3], 2), nmeaDegrees(p[4], p[5], 3)});
  }
  return out;
}

double haversineM(const Fix& a, const Fix& b) {
  const double rad = std::acos(-1.0) / 180.0;
  const double dLat = (b.latDeg - a.latDeg) * rad, dLon = (b.lonDeg - a.lonDeg) * rad;
  const double h = std::pow(std::sin(dLat / 2), 2) +
                   std::cos(a.latDeg * rad) * std::cos(b.latDeg * rad) * std::pow(std::sin(dLon / 2), 2);
  return 2.0 * kEarthRadiusM * std::asin(std::sqrt(h));
}

/// A GPX 1.1 route START -> END, written here (the project's writer is not the oracle of its reader).
QString gpxRoute(const Fix& from, const Fix& to) {
  const QString point = QStringLiteral("    <rtept lat=\"%1\" lon=\"%2\"><name>%3</name></rtept>\n");
  return QStringLiteral(
             "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
             "<gpx version=\"1.1\" creator=\"a hand\" xmlns=\"http://www.topografix.com/GPX/1/1\">\n"
             "  <rte><name>Passage</name>\n") +
         point.arg(from.latDeg, 0, 'f', 7).arg(from.lonDeg, 0, 'f', 7).arg(QStringLiteral("START")) +
         point.arg(to.latDeg, 0, 'f', 7).arg(to.lonDeg, 0, 'f', 7).arg(QStringLiteral("END")) +
         QStringLiteral("  </rte>\n</gpx>\n");
}

/// Whether a sentence's checksum is right.
bool checksumOk(const QByteArray& s) {
  const qsizetype star = s.lastIndexOf('*');
  if (!s.startsWith('$') || star < 0) return false;
  unsigned sum = 0;
  for (qsizetype i = 1; i < star; ++i) sum ^= static_cast<unsigned char>(s[i]);
  return s.mid(star + 1, 2).toUInt(nullptr, 16) == sum;
}

QStringList fieldsOf(const QByteArray& s) {
  return QString::fromLatin1(s.left(s.lastIndexOf('*'))).split(',');
}

}  // namespace

class TestLiveRouteCli : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() {
    if (!QFile::exists(kSeapath)) QSKIP("../shared/data/nmea is not here");
    QVERIFY(dir_.isValid());
  }

  void theAutopilotSentencesFollowTheRoute() {
    const std::vector<Fix> fixes = ggaFixes(kSeapath);
    QVERIFY(fixes.size() > 600);
    const Fix from = fixes.front(), to = fixes.back();
    const QString gpx = dir_.path() + "/passage.gpx";
    {
      QFile f(gpx);
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write(gpxRoute(from, to).toUtf8());
    }
    const QString out = dir_.path() + "/live", sent = dir_.path() + "/sent.nmea";
    const auto r = runCli({"live", "--file", kSeapath, "--file-rate", "200", "--route", gpx, "--nmea-out",
                           sent, "--out", out, "--quiet"});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    QFile f(sent);
    QVERIFY(f.open(QIODevice::ReadOnly));
    std::vector<QStringList> rmb, xte, apb;
    int bad = 0, gga = 0;
    for (const QByteArray& l : f.readAll().split('\n')) {
      const QByteArray s = l.trimmed();
      if (s.isEmpty()) continue;
      if (!checksumOk(s)) ++bad;
      const QByteArray kind = s.mid(3, 3);
      if (kind == "RMB") rmb.push_back(fieldsOf(s));
      if (kind == "XTE") xte.push_back(fieldsOf(s));
      if (kind == "APB") apb.push_back(fieldsOf(s));
      if (kind == "GGA") ++gga;
    }
    QCOMPARE(bad, 0);
    QFile own(out + "/ownship.csv");
    QVERIFY(own.open(QIODevice::ReadOnly));
    const auto ownRows = static_cast<std::size_t>(own.readAll().count('\n') - 1);
    qInfo("%zu own-ship rows, %d GGA sent; %zu RMB, %zu XTE, %zu APB; route %.0f m", ownRows, gga, rmb.size(),
          xte.size(), apb.size(), haversineM(from, to));
    // one of each with every own-ship epoch sent
    QCOMPARE(static_cast<int>(rmb.size()), gga);
    QVERIFY(rmb.size() > ownRows * 9 / 10);
    QCOMPARE(xte.size(), rmb.size());
    QCOMPARE(apb.size(), rmb.size());
    // $ECRMB,status,xte,dir,origin,dest,lat,N/S,lon,E/W,range,bearing,velocity,arrived,mode
    int valid = 0, rising = 0;
    std::optional<double> firstRange, lastRange;
    for (std::size_t i = 0; i < rmb.size(); ++i) {
      const QStringList& p = rmb[i];
      QCOMPARE(p.size(), 15);
      QCOMPARE(p[5], QStringLiteral("END"));
      RK_COMPARE_NEAR(nmeaDegrees(p[6], p[7], 2), to.latDeg, 1e-5);
      RK_COMPARE_NEAR(nmeaDegrees(p[8], p[9], 3), to.lonDeg, 1e-5);
      // XTE and APB give RMB's cross-track distance and direction to steer
      QCOMPARE(xte[i][3], p[2]);
      QCOMPARE(xte[i][4], p[3]);
      QCOMPARE(apb[i][3], p[2]);
      if (p[1] != QLatin1String("A")) continue;
      ++valid;
      const double range = p[10].toDouble();
      if (lastRange && range > *lastRange + 0.005) ++rising;  // NM: more than the rounding
      if (!firstRange) firstRange = range;
      lastRange = range;
    }
    QVERIFY(valid > static_cast<int>(rmb.size()) * 9 / 10);
    const double routeNm = reckoner::metresToNm(haversineM(from, to));
    qInfo("first range %.3f NM (route %.3f NM), last %.3f NM, %d rises", *firstRange, routeNm, *lastRange,
          rising);
    RK_COMPARE_NEAR(*firstRange / routeNm, 1.0, 0.01);
    QVERIFY(rising < valid / 20);
    QVERIFY(*lastRange < 0.1);                      // NM: at the last fix
    QCOMPARE(rmb.back()[13], QStringLiteral("A"));  // arrived
  }

  void aRouteFileThatCannotBeReadIsRefusedNamingIt() {
    const QString broken = dir_.path() + "/broken.rtz";
    QFile f(broken);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("<route><waypoints><waypoint id=\"1\"><position lat=\"north\" lon=\"1\"/></waypoint>");
    f.close();
    const auto r = runCli({"live", "--file", kSeapath, "--route", broken, "--out", dir_.path() + "/broken"});
    QVERIFY(r.code != 0);
    QVERIFY2(r.err.contains(QStringLiteral("broken.rtz")), qPrintable(r.err));
  }

 private:
  QTemporaryDir dir_;
};

QTEST_GUILESS_MAIN(TestLiveRouteCli)
#include "tst_live_route_cli.moc"
