// The NMEA output of runs and replays (sim/nmea_output.h, docs/outputs.md "NMEA 0183 output"):
// GIVEN the ttkf-matched scenario (GPS and Loran-C off from 200 s to 400 s) WHEN its run is sent THEN
// every position sentence while dead reckoning carries mode E / quality 6 and every other one A / 1,
// own ship goes out at most once a second, GST carries the estimate's own sd, every track's TTM/TLL
// keeps its target number, and POSITION SOURCE LOST goes out as ALR/ALF on change and every 30 s with
// the ALC list, ALR numbers and ALF instances unique across kinds and sources, OSD through the water while
// dead reckoning; the same for a replay of the run's recording; target numbers are reused round robin.
#include <QTest>

#include <map>
#include <set>

#include "files/scenario_json.h"
#include "io/iso8601.h"
#include "io/nmea.h"
#include "io/nmea_out.h"
#include "sim/nmea_export.h"
#include "sim/nmea_output.h"
#include "sim/scenario_run.h"
#include "support/compare_near.h"
#include "support/drkf_fixtures.h"

using namespace reckoner;
using namespace reckoner::sim;

namespace {

const UtcUs kUtc0 = *io::parseIso8601("2026-01-01T00:00:00Z");

std::string typeOf(const std::string& line) {
  return line.size() > 6 ? line.substr(3, 3) : std::string();
}

struct Sent {
  TimeUs timeUs;  ///< the frame's time
  bool deadReckoning;
  std::string line;
};

}  // namespace

class TestNmeaOutput : public QObject {
  Q_OBJECT
 private slots:
  void runDeadReckoningIsMarkedEstimated() {
    const Scenario s = test::builtinScenario("ttkf-matched");
    RunNmeaOutput out(s, kUtc0);
    std::vector<Sent> sent;
    std::vector<OwnShipRow> rows;
    const RunResult run =
        runScenario(s, 1, [&](const SimFrame& f, const OwnShipRow& row, std::span<const TrackRow> t) {
          for (auto& l : out.frame(f, row, t)) sent.push_back({f.timeUs, row.deadReckoning, l});
          rows.push_back(row);
        });
    QVERIFY(!run.deadReckoning.empty());
    int drPositions = 0, fixPositions = 0;
    std::map<std::string, int> types;
    std::optional<double> lastRmcS;
    for (const Sent& x : sent) {
      const auto fields = io::nmea::checkedFields(x.line);
      QVERIFY2(fields, x.line.c_str());
      QVERIFY2(x.line.size() <= io::nmea::kMaxSentenceChars, x.line.c_str());
      const std::string type = typeOf(x.line);
      ++types[type];
      if (type != "RMC" && type != "GGA" && type != "VTG" && type != "GST" && type != "HDT") continue;
      const io::nmea::ParseResult p = io::nmea::parse(x.line);
      QVERIFY2(p.sentence, (x.line + " " + p.reason).c_str());
      if (type == "RMC") {
        const auto& r = std::get<io::nmea::Rmc>(p.sentence->body);
        QCOMPARE(*r.mode, x.deadReckoning ? 'E' : 'A');
        QVERIFY(r.valid);
        QCOMPARE(io::nmea::gnssFix(r.mode), !x.deadReckoning);
        (x.deadReckoning ? drPositions : fixPositions)++;
        if (lastRmcS) QVERIFY(r.timeOfDayS - *lastRmcS >= 1.0 - 1e-9);
        lastRmcS = r.timeOfDayS;
      } else if (type == "GGA") {
        QCOMPARE(std::get<io::nmea::Gga>(p.sentence->body).quality, x.deadReckoning ? 6 : 1);
      } else if (type == "VTG") {
        QCOMPARE(*std::get<io::nmea::Vtg>(p.sentence->body).mode, x.deadReckoning ? 'E' : 'A');
      }
    }
    // The outage is 200 s of the 600: about a third of the positions are dead reckoning.
    QVERIFY2(drPositions >= 150 && drPositions <= 260, std::to_string(drPositions).c_str());
    QVERIFY(fixPositions >= 300);
    QCOMPARE(types["RMC"], types["GGA"]);
    QCOMPARE(types["RMC"], types["GST"]);
    QCOMPARE(types["RMC"], types["OSD"]);
    QVERIFY(types["HDT"] > types["RMC"] / 2);
    QCOMPARE(types["TTM"], types["TLL"]);
    QVERIFY(types["TTM"] > 0);
    QCOMPARE(out.output().counters().sentences, static_cast<long>(sent.size()));

    // GST: the estimate's own sd, the ellipse holding the same total variance.
    std::size_t rowIndex = 0;
    for (const Sent& x : sent) {
      if (typeOf(x.line) != "GST") continue;
      while (rowIndex < rows.size() && rows[rowIndex].timeUs != x.timeUs) ++rowIndex;
      QVERIFY(rowIndex < rows.size());
      const OwnShipRow& row = rows[rowIndex];
      const auto g = std::get<io::nmea::Gst>(io::nmea::parse(x.line).sentence->body);
      const double total = row.sdXM * row.sdXM + row.sdYM * row.sdYM;
      RK_COMPARE_NEAR(*g.latSdM * *g.latSdM + *g.lonSdM * *g.lonSdM, total, 0.01 * total + 0.05);
      RK_COMPARE_NEAR(*g.majorSdM * *g.majorSdM + *g.minorSdM * *g.minorSdM, total, 0.01 * total + 0.05);
      QVERIFY(*g.majorSdM >= *g.minorSdM);
    }
  }

