// live: NMEA 0183, AIS and radar plots from live connections (UDP, TCP, serial, gpsd, a file played in
// real time) through the replay's engine as they arrive (sim/live_session.h), the alerts and the AIS
// target table kept beside it (sim/live_watch.h), written to the replay's ownship.csv, targets.csv and
// summary.json plus ais.csv and alerts.csv (docs/outputs.md, "Live input"), until SIGINT, SIGTERM,
// --duration or, with files alone, their end; with --record, the voyage record of it all
// (files/voyage_recorder.h, docs/recorder.md).
#include <QCoreApplication>
#include <QSocketNotifier>
#include <QTimer>

#include <unistd.h>
#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "cli/cli_options.h"
#include "cli/commands.h"
#include "cli/nmea_out.h"
#include "cli/replay_settings.h"
#include "cli/voyage_options.h"
#include "connection_hub.h"
#include "files/live_run.h"
#include "files/voyage_recorder.h"
#include "io/input_error.h"
#include "reckoner_version.h"
#include "sim/live_session.h"
#include "sim/live_watch.h"
#include "sim/nmea_output.h"
#include "source_config.h"

namespace reckoner::cli {
namespace {

struct LiveArgs {
  std::vector<std::string> udp, tcp, serial, gpsd, file, source, radarUdp, radarTcp;
  std::optional<double> durationS;
  std::optional<std::string> nmeaOut, record;
  std::optional<double> recordMaxHours;
  bool nmeaOutAis = false;
  bool noNmeaOutAlerts = false;
  double reorderHorizonS = 1.0;
  double statusIntervalS = 1.0;
  double fileRate = 1.0;
  ReplaySettings settings;
  VoyageArgs voyage;
  OutputArgs output;
};

// SIGINT / SIGTERM end the run through a pipe the event loop watches (the handler only writes a byte).
int stopPipe[2] = {-1, -1};
/// The period of the record's wall-clock commit check, ms.
constexpr int kRecordTickMs = 100;
extern "C" void onStopSignal(int) {
  const char c = 's';
  [[maybe_unused]] const auto n = ::write(stopPipe[1], &c, 1);
}

/// The sources of the command line, each named (the spec's name= or kind and number) and unique.
std::vector<conn::SourceConfig> sourcesOf(const LiveArgs& a) {
  std::vector<conn::SourceConfig> out;
  std::set<std::string> names;
  const auto add = [&](const std::string& spec, const std::string& name, bool radar) {
    conn::SourceConfig c = conn::parseSource(spec);  // std::invalid_argument naming the spec's field
    if (spec.find("name=") == std::string::npos) c.name = name;
    if (radar) c.role = conn::Role::Radar;
    if (!names.insert(c.name).second) throw UsageError("two sources are named " + c.name);
    out.push_back(c);
  };
  int n = 0;
  const auto name = [&n](const char* kind) { return std::string(kind) + std::to_string(++n); };
  for (const auto& p : a.udp) add("udp://:" + p, name("udp"), false);
  for (const auto& p : a.tcp) add("tcp://" + p, name("tcp"), false);
  for (const auto& p : a.serial) add("serial://" + p, name("serial"), false);
  for (const auto& p : a.gpsd) add("gpsd://" + p, name("gpsd"), false);
  for (const auto& p : a.file) add("file://" + p + "?rate=x" + numberText(a.fileRate), name("file"), false);
  for (const auto& s : a.source) add(s, name("source"), false);
  for (const auto& p : a.radarUdp) add("udp://:" + p, name("radar"), true);
  for (const auto& p : a.radarTcp) add("tcp://" + p, name("radar"), true);
  if (out.empty())
    throw UsageError("live needs at least one source (--udp, --tcp, --serial, --gpsd, --file or --source)");
  return out;
}

/// The system clock, UTC microseconds (the hub's receive clock; the recorder's wall clock).
UtcUs wallNow() {
  return std::chrono::duration_cast<std::chrono::microseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

/// The recorder of --record: the run's settings and its connections in the record's meta and sources.
std::unique_ptr<files::VoyageRecorder> recorderOf(const LiveArgs& a, const sim::LiveOptions& options,
                                                  const std::vector<conn::SourceConfig>& sources) {
  if (!a.record) return nullptr;
  files::RecorderSettings s;
  s.programVersion = RECKONER_VERSION;
  s.options = options;
  s.maxHours = a.recordMaxHours;
  s.charts = a.voyage.enc;
  for (const conn::SourceConfig& c : sources)
    s.sources.push_back({0, c.name, c.role == conn::Role::Radar ? "radar" : "nmea", conn::toSpec(c)});
  return std::make_unique<files::VoyageRecorder>(*a.record, s, wallNow());
}

/// The live pipeline (files/live_run.h: session, watch, files, record) and its NMEA output, fed from
/// the hub on the thread that owns them.
class LiveEngine {
 public:
  LiveEngine(const LiveArgs& a, const sim::LiveOptions& options, const std::string& out,
             const std::vector<conn::SourceConfig>& sources)
      : a_(a),
        recorder_(recorderOf(a, options, sources)),
        run_(options, out, recorder_.get()),
        nmea_(nmeaOptions(a)) {
    // after the application: a TCP server lives in its event loop
    if (a.nmeaOut) sink_ = std::make_unique<NmeaSink>(*a.nmeaOut);
  }

  /// Every line the hub holds into the pipeline as one batch; the rows written, recorded and sent.
  void consume(conn::ConnectionHub& hub) {
    std::vector<files::InputLine> lines;
    for (conn::ReceivedLine& l : hub.take()) {
      const bool radar = l.role == conn::Role::Radar;
      if (!radar && sink_ && a_.nmeaOutAis) sink_->write(nmea_.ais(l.line));
      lines.push_back({std::move(l.source), std::move(l.line), l.receivedUtc, radar});
    }
    send(run_.batch(lines, wallNow()));
  }
  void setChartGuard(std::shared_ptr<const sim::ChartGuard> guard) {
    run_.session().setChartGuard(std::move(guard));
  }
  /// The recorder's commits on the wall clock while the input is silent.
  void tick() { run_.tick(wallNow()); }

  void printStatus(const conn::ConnectionHub& hub) const {
    const files::LiveOutputWriter& w = run_.writer();
    std::fprintf(stderr,
                 "live: %ld lines, %ld radar lines, %ld own-ship rows, %ld track rows, %ld AIS messages, "
                 "%zu AIS targets, %zu alerts",
                 run_.lines(), run_.radarLines(), w.ownRows(), w.trackRows(), w.aisRows(),
                 run_.watch().aisTable().size(), run_.watch().alerts().alerts().size());
    if (recorder_)
      std::fprintf(stderr, ", recorded %lld lines (%lld committed)",
                   static_cast<long long>(recorder_->lines()),
                   static_cast<long long>(recorder_->committedLines()));
    for (const conn::SourceStatus& s : hub.status())
      std::fprintf(stderr, "; %s %s %llu lines", s.name.c_str(), conn::stateName(s.state),
                   static_cast<unsigned long long>(s.lines));
    std::fputc('\n', stderr);
  }

  /// After the hub stopped: its last lines, the session's last rows, summary.json, the account.
  void finish(conn::ConnectionHub& hub, const std::string& out) {
    consume(hub);
    send(run_.finish("live", wallNow()));
    for (const auto& w : run_.session().result().warnings)
      std::fprintf(stderr, "reckoner-cli: warning: %s\n", w.c_str());
    const files::LiveOutputWriter& w = run_.writer();
    if (wantsTable(a_.output))
      std::printf(
          "Reckoner live: %ld lines, %ld radar lines; wrote %ld own-ship rows, %ld track rows, %ld AIS "
          "messages, %ld alert changes to %s\n",
          run_.lines(), run_.radarLines(), w.ownRows(), w.trackRows(), w.aisRows(), w.alertRows(),
          out.c_str());
    if (recorder_ && wantsTable(a_.output))
      std::printf(
          "  recorded %lld lines in %lld batches to %s (%lld commits, %lld syncs, %lld rows pruned)\n",
          static_cast<long long>(recorder_->lines()), static_cast<long long>(recorder_->batches()),
          recorder_->path().c_str(), static_cast<long long>(recorder_->commits()),
          static_cast<long long>(recorder_->syncs()), static_cast<long long>(recorder_->prunedRows()));
    if (sink_) {
      const std::string account = sink_->finish();
      if (wantsTable(a_.output)) std::printf("  sent %s\n", account.c_str());
    }
  }

 private:
  static sim::NmeaOutputOptions nmeaOptions(const LiveArgs& a) {
    sim::NmeaOutputOptions o;
    o.ais = a.nmeaOutAis;
    return o;
  }
  void send(const files::LiveBatch& batch) {
    if (!sink_) return;
    const sim::LiveSession& session = run_.session();
    if (session.started()) {
      const geo::GeoPoint o = session.result().origin;
      sink_->write(
          sim::rowsNmea(nmea_, batch.own, batch.tracks, batch.trackUtc, geo::LocalFrame(o.latDeg, o.lonDeg)));
    }
    // The autopilot's sentences (XTE, RMB, APB) of every frame monitored against the route.
    if (const auto& route = session.voyage().spec().route)
      for (const files::LiveBatch::RouteRow& r : batch.route)
        sink_->write(nmea_.route(r.utc, r.status, *route, r.deadReckoning));
    const sim::LiveWatch& watch = run_.watch();
    if (!a_.noNmeaOutAlerts && watch.zeroUtc() != 0)
      sink_->write(nmea_.alerts(watch.nowUs(), watch.nowUtc(), watch.alerts().alerts()));
  }

  const LiveArgs& a_;
  std::unique_ptr<files::VoyageRecorder> recorder_;
  files::LiveRun run_;
  sim::NmeaOutput nmea_;
  std::unique_ptr<NmeaSink> sink_;
};

int liveCommand(const LiveArgs& a) {
  const std::vector<conn::SourceConfig> sources = sourcesOf(a);
  sim::LiveOptions lo;
  lo.replay = replayOptions(a.settings);
  lo.name = "live";
  lo.reorderHorizonS = a.reorderHorizonS;
  lo.radar =
      std::any_of(sources.begin(), sources.end(), [](const auto& c) { return c.role == conn::Role::Radar; });
  lo.frames = true;  // the watch's alerts read them
  applyVoyageArgs(a.voyage, lo.replay.settings.voyage);
  const std::shared_ptr<const sim::ChartGuard> guard = chartGuardFor(lo.replay.settings.voyage, a.voyage.enc);
  if (a.recordMaxHours && !a.record) throw UsageError("--record-max-hours needs --record FILE.sqlite");
  const std::string out = prepareOutDir(a.output);

  int argc = 1;
  char arg0[] = "reckoner-cli";
  char* argv[] = {arg0, nullptr};
  QCoreApplication app(argc, argv);
  LiveEngine engine(a, lo, out, sources);
  engine.setChartGuard(guard);
  if (::pipe(stopPipe) != 0) throw std::runtime_error("cannot make the signal pipe");
  std::signal(SIGINT, onStopSignal);
  std::signal(SIGTERM, onStopSignal);
  QSocketNotifier stopNotifier(stopPipe[0], QSocketNotifier::Read);
  QObject::connect(&stopNotifier, &QSocketNotifier::activated, &app, [&app] { app.quit(); });

  conn::ConnectionHub hub;
  for (const auto& c : sources) hub.add(c);
  std::string lastError;
  QObject::connect(&hub, &conn::ConnectionHub::linesAvailable, &app, [&] {
    try {
      engine.consume(hub);
    } catch (const std::exception& e) {  // an output that cannot be written: stop, report it
      lastError = e.what();
      app.quit();
    }
  });
  QTimer status;
  QObject::connect(&status, &QTimer::timeout, &app, [&] { engine.printStatus(hub); });
  // The record's commits on the wall clock (docs/recorder.md): a pending insert waits at most 0.5 s
  // and this tick, so a silent input still has its last lines committed.
  QTimer recordTick;
  QObject::connect(&recordTick, &QTimer::timeout, &app, [&] {
    try {
      engine.tick();
    } catch (const std::exception& e) {
      lastError = e.what();
      app.quit();
    }
  });
  if (a.record) recordTick.start(kRecordTickMs);
  // A run of files alone ends when every file has been played to its end.
  const bool filesOnly =
      std::all_of(sources.begin(), sources.end(), [](const auto& c) { return c.kind == conn::Kind::File; });
  QObject::connect(&hub, &conn::ConnectionHub::stateChanged, &app, [&] {
    const auto st = hub.status();
    if (filesOnly &&
        std::all_of(st.begin(), st.end(), [](const auto& s) { return s.state == conn::State::Finished; }))
      app.quit();
  });
  if (a.statusIntervalS > 0) status.start(static_cast<int>(a.statusIntervalS * 1000.0));
  if (a.durationS) QTimer::singleShot(static_cast<int>(*a.durationS * 1000.0), &app, [&app] { app.quit(); });
  hub.start();
  app.exec();
  hub.stop();
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  if (!lastError.empty()) throw std::runtime_error(lastError);
  engine.finish(hub, out);
  return 0;
}

}  // namespace

void addLiveCommands(CLI::App& root, Commands& out) {
  auto a = std::make_shared<LiveArgs>();
  CLI::App* app = root.add_subcommand(
      "live",
      "live NMEA 0183, AIS and radar plots through the DRKF and the trackers, until SIGINT or --duration");
  app->add_option("--udp", a->udp, "NMEA over UDP on this local port (repeatable)")->type_name("PORT");
  app->add_option("--tcp", a->tcp, "NMEA from a TCP server, reconnecting when it goes away")
      ->type_name("HOST:PORT");
  app->add_option("--serial", a->serial, "NMEA from a serial port, default 4800 baud")
      ->type_name("DEV[:BAUD]");
  app->add_option("--gpsd", a->gpsd, "the NMEA a gpsd relays (its watch protocol)")->type_name("HOST:PORT");
  app->add_option("--file", a->file, "a recording played at its own pace (--file-rate)")->type_name("PATH");
  app->add_option("--source", a->source, "any source spec (docs/connections.md)")->type_name("SPEC");
  app->add_option("--radar-udp", a->radarUdp, "radar plots (radar CSV rows) over UDP")->type_name("PORT");
  app->add_option("--radar-tcp", a->radarTcp, "radar plots (radar CSV rows) from a TCP server")
      ->type_name("HOST:PORT");
  addReal(*app, "file-rate", a->fileRate, 0.01, 1e6, "X",
          "--file played this many times faster than real time");
  addReal(*app, "duration", a->durationS, 0.001, 1e9, "S", "stop after this many seconds (default: SIGINT)");
  addReal(*app, "reorder-horizon", a->reorderHorizonS, 0.0, 60.0, "S",
          "hold sentences this long for ones that arrive out of order, seconds");
  addReal(*app, "status-interval", a->statusIntervalS, 0.0, 3600.0, "S",
          "a status line on stderr this often, seconds (0: none)");
  addNmeaOut(*app, a->nmeaOut);
  addText(*app, "record", a->record, "FILE.sqlite",
          "record every input line, the estimates and the alerts in this voyage record (a new file; "
          "docs/recorder.md)");
  addReal(*app, "record-max-hours", a->recordMaxHours, 0.01, 1e6, "H",
          "keep full-rate estimates and track rows this many hours back, older ones one a minute; "
          "without it all are kept");
  app->add_flag("--nmea-out-ais", a->nmeaOutAis, "pass the AIS sentences received through to --nmea-out");
  app->add_flag("--no-nmea-out-alerts", a->noNmeaOutAlerts,
                "send no alert sentences (ALR, ALF, ALC) to --nmea-out, only own ship and tracks");
  addReplaySettings(*app, a->settings);
  addVoyageOptions(*app, a->voyage);
  addOutputOptions(*app, a->output, Summary::None,
                   "ownship.csv, summary.json, ais.csv, alerts.csv, targets.csv with radar");
  out.push_back({app, [a] { return liveCommand(*a); }, "live takes no positional arguments"});
}

}  // namespace reckoner::cli
