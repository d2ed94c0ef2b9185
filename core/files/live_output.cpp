#include "files/live_output.h"

#include <cerrno>
#include <cstring>

#include "files/ais_output.h"
#include "files/alert_output.h"
#include "files/track_output.h"
#include "io/input_error.h"
#include "io/json.h"
#include "io/text_file.h"

namespace reckoner::files {

LiveOutputWriter::File LiveOutputWriter::open(const std::string& path, const std::string& header) {
  File file{path, std::fopen(path.c_str(), "wb")};
  if (!file.f) throw io::InputError(path, 0, "", std::string("cannot write: ") + io::errnoText(errno));
  put(file, header);
  flush(file);
  return file;
}

void LiveOutputWriter::put(File& file, const std::string& line) {
  if (!file.f) return;
  if (std::fwrite(line.data(), 1, line.size(), file.f) != line.size() || std::fputc('\n', file.f) == EOF)
    throw io::InputError(file.path, 0, "", std::string("write failed: ") + io::errnoText(errno));
}

void LiveOutputWriter::flush(File& file) {
  if (file.f && std::fflush(file.f) != 0)
    throw io::InputError(file.path, 0, "", std::string("write failed: ") + io::errnoText(errno));
}

LiveOutputWriter::LiveOutputWriter(const std::string& dir, bool radar)
    : dir_(dir),
      own_(open(dir + "/ownship.csv", replayOwnShipCsvHeader())),
      ais_(open(dir + "/ais.csv", aisCsvHeader())),
      alerts_(open(dir + "/alerts.csv", alertCsvHeader())) {
  if (radar) targets_ = open(dir + "/targets.csv", replayTargetsCsvHeader());
}

LiveOutputWriter::~LiveOutputWriter() {
  for (File* file : {&own_, &targets_, &ais_, &alerts_})
    if (file->f) std::fclose(file->f);
}

LiveBatch LiveOutputWriter::append(sim::LiveSession& session, const std::vector<sim::LiveAisMessage>& ais,
                                   sim::LiveWatch& watch) {
  LiveBatch batch;
  batch.own = session.takeOwnRows();
  const std::vector<sim::ReplayOwnRow>& own = batch.own;
  for (const sim::ReplayOwnRow& r : own) put(own_, replayOwnShipCsvLine(r));
  if (!own.empty()) {
    if (!firstOwn_) firstOwn_ = own.front().timeUs;
    lastOwn_ = own.back().timeUs;
    ownRows_ += static_cast<long>(own.size());
    flush(own_);
  }
  std::vector<UtcUs>& utc = batch.trackUtc;
  batch.tracks = session.takeTrackRows(&utc);
  const std::vector<sim::TrackRow>& tracks = batch.tracks;
  if (targets_.f && !tracks.empty()) {
    for (std::size_t i = 0; i < tracks.size(); ++i)
      put(targets_, replayTargetsCsvLine(tracks[i], utc[i], session.result().targetLabels));
    trackRows_ += static_cast<long>(tracks.size());
    flush(targets_);
  }
  for (const sim::LiveAisMessage& m : ais) put(ais_, aisCsvLine(m.utc, m.source, m.message));
  if (!ais.empty()) {
    aisRows_ += static_cast<long>(ais.size());
    flush(ais_);
  }
  batch.alerts = watch.alerts().takeLog();
  batch.alertZeroUtc = watch.zeroUtc();
  const std::vector<alerts::AlertLogEntry>& log = batch.alerts;
  for (const alerts::AlertLogEntry& e : log) put(alerts_, alertCsvLine(e, watch.zeroUtc()));
  if (!log.empty()) {
    alertRows_ += static_cast<long>(log.size());
    flush(alerts_);
  }
  return batch;
}

LiveBatch LiveOutputWriter::finish(sim::LiveSession& session, const std::vector<sim::LiveAisMessage>& ais,
                                   sim::LiveWatch& watch, const std::string& inputName) {
  LiveBatch last = append(session, ais, watch);
  const track::AisTableCounts t = watch.aisTable().counts();
  const double span = firstOwn_ ? toSeconds(*lastOwn_ - *firstOwn_) : 0.0;
  const io::AisCounters& c = session.aisCounters();
  const auto aisObject = [&c, &t, &watch](io::JsonWriter& w) {
    const auto count = [&w](const char* k, std::uint64_t v) { w.key(k).value(static_cast<std::int64_t>(v)); };
    w.key("ais").beginObject();
    count("lines", c.lines);
    count("decoded", c.decoded);
    count("bad_checksum", c.badChecksum);
    count("malformed", c.malformed);
    count("bad_armour", c.badArmour);
    count("bad_fill", c.badFill);
    count("too_long", c.tooLong);
    count("orphan_fragments", c.orphanFragments);
    count("expired_partials", c.expiredPartials);
    count("evicted_partials", c.evictedPartials);
    count("unsupported_type", c.unsupportedType);
    count("too_short", c.tooShort);
    w.endObject();
    w.key("ais_targets").beginObject();
    count("targets", t.targets);
    count("dangerous", t.dangerous);
    count("lost", t.lost);
    count("messages", t.messages);
    count("own_ship_messages", t.ownShipMessages);
    count("invalid_mmsi", t.invalidMmsi);
    count("dropped_at_capacity", t.droppedAtCapacity);
    count("lost_events", t.lostEvents);
    count("removed", t.removed);
    w.endObject();
    w.key("alerts").beginObject();
    for (int k = 0; k < alerts::kAlertKindCount; ++k) {
      const auto kind = static_cast<alerts::AlertKind>(k);
      const int n = watch.alerts().raisedCount(kind);
      if (n > 0) w.key(alerts::traitsOf(kind).name).value(static_cast<std::int64_t>(n));
    }
    w.endObject();
  };
  io::writeTextFile(dir_ + "/summary.json", replaySummaryJson(session.result(), inputName, span, aisObject));
  return last;
}

}  // namespace reckoner::files