  void tracksKeepTheirNumbers() {
    const Scenario s = test::builtinScenario("ttkf-matched");
    RunNmeaOutput out(s, kUtc0);
    std::map<int, std::set<std::string>> numbersOfTrack;  // track name -> numbers seen
    std::map<std::string, std::pair<std::string, std::string>> lastTtmOfNumber;
    int ttm = 0;
    runScenario(s, 1, [&](const SimFrame& f, const OwnShipRow& row, std::span<const TrackRow> tracks) {
      const auto lines = out.frame(f, row, tracks);
      std::size_t k = 0;
      for (const auto& l : lines) {
        if (typeOf(l) != "TTM") continue;
        const auto ttmFields = *io::nmea::checkedFields(l);
        QCOMPARE(ttmFields.size(), std::size_t(16));
        // The TTM of track k of the sweep, in the rows' order.
        while (k < tracks.size() && !out.output().targetNumber(tracks[k].trackId)) ++k;
        QVERIFY(k < tracks.size());
        const TrackRow& t = tracks[k++];
        QCOMPARE(ttmFields[11], "TRK" + std::to_string(t.trackId));
        numbersOfTrack[t.trackId].insert(ttmFields[1]);
        RK_COMPARE_NEAR(std::stod(ttmFields[2]), t.rangeNm, 0.0005);
        RK_COMPARE_NEAR(std::stod(ttmFields[5]), t.speedKn, 0.005);
        QCOMPARE(ttmFields[4], std::string("T"));
        QCOMPARE(ttmFields[7], std::string("T"));
        QCOMPARE(ttmFields[10], std::string("N"));
        const char status = t.status == track::TrackStatus::Confirmed ? 'T'
                            : t.status == track::TrackStatus::Lost    ? 'L'
                                                                      : 'Q';
        QCOMPARE(ttmFields[12], std::string(1, status));
        QCOMPARE(ttmFields[15], std::string(t.manual ? "M" : "A"));
        if (std::isfinite(t.tcpaMin)) RK_COMPARE_NEAR(std::stod(ttmFields[9]), t.tcpaMin, 0.005);
        ++ttm;
      }
    });
    QVERIFY(ttm > 100);
    for (const auto& [id, numbers] : numbersOfTrack)
      QVERIFY2(numbers.size() == 1, std::to_string(id).c_str());
  }

