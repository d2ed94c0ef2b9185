#include "files/voyage_record.h"

#include <cstdint>
#include <cstdlib>

#include "files/sqlite_db.h"
#include "files/voyage_rows.h"
#include "files/voyage_schema.h"
#include "io/error_line.h"
#include "io/input_error.h"
#include "io/iso8601.h"

namespace reckoner::files {

RecordedAlert recordedAlert(const alerts::AlertLogEntry& e, UtcUs zeroUtc) {
  return {zeroUtc + e.timeUs,
          e.timeUs,
          alerts::eventName(e.event),
          alerts::priorityName(e.priority),
          alerts::traitsOf(e.id.kind).name,
          e.id.source,
          e.text};
}

VoyageRecord::VoyageRecord(const std::string& path)
    : db_(std::make_unique<sqlite::Db>(path, sqlite::Db::Mode::ReadOnly)), meta_(voyage::checkSchema(*db_)) {}

VoyageRecord::~VoyageRecord() = default;
VoyageRecord::VoyageRecord(VoyageRecord&&) noexcept = default;
VoyageRecord& VoyageRecord::operator=(VoyageRecord&&) noexcept = default;

const std::string& VoyageRecord::path() const {
  return db_->path();
}

namespace {
/// |a - b| for any two int64 (a record of another making can hold utc_us = INT64_MIN: fuzz_voyage_record
/// found `utc - a` overflowing in estimateNear).
std::uint64_t distance(std::int64_t a, std::int64_t b) {
  const auto ua = static_cast<std::uint64_t>(a), ub = static_cast<std::uint64_t>(b);
  return a >= b ? ua - ub : ub - ua;
}

std::optional<std::int64_t> integerOf(const std::map<std::string, std::string>& m, const std::string& key) {
  const auto it = m.find(key);
  if (it == m.end() || it->second.empty()) return std::nullopt;
  char* end = nullptr;
  const long long v = std::strtoll(it->second.c_str(), &end, 10);
  if (*end != '\0') return std::nullopt;
  return v;
}
}  // namespace

std::string VoyageRecord::programVersion() const {
  const auto it = meta_.find("program_version");
  return it == meta_.end() ? std::string() : it->second;
}

UtcUs VoyageRecord::startUtc() const {
  return integerOf(meta_, "start_utc_us").value_or(0);
}

std::optional<UtcUs> VoyageRecord::endUtc() const {
  return integerOf(meta_, "end_utc_us");
}

sim::LiveOptions VoyageRecord::liveOptions() const {
  return voyage::optionsFromMeta(meta_, path());
}

std::string VoyageRecord::inputName() const {
  const auto it = meta_.find("input_name");
  return it == meta_.end() ? std::string("live") : it->second;
}

std::vector<RecordedSource> VoyageRecord::sources() const {
  std::vector<RecordedSource> out;
  sqlite::Statement q(*db_, "SELECT id, name, role, spec FROM sources ORDER BY id");
  while (q.step()) out.push_back({q.integer(0), q.text(1), q.text(2), q.text(3)});
  return out;
}

std::int64_t VoyageRecord::inputCount() const {
  sqlite::Statement q(*db_, "SELECT count(*) FROM inputs");
  return q.step() ? q.integer(0) : 0;
}

std::optional<TimeSpan> VoyageRecord::inputSpan() const {
  sqlite::Statement q(*db_, "SELECT min(rx_utc_us), max(rx_utc_us) FROM inputs WHERE rx_utc_us != 0");
  if (!q.step() || q.isNull(0)) return std::nullopt;
  return TimeSpan{q.integer(0), q.integer(1)};
}

std::optional<TimeSpan> VoyageRecord::estimateSpan() const {
  sqlite::Statement q(*db_, "SELECT min(utc_us), max(utc_us) FROM ownship");
  if (!q.step() || q.isNull(0)) return std::nullopt;
  return TimeSpan{q.integer(0), q.integer(1)};
}

namespace {
/// Source id -> (name, radar) of a record.
std::map<std::int64_t, std::pair<std::string, bool>> sourceMap(const std::vector<RecordedSource>& sources) {
  std::map<std::int64_t, std::pair<std::string, bool>> m;
  for (const RecordedSource& s : sources) m[s.id] = {s.name, s.role == "radar"};
  return m;
}
}  // namespace

std::vector<RecordedInput> VoyageRecord::inputs(std::int64_t afterSeq, std::size_t max) const {
  const auto names = sourceMap(sources());
  std::vector<RecordedInput> out;
  sqlite::Statement q(
      *db_, "SELECT seq, batch, rx_utc_us, source, line FROM inputs WHERE seq > ?1 ORDER BY seq LIMIT ?2");
  q.bindAll(afterSeq, static_cast<std::int64_t>(std::min<std::size_t>(max, INT64_MAX)));
  std::int64_t previous = afterSeq;
  while (q.step()) {
    RecordedInput in;
    in.seq = q.integer(0);
    // A playback pages on seq: one that does not rise (a table of another making, with seq as text or
    // a fraction) would give the same page again and again.
    if (in.seq <= previous || q.text(0) != std::to_string(in.seq))
      throw io::InputError(path(), 0, "inputs.seq", "not a rising whole number: " + io::quoted(q.text(0)));
    previous = in.seq;
    in.batch = q.integer(1);
    in.receivedUtc = q.integer(2);
    if (const auto it = names.find(q.integer(3)); it != names.end()) {
      in.source = it->second.first;
      in.radar = it->second.second;
    }
    in.line = q.text(4);
    out.push_back(std::move(in));
  }
  return out;
}

std::int64_t VoyageRecord::inputSeqAt(UtcUs utc) const {
  // A binary search on seq (the inputs have no index on their receive time, which would cost a fifth of
  // the file): receive times rise with seq but where the system clock was stepped back, so there the
  // seek lands on one of the places the time is passed.
  sqlite::Statement range(*db_, "SELECT min(seq), max(seq) FROM inputs");
  if (!range.step() || range.isNull(0)) return 0;
  const std::int64_t first = range.integer(0), last = range.integer(1);
  sqlite::Statement at(*db_, "SELECT rx_utc_us FROM inputs WHERE seq >= ?1 ORDER BY seq LIMIT 1");
  const auto rxAt = [&at](std::int64_t seq) {
    at.bind(1, seq);
    const UtcUs rx = at.step() ? at.integer(0) : INT64_MAX;
    at.reset();
    return rx;
  };
  // The first seq in [first, last] whose input is received at utc or later, 0 when there is none. The
  // bounds are any int64 a file of another making holds (max(seq) + 1 overflowed for a seq of INT64_MAX,
  // found by reading after fuzz_voyage_record's find in estimateNear): no step below overflows.
  std::int64_t lo = first, hi = last, found = 0;
  while (lo <= hi) {
    const std::int64_t mid =
        lo + static_cast<std::int64_t>((static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo)) / 2);
    if (rxAt(mid) < utc) {
      if (mid == last) break;
      lo = mid + 1;
    } else {
      found = mid;
      if (mid == first) break;
      hi = mid - 1;
    }
  }
  return found;
}

