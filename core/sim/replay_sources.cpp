#include "sim/replay_sources.h"

#include <algorithm>
#include <cmath>

namespace reckoner::sim::sources {

const char* quantityName(Quantity q) {
  switch (q) {
    case Quantity::Position:
      return "position";
    case Quantity::Loran:
      return "loran_c";
    case Quantity::Velocity:
      return "velocity";
    case Quantity::Heading:
      return "heading";
    case Quantity::SpeedLog:
      return "speed_log";
    case Quantity::Accuracy:
      return "accuracy";
    case Quantity::Time:
      return "time";
    case Quantity::Other:
      break;
  }
  return "other";
}

const Offer* Selector::choose(Quantity q, UtcUs t, const std::vector<const Offer*>& offers) {
  State& st = state_[static_cast<std::size_t>(q)];
  const Offer* best = nullptr;
  const Offer* current = nullptr;
  for (const Offer* o : offers) {
    auto [it, fresh] = st.seen.try_emplace(o->source);
    Seen& s = it->second;
    if (fresh) {
      s.order = order_++;
      s.since = t;
    } else if (t - s.last > holdUs_) {
      s.since = t;  // back after a silence: its run starts again
    }
    s.last = t;
    s.rank = o->kind.rank;
    if (o->source == st.active && !current) current = o;  // its first value in the epoch
    const auto better = [&](const Offer* a, const Offer* b) {
      const Seen& sa = st.seen.at(a->source);
      const Seen& sb = st.seen.at(b->source);
      return sa.rank != sb.rank ? sa.rank < sb.rank : sa.order < sb.order;
    };
    if (!best || better(o, best)) best = o;
  }
  if (!best) return nullptr;
  if (st.active.empty()) {
    st.active = best->source;
    return best;
  }
  // A better source that has reported for a whole hold takes over (again), whether or not the active
  // one reports in this epoch (two receivers' epochs need not coincide).
  const Seen& b = st.seen.at(best->source);
  const auto activeSeen = st.seen.find(st.active);
  const bool bestIsBetter = activeSeen == st.seen.end() || b.rank < activeSeen->second.rank ||
                            (b.rank == activeSeen->second.rank && b.order < activeSeen->second.order);
  if (best->source != st.active && bestIsBetter && t - b.since >= holdUs_) {
    st.active = best->source;
    return best;
  }
  if (current) return current;
  // The same instrument (talker) changing sentence (a log from bottom to water track, GGA to RMC):
  // follow it at once.
  const auto talker = [](const SourceId& id) { return id.substr(0, id.find(':')); };
  const Offer* sameTalker = nullptr;
  for (const Offer* o : offers)
    if (talker(o->source) == talker(st.active) && (!sameTalker || o->kind.rank < sameTalker->kind.rank))
      sameTalker = o;
  if (sameTalker) {
    st.active = sameTalker->source;
    return sameTalker;
  }
  if (activeSeen == st.seen.end() || t - activeSeen->second.last > holdUs_) {  // the active source is lost
    st.active = best->source;
    return best;
  }
  return nullptr;  // the active source missed this epoch: nothing of this quantity, no switch yet
}

namespace {
double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(std::clamp(q, 0.0, 1.0) * static_cast<double>(v.size() - 1));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}
}  // namespace

std::map<SourceId, ClockOffset> clockOffsets(const std::vector<std::pair<SourceId, UtcUs>>& stamps,
                                             const SourceId& ref) {
  // The reference's stamps in file order, and for each other stamp the reference stamps around it.
  std::vector<std::size_t> refAt;
  for (std::size_t i = 0; i < stamps.size(); ++i)
    if (stamps[i].first == ref) refAt.push_back(i);
  std::map<SourceId, ClockOffset> out;
  if (refAt.size() < 2) return out;
  std::vector<double> refSteps;
  for (std::size_t k = 1; k < refAt.size(); ++k) {
    const double d = 1e-6 * static_cast<double>(stamps[refAt[k]].second - stamps[refAt[k - 1]].second);
    if (d > 0.0) refSteps.push_back(d);
  }
  const double interval = refSteps.empty() ? 1.0 : quantile(refSteps, 0.5);
  std::map<SourceId, std::pair<std::vector<double>, std::vector<double>>> diffs;  // (t - p, t - n)
  std::size_t k = 0;  // refAt[k] is the first reference stamp after i
  for (std::size_t i = 0; i < stamps.size(); ++i) {
    while (k < refAt.size() && refAt[k] <= i) ++k;
    if (stamps[i].first == ref || k == 0 || k == refAt.size()) continue;
    const double t = 1e-6 * static_cast<double>(stamps[i].second);
    auto& [afterPrev, beforeNext] = diffs[stamps[i].first];
    afterPrev.push_back(t - 1e-6 * static_cast<double>(stamps[refAt[k - 1]].second));
    beforeNext.push_back(t - 1e-6 * static_cast<double>(stamps[refAt[k]].second));
  }
  out[ref] = {0.0, 0.0, static_cast<long>(refAt.size())};
  for (const auto& [source, d] : diffs) {
    ClockOffset c;
    c.samples = static_cast<long>(d.first.size());
    const double prevMedian = quantile(d.first, 0.5), nextMedian = quantile(d.second, 0.5);
    const double sync = 0.1 * interval;
    if (std::abs(prevMedian) <= sync) {
      c.offsetS = prevMedian;  // written in the reference's burst, after it
    } else if (std::abs(nextMedian) <= sync) {
      c.offsetS = nextMedian;  // written in the reference's burst, before it
    } else {
      const double lower = quantile(d.second, 0.9), upper = quantile(d.first, 0.1);
      c.offsetS = 0.5 * (lower + upper);
      c.resolutionS = std::min(0.5 * interval, 0.5 * std::abs(upper - lower));
    }
    out[source] = c;
  }
  return out;
}

}  // namespace reckoner::sim::sources
