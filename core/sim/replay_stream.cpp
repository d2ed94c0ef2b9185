#include "sim/replay_stream.h"

#include <algorithm>
#include <cmath>

#include "io/error_line.h"
#include "io/input_error.h"
#include "io/iso8601.h"

namespace reckoner::sim::replay_input {
using detail::Parsed;

NmeaStream::NmeaStream(const NmeaOptions& o, std::string name, std::int64_t reorderHorizonUs, ReplayStats& st)
    : o_(o),
      name_(std::move(name)),
      horizonUs_(std::max<std::int64_t>(0, reorderHorizonUs)),
      st_(st),
      assembler_(o_, st_, stats_) {}

void NmeaStream::push(std::string_view line, std::optional<UtcUs> receivedUtc) {
  ++lineNumber_;
  std::optional<Parsed> p;
  try {
    p = detail::parseLine(line, lineNumber_, name_, st_, nullptr);
  } catch (const io::InputError& e) {
    // A datum other than WGS-84: in a file the whole file is refused; a stream goes on without it.
    ++st_.malformed;
    if (!dtmWarned_) warnings_.push_back(io::oneLine(e.what()));
    dtmWarned_ = true;
    return;
  }
  if (!p) return;
  auto [it, fresh] = stats_.try_emplace(p->source);
  if (fresh) {
    it->second.source = p->source;
    it->second.quantity = std::holds_alternative<io::nmea::Rmc>(p->sentence.body) ? "position+velocity"
                          : std::holds_alternative<io::nmea::Vhw>(p->sentence.body)
                              ? "speed_log+heading"
                              : sources::quantityName(p->kind.quantity);
    firstSeen_.push_back(p->source);
  }
  ++it->second.sentences;
  place(std::move(*p), receivedUtc);
}

std::optional<UtcUs> NmeaStream::clockAt(std::optional<UtcUs> receivedUtc) const {
  if (!lastTimedUtc_) return std::nullopt;
  if (!receivedUtc || !lastTimedReceived_ || *receivedUtc < *lastTimedReceived_) return lastTimedUtc_;
  return *lastTimedUtc_ + (*receivedUtc - *lastTimedReceived_);
}

void NmeaStream::startDays(std::optional<UtcUs> receivedUtc) {
  const auto dated = std::find_if(undated_.begin(), undated_.end(),
                                  [](const Held& q) { return detail::hasDate(q.p.sentence); });
  const Parsed* firstDated = dated == undated_.end() ? nullptr : &dated->p;
  std::optional<double> firstTod;
  for (const Held& q : undated_)
    if ((firstTod = detail::timeOfDay(q.p.sentence))) break;
  UtcUs first = 0;
  if (!firstDated && !o_.date && receivedUtc && firstTod) {
    // No date yet, but a receive clock: the day that puts the first time of day nearest to it.
    const auto inDay = static_cast<UtcUs>(std::llround(*firstTod * 1e6));
    const double day =
        std::round(static_cast<double>(*receivedUtc - inDay) / static_cast<double>(io::kUsPerDay));
    first = static_cast<UtcUs>(day) * io::kUsPerDay + inDay;
  } else {
    first = detail::firstDayOf(firstDated, firstTod, name_, o_, warnings_);
  }
  days_.emplace(first, firstDated);
  std::vector<Held> held;
  held.swap(undated_);
  for (Held& q : held) place(std::move(q.p), q.received);
}

void NmeaStream::place(Parsed p, std::optional<UtcUs> receivedUtc) {
  if (!days_) {
    const bool dated = detail::hasDate(p.sentence);
    undated_.push_back({std::move(p), receivedUtc});
    if (dated || undated_.size() >= kMaxUndated) startDays(receivedUtc);
    return;
  }
  std::optional<UtcUs> t = days_->place(p.sentence);
  if (!t && receivedUtc && lastTimedUtc_ && lastTimedReceived_ &&
      *receivedUtc - *lastTimedReceived_ >= kUntimedAfterUs) {
    // No timed sentence for a second on the receive clock (the GNSS is out, the heading and log still
    // report): the receive clock carries the sentences' clock on, so dead reckoning goes on live.
    t = *lastTimedUtc_ + (*receivedUtc - *lastTimedReceived_);
  }
  if (t) {
    lastTimedUtc_ = *t;
    lastTimedReceived_ = receivedUtc;
    Group g;
    g.utc = *t;
    g.sentences.push_back(std::move(p));
    pending_.push_back(std::move(g));
    decide(false);
  } else if (!pending_.empty() && pending_.back().sentences.size() < kMaxGroup) {
    pending_.back().sentences.push_back(std::move(p));
  } else {
    ++st_.untimed;  // before any timed sentence, or beyond what one time can hold
  }
}

void NmeaStream::decide(bool atEnd) {
  const auto w = static_cast<std::size_t>(std::max(1, o_.time.window));
  while (!pending_.empty() && (atEnd || pending_.size() >= w + 1)) {
    span_.assign(decidedTimes_.begin(), decidedTimes_.end());
    const std::size_t i = span_.size();
    for (std::size_t k = 0; k < pending_.size() && k <= w; ++k) span_.push_back(pending_[k].utc);
    const bool jump = isolatedTimeJumpAt(span_, i, o_.time, scratch_);
    Group g = std::move(pending_.front());
    pending_.pop_front();
    decidedTimes_.push_back(g.utc);
    if (decidedTimes_.size() > w) decidedTimes_.pop_front();
    if (!jump) {
      keep(std::move(g));
      continue;
    }
    ++st_.timeJumps;  // its untimed followers stay with the group before it
    ++stats_[g.sentences.front().source].timeJumps;
    if (kept_.empty()) {
      st_.untimed += static_cast<long>(g.sentences.size() - 1);
    } else {
      auto& to = kept_.back().sentences;
      std::move(g.sentences.begin() + 1, g.sentences.end(), std::back_inserter(to));
    }
  }
  release(atEnd);
}

void NmeaStream::keep(Group g) {
  if (released_ && g.utc < *released_) {
    // Older than an epoch already sent on: too late for the filters (a file replay would sort it in).
    // Every sentence of the group is skipped, its untimed followers with it: each counts as late.
    st_.late += static_cast<long>(g.sentences.size());
    return;
  }
  if (newestKept_ && g.utc < *newestKept_) ++st_.reordered;
  newestKept_ = newestKept_ ? std::max(*newestKept_, g.utc) : g.utc;
  kept_.push_back(std::move(g));
}

void NmeaStream::release(bool atEnd) {
  if (kept_.empty()) return;
  // Everything older than the horizon, but never the group kept last (a jump's followers may still join
  // it): its time is the cut-off.
  // Groups of one time go together, so the cut-off is at most the last group's time.
  const UtcUs cutoff = std::min(*newestKept_ - horizonUs_, kept_.back().utc);
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < kept_.size(); ++i)
    if (atEnd || kept_[i].utc < cutoff) out.push_back(i);
  if (out.empty()) return;
  std::stable_sort(out.begin(), out.end(),
                   [&](std::size_t a, std::size_t b) { return kept_[a].utc < kept_[b].utc; });
  std::vector<const Parsed*> sentences;
  for (std::size_t g = 0; g < out.size();) {
    const UtcUs t = kept_[out[g]].utc;
    sentences.clear();
    for (; g < out.size() && kept_[out[g]].utc == t; ++g)
      for (const Parsed& p : kept_[out[g]].sentences) sentences.push_back(&p);
    assembler_.addEpoch(t, sentences, epochs_);
    released_ = t;
  }
  std::vector<char> gone(kept_.size(), 0);
  for (const std::size_t i : out) gone[i] = 1;
  std::vector<Group> rest;
  for (std::size_t i = 0; i < kept_.size(); ++i)
    if (!gone[i]) rest.push_back(std::move(kept_[i]));
  kept_.swap(rest);
}