void VoyageRecord::forEachBatch(
    const std::function<void(std::int64_t batch, std::span<const InputLine>)>& f) const {
  const auto names = sourceMap(sources());
  sqlite::Statement q(*db_, "SELECT batch, rx_utc_us, source, line FROM inputs ORDER BY seq");
  std::vector<InputLine> lines;
  std::optional<std::int64_t> batch;
  while (q.step()) {
    const std::int64_t b = q.integer(0);
    if (batch && b != *batch) {
      f(*batch, lines);
      lines.clear();
    }
    batch = b;
    InputLine l;
    l.receivedUtc = q.integer(1);
    const auto it = names.find(q.integer(2));
    if (it == names.end())
      throw io::InputError(path(), 0, "inputs.source",
                           "source " + std::to_string(q.integer(2)) + " is not in the sources table");
    l.source = it->second.first;
    l.radar = it->second.second;
    l.line = q.text(3);
    lines.push_back(std::move(l));
  }
  if (batch) f(*batch, lines);
}

std::vector<sim::ReplayOwnRow> VoyageRecord::estimates(UtcUs from, UtcUs to, std::size_t max) const {
  sqlite::Statement q(
      *db_, voyage::selectSql("ownship") + " WHERE utc_us BETWEEN ?1 AND ?2 ORDER BY utc_us, seq LIMIT ?3");
  q.bindAll(from, to, static_cast<std::int64_t>(std::min<std::size_t>(max, INT64_MAX)));
  std::vector<sim::ReplayOwnRow> out;
  while (q.step()) out.push_back(voyage::readOwnRow(q));
  return out;
}

std::optional<sim::ReplayOwnRow> VoyageRecord::estimateNear(UtcUs utc) const {
  const std::string select = voyage::selectSql("ownship");
  sqlite::Statement before(*db_, select + " WHERE utc_us <= ?1 ORDER BY utc_us DESC, seq DESC LIMIT 1");
  sqlite::Statement after(*db_, select + " WHERE utc_us > ?1 ORDER BY utc_us, seq LIMIT 1");
  before.bind(1, utc);
  after.bind(1, utc);
  std::optional<sim::ReplayOwnRow> a, b;
  if (before.step()) a = voyage::readOwnRow(before);
  if (after.step()) b = voyage::readOwnRow(after);
  if (a && b) return distance(utc, a->utcUs) <= distance(b->utcUs, utc) ? a : b;
  return a ? a : b;
}

std::vector<RecordedTrack> VoyageRecord::tracks(UtcUs from, UtcUs to, std::size_t max) const {
  sqlite::Statement q(*db_,
                      voyage::selectSql("tracks") + " WHERE utc_us BETWEEN ?1 AND ?2 ORDER BY seq LIMIT ?3");
  q.bindAll(from, to, static_cast<std::int64_t>(std::min<std::size_t>(max, INT64_MAX)));
  std::vector<RecordedTrack> out;
  while (q.step()) out.push_back(voyage::readTrack(q));
  return out;
}

std::vector<RecordedAlert> VoyageRecord::alerts() const {
  sqlite::Statement q(*db_, voyage::selectSql("alerts") + " ORDER BY seq");
  std::vector<RecordedAlert> out;
  while (q.step()) out.push_back(voyage::readAlert(q));
  return out;
}

std::vector<OperatorAction> VoyageRecord::operatorActions() const {
  sqlite::Statement q(*db_,
                      "SELECT after_batch, wall_utc_us, stream_utc_us, action, subject, value FROM "
                      "operator_actions ORDER BY seq");
  std::vector<OperatorAction> out;
  while (q.step())
    out.push_back({q.integer(0), q.integer(1), q.optionalInteger(2), q.text(3), q.text(4), q.text(5)});
  return out;
}

std::vector<ChartEvent> VoyageRecord::charts() const {
  sqlite::Statement q(
      *db_,
      "SELECT wall_utc_us, stream_utc_us, event, name, edition, update_number, issue_date, path "
      "FROM charts ORDER BY seq");
  std::vector<ChartEvent> out;
  while (q.step())
    out.push_back({q.integer(0), q.optionalInteger(1), q.text(2), q.text(3), q.text(4), q.text(5), q.text(6),
                   q.text(7)});
  return out;
}

}  // namespace reckoner::files
