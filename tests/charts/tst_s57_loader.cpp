// GIVEN / WHEN / THEN behaviour of the S-57 loader on the real NOAA cells of ../shared/data/enc (never
// copied into this repository) and on broken files made in a temporary folder.
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "charts/s57/s57_loader.h"

using namespace reckoner::charts;
namespace fs = std::filesystem;

namespace {
const std::string kEnc = RECKONER_SHARED_DIR "/data/enc";

bool haveEnc() {
  return fs::is_directory(kEnc);
}

/// Feature counts per layer as `ogrinfo -ro -al -so` reports them (GDAL applies the updates).
std::map<std::string, std::size_t> ogrinfoCounts(const std::string& cell) {
  QProcess p;
  p.start("ogrinfo", {"-ro", "-al", "-so", QString::fromStdString(cell)});
  if (!p.waitForFinished(60000) || p.exitCode() != 0) return {};
  std::map<std::string, std::size_t> out;
  QString layer;
  for (const QString& line : QString(p.readAllStandardOutput()).split('\n')) {
    if (line.startsWith("Layer name: ")) layer = line.mid(12).trimmed();
    if (line.startsWith("Feature Count: ") && layer != "DSID")
      out[layer.toStdString()] = line.mid(15).trimmed().toULongLong();
  }
  return out;
}

void copyPrefix(const std::string& from, const QString& to, qint64 bytes) {
  QFile in(QString::fromStdString(from));
  QVERIFY(in.open(QIODevice::ReadOnly));
  QFile out(to);
  QVERIFY(out.open(QIODevice::WriteOnly));
  out.write(bytes < 0 ? in.readAll() : in.read(bytes));
}
}  // namespace

class TestS57Loader : public QObject {
  Q_OBJECT
 private slots:
  void findsTheCatalogue() { QVERIFY(!s57CatalogueDirectory().empty()); }

  void countsMatchOgrinfoForEveryCell() {
    // GIVEN every NOAA cell WHEN loaded with its updates THEN the feature count of every object class
    // equals ogrinfo's for the same cell.
    if (!haveEnc()) QSKIP("../shared/data/enc is absent: skipping the real-cell tests");
    const auto cells = findCells(kEnc);
    QCOMPARE(cells.size(), std::size_t(4));
    for (const auto& path : cells) {
      const CellPtr c = loadCell(path);
      const auto expected = ogrinfoCounts(path);
      QVERIFY2(!expected.empty(), "ogrinfo (gdal-bin) did not run");
      std::map<std::string, std::size_t> got;
      for (const auto& [cls, n] : c->countsByClass()) got[cls] = n;
      for (const auto& [cls, n] : expected) {
        if (n == 0 && !got.count(cls)) continue;
        QVERIFY2(got[cls] == n,
                 qPrintable(QString("%1 %2: %3 vs ogrinfo %4")
                                .arg(QString::fromStdString(c->info().name), QString::fromStdString(cls))
                                .arg(got[cls])
                                .arg(n)));
      }
      QCOMPARE(got.size(),
               static_cast<std::size_t>(std::count_if(expected.begin(), expected.end(),
                                                      [](const auto& e) { return e.second > 0; })));
      qInfo("%s: %zu features in %zu classes, update %d", c->info().name.c_str(), c->features().size(),
            got.size(), c->info().updateNumber);
    }
  }

