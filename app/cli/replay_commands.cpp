// replay --nmea FILE and export SCENARIO: recorded NMEA (and radar plots) through the DRKF and the
// trackers, and a simulated run written as such a recording; replay --recording FILE.sqlite: a voyage
// record of `live --record` through the live run's own pipeline again (docs/recorder.md).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <span>
#include <string>

#include "cli/cli_options.h"
#include "cli/commands.h"
#include "cli/nmea_out.h"
#include "cli/replay_settings.h"
#include "cli/voyage_options.h"
#include "common/angles.h"
#include "common/time.h"
#include "files/live_run.h"
#include "files/recorded_actions.h"
#include "files/track_output.h"
#include "files/voyage_compare.h"
#include "files/voyage_record.h"
#include "io/error_line.h"
#include "io/iso8601.h"
#include "io/text_file.h"
#include "io/text_format.h"
#include "sim/nmea_export.h"
#include "sim/nmea_output.h"
#include "sim/replay.h"

namespace reckoner::cli {
namespace {

// ---- replay --------------------------------------------------------------------------------------
struct ReplayArgs {
  std::optional<std::string> nmea, radar, nmeaOut, recording;
  ReplaySettings settings;
  OutputArgs output;
};

void printReplayInput(const sim::ReplayResult& r) {
  const auto& st = r.stats;
  std::printf(
      "  NMEA: %ld lines, %ld sentences used, %ld skipped (%ld comments, %ld bad checksum, %ld unknown, %ld "
      "proprietary, "
      "%ld malformed, %ld untimed, %ld time jumps, %ld unusable, %ld not GNSS fixes, %ld implausible, %ld "
      "without variation); %ld standby, %ld repeated, %ld not used; %ld replayed out of file order\n",
      st.nmeaLines, st.sentencesUsed, st.nmeaSkipped(), st.comments, st.badChecksum, st.unknownSentences,
      st.proprietary, st.malformed, st.untimed, st.timeJumps, st.unusable, st.notGnss, st.implausible,
      st.noVariation, st.standby, st.repeated, st.notUsed, st.reordered);
  const double span = r.own.empty() ? 0.0 : toSeconds(r.own.back().timeUs - r.own.front().timeUs);
  for (const auto& src : r.sources) {
    if (src.used + src.standby + src.repeated == 0) continue;
    std::printf("    %-14s %-9s %6ld used %6ld standby, active %3.0f%%, clock %+.2f s%s\n",
                src.source.c_str(), src.quantity.c_str(), src.used, src.standby,
                span > 0 ? 100.0 * std::min(1.0, src.activeS / span) : 0.0, src.clockOffsetS,
                src.clockCorrected ? " (corrected)" : "");
  }
}

void printReplay(const sim::ReplayResult& r, const ReplayArgs& a, const std::string& out) {
  const auto& st = r.stats;
  const bool radar = a.radar.has_value();
  std::printf("Reckoner replay of %s%s%s from %s\n", a.nmea->c_str(), radar ? " and " : "",
              radar ? a.radar->c_str() : "", io::formatIso8601(r.utc0).c_str());
  printReplayInput(r);
  std::printf("  %ld own-ship epochs (%ld before the first fix), origin %s %s\n", st.epochs,
              st.epochsBeforeFix, io::formatLatitude(r.origin.latDeg).c_str(),
              io::formatLongitude(r.origin.lonDeg).c_str());
  std::printf("  DRKF updates accepted/gated/failed:");
  for (int b = 0; b < nav::kDrkfBlockCount; ++b) {
    const auto& c = r.updates[static_cast<std::size_t>(b)];
    std::printf(" %s %ld/%ld/%ld", nav::blockName(static_cast<nav::DrkfBlock>(b)), c.accepted, c.gated,
                c.failed);
  }
  std::printf("; restarts: %ld after a gap, %ld after failures\n", st.restartsAfterGap,
              st.restartsAfterFailure);
  if (radar)
    std::printf(
        "  radar: %ld lines, %ld plots, %ld bad, %ld duplicates, %ld time jumps; %ld tracks started, %ld "
        "confirmed (%s)\n",
        st.radarLines, st.radarPlots, st.radarBad, st.radarDuplicates, st.radarTimeJumps,
        r.tracking.tracksStarted, r.tracking.tracksConfirmed,
        a.settings.assumeAssociation ? "association by target_id" : "nearest neighbour");
  if (!r.own.empty()) {
    const auto& last = r.own.back();
    std::printf("  final estimate %s %s, position sd %.1f m\n",
                io::formatLatitude(last.estimate.latDeg).c_str(),
                io::formatLongitude(last.estimate.lonDeg).c_str(),
                std::hypot(last.estimate.sdXM, last.estimate.sdYM));
  }
  std::printf("  wrote %s/ownship.csv%s and %s/summary.json\n", out.c_str(),
              radar ? (", " + out + "/targets.csv").c_str() : "", out.c_str());
}

void printPlayback(const files::VoyageRecord& rec, const files::LiveRun& run, long batches,
                   const files::RecordComparison& c, const std::string& out) {
  const std::optional<UtcUs> end = rec.endUtc();
  std::printf("Reckoner replay of the voyage record %s (%s %s, recorded from %s %s%s)\n", rec.path().c_str(),
              rec.meta().count("program") ? rec.meta().at("program").c_str() : "?",
              rec.programVersion().c_str(), io::formatIso8601(rec.startUtc()).c_str(), end ? "to " : "",
              end ? io::formatIso8601(*end).c_str() : "to a stop without an end (killed)");
  const files::LiveOutputWriter& w = run.writer();
  std::printf(
      "  %ld lines, %ld radar lines in %ld batches; wrote %ld own-ship rows, %ld track rows, %ld AIS "
      "messages, "
      "%ld alert changes to %s\n",
      run.lines(), run.radarLines(), batches, w.ownRows(), w.trackRows(), w.aisRows(), w.alertRows(),
      out.c_str());
  std::printf(
      "  playback against the record: own-ship rows %ld equal, %ld different, %ld not recorded, %ld not "
      "replayed; track rows %ld equal, %ld different, %ld not recorded, %ld not replayed; alert entries %ld "
      "equal, %ld different, %ld not recorded, %ld not replayed\n",
      c.ownEqual, c.ownDifferent, c.ownNotRecorded, c.ownNotReplayed, c.tracksEqual, c.tracksDifferent,
      c.tracksNotRecorded, c.tracksNotReplayed, c.alertsEqual, c.alertsDifferent, c.alertsNotRecorded,
      c.alertsNotReplayed);
}

/// replay --recording: the recorded batches through files::LiveRun with the recorded settings, the
/// live run's files written again and compared with the recorded estimates.
int replayRecording(const ReplayArgs& a) {
  if (a.nmea || a.radar) throw UsageError("--recording cannot be given with --nmea or --radar");
  if (a.nmeaOut) throw UsageError("--nmea-out is not available with --recording");
  if (anyGiven(a.settings))
    throw UsageError(
        "--recording replays with the settings it recorded: --config, --profile, --date, "
        "--variation, --max-gap, --adaptive-gnss and --assume-association cannot be given with it");
  const files::VoyageRecord rec(*a.recording);
  const sim::LiveOptions options = rec.liveOptions();
  const std::string out = prepareOutDir(a.output);
  files::LiveRun run(options, out);
  // The look-ahead's charts, from where the run had them (the record names them, it does not hold them).
  if (const auto charts = rec.chartsPath()) {
    if (std::filesystem::exists(*charts))
      run.session().setChartGuard(chartGuardFor(options.replay.settings.voyage, charts));
    else
      std::fprintf(
          stderr,
          "reckoner-cli: warning: %s: the run's look-ahead charts %s are not there: replayed without "
          "the look-ahead (its alerts will differ)\n",
          rec.path().c_str(), charts->c_str());
  }
  files::RecordComparer compare(rec);
  long batches = 0;
  // The operator's actions put to the watch after the batch each followed, as in the run.
  files::ActionReplayer actions(rec.operatorActions());
  rec.forEachBatch([&](std::int64_t batch, std::span<const files::InputLine> lines) {
    compare.add(run.batch(lines, 0), run.session().result().targetLabels);
    actions.afterBatch(batch, run.watch());
    ++batches;
  });
  if (actions.skipped() > 0)
    std::fprintf(stderr,
                 "reckoner-cli: warning: %s: %ld operator actions this program cannot apply were skipped\n",
                 rec.path().c_str(), actions.skipped());
  compare.add(run.finish(rec.inputName(), 0), run.session().result().targetLabels);
  const files::RecordComparison c = compare.finish();
  for (const auto& w : run.session().result().warnings)
    std::fprintf(stderr, "reckoner-cli: warning: %s\n", w.c_str());
  if (!c.equal())
    std::fprintf(
        stderr, "reckoner-cli: warning: %s\n",
        io::oneLine(rec.path() + ": the replay differs from the record: " + c.firstDifference).c_str());
  printSummary(a.output, io::readTextFile(out + "/summary.json"));
  if (wantsTable(a.output)) printPlayback(rec, run, batches, c, out);
  return 0;
}

int replayCommand(const ReplayArgs& a) {
  if (a.recording) return replayRecording(a);
  if (!a.nmea) throw UsageError("--nmea FILE or --recording FILE.sqlite is required");
  const sim::ReplayOptions o = replayOptions(a.settings);
  std::unique_ptr<NmeaSink> sink;
  if (a.nmeaOut) sink = std::make_unique<NmeaSink>(*a.nmeaOut);
  const std::string out = prepareOutDir(a.output);
  const std::string nmea = io::readTextFile(*a.nmea);
  std::optional<std::string> radar;
  if (a.radar) radar = io::readTextFile(*a.radar);
  const sim::ReplayResult r = sim::replay(nmea, *a.nmea, radar ? &*radar : nullptr, a.radar.value_or(""), o);
  for (const auto& w : r.warnings) std::fprintf(stderr, "reckoner-cli: warning: %s\n", w.c_str());
  files::writeReplayOwnShipCsv(out + "/ownship.csv", r);
  if (radar) files::writeReplayTargetsCsv(out + "/targets.csv", r);
  const std::string summary = files::replaySummaryJson(r, *a.nmea);
  io::writeTextFile(out + "/summary.json", summary);
  printSummary(a.output, summary);
  if (wantsTable(a.output)) printReplay(r, a, out);
  if (sink) {
    sink->write(sim::replayNmea(r));
    const std::string account = sink->finish();
    if (wantsTable(a.output)) std::printf("  sent %s\n", account.c_str());
  }
  return 0;
}

void addReplay(CLI::App& root, Commands& out) {
  auto a = std::make_shared<ReplayArgs>();
  CLI::App* app =
      root.add_subcommand("replay", "recorded NMEA 0183 (and radar plots) through the DRKF and the trackers");
  addText(*app, "nmea", a->nmea, "FILE", "the NMEA 0183 log, required");
  addText(*app, "radar", a->radar, "FILE.csv", "radar plots (docs/outputs.md, radar.csv)");
  addText(*app, "recording", a->recording, "FILE.sqlite",
          "a voyage record of live --record instead of --nmea: its lines through the live run again, with "
          "its settings; the live run's files, and its estimates compared (docs/recorder.md)");
  addReplaySettings(*app, a->settings);
  addNmeaOut(*app, a->nmeaOut);
  addOutputOptions(
      *app, a->output, Summary::Json,
      "ownship.csv, summary.json, targets.csv with --radar; with --recording also ais.csv, alerts.csv");
  out.push_back(
      {app, [a] { return replayCommand(*a); }, "replay takes no positional arguments (use --nmea FILE)"});
}

// ---- export --------------------------------------------------------------------------------------
struct ExportArgs {
  std::string scenario;
  std::optional<std::uint64_t> seed;
  std::string date = "2026-01-01";
  OutputArgs output;
};

int exportCommand(const ExportArgs& a) {
  if (a.scenario.empty()) throw UsageError("export needs exactly one SCENARIO");
  const sim::Scenario s = loadScenario(a.scenario);
  const std::uint64_t seed = a.seed.value_or(s.seed);
  const auto utc0 = io::parseIso8601(a.date + "T00:00:00Z");
  if (!utc0) throw UsageError("--date: expected YYYY-MM-DD, got " + io::quoted(a.date));
  const std::string out = prepareOutDir(a.output);
  const auto e = sim::exportRun(s, seed, *utc0);
  io::writeTextFile(out + "/ownship.nmea", e.nmea);
  io::writeTextFile(out + "/radar.csv", e.radarCsv);
  if (wantsTable(a.output))
    std::printf("wrote %s/ownship.nmea and %s/radar.csv (%s, seed %llu, from %sT00:00:00Z)\n", out.c_str(),
                out.c_str(), s.name.c_str(), static_cast<unsigned long long>(seed), a.date.c_str());
  return 0;
}

void addExport(CLI::App& root, Commands& out) {
  auto a = std::make_shared<ExportArgs>();
  CLI::App* app =
      root.add_subcommand("export", "a simulated run as a recording: NMEA 0183 and radar plots (CSV)");
  addScenarioArgument(*app, a->scenario);
  addSeed(*app, a->seed, "the scenario's");
  addValue(*app, "date", "YYYY-MM-DD", "the UTC day the run starts at midnight of (default 2026-01-01)",
           [p = a.get()](const std::string& t) { p->date = t; });
  addOutputOptions(*app, a->output, Summary::None, "ownship.nmea, radar.csv");
  out.push_back({app, [a] { return exportCommand(*a); }, "export needs exactly one SCENARIO"});
}

}  // namespace

void addReplayCommands(CLI::App& root, Commands& out) {
  addReplay(root, out);
  addExport(root, out);
}

}  // namespace reckoner::cli
