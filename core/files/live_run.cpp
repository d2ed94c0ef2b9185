#include "files/live_run.h"

#include "files/voyage_recorder.h"

namespace reckoner::files {

sim::LiveWatchSettings liveWatchSettings(const sim::LiveOptions& o) {
  sim::LiveWatchSettings w;
  w.alerts = sim::alertFeedSettingsFor(o.replay.settings);
  w.ais.cpaLimitM = w.alerts.cpa.cpaM;
  w.ais.tcpaLimitS = w.alerts.cpa.tcpaS;
  return w;
}

LiveRun::LiveRun(const sim::LiveOptions& options, const std::string& outDir, VoyageRecorder* recorder)
    : session_(options),
      watch_(liveWatchSettings(options)),
      writer_(outDir, options.radar),
      recorder_(recorder) {}

LiveRun::~LiveRun() = default;

LiveBatch LiveRun::batch(std::span<const InputLine> lines, UtcUs wallUtc) {
  if (lines.empty()) return {};
  std::optional<UtcUs> received;
  for (const InputLine& l : lines) {
    if (l.receivedUtc != 0) received = l.receivedUtc;
    if (l.radar) {
      session_.radar(l.line, l.receivedUtc);
      ++radarLines_;
    } else {
      session_.nmea(l.line, l.receivedUtc, l.source);
      ++lines_;
    }
  }
  const sim::LiveWatch::Taken taken = watch_.absorb(session_, received);
  LiveBatch out = writer_.append(session_, taken.ais, watch_);
  addRoute(taken.frames, out);
  if (recorder_)
    recorder_->batch(lines, out, session_.result().targetLabels, session_.clockAt(received), wallUtc);
  return out;
}

void LiveRun::addRoute(const std::vector<sim::SimFrame>& frames, LiveBatch& out) const {
  for (const sim::SimFrame& f : frames)
    if (f.route) out.route.push_back({session_.result().utc0 + f.timeUs, *f.route, f.deadReckoning.active});
}

void LiveRun::tick(UtcUs wallUtc) {
  if (recorder_) recorder_->tick(wallUtc);
}

LiveBatch LiveRun::finish(const std::string& inputName, UtcUs wallUtc) {
  session_.finish();
  const sim::LiveWatch::Taken taken = watch_.absorb(session_, std::nullopt);
  LiveBatch last = writer_.finish(session_, taken.ais, watch_, inputName);
  addRoute(taken.frames, last);
  if (recorder_) recorder_->finish(last, session_.result().targetLabels, wallUtc);
  return last;
}

}  // namespace reckoner::files