  void theDefaultChartIsACompleteFictionalHarbour() {
    // GIVEN the chart compiled into the program WHEN loaded through the same path as any ENC
    const CellPtr c = loadCell(std::string(kDefaultChartPath));
    QCOMPARE(c->info().name, std::string("RK5SOUND"));
    QVERIFY(c->info().comment.find("NOT FOR NAVIGATION") != std::string::npos);
    QCOMPARE(c->coverage().size(), std::size_t{1});
    // THEN GDAL's own reading of the same bytes (the cell the build wrote) agrees class by class
    const auto expected = ogrinfoCounts(RECKONER_DEFAULT_CHART_FILE);
    QVERIFY2(!expected.empty(), "ogrinfo (gdal-bin) did not run");
    std::map<std::string, std::size_t> got;
    for (const auto& [cls, n] : c->countsByClass()) got[cls] = n;
    for (const auto& [cls, n] : expected) QCOMPARE(got[cls], n);
    // AND it has what the harbour must have
    std::set<double> bands;
    std::set<std::int64_t> lateral;
    int sectored = 0;
    for (const auto& f : c->features()) {
      if (f.objectClass == "DEPARE") bands.insert(*f.number("DRVAL1"));
      if (f.objectClass == "BOYLAT") lateral.insert(f.list("CATLAM").at(0));
      if (f.objectClass == "LIGHTS" && f.number("SECTR1")) ++sectored;
    }
    QVERIFY(bands.size() >= 5);
    QVERIFY(got["DEPCNT"] >= 5);
    QVERIFY(c->soundingCount() >= 100);
    QCOMPARE(lateral, (std::set<std::int64_t>{1, 2}));  // port and starboard marks
    QVERIFY(got["BOYLAT"] >= 6 && got["BOYCAR"] >= 1 && got["BOYISD"] >= 1 && got["TOPMAR"] >= 4);
    QVERIFY(got["LIGHTS"] >= 5 && sectored >= 2);
    QVERIFY(got["LNDARE"] >= 3);  // the mainland and two islands
    for (const char* cls : {"COALNE", "WRECKS", "OBSTRN", "RESARE", "ACHARE", "TSSLPT", "TSEZNE", "M_NSYS"})
      QVERIFY2(got[cls] >= 1, cls);
    // AND every sounding lies in a depth area whose range holds it (areas and soundings agree)
    int checked = 0, agreeing = 0;
    for (const auto& s : c->features()) {
      if (s.objectClass != "SOUNDG") continue;
      for (std::size_t i = 0; i < s.geometry.parts[0].size(); ++i) {
        const double depth = s.geometry.depthsM[i];
        ++checked;
        for (const auto& a : c->features())
          if (a.objectClass == "DEPARE" && a.geometry.contains(s.geometry.parts[0][i])) {
            const bool ok = depth >= *a.number("DRVAL1") - 0.05 && depth <= *a.number("DRVAL2") + 0.05;
            agreeing += ok;
            if (!ok)
              qWarning("sounding %.1f m at %.5f %.5f in a %.0f-%.0f m area", depth,
                       s.geometry.parts[0][i].latDeg, s.geometry.parts[0][i].lonDeg, *a.number("DRVAL1"),
                       *a.number("DRVAL2"));
            break;
          }
      }
    }
    QVERIFY(checked >= 100);
    QCOMPARE(agreeing, checked);
    // AND an unknown built-in chart is a named error
    QVERIFY_THROWS_EXCEPTION(ChartLoadError, loadCell("builtin:atlantis"));
  }

  void metadataAttributesAndGeometry() {
    if (!haveEnc()) QSKIP("../shared/data/enc is absent");
    const CellPtr c = loadCell(kEnc + "/US5WA22M/US5WA22M.000");
    const CellInfo& i = c->info();
    QCOMPARE(i.name, std::string("US5WA22M"));
    QCOMPARE(i.edition, std::string("40"));
    QCOMPARE(i.updateNumber, 4);
    QCOMPARE(i.updatesApplied.size(), std::size_t(4));
    QCOMPARE(i.agency, 550);
    QCOMPARE(i.intendedUsage, 5);
    QCOMPARE(i.compilationScale, 15000);
    QCOMPARE(i.issueDate.size(), std::size_t(8));
    QVERIFY(!c->coverage().empty());
    // NOTICE.md: -122.552, 47.231 to -122.354, 47.325
    QVERIFY(c->bounds().contains({47.28, -122.45}));
    QVERIFY(!c->bounds().contains({47.5, -122.45}));
    // Typed attributes: depth areas carry their depth range; buoys their shape and colour list.
    int depare = 0, lateral = 0;
    for (const auto& f : c->features()) {
      if (f.objectClass == "DEPARE") {
        ++depare;
        QVERIFY(f.number("DRVAL1").has_value());
        QCOMPARE(f.geometry.primitive, Primitive::Area);
        QVERIFY(!f.geometry.polygonStarts.empty());
      }
      if (f.objectClass == "BOYLAT") {
        ++lateral;
        QVERIFY(!f.list("COLOUR").empty());
        QCOMPARE(f.geometry.primitive, Primitive::Point);
        QVERIFY(c->bounds().contains(f.geometry.parts[0][0]));
      }
    }
    QVERIFY(depare > 10);
    QVERIFY(lateral >= 1);  // Tacoma has few lateral buoys and many beacons
    // Soundings are individual points, each with its depth.
    QVERIFY(c->soundingCount() > 100);
    for (const auto& f : c->features())
      if (f.objectClass == "SOUNDG") {
        QCOMPARE(f.geometry.depthsM.size(), f.geometry.parts[0].size());
        for (double d : f.geometry.depthsM) QVERIFY(std::isfinite(d) && d > -30.0 && d < 500.0);
      }
  }