  void targetNumbersRoundRobin() {
    NmeaOutput out;
    const auto rowsOf = [](std::initializer_list<int> ids) {
      std::vector<TrackRow> v;
      for (int id : ids) {
        TrackRow r;
        r.trackId = id;
        v.push_back(r);
      }
      return v;
    };
    auto v = rowsOf({10, 20, 30});
    out.sweep(1, v);
    QCOMPARE(*out.targetNumber(10), 1);
    QCOMPARE(*out.targetNumber(20), 2);
    QCOMPARE(*out.targetNumber(30), 3);
    v = rowsOf({10, 30, 40});
    out.sweep(2, v);
    QVERIFY(!out.targetNumber(20));
    QCOMPARE(*out.targetNumber(40), 4);  // not 2: freed numbers come round last
    QCOMPARE(*out.targetNumber(30), 3);
    // The same sweep again is not sent twice.
    QVERIFY(out.sweep(2, v).empty());
    QCOMPARE(out.counters().sweepsSkipped, 1L);
    // 101 tracks: one has no number and is counted.
    std::vector<TrackRow> many;
    many.reserve(101);
    for (int i = 0; i < 101; ++i) many.push_back(rowsOf({100 + i})[0]);
    const auto lines = out.sweep(3, many);
    QCOMPARE(lines.size(), std::size_t(200));
    QCOMPARE(out.counters().tracksUnnumbered, 1L);
    std::set<int> numbers;
    for (const auto& t : many)
      if (out.targetNumber(t.trackId)) numbers.insert(*out.targetNumber(t.trackId));
    QCOMPARE(numbers.size(), std::size_t(100));
  }

  void alertsOnChangeAndEvery30s() {
    NmeaOutput out;
    alerts::AlertManager m;
    const alerts::AlertId id{alerts::AlertKind::PositionSourceLost, 0};
    std::vector<std::pair<TimeUs, std::string>> lines;
    for (int t = 0; t <= 100; ++t) {
      const TimeUs now = fromSeconds(t);
      if (t == 10) m.report(now, id, true, "no GPS, no Loran-C");
      if (t == 50) m.acknowledge(now, id);
      if (t == 80) m.report(now, id, false);
      m.tick(now);
      for (auto& l : out.alerts(now, kUtc0 + now, m.alerts())) lines.emplace_back(now, l);
    }
    std::vector<std::pair<int, std::string>> alf;  // (time s, state) of the first ALF sentences
    std::vector<int> alc;
    for (const auto& [t, l] : lines) {
      const auto f = io::nmea::checkedFields(l);
      QVERIFY2(f, l.c_str());
      if (typeOf(l) == "ALF" && (*f)[2] == "1") {
        alf.emplace_back(static_cast<int>(toSeconds(t)), (*f)[7]);
        QCOMPARE((*f)[6], std::string("A"));      // POSITION SOURCE LOST is an alarm
        QCOMPARE((*f)[9], std::string("10005"));  // Reckoner's own identifiers: 10001 + kind
      }
      if (typeOf(l) == "ALC") alc.push_back(static_cast<int>(toSeconds(t)));
    }
    // Raised at 10 (V), repeated at 40, acknowledged at 50 (A), repeated at 80? No: cleared at 80 (N).
    const std::vector<std::pair<int, std::string>> expected{{10, "V"}, {40, "V"}, {50, "A"}, {80, "N"}};
    QCOMPARE(alf, expected);
    QCOMPARE(alc, (std::vector<int>{0, 30, 60, 90}));
  }

  void osdWhileDeadReckoningIsThroughTheWater() {
    // GIVEN own ship dead reckoning over ground 090 at 10 kn in a current setting 000 at 2 kn: through
    // the water she makes 10 kn on 090 less 2 kn north, 10.198 kn on 101.31 degrees (worked by hand)
    NmeaOutput out;
    OwnShipFix fix;
    fix.utcUs = kUtc0;
    fix.latDeg = 50.0;
    fix.lonDeg = -3.0;
    fix.sogKn = 10.0;
    fix.cogTrueDeg = 90.0;
    fix.setTrueDeg = 0.0;
    fix.driftKn = 2.0;
    fix.deadReckoning = true;
    const auto osdOf = [&](const OwnShipFix& x) {
      for (const auto& l : out.ownShip(x))
        if (typeOf(l) == "OSD") return *io::nmea::checkedFields(l);
      return std::vector<std::string>{};
    };
    // THEN OSD gives that, referenced to the water, with set and drift
    auto o = osdOf(fix);
    QCOMPARE(o.size(), std::size_t(10));
    QCOMPARE(o[3], std::string("101.3"));
    QCOMPARE(o[4], std::string("W"));
    QCOMPARE(o[5], std::string("10.20"));
    QCOMPARE(o[6], std::string("W"));
    QCOMPARE(o[7], std::string("0.0"));
    QCOMPARE(o[8], std::string("2.00"));
    // AND with a fix the same motion is over ground, from the positioning system
    fix.deadReckoning = false;
    fix.utcUs += fromSeconds(2);
    o = osdOf(fix);
    QCOMPARE(o[3], std::string("90.0"));
    QCOMPARE(o[4], std::string("P"));
    QCOMPARE(o[5], std::string("10.00"));
  }

