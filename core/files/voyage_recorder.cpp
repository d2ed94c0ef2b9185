#include "files/voyage_recorder.h"

#include <cmath>
#include <stdexcept>

#include "files/sqlite_db.h"
#include "files/voyage_rows.h"
#include "files/voyage_schema.h"
#include "io/input_error.h"
#include "io/iso8601.h"

namespace reckoner::files {
namespace {

constexpr std::int64_t kMinuteUs = 60 * kMicrosPerSecond;
/// Pruning (--record-max-hours) runs at most once per this much stream time.
constexpr std::int64_t kPruneEveryUs = kMinuteUs;
/// The file's SQLite application_id: "RCKR", so `file` and tools can tell a voyage record.
constexpr int kApplicationId = 0x52434b52;

std::int64_t minuteOf(UtcUs utc) {
  return utc >= 0 ? utc / kMinuteUs : (utc - kMinuteUs + 1) / kMinuteUs;
}

bool positiveFinite(double v) {
  return std::isfinite(v) && v > 0.0;
}

}  // namespace

void validate(const RecorderSettings& s) {
  if (!positiveFinite(s.commitStreamS))
    throw std::invalid_argument("commit_stream_s: must be finite and above 0");
  if (!positiveFinite(s.commitWallS))
    throw std::invalid_argument("commit_wall_s: must be finite and above 0");
  if (!positiveFinite(s.syncWallS)) throw std::invalid_argument("sync_wall_s: must be finite and above 0");
  if (s.maxHours && !positiveFinite(*s.maxHours))
    throw std::invalid_argument("record_max_hours: must be finite and above 0");
}

struct VoyageRecorder::Statements {
  explicit Statements(sqlite::Db& db)
      : input(db, "INSERT INTO inputs(batch, rx_utc_us, source, line) VALUES(?1, ?2, ?3, ?4)"),
        source(db, "INSERT INTO sources(name, role, spec) VALUES(?1, ?2, ?3)"),
        own(db, voyage::insertSql("ownship")),
        track(db, voyage::insertSql("tracks")),
        alert(db, voyage::insertSql("alerts")),
        meta(db, "INSERT INTO meta(key, value) VALUES(?1, ?2)"),
        action(db, voyage::insertSql("operator_actions")),
        chart(db, voyage::insertSql("charts")),
        pruneOwn(db, "DELETE FROM ownship WHERE minute = 0 AND utc_us < ?1"),
        pruneTracks(db, "DELETE FROM tracks WHERE minute = 0 AND utc_us < ?1") {}
  sqlite::Statement input, source, own, track, alert, meta, action, chart, pruneOwn, pruneTracks;
};

VoyageRecorder::VoyageRecorder(const std::string& path, const RecorderSettings& settings, UtcUs wallUtc)
    : s_((validate(settings), settings)),
      db_(std::make_unique<sqlite::Db>(path, sqlite::Db::Mode::Create)),
      lastSyncWall_(wallUtc) {
  {
    sqlite::Statement mode(*db_, "PRAGMA journal_mode=WAL");
    if (!mode.step() || mode.text(0) != "wal")
      throw io::InputError(path, 0, "", "the file system refuses SQLite's write-ahead log (WAL)");
  }
  db_->exec("PRAGMA synchronous=NORMAL");
  db_->exec("PRAGMA application_id=" + std::to_string(kApplicationId));
  db_->exec("BEGIN");
  voyage::createSchema(*db_);
  st_ = std::make_unique<Statements>(*db_);
  std::vector<std::pair<std::string, std::string>> meta{
      {"schema_version", std::to_string(voyage::kSchemaVersion)},
      {"program", s_.program},
      {"program_version", s_.programVersion},
      {"start_utc", io::formatIso8601(wallUtc)},
      {"start_utc_us", std::to_string(wallUtc)},
      {"input_name", s_.inputName},
      {"commit_stream_s", voyage::exactText(s_.commitStreamS)},
      {"commit_wall_s", voyage::exactText(s_.commitWallS)},
      {"sync_wall_s", voyage::exactText(s_.syncWallS)},
  };
  if (s_.maxHours) meta.emplace_back("record_max_hours", voyage::exactText(*s_.maxHours));
  if (s_.charts) meta.emplace_back("voyage.enc", *s_.charts);
  for (auto& kv : voyage::optionsMeta(s_.options)) meta.push_back(std::move(kv));
  for (const auto& [key, value] : meta) st_->meta.bindAll(key, value).run();
  for (const RecordedSource& src : s_.sources) {
    st_->source.bindAll(src.name, src.role, src.spec).run();
    sources_[src.name] = db_->lastInsertId();
  }
  db_->exec("COMMIT");
  db_->syncWal();
}

VoyageRecorder::~VoyageRecorder() {
  if (!inTransaction_) return;
  try {
    db_->exec("COMMIT");
  } catch (const std::exception&) {  // NOLINT(bugprone-empty-catch): a destructor does not throw
  }
}

const std::string& VoyageRecorder::path() const {
  return db_->path();
}

void VoyageRecorder::begin(UtcUs wallUtc) {
  if (inTransaction_) return;
  db_->exec("BEGIN");
  inTransaction_ = true;
  pendingSinceWall_ = wallUtc;
}

std::int64_t VoyageRecorder::sourceId(const InputLine& l) {
  const auto it = sources_.find(l.source);
  if (it != sources_.end()) return it->second;
  st_->source.bindAll(l.source, l.radar ? "radar" : "nmea", "").run();
  return sources_[l.source] = db_->lastInsertId();
}

void VoyageRecorder::batch(std::span<const InputLine> lines, const LiveBatch& out,
                           std::span<const std::string> targetLabels, std::optional<UtcUs> streamUtc,
                           UtcUs wallUtc) {
  if (lines.empty()) return;
  begin(wallUtc);
  ++batch_;
  for (const InputLine& l : lines)
    st_->input.bindAll(batch_, l.receivedUtc, sourceId(l), std::string_view(l.line)).run();
  lines_ += static_cast<std::int64_t>(lines.size());
  rows(out, targetLabels);
  if (streamUtc) lastStream_ = streamUtc;
  if (!lastCommitStream_) lastCommitStream_ = streamUtc;
  maybeCommit(streamUtc, wallUtc);
}

void VoyageRecorder::forgetTracksBefore(std::int64_t minute) {
  // A track whose last row is from before `minute` has its next row (later) in another minute, and one
  // not remembered is written as its minute's row too: forgetting it changes nothing, and the map holds
  // only the tracks of the last minutes instead of every track ever seen (the soak's clutter starts
  // thousands an hour).
  if (minute <= forgottenBefore_) return;
  forgottenBefore_ = minute;
  std::erase_if(trackMinute_, [minute](const auto& kv) { return kv.second < minute; });
}

void VoyageRecorder::rows(const LiveBatch& out, std::span<const std::string> targetLabels) {
  for (const sim::ReplayOwnRow& r : out.own) {
    const std::int64_t minute = minuteOf(r.utcUs);
    st_->own.reset();
    voyage::bindOwnRow(st_->own, r, !ownMinute_ || *ownMinute_ != minute);
    st_->own.run();
    ownMinute_ = minute;
    newestUtc_ = r.utcUs;
  }
  for (std::size_t i = 0; i < out.tracks.size(); ++i) {
    RecordedTrack t{i < out.trackUtc.size() ? out.trackUtc[i] : 0, {}, out.tracks[i]};
    const int label = t.row.targetId;
    if (label >= 0 && static_cast<std::size_t>(label) < targetLabels.size())
      t.target = targetLabels[static_cast<std::size_t>(label)];
    const std::int64_t minute = minuteOf(t.utc);
    const auto it = trackMinute_.find(t.row.trackId);
    st_->track.reset();
    voyage::bindTrack(st_->track, t, it == trackMinute_.end() || it->second != minute);
    st_->track.run();
    trackMinute_[t.row.trackId] = minute;
    forgetTracksBefore(minute - 1);
  }
  for (const alerts::AlertLogEntry& e : out.alerts) {
    voyage::bindAlert(st_->alert, recordedAlert(e, out.alertZeroUtc));
    st_->alert.run();
  }
}

void VoyageRecorder::operatorAction(OperatorAction a) {
  a.afterBatch = batch_;
  begin(a.wallUtc);
  st_->action.bindAll(a.afterBatch, a.wallUtc, a.streamUtc, a.action, a.subject, a.value).run();
}

void VoyageRecorder::chart(const ChartEvent& c) {
  begin(c.wallUtc);
  st_->chart.bindAll(c.wallUtc, c.streamUtc, c.event, c.name, c.edition, c.updateNumber, c.issueDate, c.path)
      .run();
}

void VoyageRecorder::maybeCommit(std::optional<UtcUs> streamUtc, UtcUs wallUtc) {
  if (!inTransaction_) return;
  const auto passed = [](UtcUs since, UtcUs now, double periodS) {
    return now < since || toSeconds(now - since) >= periodS;  // a clock stepped back commits too
  };
  const bool wallDue = passed(pendingSinceWall_, wallUtc, s_.commitWallS);
  const bool streamDue =
      streamUtc && lastCommitStream_ && passed(*lastCommitStream_, *streamUtc, s_.commitStreamS);
  if (wallDue || streamDue) commit(streamUtc, wallUtc);
}

void VoyageRecorder::commit(std::optional<UtcUs> streamUtc, UtcUs wallUtc) {
  if (s_.maxHours && newestUtc_ && (!lastPruneUtc_ || *newestUtc_ - *lastPruneUtc_ >= kPruneEveryUs)) prune();
  db_->exec("COMMIT");
  inTransaction_ = false;
  ++commits_;
  committedLines_ = lines_;
  if (streamUtc) lastCommitStream_ = streamUtc;
  unsynced_ = true;
  if (wallUtc < lastSyncWall_ || toSeconds(wallUtc - lastSyncWall_) >= s_.syncWallS) {
    db_->syncWal();
    lastSyncWall_ = wallUtc;
    unsynced_ = false;
    ++syncs_;
  }
}

void VoyageRecorder::prune() {
  const UtcUs before = *newestUtc_ - fromSeconds(*s_.maxHours * 3600.0);
  for (sqlite::Statement* q : {&st_->pruneOwn, &st_->pruneTracks}) {
    q->bind(1, before).run();
    pruned_ += db_->changes();
  }
  lastPruneUtc_ = newestUtc_;
}

void VoyageRecorder::tick(UtcUs wallUtc) {
  maybeCommit(std::nullopt, wallUtc);
  if (!inTransaction_ && unsynced_ &&
      (wallUtc < lastSyncWall_ || toSeconds(wallUtc - lastSyncWall_) >= s_.syncWallS)) {
    db_->syncWal();
    lastSyncWall_ = wallUtc;
    unsynced_ = false;
    ++syncs_;
  }
}

void VoyageRecorder::finish(const LiveBatch& last, std::span<const std::string> targetLabels, UtcUs wallUtc) {
  begin(wallUtc);
  rows(last, targetLabels);
  for (const auto& [key, value] :
       std::vector<std::pair<std::string, std::string>>{{"end_utc", io::formatIso8601(wallUtc)},
                                                        {"end_utc_us", std::to_string(wallUtc)},
                                                        {"end_lines", std::to_string(lines_)},
                                                        {"end_batches", std::to_string(batch_)}})
    st_->meta.bindAll(key, value).run();
  commit(lastStream_, wallUtc);
  if (unsynced_) db_->syncWal();
  unsynced_ = false;
  db_->exec("PRAGMA wal_checkpoint(TRUNCATE)");
}

}  // namespace reckoner::files
