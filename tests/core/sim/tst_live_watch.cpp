// GIVEN / WHEN / THEN: the watch of a live run (sim/live_watch.h) on a real recording
// (../shared/data/nmea/gpsd-bundg_zeus_9.log, read at test time, never copied) with AIS sentences of
// our own encoding interleaved: an AIS target on a collision course raises AIS CPA/TCPA with the CPA
// and TCPA an independent calculation in the test gives, becomes lost and raises LOST AIS TARGET when
// it falls silent; the GNSS falling silent raises POSITION SOURCE LOST from the live frames; with no
// own-ship sentences at all, the own ship of !AIVDO reports is used. The session's frames carry no
// truth and come one per own-ship row.
#include <QTest>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "common/angles.h"
#include "common/units.h"
#include "io/iso8601.h"
#include "io/text_file.h"
#include "sim/live_session.h"
#include "sim/live_watch.h"
#include "support/ais_corpus.h"
#include "support/compare_near.h"
#include "support/text_lines.h"

using namespace reckoner;
namespace ais = reckoner::test::ais;

namespace {

// The test's own flat-earth arithmetic (metres per degree at the recording's latitude), independent
// of the project's geodesy: good to a few metres over the 3 NM the test spans.
constexpr double kMetresPerDegLat = 111250.0;  // at 52.85 N
const double kMetresPerDegLon = 111320.0 * std::cos(degToRad(52.85));

struct Fix {
  double tS, latDeg, lonDeg, sogKn, cogDeg;
};

/// hhmmss of an RMC, GGA or GLL sentence as seconds of the day; nullopt for other lines.
std::optional<double> timeOfDay(const std::string& l) {
  std::size_t field = 0;
  if (l.rfind("$GPRMC,", 0) == 0 || l.rfind("$GPGGA,", 0) == 0)
    field = 1;
  else if (l.rfind("$GPGLL,", 0) == 0)
    field = 5;
  else
    return std::nullopt;
  std::size_t at = 0;
  for (std::size_t i = 0; i < field; ++i) at = l.find(',', at) + 1;
  const std::string hms = l.substr(at, 6);
  if (hms.size() < 6) return std::nullopt;
  return std::stoi(hms.substr(0, 2)) * 3600.0 + std::stoi(hms.substr(2, 2)) * 60.0 +
         std::stoi(hms.substr(4, 2));
}

/// The recording's RMC fixes (time of day, position, SOG, COG).
std::vector<Fix> rmcFixes(const std::vector<std::string>& lines) {
  std::vector<Fix> out;
  for (const std::string& l : lines) {
    if (l.rfind("$GPRMC,", 0) != 0) continue;
    std::vector<std::string> f;
    std::size_t a = 0;
    for (std::size_t b; (b = l.find(',', a)) != std::string::npos; a = b + 1) f.push_back(l.substr(a, b - a));
    const double lat = std::stod(f[3].substr(0, 2)) + std::stod(f[3].substr(2)) / 60.0;
    const double lon = std::stod(f[5].substr(0, 3)) + std::stod(f[5].substr(3)) / 60.0;
    out.push_back({*timeOfDay(l), lat, lon, std::stod(f[7]), std::stod(f[8])});
  }
  return out;
}

/// A class A target moving straight: where it is at time of day t.
struct Target {
  long long mmsi;
  double t0, lat0, lon0, sogKn, cogDeg;
  [[nodiscard]] std::pair<double, double> at(double t) const {
    const double d = knotsToMps(sogKn) * (t - t0), c = degToRad(cogDeg);
    return {lat0 + d * std::cos(c) / kMetresPerDegLat, lon0 + d * std::sin(c) / kMetresPerDegLon};
  }
  [[nodiscard]] std::string report(double t, bool ownShip = false) const {
    const auto [lat, lon] = at(t);
    const auto p =
        ais::classA(1, mmsi, 0, 0, static_cast<int>(std::lround(sogKn * 10)), std::llround(lon * 600000.0),
                    std::llround(lat * 600000.0), static_cast<int>(std::lround(cogDeg * 10)),
                    static_cast<int>(std::lround(cogDeg)));
    if (!ownShip) return ais::sentence(p);
    const auto [payload, fill] = p.armoured();
    return ais::withSum("AIVDO,1,1,,A," + payload + "," + std::to_string(fill));
  }
};

/// CPA (m) and TCPA (s) of two straight motions from time t, in the test's flat-earth frame.
std::pair<double, double> cpaOf(double latA, double lonA, double sogA, double cogA, double latB, double lonB,
                                double sogB, double cogB) {
  const double rx = (lonB - lonA) * kMetresPerDegLon, ry = (latB - latA) * kMetresPerDegLat;
  const auto v = [](double sog, double cog) {
    return std::pair{knotsToMps(sog) * std::sin(degToRad(cog)), knotsToMps(sog) * std::cos(degToRad(cog))};
  };
  const auto [ax, ay] = v(sogA, cogA);
  const auto [bx, by] = v(sogB, cogB);
  const double vx = bx - ax, vy = by - ay;
  const double tcpa = -(rx * vx + ry * vy) / (vx * vx + vy * vy);
  return {std::hypot(rx + vx * tcpa, ry + vy * tcpa), tcpa};
}

const alerts::Alert* findAlert(const sim::LiveWatch& w, alerts::AlertKind kind, int source) {
  return w.alerts().find({kind, source});
}

/// The alert is shown and its condition holds (not merely rectified and waiting for acknowledgement).
bool holds(const sim::LiveWatch& w, alerts::AlertKind kind, int source) {
  const alerts::Alert* a = findAlert(w, kind, source);
  return a && a->state != alerts::AlertState::Rectified;
}

int raised(const std::vector<alerts::AlertLogEntry>& log, alerts::AlertKind kind) {
  int n = 0;
  for (const auto& e : log) n += e.id.kind == kind && e.event == alerts::AlertLogEntry::Event::Raised;
  return n;
}

}  // namespace

