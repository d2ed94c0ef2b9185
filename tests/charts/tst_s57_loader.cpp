// GIVEN / WHEN / THEN behaviour of the S-57 loader on the real NOAA cells of ../shared/data/enc (never
// copied into this repository) and on broken files made in a temporary folder.
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <sys/stat.h>

#include <QElapsedTimer>

#include <cmath>
#include <filesystem>
#include <map>
#include <random>
#include <set>

#include "charts/s57/iso8211.h"
#include "charts/s57/s57_checks.h"
#include "charts/s57/s57_loader.h"
#include "support/compare_near.h"
#include "support/resource_limits.h"

using namespace reckoner::charts;
namespace s57 = reckoner::charts::s57;
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

QByteArray readAll(const std::string& path) {
  QFile in(QString::fromStdString(path));
  return in.open(QIODevice::ReadOnly) ? in.readAll() : QByteArray();
}

bool writeAll(const QString& path, const QByteArray& bytes) {
  QFile out(path);
  return out.open(QIODevice::WriteOnly) && out.write(bytes) == bytes.size();
}

std::string_view view(const QByteArray& b) {
  return {b.constData(), static_cast<std::size_t>(b.size())};
}

/// Where each record starts, read from the five-digit record lengths alone (independent of the
/// loader's walker).
std::vector<qint64> recordStarts(const QByteArray& b) {
  std::vector<qint64> out;
  for (qint64 at = 0; at + 5 <= b.size();) {
    out.push_back(at);
    const qint64 length = b.mid(at, 5).toLongLong();
    if (length <= 0) break;
    at += length;
  }
  return out;
}

/// 4208 -> "4,208", written here rather than borrowed from the loader.
std::string grouped(qint64 n) {
  std::string d = std::to_string(n), out;
  for (std::size_t i = 0; i < d.size(); ++i) {
    if (i > 0 && (d.size() - i) % 3 == 0) out += ',';
    out += d[i];
  }
  return out;
}

/// The file and message of the ChartLoadError that loadCell() throws, or two empty strings.
std::pair<std::string, std::string> loadError(const QString& path) {
  try {
    loadCell(path.toStdString());
  } catch (const ChartLoadError& e) {
    return {e.file(), e.what()};
  }
  return {};
}

const LoadFailure* failureOf(const LoadResult& r, const QString& file) {
  for (const auto& f : r.failures)
    if (f.file == file.toStdString()) return &f;
  return nullptr;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

/// The byte offset in `bytes` of the first coordinate field (SG2D) of a record at or after `from`.
std::size_t firstCoordinate(const QByteArray& bytes, std::size_t from) {
  std::size_t at = 0;
  reckoner::charts::iso8211::walk(view(bytes), [&](const reckoner::charts::iso8211::Record& r) {
    if (r.offset < from) return true;
    const auto* f = r.find("SG2D");
    if (!f) return true;
    at = static_cast<std::size_t>(f->data.data() - bytes.constData());
    return false;
  });
  return at;
}

/// The northernmost vertex of a cell: the byte offset of its YCOO (b24, little-endian) in `bytes`.
std::size_t northernmostLatitude(const QByteArray& bytes) {
  std::size_t best = 0;
  std::int32_t bestY = INT32_MIN;
  reckoner::charts::iso8211::walk(view(bytes), [&](const reckoner::charts::iso8211::Record& r) {
    for (const char* tag : {"SG2D", "SG3D"}) {
      const auto* f = r.find(tag);
      if (!f) continue;
      const std::size_t stride = tag[2] == '2' ? 8 : 12;
      for (std::size_t i = 0; i + stride <= f->data.size(); i += stride) {
        std::uint32_t u = 0;
        for (int k = 3; k >= 0; --k)
          u = (u << 8) | static_cast<unsigned char>(f->data[i + static_cast<std::size_t>(k)]);
        const auto y = static_cast<std::int32_t>(u);
        if (y > bestY) {
          bestY = y;
          best = static_cast<std::size_t>(f->data.data() - bytes.constData()) + i;
        }
      }
    }
    return true;
  });
  return best;
}
}  // namespace