  void alertNumbersAreUniqueAcrossKindsAndSources() {
    // GIVEN every kind of alert from sources that collided before (0, 50, 100: the same source mod 50
    // and 100) and AIS alerts of MMSIs (all above 999999, which were clamped to one instance)
    NmeaOutput out;
    alerts::AlertManager m;
    std::vector<alerts::AlertId> ids;
    for (int k = 0; k < alerts::kAlertKindCount; ++k)
      for (const int source : {0, 50, 100}) ids.push_back({static_cast<alerts::AlertKind>(k), source});
    for (const int mmsi : {244000001, 244999999, 245000000, 211999998})
      ids.push_back({alerts::AlertKind::AisCpaTcpa, mmsi});
    const TimeUs now = fromSeconds(1);
    for (const auto& id : ids) m.report(now, id, true, "test");
    m.tick(now);
    QCOMPARE(m.alerts().size(), ids.size());
    // WHEN they are sent
    std::set<std::string> alr, alf;
    std::size_t alrCount = 0, alfCount = 0;
    for (const auto& l : out.alerts(now, kUtc0 + now, m.alerts())) {
      const auto f = io::nmea::checkedFields(l);
      QVERIFY2(f, l.c_str());
      if (typeOf(l) == "ALR") {
        ++alrCount;
        alr.insert((*f)[2]);
      }
      if (typeOf(l) == "ALF" && (*f)[2] == "1") {
        ++alfCount;
        QVERIFY2(std::stoi((*f)[9]) >= 10001 && std::stoi((*f)[9]) <= 10000 + alerts::kAlertKindCount,
                 l.c_str());
        alf.insert((*f)[9] + "/" + (*f)[10]);
      }
    }
    // THEN every alert has its own ALR number and its own (identifier, instance) pair
    QCOMPARE(alrCount, ids.size());
    QCOMPARE(alr.size(), ids.size());
    QCOMPARE(alfCount, ids.size());
    QCOMPARE(alf.size(), ids.size());
    // AND a number stays with its alert while it lasts: sent again 30 s later, the same set
    std::set<std::string> again;
    const TimeUs later = fromSeconds(31);
    m.tick(later);
    for (const auto& l : out.alerts(later, kUtc0 + later, m.alerts()))
      if (typeOf(l) == "ALR") again.insert((*io::nmea::checkedFields(l))[2]);
    QCOMPARE(again, alr);
  }

  void replayOfTheRecordingIsMarkedToo() {
    const Scenario s = test::builtinScenario("ttkf-matched");
    const ExportedRun e = exportRun(s, 1, kUtc0);
    ReplayOptions o;
    o.settings = s;
    o.originFromSettings = true;
    const ReplayResult r = replay(e.nmea, "ttkf.nmea", &e.radarCsv, "ttkf.csv", o);
    const auto lines = replayNmea(r);
    int dr = 0, fix = 0, ttm = 0;
    for (const auto& l : lines) {
      QVERIFY2(io::nmea::checkedFields(l), l.c_str());
      if (typeOf(l) == "TTM") ++ttm;
      if (typeOf(l) != "GGA") continue;
      const auto g = std::get<io::nmea::Gga>(io::nmea::parse(l).sentence->body);
      // The recording's outage is 200 s to 400 s; the fix counts for 3 s after the last one.
      const bool outage = g.timeOfDayS > 203.5 && g.timeOfDayS < 399.5;
      const bool fixed = g.timeOfDayS < 199.5 || g.timeOfDayS > 404.5;
      if (outage) QCOMPARE(g.quality, 6);
      if (fixed) QCOMPARE(g.quality, 1);
      (g.quality == 6 ? dr : fix)++;
    }
    QVERIFY(dr >= 190);
    QVERIFY(fix >= 350);
    QVERIFY(ttm > 100);
  }
};

QTEST_GUILESS_MAIN(TestNmeaOutput)
#include "tst_nmea_output.moc"