void NmeaStream::finish() {
  if (!days_ && !undated_.empty()) startDays(std::nullopt);
  decide(true);
  if (days_) days_->warn(name_, warnings_);
}

std::vector<Epoch> NmeaStream::takeEpochs() {
  std::vector<Epoch> out;
  out.swap(epochs_);
  return out;
}

std::vector<SourceStats> NmeaStream::sources() const {
  std::vector<SourceStats> out;
  out.reserve(firstSeen_.size());
  for (const auto& id : firstSeen_) out.push_back(stats_.at(id));
  return out;
}

PlotStream::PlotStream(const StreamTimePolicy& policy, ReplayStats& st, std::vector<std::string>& labels)
    : policy_(policy), st_(st), labels_(labels) {}

void PlotStream::push(std::string_view line, std::optional<UtcUs> receivedUtc) {
  const std::string_view row = trimmed(line);
  if (row.empty()) return;
  if (row.rfind("utc,", 0) == 0) {  // a header
    std::string header(row);
    header.erase(std::remove(header.begin(), header.end(), ' '), header.end());
    if (header == "utc,range_m,bearing_deg,target_id" || header == "utc,range_m,bearing_deg") {
      withId_ = header.size() > 23;
      return;
    }
  }
  ++st_.radarLines;
  const bool withId = withId_.value_or(std::count(row.begin(), row.end(), ',') == 3);
  std::string why;
  auto p = readRadarRow(row, withId, labels_, tagOf_, why);
  if (!p) {
    ++st_.radarBad;
    return;
  }
  if (labels_.size() > kMaxLabels) {  // a stream of endless new labels keeps no more of them
    tagOf_.erase(labels_.back());
    labels_.pop_back();
    p->tag = -1;
  }
  if (std::find(recent_.begin(), recent_.end(), *p) != recent_.end()) {
    ++st_.radarDuplicates;
    return;
  }
  recent_.push_back(*p);
  if (recent_.size() > kRecentPlots) recent_.pop_front();
  pending_.emplace_back(*p, receivedUtc);
  decide(false, receivedUtc ? std::optional<UtcUs>(*receivedUtc - kDecideAfterUs) : std::nullopt);
}