class TestS57Loader : public QObject {
  Q_OBJECT
 private slots:
  // Damaged and mutated cells below: a hang or an unbounded allocation fails inside these limits.
  void initTestCase() { reckoner::test::limitThisProcess(600, std::size_t{4} << 30); }
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
    RK_COMPARE_NEAR(buoy->geometry.parts[0][0].latDeg, 42.3874441, 1e-6);
    RK_COMPARE_NEAR(buoy->geometry.parts[0][0].lonDeg, -71.0547772, 1e-6);
  }

  void givenACellCutInHalfAtARecordBoundary_whenLoaded_thenItFailsCountingTheMissingRecords() {
    if (!haveEnc()) QSKIP("../shared/data/enc is absent");
    // GIVEN US5WA22M.000 cut at the first record boundary past half its length (GDAL reads what is
    // left without a word)
    QTemporaryDir dir;
    const QByteArray whole = readAll(kEnc + "/US5WA22M/US5WA22M.000");
    const auto starts = recordStarts(whole);
    QVERIFY(starts.size() > 1000);
    const qint64 cut = *std::lower_bound(starts.begin(), starts.end(), whole.size() / 2);
    const QString cell = dir.path() + "/US5WA22M.000";
    QVERIFY(writeAll(cell, whole.left(cut)));
    // WHEN it is loaded THEN it fails, naming the cell and what its DSID says it should hold
    const auto [file, what] = loadError(cell);
    qInfo("%s", what.c_str());
    QCOMPARE(file, cell.toStdString());
    QVERIFY2(what.rfind(cell.toStdString() + ": holds ", 0) == 0, what.c_str());
    QVERIFY2(contains(what, " records, its DSID says ") && contains(what, "(truncated or damaged)"),
             what.c_str());
    QVERIFY2(contains(what, "holds 0 feature records, its DSID says 4,208"), what.c_str());
    // AND through loadCharts (what chart info and the window use) it is a failure and no cell
    const LoadResult r = loadCharts({dir.path().toStdString()});
    QVERIFY(r.cells.empty());
    QCOMPARE(r.failures.size(), std::size_t(1));
    QCOMPARE(r.failures[0].file, cell.toStdString());
  }

  void givenACellCutInsideARecord_whenLoaded_thenTheByteAndTheRecordAreNamed() {
    if (!haveEnc()) QSKIP("../shared/data/enc is absent");
    QTemporaryDir dir;
    const QByteArray whole = readAll(kEnc + "/US5BOSDC/US5BOSDC.000");
    const auto starts = recordStarts(whole);
    QVERIFY(starts.size() > 100);
    const QString cell = dir.path() + "/US5BOSDC.000";
    // GIVEN cuts in the middle of a record's fields, inside a leader, and one byte short of the end
    const std::size_t k = starts.size() / 3;
    for (const qint64 cut : {starts[k] + 40, starts[k] + 10, static_cast<qint64>(whole.size()) - 1}) {
      QVERIFY(writeAll(cell, whole.left(cut)));
      const std::size_t record =
          static_cast<std::size_t>(std::upper_bound(starts.begin(), starts.end(), cut - 1) - starts.begin());
      // WHEN loaded THEN "truncated at byte N, inside record K" (the DDR is record 1)
      const auto [file, what] = loadError(cell);
      qInfo("%s", what.c_str());
      QCOMPARE(file, cell.toStdString());
      std::string expected = cell.toStdString();
      expected.append(": truncated at byte ").append(grouped(cut));
      expected.append(", inside record ").append(grouped(static_cast<qint64>(record)));
      std::string context = what;
      context.append("\nexpected: ").append(expected);
      QVERIFY2(what.rfind(expected, 0) == 0, context.c_str());
    }
  }

  void givenAnUpdateOfAnotherCell_whenTheCellLoads_thenTheUpdateIsNamedAndNotApplied() {
    if (!haveEnc()) QSKIP("../shared/data/enc is absent");
    // GIVEN US5BOSDC (edition 5) with US5BOSCC's first update (also edition 5, update 1) beside it
    // as US5BOSDC.001
    QTemporaryDir dir;
    const QString cell = dir.path() + "/US5BOSDC.000", update = dir.path() + "/US5BOSDC.001";
    copyPrefix(kEnc + "/US5BOSDC/US5BOSDC.000", cell, -1);
    const QByteArray foreign = readAll(kEnc + "/US5BOSCC/US5BOSCC.001");
    QVERIFY(writeAll(update, foreign));
    // WHEN loaded alone THEN it fails naming the update and whose it is
    const auto [file, what] = loadError(cell);
    QCOMPARE(file, update.toStdString());
    QCOMPARE(what, update.toStdString() + ": is an update of US5BOSCC, not of US5BOSDC");
    // WHEN loaded through loadCharts THEN the cell loads as it is without the update, and the
    // failure list says so
    const LoadResult r = loadCharts({dir.path().toStdString()});
    QCOMPARE(r.cells.size(), std::size_t(1));
    QCOMPARE(r.cells[0]->info().updateNumber, 0);
    QCOMPARE(r.cells[0]->features().size(), loadCell(kEnc + "/US5BOSDC/US5BOSDC.000")->features().size());
    const LoadFailure* f = failureOf(r, update);
    QVERIFY(f);
    qInfo("%s", f->reason.c_str());
    QCOMPARE(
        f->reason,
        std::string("is an update of US5BOSCC, not of US5BOSDC; US5BOSDC is loaded at update 0 without it"));
    // GIVEN the same update with its DSID renamed to US5BOSDC.001 THEN its records give it away
    QByteArray renamed = foreign;
    const qsizetype at = renamed.indexOf("US5BOSCC.001");
    QVERIFY(at > 0);
    renamed.replace(at, 12, "US5BOSDC.001");
    QVERIFY(writeAll(update, renamed));
    const auto [file2, what2] = loadError(cell);
    qInfo("%s", what2.c_str());
    QCOMPARE(file2, update.toStdString());
    QVERIFY2(contains(what2, "modifies feature record 1411, which the cell does not hold"), what2.c_str());
  }

  void givenADamagedUpdate_whenTheCellLoads_thenTheUpdateFileIsNamedAndTheCellStopsBeforeIt() {
    if (!haveEnc()) QSKIP("../shared/data/enc is absent");
    // GIVEN US5WA22M with its four updates, the third cut in half
    QTemporaryDir dir, upTo2;
    for (const char* ext : {"000", "001", "002", "003", "004"}) {
      const std::string from = kEnc + "/US5WA22M/US5WA22M." + ext;
      copyPrefix(from, dir.path() + "/US5WA22M." + ext, std::string(ext) == "003" ? 2800 : -1);
      if (std::string(ext) <= "002") copyPrefix(from, upTo2.path() + "/US5WA22M." + ext, -1);
    }
    const QString cell = dir.path() + "/US5WA22M.000", third = dir.path() + "/US5WA22M.003";
    // WHEN loaded alone THEN the error names the update, not the cell
    const auto [file, what] = loadError(cell);
    qInfo("%s", what.c_str());
    QCOMPARE(file, third.toStdString());
    QVERIFY2(what.rfind(third.toStdString() + ": truncated at byte 2,800, inside record ", 0) == 0,
             what.c_str());
    // WHEN loaded through loadCharts THEN the cell is at update 2, exactly as with updates 1 and 2
    // only, and the failure names the third update and what was left out
    const LoadResult r = loadCharts({dir.path().toStdString()});
    QCOMPARE(r.cells.size(), std::size_t(1));
    const CellInfo& info = r.cells[0]->info();
    QCOMPARE(info.updateNumber, 2);
    QCOMPARE(info.updatesApplied, (std::vector<std::string>{"US5WA22M.001", "US5WA22M.002"}));
    QVERIFY(r.cells[0]->countsByClass() ==
            loadCell((upTo2.path() + "/US5WA22M.000").toStdString())->countsByClass());
    QCOMPARE(r.failures.size(), std::size_t(1));
    QCOMPARE(r.failures[0].file, third.toStdString());
    qInfo("%s", r.failures[0].reason.c_str());
    QVERIFY2(contains(r.failures[0].reason,
                      "; US5WA22M is loaded at update 2 without it and the 1 update file(s) after it"),
             r.failures[0].reason.c_str());
  }

  void givenAnExchangeSetCatalogue_whenAFileDiffersByOneBit_thenItsCrcFails() {
    if (!haveEnc()) QSKIP("../shared/data/enc is absent");
    // GIVEN the two exchange sets with a CATALOG.031 THEN every CRC it lists matches its file
    for (const char* set : {"US5BOSCC", "US5BOSDC"}) {
      const std::string folder = kEnc + "/" + set;
      std::vector<s57::CatalogueEntry> entries;
      QCOMPARE(s57::readCatalogue(view(readAll(folder + "/CATALOG.031")), entries), std::string());
      int checked = 0;
      for (const auto& e : entries) {
        if (!e.crc) continue;
        const std::string name = e.file.substr(e.file.find_last_of("\\/") + 1);  // "US5BOSCC\\US5BOSCC.000"
        std::string path = folder;
        path.append("/").append(name);
        QVERIFY2(fs::exists(path), path.c_str());
        QCOMPARE(s57::crc32(view(readAll(path))), *e.crc);
        ++checked;
      }
      QVERIFY(checked >= 4);
      QVERIFY(loadCell(folder + "/" + set + ".000"));  // and the originals load with the check on
    }
    // GIVEN a copy of US5BOSDC with one bit flipped in its northernmost latitude
    QByteArray damaged = readAll(kEnc + "/US5BOSDC/US5BOSDC.000");
    const std::size_t y = northernmostLatitude(damaged);
    QVERIFY(y > 0);
    const auto at = static_cast<qsizetype>(y) + 2;
    const auto high = static_cast<unsigned char>(damaged[at]);
    int bit = 7;
    while (bit > 0 && (high & (1u << bit))) --bit;  // a bit that is 0, so the latitude grows
    damaged[at] = static_cast<char>(high | (1u << bit));
    QTemporaryDir bare, withCatalogue;
    QVERIFY(writeAll(bare.path() + "/US5BOSDC.000", damaged));
    QVERIFY(writeAll(withCatalogue.path() + "/US5BOSDC.000", damaged));
    copyPrefix(kEnc + "/US5BOSDC/CATALOG.031", withCatalogue.path() + "/CATALOG.031", -1);
    // WHEN loaded without the catalogue THEN nothing notices, and the chart reaches further north
    const CellPtr moved = loadCell((bare.path() + "/US5BOSDC.000").toStdString());
    const CellPtr original = loadCell(kEnc + "/US5BOSDC/US5BOSDC.000");
    qInfo("max latitude %.6f, damaged %.6f", original->bounds().maxLatDeg, moved->bounds().maxLatDeg);
    QVERIFY(moved->bounds().maxLatDeg > original->bounds().maxLatDeg + 1e-4);
    // WHEN loaded beside the catalogue THEN the CRC fails, naming the file
    const QString cell = withCatalogue.path() + "/US5BOSDC.000";
    const auto [file, what] = loadError(cell);
    qInfo("%s", what.c_str());
    QCOMPARE(file, cell.toStdString());
    char expected[64];
    std::snprintf(expected, sizeof expected, "CRC %08X, CATALOG.031 says 65453D1E (damaged copy)",
                  static_cast<unsigned>(s57::crc32(view(damaged))));
    QCOMPARE(what, cell.toStdString() + ": " + expected);
    // AND an update one bit off is named, and the cell loads without it
    QTemporaryDir boscc;
    for (const char* name : {"CATALOG.031", "US5BOSCC.000", "US5BOSCC.001"})
      copyPrefix(kEnc + "/US5BOSCC/" + name, boscc.path() + "/" + name, -1);
    QByteArray update = readAll(kEnc + "/US5BOSCC/US5BOSCC.001");
    const std::size_t c = firstCoordinate(update, 0);
    QVERIFY(c > 0);
    const auto flipAt = static_cast<qsizetype>(c) + 1;
    update[flipAt] = static_cast<char>(update[flipAt] ^ 0x10);
    const QString updatePath = boscc.path() + "/US5BOSCC.001";
    QVERIFY(writeAll(updatePath, update));
    const LoadResult r = loadCharts({boscc.path().toStdString()});
    QCOMPARE(r.cells.size(), std::size_t(1));
    QCOMPARE(r.cells[0]->info().updateNumber, 0);
    const LoadFailure* f = failureOf(r, updatePath);
    QVERIFY(f);
    qInfo("%s", f->reason.c_str());
    QVERIFY2(
        f->reason.rfind("CRC ", 0) == 0 && contains(f->reason, "CATALOG.031 says A42FDADD (damaged copy)"),
        f->reason.c_str());
  }

  void givenAFifoAsAChartPath_whenLoaded_thenItIsRefusedWithoutBeingOpened() {
    // GIVEN a FIFO named like a cell (opening it for reading would wait for a writer for ever)
    QTemporaryDir dir;
    const QString fifo = dir.path() + "/US5FIFO0.000";
    QCOMPARE(::mkfifo(fifo.toLocal8Bit().constData(), 0600), 0);
    const std::string expected = fifo.toStdString() + ": is a FIFO (named pipe), not a chart file";
    // WHEN loaded, found or listed THEN each refuses it at once (this thread would hang otherwise)
    QCOMPARE(loadError(fifo).second, expected);
    try {
      findCells(fifo.toStdString());
      QFAIL("findCells accepted a FIFO");
    } catch (const ChartLoadError& e) {
      QCOMPARE(std::string(e.what()), expected);
    }
    const LoadResult r = loadCharts({fifo.toStdString()});
    QVERIFY(r.cells.empty());
    QCOMPARE(r.failures.size(), std::size_t(1));
    QCOMPARE(r.failures[0].file + ": " + r.failures[0].reason, expected);
    // AND a folder is a folder of cells for findCells, but not a cell
    QVERIFY(contains(loadError(dir.path()).second, "is a folder, not a cell file"));
    if (!haveEnc()) QSKIP("../shared/data/enc is absent: the FIFO-as-update case needs a real cell");
    // GIVEN a real cell with a FIFO as its first update THEN the cell loads without it, and the
    // FIFO is the failure
    QTemporaryDir cellDir;
    copyPrefix(kEnc + "/US5BOSDC/US5BOSDC.000", cellDir.path() + "/US5BOSDC.000", -1);
    const QString updateFifo = cellDir.path() + "/US5BOSDC.001";
    QCOMPARE(::mkfifo(updateFifo.toLocal8Bit().constData(), 0600), 0);
    const LoadResult withFifo = loadCharts({cellDir.path().toStdString()});
    QCOMPARE(withFifo.cells.size(), std::size_t(1));
    const LoadFailure* f = failureOf(withFifo, updateFifo);
    QVERIFY(f);
    QVERIFY2(f->reason.rfind("is a FIFO (named pipe), not a chart file", 0) == 0, f->reason.c_str());
  }

  void givenACellWithCoordinatesOffTheEarth_whenLoaded_thenItIsRefusedNamingTheFeature() {
    // GIVEN tests/charts/data/OFFEARTH.000: fuzz_s57's mutation of its seed area.000 (written from scratch
    // by s57_seeds), four bytes of its DDR changed; GDAL gives its points at latitude 495,250,000
    const QString cell = QStringLiteral(RECKONER_CHART_TEST_DATA "/OFFEARTH.000");
    // WHEN loaded THEN one error naming the cell and the coordinate, never a cell drawn off the Earth
    const auto [file, what] = loadError(cell);
    qInfo("%s", what.c_str());
    QCOMPARE(file, cell.toStdString());
    QVERIFY2(contains(what, "feature has a coordinate off the Earth, (495250000, -294750000)"), what.c_str());
    QVERIFY(what.find('\n') == std::string::npos);
  }

  void givenAnUpdateThatLeavesAnAreaWithoutRings_whenLoaded_thenEveryPolygonStartNamesARing() {
    // GIVEN tests/charts/data/EMPTYPLY.000 and .001: fuzz_s57's mutation of its seeds area.000 and its
    // update (written from scratch by s57_seeds); GDAL gives one area an empty polygon
    const QString cellDir = QStringLiteral(RECKONER_CHART_TEST_DATA);
    const LoadResult r = loadCharts({(cellDir + "/EMPTYPLY.000").toStdString()});
    // WHEN loaded with its update THEN the cell loads, and every polygon's first ring exists (the empty
    // polygon used to leave a start one past the last ring)
    QCOMPARE(r.cells.size(), std::size_t(1));
    std::size_t areas = 0;
    for (const ChartFeature& f : r.cells[0]->features()) {
      if (f.geometry.primitive != Primitive::Area) continue;
      ++areas;
      for (const std::size_t s : f.geometry.polygonStarts)
        QVERIFY2(s < f.geometry.parts.size(), f.objectClass.c_str());
    }
    QVERIFY(areas > 0);
  }

  void givenAMultiLineGdalError_whenTheCellFails_thenTheReasonIsOneLine() {
    if (!haveEnc()) QSKIP("../shared/data/enc is absent");
    // GIVEN a cell whose DDR gives DSPM a field control byte 0xFF: the ISO 8211 structure is whole,
    // GDAL's reader objects on two lines with the raw byte in them
    QByteArray bytes = readAll(kEnc + "/US5BOSDC/US5BOSDC.000");
    const qint64 base = bytes.mid(12, 5).toLongLong();
    const int sizeLength = bytes[20] - '0', sizePosition = bytes[21] - '0', sizeTag = bytes[23] - '0';
    const int entry = sizeTag + sizeLength + sizePosition;
    qint64 controls = -1;
    for (qint64 e = 24; e + entry < base; e += entry)
      if (bytes.mid(e, sizeTag) == "DSPM")
        controls = base + bytes.mid(e + sizeTag + sizeLength, sizePosition).toLongLong();
    QVERIFY(controls > 0);
    bytes[controls] = '\xFF';
    QTemporaryDir dir;
    const QString cell = dir.path() + "/US5BOSDC.000";
    QVERIFY(writeAll(cell, bytes));
    // WHEN loaded THEN the reason is one line, the byte shown as an escape
    const LoadResult r = loadCharts({cell.toStdString()});
    QCOMPARE(r.failures.size(), std::size_t(1));
    const std::string& why = r.failures[0].reason;
    qInfo("%s", why.c_str());
    QVERIFY2(why.find('\n') == std::string::npos && why.find('\r') == std::string::npos, why.c_str());
    QVERIFY2(contains(why, "Unrecognized data_struct_code value \\xFF") && contains(why, "Field DSPM"),
             why.c_str());
    for (const unsigned char c : why) QVERIFY2(c >= 0x20 && c != 0x7F, why.c_str());
  }

  void givenRandomTruncationsAndBitFlipsOfARealCell_whenWalkedAndLoaded_thenEachEndsWithAnAnswer() {
    if (!haveEnc()) QSKIP("../shared/data/enc is absent");
    // GIVEN a few thousand damaged copies of US5BOSDC.000, one of its exchange set's catalogue and
    // of an update, made by a fixed seed: cuts anywhere, cuts at record boundaries, bit flips,
    // terminator bytes written over others
    const QByteArray cell = readAll(kEnc + "/US5BOSDC/US5BOSDC.000");
    const QByteArray catalogue = readAll(kEnc + "/US5BOSCC/CATALOG.031");
    const QByteArray update = readAll(kEnc + "/US5WA22M/US5WA22M.003");
    const auto starts = recordStarts(cell);
    std::mt19937 rng(57);
    const auto below = [&](std::size_t n) {
      return n == 0 ? std::size_t{0} : static_cast<std::size_t>(rng() % n);
    };
    const auto mutate = [&](const QByteArray& in, int how) {
      QByteArray b = in;
      const auto size = static_cast<std::size_t>(b.size());
      switch (how) {
        case 0:  // a cut anywhere
          b.truncate(static_cast<qsizetype>(below(size)));
          break;
        case 1:  // a cut at a record boundary (of the cell)
          b.truncate(starts[below(starts.size())]);
          break;
        case 2:  // one to four bit flips
          for (std::size_t k = 0, n = 1 + below(4); k < n; ++k) {
            const auto at = static_cast<qsizetype>(below(size));
            b[at] = static_cast<char>(b[at] ^ (1 << below(8)));
          }
          break;
        default: {  // a byte overwritten with a terminator, a digit or 0xFF
          const char pick[] = {'\x1e', '\x1f', '0', '9', '\xFF', ' '};
          b[static_cast<qsizetype>(below(size))] = pick[below(sizeof pick)];
        }
      }
      return b;
    };
    const auto kinds = s57::ObjectClassKinds::fromCatalogue(
        view(readAll(s57CatalogueDirectory() + "/s57objectclasses.csv")));
    QElapsedTimer clock;
    clock.start();
    // WHEN each is walked and summarised THEN each ends with an answer; every cut of the cell is caught
    int walked = 0, found = 0;
    for (int i = 0; i < 3000; ++i) {
      const int how = i % 4;
      const QByteArray b = mutate(i % 3 == 0   ? cell
                                  : i % 3 == 1 ? catalogue
                                               : update,
                                  i % 3 == 0 ? how : (how == 1 ? 0 : how));
      s57::DataSetSummary summary;
      std::vector<s57::CatalogueEntry> entries;
      std::string why =
          i % 3 == 1 ? s57::readCatalogue(view(b), entries) : s57::summarise(view(b), kinds, summary);
      if (why.empty() && i % 3 != 1) why = s57::checkCounts(summary);
      ++walked;
      found += !why.empty();
      QVERIFY2(why.find('\n') == std::string::npos, why.c_str());
      if (i % 3 == 0 && how <= 1 && b.size() < cell.size())
        QVERIFY2(!why.empty(), qPrintable(QString("cut at %1 not caught").arg(b.size())));
    }
    const qint64 walkMs = clock.restart();
    // AND through loadCell (GDAL included for what the walker lets through) each load returns a cell
    // or throws ChartLoadError
    QTemporaryDir dir;
    const QString path = dir.path() + "/US5BOSDC.000";
    int loaded = 0, refused = 0;
    for (int i = 0; i < 80; ++i) {
      QVERIFY(writeAll(path, mutate(cell, i % 4)));
      try {
        loadCell(path.toStdString());
        ++loaded;
      } catch (const ChartLoadError& e) {
        ++refused;
        QVERIFY2(std::string(e.what()).find('\n') == std::string::npos, e.what());
      }
    }
    qInfo("%d mutations walked in %lld ms (%d found damaged); 80 loaded in %lld ms (%d refused, %d loaded)",
          walked, walkMs, found, clock.elapsed(), refused, loaded);
    QCOMPARE(loaded + refused, 80);
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
    // The cell with the garbage update loads without it, and the update is the failure.
    QCOMPARE(r.cells.size(), std::size_t(2));
    QCOMPARE(r.cells[0]->info().name, std::string("US5BOSDC"));
    QCOMPARE(r.cells[1]->info().name, std::string("US5BOSCC"));
    QCOMPARE(r.cells[1]->info().updateNumber, 0);
    QVERIFY(r.cells[1]->info().updatesApplied.empty());
    QCOMPARE(calls, std::size_t(4));  // good, text, trunc, upd
    QCOMPARE(r.failures.size(), std::size_t(3));
    std::map<std::string, std::string> why;
    for (const auto& f : r.failures)
      why[fs::path(f.file).parent_path().filename().string() + "/" + fs::path(f.file).filename().string()] =
          f.reason;
    for (const auto& [k, v] : why) qInfo("%s: %s", k.c_str(), v.c_str());
    QVERIFY(why.count("trunc/US5BOSDC.000"));
    QVERIFY(why.count("upd/US5BOSCC.001"));
    for (const auto& f : r.failures) QVERIFY2(f.reason.find('\n') == std::string::npos, f.reason.c_str());
  }
};

QTEST_GUILESS_MAIN(TestS57Loader)
#include "tst_s57_loader.moc"
