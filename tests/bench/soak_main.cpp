// reckoner-soak: the engine for hours of simulated time at full speed (docs/robustness.md, "Soak").
// Own ship follows a square route round and round; vessels cross the radar picture and a ring of AIS
// traffic beyond it, entering and leaving; sea clutter; a GPS and a gyro drop-out every hour; the alert
// feed and the voyage recorder run on every frame. Every frame is checked (soak_checks.h); memory and
// the record's size are sampled every simulated minute. Exit 0 when every check holds, 1 when one
// fails, 2 for a usage error.
//
//   reckoner-soak --hours 24 --out /tmp/soak      (the soak; --hours 1 is CI's)
#include <malloc.h>
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "alerts/alert_manager.h"
#include "common/allocator_settings.h"
#include "files/sqlite_db.h"
#include "files/voyage_recorder.h"
#include "sim/alert_feed.h"
#include "sim/nmea_export.h"
#include "sim/run_rows.h"
#include "soak_checks.h"
#include "soak_report.h"
#include "soak_scenario.h"
#include "support/ais_corpus.h"

using namespace reckoner;

namespace {

UtcUs wallNow() {
  return std::chrono::duration_cast<std::chrono::microseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

/// The process's resident memory from /proc/self/status, MB: all of it (VmRSS), its anonymous part (the
/// heap, stacks: what the program allocated) and its file-backed part (pages of the program and its
/// libraries' code and data, mapped as they are first touched).
struct Resident {
  double totalMb = 0.0, anonMb = 0.0, fileMb = 0.0;
};
Resident resident() {
  std::ifstream status("/proc/self/status");
  Resident r;
  std::string key;
  double kb = 0.0;
  std::string unit;
  while (status >> key) {
    if (key == "VmRSS:" || key == "RssAnon:" || key == "RssFile:") {
      status >> kb >> unit;
      (key == "VmRSS:" ? r.totalMb : key == "RssAnon:" ? r.anonMb : r.fileMb) = kb / 1024.0;
    }
    status.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
  }
  return r;
}

/// The heap in use (glibc's count of allocated bytes, small and mmapped): what the program holds, apart
/// from the allocator keeping freed pages (RSS counts those too).
double heapMb() {
  const struct mallinfo2 m = mallinfo2();
  return static_cast<double>(m.uordblks + m.hblkhd) / (1024.0 * 1024.0);
}

double fileMb(const std::string& path) {
  std::error_code ec;
  double bytes = 0.0;
  for (const char* suffix : {"", "-wal"}) {
    const auto n = std::filesystem::file_size(path + suffix, ec);
    if (!ec) bytes += static_cast<double>(n);
  }
  return bytes / (1024.0 * 1024.0);
}

/// An AIS position report as the receiver would put it on the bus (type 1 for both classes: the same
/// 168 bits as a type 18).
std::string aisSentence(const io::AisMessage& m) {
  const auto scaled = [](const std::optional<double>& v, double k, long long na) {
    return v ? static_cast<long long>(std::llround(*v * k)) : na;
  };
  return test::ais::sentence(test::ais::classA(
      1, m.mmsi, m.navStatus.value_or(15), -128, static_cast<int>(scaled(m.sogKn, 10.0, 1023)),
      scaled(m.lonDeg, 600000.0, 181 * 600000LL), scaled(m.latDeg, 600000.0, 91 * 600000LL),
      static_cast<int>(scaled(m.cogDeg, 10.0, 3600)), m.headingDeg.value_or(511)));
}

struct Lines {
  std::vector<files::InputLine> lines;
  void add(std::vector<std::string> text, const char* source, bool radar, UtcUs rx) {
    for (auto& t : text) lines.push_back({source, std::move(t), rx, radar});
  }
};

/// What the recorder gets from one frame: its sensor lines and its rows.
files::LiveBatch batchOf(const sim::SimFrame& f, const geo::LocalFrame& geo, UtcUs utc0,
                         alerts::AlertManager& alerts) {
  files::LiveBatch b;
  sim::ReplayOwnRow own;
  own.timeUs = f.timeUs;
  own.utcUs = utc0 + f.timeUs;
  own.estimate = sim::groundEstimateOf(f.estimate, geo);
  own.sensors = sim::sensorLabel(f.sensors);
  own.rowsApplied = static_cast<int>(f.updates.size());
  own.deadReckoning = f.deadReckoning.active;
  b.own.push_back(std::move(own));
  for (const sim::SweepSnapshot& sw : f.sweeps)
    for (const sim::TrackSnapshot& t : sw.tracks) {
      b.tracks.push_back(sim::trackEstimateRow(sw.timeUs, t.trackId, t.targetId, t.status, t.dangerous,
                                               t.estimate, t.kinematics, t.lastNis, geo));
      b.trackUtc.push_back(utc0 + sw.timeUs);
    }
  b.alerts = alerts.takeLog();
  b.alertZeroUtc = utc0;
  return b;
}

struct Options {
  double hours = 24.0;
  std::uint64_t seed = 1;
  std::string out = "soak-out";
  double recordHours = 1.0;
};

int run(const Options& o) {
  soak::SoakPlan plan;
  plan.hours = o.hours;
  const sim::Scenario scenario = soak::soakScenario(plan, o.seed);
  sim::SimulationEngine engine(scenario, o.seed);
  soak::FrameChecker checker(scenario, engine.drkf().config().process);
  sim::AlertFeed feed(sim::alertFeedSettingsFor(scenario));
  alerts::AlertManager alerts;

  std::filesystem::create_directories(o.out);
  const std::string recordPath = o.out + "/soak.rkrec";
  std::filesystem::remove(recordPath);
  std::filesystem::remove(recordPath + "-wal");
  std::filesystem::remove(recordPath + "-shm");
  files::RecorderSettings rs;
  rs.program = "reckoner-soak";
  rs.inputName = "soak";
  rs.options.radar = true;
  rs.sources = {{0, "nav", "nmea", ""}, {0, "radar", "radar", ""}, {0, "ais", "nmea", ""}};
  rs.maxHours = o.recordHours;
  files::VoyageRecorder recorder(recordPath, rs, wallNow());
  const std::vector<std::string> labels;
  const UtcUs utc0 = 1767225600LL * kMicrosPerSecond;  // 2026-01-01T00:00:00Z

  soak::Samples samples;
  const auto start = std::chrono::steady_clock::now();
  TimeUs nextSampleUs = 0;
  std::size_t peakAlerts = 0;
  while (!engine.finished()) {
    const sim::SimFrame f = engine.step();
    checker.check(f);
    feed.feed(f, alerts);
    Lines in;
    const UtcUs rx = wallNow();
    in.add(sim::ownShipSentences(f, engine.frame(), utc0), "nav", false, rx);
    in.add(sim::radarCsvRows(f, utc0), "radar", true, rx);
    for (const auto& r : f.aisReceived) in.lines.push_back({"ais", aisSentence(r.message), rx, false});
    recorder.batch(in.lines, batchOf(f, engine.frame(), utc0, alerts), labels, utc0 + f.timeUs, wallNow());
    if (f.timeUs >= nextSampleUs) {
      // The officer of the watch acknowledges what is on the list once a minute (BAM keeps a rectified
      // alarm until it is acknowledged: an unattended run would pile them up).
      const std::size_t shown = alerts.alerts().size();
      peakAlerts = std::max(peakAlerts, shown);
      for (const alerts::Alert& a : alerts.alerts())
        if (a.state == alerts::AlertState::Unacknowledged || a.state == alerts::AlertState::Silenced ||
            a.state == alerts::AlertState::Rectified)
          alerts.acknowledge(f.timeUs, a.id);
      const double wallS = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const Resident mem = resident();
      samples.add({toSeconds(f.timeUs), wallS, mem.totalMb, mem.anonMb, mem.fileMb, heapMb(),
                   fileMb(recordPath), static_cast<int>(f.tracks.size()),
                   f.aisTargets ? static_cast<int>(f.aisTargets->size()) : 0, static_cast<int>(shown)});
      if (f.timeUs % (3600 * kMicrosPerSecond) == 0) samples.printHour(checker.result());
      nextSampleUs += 60 * kMicrosPerSecond;
    }
  }
  recorder.finish({}, labels, wallNow());
  const double wallS = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const Resident mem = resident();
  samples.add({toSeconds(engine.timeUs()), wallS, mem.totalMb, mem.anonMb, mem.fileMb, heapMb(),
               fileMb(recordPath), 0, 0, 0});

  soak::RecordFigures record = soak::recordFigures(recordPath, o.recordHours, utc0 + engine.timeUs());
  record.lines = recorder.lines();
  record.prunedRows = recorder.prunedRows();
  const soak::Verdict v = soak::verdict(plan, checker.result(), samples, record);
  soak::writeReport(o.out + "/soak.json", plan, o.seed, checker.result(), samples, record, engine, v);
  soak::printSummary(checker.result(), samples, record, engine, v);
  std::printf("alerts on the list: at most %zu (acknowledged once a minute)\n", peakAlerts);
  return v.pass ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  applyAllocatorSettings();  // as reckoner and reckoner-cli
  try {
    CLI::App app{
        "reckoner-soak: hours of the engine at full speed, every frame checked (docs/robustness.md)"};
    Options o;
    app.add_option("--hours", o.hours, "simulated hours (the issue's soak: 24; CI: 1)")
        ->check(CLI::Range(0.25, 720.0));
    app.add_option("--seed", o.seed, "random seed of the traffic and the sensors");
    app.add_option("--out", o.out, "folder for soak.rkrec (the voyage record) and soak.json (the figures)");
    app.add_option("--record-max-hours", o.recordHours,
                   "the recorder's full-rate window (older rows: one a minute)")
        ->check(CLI::Range(0.01, 720.0));
    CLI11_PARSE(app, argc, argv);
    return run(o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "reckoner-soak: %s\n", e.what());
  } catch (...) {
    std::fprintf(stderr, "reckoner-soak: an unknown error\n");
  }
  return 2;
}