class TestLiveWatch : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    lines_ = test::splitLines(io::readTextFile(RECKONER_SHARED_DIR "/data/nmea/gpsd-bundg_zeus_9.log"));
    fixes_ = rmcFixes(lines_);
    QVERIFY(fixes_.size() > 100);
    day_ = *io::parseIso8601("2018-08-20T00:00:00Z");
  }

  void anAisTargetOnACollisionCourseRaisesAisCpaAndIsLostWhenSilent() {
    // GIVEN the recording (own ship 5.6 kn on about 232 degrees) and a class A target 1.5 NM ahead of it
    // on the reciprocal course at 10 kn, reporting every 10 s after the RMC of its second, silent after
    // 60 s of the recording
    const Fix& f0 = fixes_.front();
    const double d = nmToMetres(1.5), c = degToRad(f0.cogDeg);
    const Target target{244123456,
                        f0.tS,
                        f0.latDeg + d * std::cos(c) / kMetresPerDegLat,
                        f0.lonDeg + d * std::sin(c) / kMetresPerDegLon,
                        10.0,
                        std::fmod(f0.cogDeg + 180.0, 360.0)};
    sim::LiveOptions lo;
    lo.frames = true;
    sim::LiveSession session(lo);
    sim::LiveWatch watch;
    std::vector<alerts::AlertLogEntry> log;
    long frames = 0, ownRows = 0;
    std::optional<std::pair<double, double>> expected;  // CPA, TCPA from the test's own figures
    const track::AisTarget* seen = nullptr;
    track::AisTarget atCheck;
    // WHEN the lines are fed one by one and the watch absorbs after each
    for (const std::string& l : lines_) {
      session.nmea(l, std::nullopt, "bus");
      if (const auto t = timeOfDay(l);
          t && l.rfind("$GPRMC,", 0) == 0 && std::fmod(*t - f0.tS, 10.0) == 0.0 && *t - f0.tS <= 60.0)
        session.nmea(target.report(*t), std::nullopt, "ais");
      const sim::LiveWatch::Taken taken = watch.absorb(session, std::nullopt);
      for (const sim::SimFrame& f : taken.frames) QVERIFY(!f.hasTruth);
      frames += static_cast<long>(taken.frames.size());
      ownRows += static_cast<long>(session.takeOwnRows().size());
      const auto more = watch.alerts().takeLog();
      log.insert(log.end(), more.begin(), more.end());
      // The table's CPA at 50 s into the recording, against the test's: own ship from that RMC on
      if (const auto t = timeOfDay(l); t && l.rfind("$GPRMC,", 0) == 0 && *t - f0.tS == 50.0) {
        seen = watch.aisTable().find(static_cast<std::uint32_t>(target.mmsi));
        QVERIFY(seen && seen->cpaValid);
        atCheck = *seen;
        const Fix* own = nullptr;
        for (const Fix& f : fixes_)
          if (f.tS <= toSeconds(watch.aisUtc() - day_)) own = &f;
        QVERIFY(own);
        const double tNow = toSeconds(watch.aisUtc() - day_);
        const auto [lat, lon] = target.at(tNow);
        const double dt = tNow - own->tS;  // own ship carried on from its fix
        const double oc = degToRad(own->cogDeg), od = knotsToMps(own->sogKn) * dt;
        expected = cpaOf(own->latDeg + od * std::cos(oc) / kMetresPerDegLat,
                         own->lonDeg + od * std::sin(oc) / kMetresPerDegLon, own->sogKn, own->cogDeg, lat,
                         lon, target.sogKn, target.cogDeg);
      }
    }
    session.finish();
    const sim::LiveWatch::Taken last = watch.absorb(session, std::nullopt);
    frames += static_cast<long>(last.frames.size());
    ownRows += static_cast<long>(session.takeOwnRows().size());
    const auto more = watch.alerts().takeLog();
    log.insert(log.end(), more.begin(), more.end());
    // THEN one frame per own-ship row
    QVERIFY(ownRows > 100);
    QCOMPARE(frames, ownRows);
    // AND the target was dangerous with the CPA and TCPA of the test's own arithmetic (the DRKF's own
    // ship is not the RMC's: 40 m and 10 s allowed)
    QVERIFY(expected);
    qInfo("CPA %.0f m (test %.0f m), TCPA %.0f s (test %.0f s)", atCheck.cpa.cpaM, expected->first,
          atCheck.cpa.tcpaS, expected->second);
    RK_COMPARE_NEAR(atCheck.cpa.cpaM, expected->first, 40.0);
    RK_COMPARE_NEAR(atCheck.cpa.tcpaS, expected->second, 10.0);
    QVERIFY(atCheck.dangerous && atCheck.activated);
    QCOMPARE(raised(log, alerts::AlertKind::AisCpaTcpa), 1);
    // AND silent for more than five reporting intervals, it is lost: LOST AIS TARGET raised
    const track::AisTarget* end = watch.aisTable().find(static_cast<std::uint32_t>(target.mmsi));
    QVERIFY(end && end->lost);
    QCOMPARE(raised(log, alerts::AlertKind::LostAisTarget), 1);
    QVERIFY(holds(watch, alerts::AlertKind::LostAisTarget, static_cast<int>(target.mmsi)));
    QVERIFY(!holds(watch, alerts::AlertKind::AisCpaTcpa, static_cast<int>(target.mmsi)));
    QCOMPARE(watch.ownShipSource(), sim::LiveOwnShipSource::Drkf);
  }

  void theGnssFallingSilentRaisesPositionSourceLostFromTheLiveFrames() {
    // GIVEN the recording with receive times (each line at its second) and the GNSS ($GP...) removed from
    // 40 s to 80 s while the compass and the log go on
    const double t0 = fixes_.front().tS;
    sim::LiveOptions lo;
    lo.frames = true;
    sim::LiveSession session(lo);
    sim::LiveWatch watch;
    std::vector<alerts::AlertLogEntry> log;
    double second = t0;
    bool lostWhileOut = false;
    // WHEN fed with the receive clock
    for (const std::string& l : lines_) {
      if (const auto t = timeOfDay(l)) second = std::max(second, *t);
      const bool out = second - t0 > 40.0 && second - t0 < 80.0;
      if (out && l.rfind("$GP", 0) == 0) continue;
      const UtcUs rx = day_ + fromSeconds(second);
      session.nmea(l, rx, "bus");
      watch.absorb(session, rx);
      const auto more = watch.alerts().takeLog();
      log.insert(log.end(), more.begin(), more.end());
      if (out && second - t0 > 60.0 && holds(watch, alerts::AlertKind::PositionSourceLost, 0))
        lostWhileOut = true;
    }
    // THEN POSITION SOURCE LOST was raised while the GNSS was out and is gone after it came back
    QVERIFY(lostWhileOut);
    QCOMPARE(raised(log, alerts::AlertKind::PositionSourceLost), 1);
    QVERIFY(!holds(watch, alerts::AlertKind::PositionSourceLost, 0));
  }

  void withNoOwnShipSentencesTheAisVdoOwnShipIsUsed() {
    // GIVEN a bus with AIS only: own ship's transponder (!AIVDO) and a target crossing ahead
    const double t0 = 9 * 3600.0;
    const Target own{211000001, t0, 52.85, 5.30, 8.0, 90.0};
    const Target other{244000002, t0,   52.85 + 1000.0 / kMetresPerDegLat, 5.30 + 1500.0 / kMetresPerDegLon,
                       8.0,       180.0};
    const sim::LiveOptions options;
    sim::LiveSession session(options);
    sim::LiveWatch watch;
    // WHEN they report every 10 s for two minutes, with receive times
    for (double t = t0; t <= t0 + 120.0; t += 10.0) {
      const UtcUs rx = day_ + fromSeconds(t);
      session.nmea(own.report(t, true), rx, "ais");
      session.nmea(other.report(t), rx, "ais");
      watch.absorb(session, rx);
    }
    // THEN own ship is the VDO's, the target's CPA and TCPA are those of the two motions
    QCOMPARE(watch.ownShipSource(), sim::LiveOwnShipSource::AisVdo);
    QVERIFY(!session.started());
    const track::AisTarget* t = watch.aisTable().find(244000002);
    QVERIFY(t && t->cpaValid);
    QVERIFY(watch.aisTable().find(211000001) == nullptr);  // own ship is never a target
    const double now = toSeconds(watch.aisUtc() - day_);
    const auto [olat, olon] = own.at(now);
    const auto [tlat, tlon] = other.at(now);
    const auto [cpa, tcpa] = cpaOf(olat, olon, own.sogKn, own.cogDeg, tlat, tlon, other.sogKn, other.cogDeg);
    qInfo("VDO own ship: CPA %.0f m (test %.0f m), TCPA %.0f s (test %.0f s)", t->cpa.cpaM, cpa, t->cpa.tcpaS,
          tcpa);
    RK_COMPARE_NEAR(t->cpa.cpaM, cpa, 15.0);
    RK_COMPARE_NEAR(t->cpa.tcpaS, tcpa, 3.0);
  }

  void aisHeardBeforeARecordingsFirstTimeStartsTheTableAgainOnTheStreamsClock() {
    // GIVEN a recording played from a file years after it was made: the receive clock says 2026, the
    // sentences 2018, and an AIS target is heard before the first own-ship sentence
    const Fix& f0 = fixes_.front();
    const Target target{244654321, f0.tS, f0.latDeg + 0.01, f0.lonDeg, 6.0, 180.0};
    const UtcUs now = *io::parseIso8601("2026-12-03T12:00:00Z");
    sim::LiveOptions lo;
    lo.frames = true;
    sim::LiveSession session(lo);
    sim::LiveWatch watch;
    watch.tick(now);  // the window's timer, before anything is heard: no clock to set
    QCOMPARE(watch.aisUtc(), UtcUs{0});
    session.nmea(target.report(f0.tS), now, "ais");
    watch.absorb(session, now);
    QVERIFY(watch.aisTable().find(244654321));
    // WHEN the recording follows (at a thousand times its pace), the target reporting every 10 s
    UtcUs rx = now;
    for (const std::string& l : lines_) {
      rx += 300;
      session.nmea(l, rx, "bus");
      if (const auto t = timeOfDay(l); t && l.rfind("$GPRMC,", 0) == 0 && std::fmod(*t - f0.tS, 10.0) == 0.0)
        session.nmea(target.report(*t), rx, "ais");
      watch.absorb(session, rx);
    }
    // THEN the table started again once, on the recording's clock, and has the target with its CPA
    QCOMPARE(watch.clockRebases(), 1L);
    QVERIFY(watch.aisUtc() < now - fromSeconds(86400.0 * 365));
    const track::AisTarget* t = watch.aisTable().find(244654321);
    QVERIFY(t && t->rangeValid && !t->lost);
    QCOMPARE(watch.ownShipSource(), sim::LiveOwnShipSource::Drkf);
  }

  void impossibleSettingsAreRefusedNamingTheField() {
    sim::LiveWatchSettings s;
    s.ownShipFreshS = -1.0;
    try {
      sim::LiveWatch w(s);
      QFAIL("expected an error");
    } catch (const std::invalid_argument& e) {
      QVERIFY2(std::string(e.what()).find("own_ship_fresh_s") != std::string::npos, e.what());
    }
    sim::LiveWatch w;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, w.setCpaLimits(-5.0, 600.0));
    QCOMPARE(w.settings().alerts.cpa.cpaM, sim::LiveWatchSettings{}.alerts.cpa.cpaM);
  }

 private:
  std::vector<std::string> lines_;
  std::vector<Fix> fixes_;
  UtcUs day_ = 0;
};

QTEST_GUILESS_MAIN(TestLiveWatch)
#include "tst_live_watch.moc"
