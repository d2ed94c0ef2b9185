#include "sim/live_session.h"

#include <cmath>

#include "io/error_line.h"
#include "io/input_error.h"
#include "sim/replay_runner.h"
#include "sim/replay_stream.h"
#include "tracking/ais_targets.h"

namespace reckoner::sim {
namespace {

replay_input::NmeaOptions nmeaOptionsOf(const ReplayOptions& o) {
  replay_input::NmeaOptions n;
  n.time = o.time;
  n.date = o.date;
  n.variationDeg = o.variationDeg;
  n.holdS = o.sourceHoldS;
  return n;
}

/// An AIS sentence: "!xxVDM" or "!xxVDO", after an NMEA 4 tag block "\\...\\" when there is one.
bool isAisLine(std::string_view line) {
  if (!line.empty() && line.front() == '\\') {
    const auto end = line.find('\\', 1);
    if (end == std::string_view::npos) return false;
    line.remove_prefix(end + 1);
  }
  return line.size() >= 6 && line[0] == '!' && line.substr(3, 2) == "VD" &&
         (line[5] == 'M' || line[5] == 'O');
}

/// The stream's clock may lead the last epoch run (by the receive clock since) by at most this before
/// it is taken for a clock error (a sentence stamped far ahead that the jump rule will drop).
constexpr std::int64_t kMaxClockLeadUs = 30'000'000;

}  // namespace

LiveSession::LiveSession(LiveOptions options)
    : o_(std::move(options)),
      stream_(std::make_unique<replay_input::NmeaStream>(
          nmeaOptionsOf(o_.replay), o_.name,
          static_cast<std::int64_t>(std::llround(std::max(0.0, o_.reorderHorizonS) * 1e6)), res_.stats)),
      voyage_(o_.replay.settings.voyage) {
  if (!o_.radar) return;
  plots_ = std::make_unique<replay_input::PlotStream>(o_.replay.time, res_.stats, res_.targetLabels);
  res_.sweepPeriodS = o_.replay.settings.radar.sweepPeriodS;
  const track::TrackManagerConfig c = replay_runner::trackerConfigOf(o_.replay);
  if (const std::string problem = c.check(); !problem.empty())
    throw io::InputError(o_.replay.settingsName.empty() ? "settings" : o_.replay.settingsName, 0, "tracker",
                         problem);
}

LiveSession::~LiveSession() = default;

void LiveSession::nmea(std::string_view line, std::optional<UtcUs> receivedUtc, std::string_view source) {
  if (finished_) return;
  if (isAisLine(line)) {
    const std::optional<UtcUs> at = clockAt(receivedUtc);
    auto m = ais_.feed(line, at ? static_cast<double>(*at) * 1e-6 : -1.0);
    if (m)
      aisOut_.push_back({at.value_or(0), track::isOwnShipSentence(line), std::string(source), std::move(*m)});
    return;
  }
  stream_->push(line, receivedUtc);
  for (replay_input::Epoch& e : stream_->takeEpochs()) waiting_.push_back(std::move(e));
  if (plots_ && receivedUtc) plots_->expire(*receivedUtc);
  const std::optional<UtcUs> ran = lastRun_;
  drain(false);
  if (lastRun_ != ran) receivedAtLastRun_ = receivedUtc;
}

std::optional<UtcUs> LiveSession::clockAt(std::optional<UtcUs> receivedUtc) const {
  const std::optional<UtcUs> stream = stream_->clockAt(receivedUtc);
  std::optional<UtcUs> run = lastRun_;
  if (run && receivedUtc && receivedAtLastRun_ && *receivedUtc > *receivedAtLastRun_)
    *run += *receivedUtc - *receivedAtLastRun_;
  if (stream && run && *stream - *run > kMaxClockLeadUs) return run;  // a clock error ahead
  if (stream) return stream;
  if (run) return run;
  return receivedUtc;
}

void LiveSession::radar(std::string_view line, std::optional<UtcUs> receivedUtc) {
  if (finished_ || !plots_) return;
  plots_->push(line, receivedUtc);
  drain(false);
}

void LiveSession::drain(bool atEnd) {
  while (!waiting_.empty()) {
    const replay_input::Epoch& e = waiting_.front();
    if (plots_) {
      const auto undecided = plots_->undecidedFrom();
      if (!atEnd && undecided && *undecided < e.utc) return;  // a plot before it may still come
      for (const replay_input::Plot& p : plots_->take(e.utc)) plot(p);
    }
    run(e);
    lastRun_ = e.utc;
    waiting_.pop_front();
  }
}

void LiveSession::plot(const replay_input::Plot& p) {
  if (lastRun_ && p.utc < *lastRun_) {
    ++res_.stats.radarLate;  // its epoch has run: too late for the bank
    return;
  }
  if (!runner_) {
    ++res_.stats.radarBeforeFix;
    return;
  }
  runner_->plot(p);
}

void LiveSession::run(const replay_input::Epoch& e) {
  if (!anyEpoch_) {
    res_.utc0 = e.utc;  // as a file replay: time zero is the first epoch's
    anyEpoch_ = true;
  }
  if (!runner_) {
    if (!e.hasFix()) {
      // What the engine counts of the epochs before the first fix (replay_runner.h).
      ++res_.stats.epochs;
      if (e.empty()) ++res_.stats.epochsTimeOnly;
      ++res_.stats.epochsBeforeFix;
      return;
    }
    res_.origin = replay_runner::chooseOrigin(o_.replay, e, o_.name, res_.warnings);
    frame_.emplace(res_.origin.latDeg, res_.origin.lonDeg);
    runner_ = std::make_unique<replay_runner::Runner>(o_.replay, res_, o_.radar);
    if (o_.frames)
      runner_->setFrameSink([this](SimFrame&& f) {
        if (const nav::Drkf* filter = runner_->drkf()) voyage_.observe(f.timeUs, *filter, f);
        if (frames_.size() >= kMaxFrames) {
          frames_.pop_front();
          ++framesDropped_;
        }
        frames_.push_back(std::move(f));
      });
  }
  runner_->ownShip(e);
}

void LiveSession::finish() {
  if (finished_) return;
  finished_ = true;
  stream_->finish();
  for (replay_input::Epoch& e : stream_->takeEpochs()) waiting_.push_back(std::move(e));
  if (plots_) plots_->finish();
  drain(true);
  if (plots_)
    for (const replay_input::Plot& p : plots_->take(std::nullopt)) plot(p);  // against the last estimate
  if (runner_) runner_->finish();
  refreshSources();
  const ReplayStats& st = res_.stats;
  if (st.reordered > 0)
    res_.warnings.push_back(io::oneLine(o_.name + ": " + std::to_string(st.reordered) +
                                        " timed sentences arrived out of time order; run in time order"));
  if (st.timeJumps > 0)
    res_.warnings.push_back(
        io::oneLine(o_.name + ": " + std::to_string(st.timeJumps) +
                    " sentences stamped far from their neighbours were dropped as clock errors"));
  if (st.late > 0)
    res_.warnings.push_back(io::oneLine(o_.name + ": " + std::to_string(st.late) +
                                        " timed sentences arrived after later epochs had been run: skipped"));
  for (const std::string& w : stream_->warnings()) res_.warnings.push_back(w);
  if (!runner_)
    res_.warnings.push_back(io::oneLine(o_.name + ": no position fix (RMC, GGA or GLL) to start from"));
}

void LiveSession::refreshSources() {
  res_.sources = stream_->sources();
}

std::vector<ReplayOwnRow> LiveSession::takeOwnRows() {
  refreshSources();
  std::vector<ReplayOwnRow> out;
  out.swap(res_.own);
  return out;
}

std::vector<LiveAisMessage> LiveSession::takeAisMessages() {
  std::vector<LiveAisMessage> out;
  out.swap(aisOut_);
  return out;
}

std::vector<SimFrame> LiveSession::takeFrames() {
  std::vector<SimFrame> out(std::make_move_iterator(frames_.begin()), std::make_move_iterator(frames_.end()));
  frames_.clear();
  return out;
}

std::vector<TrackRow> LiveSession::takeTrackRows(std::vector<UtcUs>* utc) {
  std::vector<TrackRow> out;
  out.swap(res_.tracks);
  if (utc) utc->swap(res_.trackRowUtc);
  res_.trackRowUtc.clear();
  return out;
}

}  // namespace reckoner::sim
