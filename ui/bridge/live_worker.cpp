#include "ui/bridge/live_worker.h"

#include <QCoreApplication>
#include <QDateTime>
#include <algorithm>
#include <cmath>
#include <exception>

#include "files/live_run.h"
#include "files/recorded_actions.h"

namespace reckoner::ui {
namespace {
constexpr int kTickMs = 1000;
constexpr qint64 kMinEmitIntervalNs = 33'000'000;  // <= 30 frames per second
constexpr qint64 kAisRefreshNs = 250'000'000;
constexpr int kPlayTickMs = 20;
constexpr int kRecordTickMs = 100;  // the record's wall-clock commits (as reckoner-cli live's) // the
                                    // playback clock's step
constexpr qint64 kPlayBudgetNs = 15'000'000;  // of a tick's wall time fed to the pipeline
constexpr qint64 kSeekBudgetNs =
    3'600'000'000'000;  // a seek runs to its time (an hour of wall time: never)  // the AIS table copied for
                        // the GUI at most 4 times a second

UtcUs systemUtc() {
  return static_cast<UtcUs>(QDateTime::currentMSecsSinceEpoch()) * 1000;
}
}  // namespace

LiveWorker::LiveWorker(QObject* parent)
    : QObject(parent), timer_(new QTimer(this)), playTimer_(new QTimer(this)) {
  timer_->setInterval(kTickMs);
  connect(timer_, &QTimer::timeout, this, &LiveWorker::tick);
  recordTimer_ = new QTimer(this);
  recordTimer_->setInterval(kRecordTickMs);
  connect(recordTimer_, &QTimer::timeout, this, [this] {
    try {
      if (recorder_) recorder_->tick(systemUtc());
    } catch (const std::exception& e) {
      recorder_.reset();
      recordTimer_->stop();
      emit failed(QString::fromStdString(std::string("the voyage record stopped: ") + e.what()));
    }
  });
  playTimer_->setInterval(kPlayTickMs);
  connect(playTimer_, &QTimer::timeout, this, &LiveWorker::playbackTick);
  wall_.start();
}

LiveWorker::~LiveWorker() = default;

void LiveWorker::start(conn::ConnectionHub* hub, const sim::LiveOptions& options,
                       const sim::LiveWatchSettings& watch, quint64 generation) {
  stop();
  generation_ = generation;
  sim::LiveOptions o = options;
  o.frames = true;  // the window draws them
  try {
    session_ = std::make_unique<sim::LiveSession>(o);
    watch_ = std::make_unique<sim::LiveWatch>(watch);
  } catch (const std::exception& e) {
    session_.reset();
    watch_.reset();
    emit failed(QString::fromStdString(std::string("cannot start the live run: ") + e.what()));
    return;
  }
  applyVoyage();
  process_ = sim::drkfConfigFor(o.replay.settings).process;
  hub_ = hub;
  startRecording(o);
  pending_ = LiveFrame{};
  pending_.live = true;
  folder_.clear();
  lines_ = 0;
  inFlight_ = dirty_ = false;
  aisVersion_ = 0;
  linesConnection_ =
      connect(hub_, &conn::ConnectionHub::linesAvailable, this, &LiveWorker::consume, Qt::QueuedConnection);
  timer_->start();
  consume();  // what is queued already
}

void LiveWorker::stop() {
  playTimer_->stop();
  playback_.reset();
  playbackAlerts_.reset();
  playbackActions_.reset();
  if (!session_) return;
  disconnect(linesConnection_);
  timer_->stop();
  finishRecording();
  session_.reset();
  watch_.reset();
  hub_ = nullptr;
}

void LiveWorker::consume() {
  if (!session_ || !hub_) return;
  const std::vector<conn::ReceivedLine> lines = hub_->take(kBatchLines);
  std::optional<UtcUs> received;
  std::vector<files::InputLine> in;
  if (recorder_) in.reserve(lines.size());
  for (const conn::ReceivedLine& l : lines) {
    received = l.receivedUtc;
    const bool radar = l.role == conn::Role::Radar;
    if (radar)
      session_->radar(l.line, l.receivedUtc);
    else
      session_->nmea(l.line, l.receivedUtc, l.source);
    if (recorder_) in.push_back({l.source, l.line, l.receivedUtc, radar});
  }
  lines_ += lines.size();
  absorb(received, in);
  // A full batch leaves lines queued: come back after the commands waiting in the event loop.
  if (lines.size() == kBatchLines)
    QMetaObject::invokeMethod(this, &LiveWorker::consume, Qt::QueuedConnection);
  maybeEmit(false);
}

void LiveWorker::tick() {
  if (!session_ || playback_) return;
  absorb(systemUtc());
  maybeEmit(true);
}

void LiveWorker::absorb(std::optional<UtcUs> receivedUtc, std::span<const files::InputLine> lines) {
  sim::LiveWatch::Taken taken = watch_->absorb(*session_, receivedUtc);
  files::LiveBatch out;
  out.own = session_->takeOwnRows();
  out.tracks = session_->takeTrackRows(&out.trackUtc);
  out.alerts = watch_->alerts().takeLog();
  out.alertZeroUtc = watch_->zeroUtc();
  const std::vector<alerts::AlertLogEntry> log = out.alerts;
  sendNmea(out, taken.frames);
  if (recorder_) {
    // What a tick took waits for the next batch: a record holds rows only with the lines they came of.
    files::LiveBatch& r = unrecorded_;
    r.own.insert(r.own.end(), out.own.begin(), out.own.end());
    r.tracks.insert(r.tracks.end(), out.tracks.begin(), out.tracks.end());
    r.trackUtc.insert(r.trackUtc.end(), out.trackUtc.begin(), out.trackUtc.end());
    r.alerts.insert(r.alerts.end(), out.alerts.begin(), out.alerts.end());
    r.alertZeroUtc = out.alertZeroUtc;
    if (!lines.empty()) {
      try {
        recorder_->batch(lines, r, session_->result().targetLabels, session_->clockAt(receivedUtc),
                         systemUtc());
      } catch (const std::exception& e) {
        recorder_.reset();
        recordTimer_->stop();
        emit failed(QString::fromStdString(std::string("the voyage record stopped: ") + e.what()));
      }
      unrecorded_ = files::LiveBatch{};
    }
  }
  if (session_->started()) {
    pending_.liveOrigin = session_->result().origin;
    pending_.liveUtc0 = session_->result().utc0;
  }
  for (sim::SimFrame& f : taken.frames) {
    if (f.lookAhead)
      pending_.lookAhead = std::make_shared<const sim::GroundingOutlook>(std::move(*f.lookAhead));
    f.lookAhead.reset();
    folder_.fold(f, session_->frame(), process_, {}, pending_);
    f.sweeps.clear();  // in trackHistory now
    pending_.frame = std::move(f);
    dirty_ = true;
  }
  if (!log.empty()) {
    pending_.alertLog.insert(pending_.alertLog.end(), log.begin(), log.end());
    dirty_ = true;
  }
  refreshAis(false);
}

void LiveWorker::sendNmea(const files::LiveBatch& out, const std::vector<sim::SimFrame>& frames) {
  if (!nmeaDest_) return;
  std::vector<std::string> lines;
  if (session_->started())
    lines = sim::rowsNmea(*nmea_, out.own, out.tracks, out.trackUtc, session_->frame());
  // The autopilot's sentences of every frame monitored against the route.
  if (const auto& route = session_->voyage().spec().route)
    for (const sim::SimFrame& f : frames)
      if (f.route)
        for (std::string& l :
             nmea_->route(session_->result().utc0 + f.timeUs, *f.route, *route, f.deadReckoning.active))
          lines.push_back(std::move(l));
  if (watch_->zeroUtc() != 0) {
    const auto alerts = nmea_->alerts(watch_->nowUs(), watch_->nowUtc(), watch_->alerts().alerts());
    lines.insert(lines.end(), alerts.begin(), alerts.end());
  }
  if (!lines.empty()) nmeaDest_->write(lines);
}

void LiveWorker::setRoute(const std::optional<geo::Route>& route) {
  route_ = route;
  applyVoyage();
}

void LiveWorker::setCharts(std::vector<charts::CellPtr> cells) {
  cells_ = cells;
  recordCharts();
  guard_.setCells(std::move(cells));
  applyVoyage();
}

void LiveWorker::setSafety(const charts::SafetySettings& safety) {
  guard_.setSafety(safety);
  applyVoyage();
}

void LiveWorker::applyVoyage() {
  if (!session_) return;
  std::shared_ptr<const charts::ChartSafety> guard;
  try {
    // A playback monitors the recorded route (its alerts are the record's); a live run the window's.
    if (!playback_) session_->setRoute(route_);
    guard = guard_.guardFor(session_->voyage().spec());
    session_->setChartGuard(guard);
  } catch (const std::exception& e) {
    emit failed(QString::fromStdString(std::string("live route monitoring: ") + e.what()));
  }
  pending_.route = session_->voyage().spec().route
                       ? std::make_shared<const geo::Route>(*session_->voyage().spec().route)
                       : nullptr;
  if (!guard) pending_.lookAhead.reset();
  dirty_ = true;
}

void LiveWorker::setNmeaOut(const QString& spec) {
  nmeaDest_.reset();
  if (spec.trimmed().isEmpty()) return;
  try {
    nmeaDest_ = std::make_unique<conn::NmeaDestination>(conn::parseDestination(spec.trimmed().toStdString()));
    nmea_ = std::make_unique<sim::NmeaOutput>();
  } catch (const std::exception& e) {
    nmeaDest_.reset();
    emit failed(QStringLiteral("NMEA output %1: %2").arg(spec, QString::fromStdString(e.what())));
  }
}

void LiveWorker::refreshAis(bool force) {
  if (watch_->aisVersion() == aisVersion_) return;
  const qint64 now = wall_.nsecsElapsed();
  if (!force && now - lastAisNs_ < kAisRefreshNs) return;
  aisVersion_ = watch_->aisVersion();
  lastAisNs_ = now;
  const track::AisTargetTable& table = watch_->aisTable();
  pending_.aisTargets = std::make_shared<const std::vector<track::AisTarget>>(table.targets());
  pending_.aisOwnShip = table.ownShip();
  pending_.aisCounts = table.counts();
  pending_.aisUtc = watch_->aisUtc();
  pending_.ownShipSource = watch_->ownShipSource();
  dirty_ = true;
}

void LiveWorker::maybeEmit(bool force) {
  if (!session_ || inFlight_ || !dirty_ || !session_->started()) return;
  const qint64 now = wall_.nsecsElapsed();
  if (!force && now - lastEmitNs_ < kMinEmitIntervalNs) return;
  refreshAis(true);
  pending_.sequence = ++sequence_;
  pending_.loadGeneration = generation_;
  pending_.recentPlots.assign(folder_.plots().begin(), folder_.plots().end());
  pending_.alerts = watch_->alerts().alerts();
  pending_.alertAudible = watch_->alerts().audible();
  pending_.positionFixUsed = !pending_.frame.deadReckoning.active;
  pending_.drLimitM = watch_->settings().alerts.drLimitM;
  pending_.running = true;
  pending_.rate = 1.0;
  pending_.achievedRate = 1.0;
  pending_.radarOn = session_->result().sweepPeriodS > 0.0 && !pending_.frame.tracks.empty();
  pending_.liveLines = lines_;
  pending_.liveRows = static_cast<long>(session_->result().stats.epochs);
  setPlaybackState();
  inFlight_ = true;
  dirty_ = false;
  lastEmitNs_ = now;
  emit frameReady(pending_);
  pending_.clearBatches();
  pending_.restarted = false;
}

void LiveWorker::frameConsumed() {
  inFlight_ = false;
  maybeEmit(false);
}

void LiveWorker::acknowledgeAlert(alerts::AlertId id) {
  if (!watch_ || !watch_->acknowledge(id)) return;
  recordAction("acknowledge",
               std::string("alert:") + alerts::traitsOf(id.kind).name + ':' + std::to_string(id.source), "");
  dirty_ = true;
  maybeEmit(true);
}

void LiveWorker::silenceAlerts() {
  if (!watch_ || watch_->silenceAll() == 0) return;
  recordAction("silence_all", "", "");
  dirty_ = true;
  maybeEmit(true);
}

void LiveWorker::setCpaLimits(double cpaM, double tcpaS) {
  if (!watch_) return;
  try {
    watch_->setCpaLimits(cpaM, tcpaS);
    recordAction("cpa_limits", "", "cpa_m=" + std::to_string(cpaM) + ";tcpa_s=" + std::to_string(tcpaS));
  } catch (const std::exception& e) {
    emit failed(QString::fromStdString(std::string("CPA/TCPA limits: ") + e.what()));
  }
}

void LiveWorker::setDrLimit(double metres) {
  if (!watch_) return;
  try {
    watch_->setDrLimit(metres);
    recordAction("dr_limit", "", "m=" + std::to_string(metres));
  } catch (const std::exception& e) {
    emit failed(QString::fromStdString(std::string("dead-reckoning limit: ") + e.what()));
  }
}

void LiveWorker::activateAis(quint32 mmsi, bool on) {
  if (watch_ && watch_->activate(mmsi, on)) {
    recordAction(on ? "ais_activate" : "ais_sleep", "mmsi:" + std::to_string(mmsi), "");
    refreshAis(true);
  }
  maybeEmit(true);
}

void LiveWorker::selectAis(quint32 mmsi) {
  if (watch_ && watch_->select(mmsi)) {
    recordAction("ais_select", "mmsi:" + std::to_string(mmsi), "");
    refreshAis(true);
  }
  maybeEmit(true);
}

// ---- recording ----------------------------------------------------------------------------------

void LiveWorker::setRecordPath(const QString& path) {
  recordPath_ = path;
}

void LiveWorker::startRecording(const sim::LiveOptions& options) {
  recorder_.reset();
  unrecorded_ = files::LiveBatch{};
  recordedCells_.clear();
  if (recordPath_.isEmpty() || !hub_) return;
  files::RecorderSettings s;
  s.program = "reckoner";
  s.programVersion = QCoreApplication::applicationVersion().toStdString();
  s.options = options;
  for (const conn::SourceConfig& c : hub_->sources())
    s.sources.push_back({0, c.name, c.role == conn::Role::Radar ? "radar" : "nmea", conn::toSpec(c)});
  try {
    recorder_ = std::make_unique<files::VoyageRecorder>(recordPath_.toStdString(), s, systemUtc());
  } catch (const std::exception& e) {
    emit failed(QString::fromStdString(std::string("the live run is not recorded: ") + e.what()));
    return;
  }
  recordCharts();
  recordTimer_->start();
}

void LiveWorker::finishRecording() {
  if (!recorder_ || !session_) return;
  recordTimer_->stop();
  try {
    session_->finish();
    absorb(std::nullopt);  // the session's last rows join what is not recorded yet
    recorder_->finish(unrecorded_, session_->result().targetLabels, systemUtc());
  } catch (const std::exception& e) {
    emit failed(QString::fromStdString(std::string("the voyage record's end: ") + e.what()));
  }
  recorder_.reset();
  unrecorded_ = files::LiveBatch{};
}

void LiveWorker::recordAction(const char* action, const std::string& subject, const std::string& value) {
  if (!recorder_ || !watch_) return;
  try {
    files::OperatorAction a;
    a.afterBatch = recorder_->batches();
    a.wallUtc = systemUtc();
    if (watch_->zeroUtc() != 0) a.streamUtc = watch_->nowUtc();
    a.action = action;
    a.subject = subject;
    a.value = value;
    recorder_->operatorAction(std::move(a));
  } catch (const std::exception& e) {
    emit failed(QString::fromStdString(std::string("the voyage record: ") + e.what()));
  }
}

void LiveWorker::recordCharts() {
  if (!recorder_) return;
  const auto has = [](const std::vector<charts::CellPtr>& in, const charts::CellPtr& c) {
    return std::find(in.begin(), in.end(), c) != in.end();
  };
  const auto event = [&](const charts::CellPtr& c, const char* what) {
    const charts::CellInfo& i = c->info();
    files::ChartEvent e;
    e.wallUtc = systemUtc();
    if (watch_ && watch_->zeroUtc() != 0) e.streamUtc = watch_->nowUtc();
    e.event = what;
    e.name = i.name;
    e.edition = i.edition;
    e.updateNumber = std::to_string(i.updateNumber);
    e.issueDate = i.issueDate;
    e.path = i.path;
    recorder_->chart(e);
  };
  try {
    for (const charts::CellPtr& c : recordedCells_)
      if (!has(cells_, c)) event(c, "unloaded");
    for (const charts::CellPtr& c : cells_)
      if (!has(recordedCells_, c)) event(c, "loaded");
    recordedCells_ = cells_;
  } catch (const std::exception& e) {
    emit failed(QString::fromStdString(std::string("the voyage record: ") + e.what()));
  }
}

// ---- playback -----------------------------------------------------------------------------------

void LiveWorker::startPlayback(const QString& path, quint64 generation) {
  stop();
  generation_ = generation;
  try {
    playback_ = std::make_unique<files::RecordPlayback>(path.toStdString());
  } catch (const std::exception& e) {
    playback_.reset();
    emit failed(QString::fromStdString(std::string("cannot play the record back: ") + e.what()));
    return;
  }
  playbackPath_ = path;
  playbackAlerts_ = std::make_shared<const std::vector<files::RecordedAlert>>(playback_->alerts());
  playbackActions_.emplace(playback_->record().operatorActions());
  playbackRate_ = 0.0;
  if (!restartPlayback()) return;
  // To the first estimate, so the window has own ship to show.
  while (pending_.ownHistory.empty() && !playback_->atEnd()) playTo(playback_->span().last, kSeekBudgetNs, 1);
  dirty_ = true;
  maybeEmit(true);
}

bool LiveWorker::restartPlayback() {
  sim::LiveOptions o = playback_->options();
  o.frames = true;  // the window draws them
  try {
    session_ = std::make_unique<sim::LiveSession>(o);
    watch_ = std::make_unique<sim::LiveWatch>(files::liveWatchSettings(o));
  } catch (const std::exception& e) {
    stop();
    emit failed(QString::fromStdString(std::string("cannot play the record back: ") + e.what()));
    return false;
  }
  process_ = sim::drkfConfigFor(o.replay.settings).process;
  playback_->rewind();
  if (playbackActions_) playbackActions_->rewind();
  playbackClock_ = playback_->span().first;
  pending_ = LiveFrame{};
  pending_.live = true;
  pending_.restarted = true;
  folder_.clear();
  lines_ = 0;
  aisVersion_ = 0;
  applyVoyage();
  return true;
}

void LiveWorker::playTo(UtcUs utc, qint64 budgetNs, std::size_t maxBatches) {
  const qint64 start = wall_.nsecsElapsed();
  const auto feed = [this](std::int64_t batch, std::span<const files::InputLine> lines) {
    // As files::LiveRun::batch: every line into the session, then the watch absorbs at the last one's time.
    std::optional<UtcUs> received;
    for (const files::InputLine& l : lines) {
      if (l.receivedUtc != 0) received = l.receivedUtc;
      if (l.radar)
        session_->radar(l.line, l.receivedUtc);
      else
        session_->nmea(l.line, l.receivedUtc, l.source);
    }
    lines_ += lines.size();
    absorb(received);
    if (playbackActions_) playbackActions_->afterBatch(batch, *watch_);  // the operator's, as in the run
  };
  bool all = false;
  std::size_t fed = 0;
  while (fed < maxBatches && wall_.nsecsElapsed() - start < budgetNs) {
    const std::size_t n = playback_->feedTo(utc, feed, std::min<std::size_t>(16, maxBatches - fed));
    if (n == 0) {
      all = true;
      break;
    }
    fed += n;
  }
  playbackClock_ = all ? std::max(playbackClock_, utc) : std::max(playbackClock_, playback_->position());
  if (playback_->atEnd()) {
    playbackClock_ = std::max(playbackClock_, playback_->span().last);
    session_->finish();
    absorb(std::nullopt);
    playbackRate_ = 0.0;
    playTimer_->stop();
  }
  dirty_ = true;
}

void LiveWorker::playbackTick() {
  if (!playback_ || playbackRate_ == 0.0) return;
  const qint64 now = wall_.nsecsElapsed();
  const double dtS = static_cast<double>(now - lastPlayNs_) * 1e-9;
  lastPlayNs_ = now;
  const UtcUs target = playbackRate_ < 0.0
                           ? playback_->span().last
                           : playbackClock_ + static_cast<UtcUs>(std::llround(dtS * playbackRate_ * 1e6));
  playTo(target, kPlayBudgetNs);
  maybeEmit(false);
}

void LiveWorker::setPlaybackRate(double rate) {
  if (!playback_) return;
  playbackRate_ = std::isfinite(rate) ? rate : -1.0;
  lastPlayNs_ = wall_.nsecsElapsed();
  if (playbackRate_ != 0.0 && !playback_->atEnd())
    playTimer_->start();
  else
    playTimer_->stop();
  if (playback_->atEnd()) playbackRate_ = 0.0;
  dirty_ = true;
  maybeEmit(true);
}

void LiveWorker::seekPlayback(qint64 utc) {
  if (!playback_) return;
  const files::TimeSpan span = playback_->span();
  const UtcUs to = std::clamp<UtcUs>(utc, span.first, span.last);
  if (to < playbackClock_ && !restartPlayback()) return;
  playTo(to, kSeekBudgetNs);
  lastPlayNs_ = wall_.nsecsElapsed();
  if (playbackRate_ != 0.0 && !playback_->atEnd()) playTimer_->start();
  dirty_ = true;
  maybeEmit(true);
}

void LiveWorker::setPlaybackState() {
  if (!playback_) {
    pending_.playback.reset();
    return;
  }
  LiveFrame::Playback p;
  p.path = playbackPath_;
  p.first = playback_->span().first;
  p.last = playback_->span().last;
  p.clock = playbackClock_;
  if (const auto stream = playback_->record().estimateSpan()) {
    p.streamFirst = stream->first;
    p.streamLast = stream->last;
  }
  p.rate = playbackRate_;
  p.atEnd = playback_->atEnd();
  p.alerts = playbackAlerts_;
  pending_.playback = std::move(p);
  pending_.running = playbackRate_ != 0.0;
  pending_.rate = playbackRate_;
}

}  // namespace reckoner::ui