  void aKnownBuoy() {
    if (!haveEnc()) QSKIP("../shared/data/enc is absent");
    const CellPtr c = loadCell(kEnc + "/US5BOSDC/US5BOSDC.000");
    const ChartFeature* buoy = nullptr;
    for (const auto& f : c->features())
      if (f.text("OBJNAM") == std::optional<std::string>("Mystic River Island End Point Buoy 4")) buoy = &f;
    QVERIFY(buoy);
    QCOMPARE(buoy->objectClass, std::string("BOYLAT"));
    QCOMPARE(buoy->objectCode, 17);
    QCOMPARE(*buoy->number("BOYSHP"), 1.0);
    QCOMPARE(*buoy->number("CATLAM"), 2.0);
    QCOMPARE(buoy->list("COLOUR"), std::vector<std::int64_t>{3});
    QVERIFY(std::abs(buoy->geometry.parts[0][0].latDeg - 42.3874441) < 1e-6);
    QVERIFY(std::abs(buoy->geometry.parts[0][0].lonDeg + 71.0547772) < 1e-6);
  }

  void brokenFilesAreNamedAndDoNotStopTheOthers() {
    QTemporaryDir dir;
    const QString root = dir.path();
    // Missing, and not S-57.
    QVERIFY_THROWS_EXCEPTION(ChartLoadError, loadCell((root + "/nothing.000").toStdString()));
    {
      QFile f(root + "/text.000");
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write("this is not an ISO 8211 file\n");
    }
    try {
      loadCell((root + "/text.000").toStdString());
      QFAIL("opened a text file");
    } catch (const ChartLoadError& e) {
      QVERIFY2(QString(e.what()).startsWith(root + "/text.000: "), e.what());
    }
    QVERIFY_THROWS_EXCEPTION(ChartLoadError, findCells((root + "/missing").toStdString()));
    if (!haveEnc()) QSKIP("../shared/data/enc is absent: the truncated and update cases need a real cell");
    // Truncated: the first 20 kB of a real cell.
    QDir(root).mkpath("trunc");
    copyPrefix(kEnc + "/US5BOSDC/US5BOSDC.000", root + "/trunc/US5BOSDC.000", 20000);
    // An update that cannot be read: a real base cell and a garbage .001.
    QDir(root).mkpath("upd");
    copyPrefix(kEnc + "/US5BOSCC/US5BOSCC.000", root + "/upd/US5BOSCC.000", -1);
    {
      QFile f(root + "/upd/US5BOSCC.001");
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write(QByteArray(3000, 'x'));
    }
    // A good cell beside them.
    QDir(root).mkpath("good");
    copyPrefix(kEnc + "/US5BOSDC/US5BOSDC.000", root + "/good/US5BOSDC.000", -1);
    std::size_t calls = 0;
    const LoadResult r =
        loadCharts({root.toStdString()}, [&](std::size_t done, std::size_t total, const std::string&) {
          ++calls;
          QVERIFY(done <= total);
        });
    QCOMPARE(r.cells.size(), std::size_t(1));
    QCOMPARE(r.cells[0]->info().name, std::string("US5BOSDC"));
    QCOMPARE(calls, std::size_t(4));  // good, text, trunc, upd
    QCOMPARE(r.failures.size(), std::size_t(3));
    std::map<std::string, std::string> why;
    for (const auto& f : r.failures)
      why[fs::path(f.file).parent_path().filename().string() + "/" + fs::path(f.file).filename().string()] =
          f.reason;
    for (const auto& [k, v] : why) qInfo("%s: %s", k.c_str(), v.c_str());
    QVERIFY(why.count("trunc/US5BOSDC.000"));
    QVERIFY(why.count("upd/US5BOSCC.000"));
  }
};

QTEST_GUILESS_MAIN(TestS57Loader)
#include "tst_s57_loader.moc"
