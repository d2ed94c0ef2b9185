// The own-ship filter on real recordings (issue 16): ../shared/data/nmea holds two voyages that nobody
// here recorded (NOTICE.md there). Each is replayed by `reckoner-cli replay` with its default settings
// after its GNSS sentences (GGA, GNS, RMC, GLL, VTG, GST) are withheld in windows; the receiver's own
// fixes in those windows are the reference. What must hold, per file:
//   - in the windows, RMS position error over RMS reported sd between 0.3 and 2 (the sd tells how far
//     off dead reckoning is, neither hiding the error nor crying wolf);
//   - outside them, with GNSS on, at least 75% of the fixes within 2 reported sd per axis;
//   - every file replays (exit 0).
// A receiver's fix is a few metres off the truth; against errors of tens of metres in the windows that
// is small, and outside them it is what the 2-sd test measures against. Without ../shared the test skips.
#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <GeographicLib/LocalCartesian.hpp>

#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "support/campaign_tools.h"
#include "support/resource_limits.h"

namespace {
namespace test = reckoner::test;

struct Window {
  double fromS, toS;  ///< seconds after the file's first fix
};

/// hhmmss.ss to seconds of the day; nullopt for an empty or short field.
std::optional<double> timeOfDay(const std::string& f) {
  if (f.size() < 6) return std::nullopt;
  try {
    return std::stoi(f.substr(0, 2)) * 3600.0 + std::stoi(f.substr(2, 2)) * 60.0 + std::stod(f.substr(4));
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

/// ddmm.mmm / dddmm.mmm with its hemisphere to signed degrees.
double degrees(const std::string& v, const std::string& hemisphere, int degreeDigits) {
  const double d = std::stod(v.substr(0, static_cast<std::size_t>(degreeDigits))) +
                   std::stod(v.substr(static_cast<std::size_t>(degreeDigits))) / 60.0;
  return hemisphere == "S" || hemisphere == "W" ? -d : d;
}

struct Fix {
  double latDeg, lonDeg;
};

/// The recording split: the lines replay gets (GNSS withheld in the windows) and the GGA fixes by time
/// of day (to the hundredth of a second), the reference.
struct Withheld {
  QByteArray nmea;
  std::map<long, Fix> fixes;
  double firstFixS = -1;
  int withheldSentences = 0;
};

long key(double tod) {
  return std::lround(tod * 100.0);
}

Withheld withhold(const QString& path, const std::vector<Window>& windows) {
  QFile f(path);
  Withheld w;
  if (!f.open(QIODevice::ReadOnly)) return w;
  const QList<QByteArray> lines = f.readAll().split('\n');
  // Pass 1: the first fix's time, the origin of the windows.
  std::optional<double> lastTime;
  for (const QByteArray& raw : lines) {
    const std::string l = raw.trimmed().toStdString();
    const auto star = l.find('*');
    if (l.size() < 7 || l[0] != '$' || star == std::string::npos) continue;
    const auto v = test::splitFields(l.substr(1, star - 1), ',');
    const std::string type = v[0].size() == 5 ? v[0].substr(2) : "";
    if (type == "GGA" && v.size() > 6 && !v[2].empty() && v[6] != "0" && v[6] != "6" && v[6] != "7" &&
        v[6] != "8") {
      const auto t = timeOfDay(v[1]);
      if (!t) continue;
      if (w.firstFixS < 0) w.firstFixS = *t;
      w.fixes.emplace(key(*t), Fix{degrees(v[2], v[3], 2), degrees(v[4], v[5], 3)});
    }
  }
  const auto withheldAt = [&](double tod) {
    for (const Window& win : windows)
      if (tod - w.firstFixS >= win.fromS && tod - w.firstFixS < win.toS) return true;
    return false;
  };
  // Pass 2: copy, dropping GNSS sentences in the windows (VTG, untimed, goes with the last timed one).
  for (const QByteArray& raw : lines) {
    const std::string l = raw.trimmed().toStdString();
    const auto star = l.find('*');
    if (l.size() >= 7 && l[0] == '$' && star != std::string::npos) {
      const auto v = test::splitFields(l.substr(1, star - 1), ',');
      const std::string type = v[0].size() == 5 ? v[0].substr(2) : "";
      std::optional<double> t;
      if ((type == "GGA" || type == "GNS" || type == "GST" || type == "RMC" || type == "ZDA") && v.size() > 1)
        t = timeOfDay(v[1]);
      else if (type == "GLL" && v.size() > 5)
        t = timeOfDay(v[5]);
      if (t) lastTime = t;
      const bool gnss =
          type == "GGA" || type == "GNS" || type == "RMC" || type == "GLL" || type == "VTG" || type == "GST";
      if (gnss && lastTime && withheldAt(*lastTime)) {
        ++w.withheldSentences;
        continue;
      }
    }
    w.nmea += raw;
    w.nmea += '\n';
  }
  return w;
}

}  // namespace

class TstRealRecordings : public QObject {
  Q_OBJECT

  void recording(const char* file, const std::vector<Window>& windows) {
    const QString path = QString(RECKONER_SHARED_DIR) + "/data/nmea/" + file;
    if (!QFile::exists(path)) QSKIP(qPrintable(path + " is absent (../shared/data/nmea)"));
    test::limitThisProcess(600, std::size_t{4} << 30);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const Withheld w = withhold(path, windows);
    QVERIFY2(w.firstFixS >= 0 && w.withheldSentences > 0, qPrintable(path + ": no GGA fix to withhold"));
    const QString nmea = dir.filePath("withheld.nmea");
    {
      QFile out(nmea);
      QVERIFY(out.open(QIODevice::WriteOnly));
      out.write(w.nmea);
    }
    QString err;
    QVERIFY2(test::runTool(test::toolPath(RECKONER_CLI, "RECKONER_CLI_UNDER_TEST"),
                           {"replay", "--nmea", nmea, "--out", dir.filePath("out"), "--quiet"}, err),
             qPrintable(err));
    test::Csv est;
    try {
      est = test::readCsv(dir.filePath("out/ownship.csv"));
    } catch (const std::exception& e) {
      QFAIL(e.what());
    }
    double err2 = 0, sd2 = 0;
    int inWindow = 0, axesOn = 0, axesWithin = 0;
    for (const auto& row : est.rows) {
      const std::string& utc = est.get(row, "utc");  // YYYY-MM-DDThh:mm:ss.ssssssZ
      const auto tod = timeOfDay(utc.substr(11, 2) + utc.substr(14, 2) + utc.substr(17, 9));
      if (!tod) continue;
      const auto fix = w.fixes.find(key(*tod));
      if (fix == w.fixes.end()) continue;
      const GeographicLib::LocalCartesian enu(fix->second.latDeg, fix->second.lonDeg, 0.0);
      double x = 0, y = 0, z = 0;
      enu.Forward(est.number(row, "est_lat_deg"), est.number(row, "est_lon_deg"), 0.0, x, y, z);
      const double sx = est.number(row, "sd_x_m"), sy = est.number(row, "sd_y_m");
      bool withheld = false;
      for (const Window& win : windows)
        withheld = withheld || (*tod - w.firstFixS >= win.fromS && *tod - w.firstFixS < win.toS);
      if (withheld) {
        err2 += x * x + y * y;
        sd2 += sx * sx + sy * sy;
        ++inWindow;
      } else {
        axesOn += 2;
        axesWithin += (std::abs(x) <= 2.0 * sx) + (std::abs(y) <= 2.0 * sy);
      }
    }
    QVERIFY2(inWindow > 0 && axesOn > 0, "no estimate at a fix's time");
    const double ratio = std::sqrt(err2 / sd2), within = static_cast<double>(axesWithin) / axesOn;
    qInfo(
        "%s: %d fixes withheld (%d sentences): RMS error %.1f m, RMS sd %.1f m, ratio %.2f; GNSS on: %.1f%% "
        "of %d axis errors within 2 sd",
        file, inWindow, w.withheldSentences, std::sqrt(err2 / inWindow), std::sqrt(sd2 / inWindow), ratio,
        100.0 * within, axesOn);
    QVERIFY2(ratio >= 0.3 && ratio <= 2.0, qPrintable(QString("RMS error / RMS sd %1").arg(ratio)));
    QVERIFY2(within >= 0.75, qPrintable(QString("%1% within 2 sd").arg(100.0 * within)));
  }

 private slots:
  /// Research icebreaker, 12 minutes at 8-11 kn, GNSS and gyro: two windows of 3 and 4 minutes.
  void icebreakerGnssAndGyro() {
    recording("openrvdas-NBP1406_seap-2014-08-01.nmea", {{120.0, 300.0}, {420.0, 660.0}});
  }
  /// Sailing boat, 148 s, GNSS, magnetic heading and a log: one window of 60 s (all the file allows).
  void sailingBoatWithLogAndCompass() { recording("gpsd-bundg_zeus_9.log", {{40.0, 100.0}}); }
};

QTEST_GUILESS_MAIN(TstRealRecordings)
#include "tst_real_recordings.moc"