void PlotStream::expire(UtcUs now) {
  decide(false, now - kDecideAfterUs);
}

void PlotStream::finish() {
  decide(true, std::nullopt);
}

void PlotStream::decide(bool all, std::optional<UtcUs> receivedBefore) {
  const auto w = static_cast<std::size_t>(std::max(1, policy_.window));
  while (!pending_.empty()) {
    const bool full = pending_.size() >= w + 1;
    const bool waited =
        receivedBefore && pending_.front().second && *pending_.front().second < *receivedBefore;
    if (!all && !full && !waited) break;
    span_.assign(decidedTimes_.begin(), decidedTimes_.end());
    const std::size_t i = span_.size();
    for (std::size_t k = 0; k < pending_.size() && k <= w; ++k) span_.push_back(pending_[k].first.utc);
    const bool jump = isolatedTimeJumpAt(span_, i, policy_, scratch_);
    const Plot p = pending_.front().first;
    pending_.pop_front();
    decidedTimes_.push_back(p.utc);
    if (decidedTimes_.size() > w) decidedTimes_.pop_front();
    if (jump) {
      ++st_.radarTimeJumps;
      continue;
    }
    if (newest_ && p.utc < *newest_) ++st_.radarReordered;
    newest_ = newest_ ? std::max(*newest_, p.utc) : p.utc;
    const auto at = std::upper_bound(ready_.begin(), ready_.end(), p.utc,
                                     [](UtcUs t, const Plot& q) { return t < q.utc; });
    ready_.insert(at, p);
  }
}

std::optional<UtcUs> PlotStream::undecidedFrom() const {
  std::optional<UtcUs> t;
  for (const auto& [p, r] : pending_) t = t ? std::min(*t, p.utc) : p.utc;
  return t;
}

std::vector<Plot> PlotStream::take(std::optional<UtcUs> before) {
  const auto end = before ? std::lower_bound(ready_.begin(), ready_.end(), *before,
                                             [](const Plot& q, UtcUs t) { return q.utc < t; })
                          : ready_.end();
  std::vector<Plot> out(ready_.begin(), end);
  ready_.erase(ready_.begin(), end);
  return out;
}

}  // namespace reckoner::sim::replay_input
