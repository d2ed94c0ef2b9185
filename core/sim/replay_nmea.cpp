// Reading an NMEA 0183 recording into own-ship epochs (sim/replay_input.h): sentences, their sources,
// their times (dates, midnight, week roll-overs, each source's clock) and the stream-time policy; the
// epochs with the active source of each quantity are replay_nmea_epochs.cpp's.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <deque>
#include <map>

#include "common/angles.h"
#include "common/units.h"
#include "io/error_line.h"
#include "io/input_error.h"
#include "io/iso8601.h"
#include "io/nmea.h"
#include "sim/replay_input.h"
#include "sim/replay_nmea_detail.h"
#include "sim/replay_sources.h"

namespace reckoner::sim::replay_input {
namespace {
namespace nm = io::nmea;
using detail::Parsed;
using detail::TimedGroups;
using sources::Kind;
using sources::Quantity;
/// 1024 GPS weeks: the date a receiver with a week-number roll-over bug reports is this far back.
constexpr std::int64_t kRolloverUs = 1024LL * 7 * kUsPerDay;

const char* typeName(const nm::Body& b) {
  static constexpr const char* kNames[] = {"RMC", "GGA", "VTG", "GLL", "HDT", "VHW", "VBW", "ZDA",
                                           "THS", "HDG", "HDM", "ROT", "GNS", "GST", "DTM"};
  static_assert(std::size(kNames) == std::variant_size_v<nm::Body>);
  return kNames[b.index()];
}

/// The quantity a sentence gives (its first, for RMC: position) and its rank (replay_sources.h).
Kind kindOf(const nm::Sentence& s) {
  return std::visit(
      [&](const auto& b) -> Kind {
        using T = std::decay_t<decltype(b)>;
        if constexpr (std::is_same_v<T, nm::Gns>) return {Quantity::Position, 0};
        if constexpr (std::is_same_v<T, nm::Gga>) return {Quantity::Position, 1};
        if constexpr (std::is_same_v<T, nm::Rmc>) return {Quantity::Position, 2};
        if constexpr (std::is_same_v<T, nm::Gll>)
          return s.talker == "LC" ? Kind{Quantity::Loran, 0} : Kind{Quantity::Position, 3};
        if constexpr (std::is_same_v<T, nm::Vtg>) return {Quantity::Velocity, 1};
        if constexpr (std::is_same_v<T, nm::Ths>) return {Quantity::Heading, 0};
        if constexpr (std::is_same_v<T, nm::Hdt>) return {Quantity::Heading, 1};
        if constexpr (std::is_same_v<T, nm::Hdg>) return {Quantity::Heading, 2};
        if constexpr (std::is_same_v<T, nm::Hdm>) return {Quantity::Heading, 3};
        if constexpr (std::is_same_v<T, nm::Vhw>) return {Quantity::SpeedLog, 1};
        if constexpr (std::is_same_v<T, nm::Vbw>) return {Quantity::SpeedLog, 0};
        if constexpr (std::is_same_v<T, nm::Gst>) return {Quantity::Accuracy, 0};
        if constexpr (std::is_same_v<T, nm::Zda>) return {Quantity::Time, 0};
        return {Quantity::Other, 0};  // ROT, DTM
      },
      s.body);
}

std::optional<double> timeOfDayOf(const nm::Sentence& s) {
  std::optional<double> tod;
  std::visit(
      [&](const auto& b) {
        using T = std::decay_t<decltype(b)>;
        if constexpr (std::is_same_v<T, nm::Rmc> || std::is_same_v<T, nm::Gga> ||
                      std::is_same_v<T, nm::Zda> || std::is_same_v<T, nm::Gns> ||
                      std::is_same_v<T, nm::Gst> || std::is_same_v<T, nm::Gll>)
          tod = b.timeOfDayS;
      },
      s.body);
  return tod;
}

std::optional<nm::Date> dateOf(const nm::Sentence& s) {
  if (const auto* rmc = std::get_if<nm::Rmc>(&s.body)) return rmc->date;
  if (const auto* zda = std::get_if<nm::Zda>(&s.body)) return zda->date;
  return std::nullopt;
}

UtcUs utcOf(const nm::Date& d, double tod) {
  return io::daysFromCivil(d.year, d.month, d.day) * kUsPerDay + static_cast<UtcUs>(std::llround(tod * 1e6));
}

}  // namespace

namespace detail {

std::optional<double> timeOfDay(const io::nmea::Sentence& s) {
  return timeOfDayOf(s);
}
bool hasDate(const io::nmea::Sentence& s) {
  return dateOf(s).has_value();
}

std::optional<Parsed> parseLine(std::string_view text, int number, const std::string& name, ReplayStats& st,
                                std::string* whyBad) {
  if (!text.empty() && text.front() == '#') {  // a comment (gpsd's logs open with some)
    ++st.nmeaLines;
    ++st.comments;
    return std::nullopt;
  }
  auto r = nm::parse(text);
  if (r.error == nm::Error::Empty) return std::nullopt;
  ++st.nmeaLines;
  switch (r.error) {
    case nm::Error::BadChecksum:
      ++st.badChecksum;
      break;
    case nm::Error::Unknown:
      ++st.unknownSentences;
      break;
    case nm::Error::Proprietary:
      ++st.proprietary;
      break;
    case nm::Error::Malformed:
      ++st.malformed;
      break;
    default: {
      if (const auto* dtm = std::get_if<nm::Dtm>(&r.sentence->body); dtm && dtm->localDatum != "W84")
        throw io::InputError(name, number, "DTM",
                             "datum " + io::quoted(dtm->localDatum, 8) +
                                 " is not WGS-84 (W84): Reckoner takes positions on WGS-84 only");
      Parsed p{number, std::move(*r.sentence), {}, {}};
      p.source = p.sentence.talker + ":" + typeName(p.sentence.body);
      p.kind = kindOf(p.sentence);
      return p;
    }
  }
  if (whyBad) *whyBad = std::string(nm::errorName(r.error)) + ": " + r.reason;
  return std::nullopt;
}

UtcUs firstDayOf(const Parsed* firstDated, std::optional<double> firstTod, const std::string& name,
                 const NmeaOptions& o, std::vector<std::string>& warnings) {
  if (firstDated) {
    const UtcUs t = utcOf(*dateOf(firstDated->sentence), *timeOfDayOf(firstDated->sentence));
    if (!o.date) return t;
    // --date against the file's dates: a whole number of 1024-week roll-overs is the receiver's bug.
    const UtcUs given = io::daysFromCivil((*o.date)[0], (*o.date)[1], (*o.date)[2]) * kUsPerDay;
    const double k = std::round(static_cast<double>(given - t) / static_cast<double>(kRolloverUs));
    if (k >= 1.0 &&
        std::abs(static_cast<double>(given - t) - k * static_cast<double>(kRolloverUs)) < 2.0 * 86400e6)
      return t + static_cast<UtcUs>(k) * kRolloverUs;
    warnings.push_back(
        io::oneLine(name + ": --date is for a log without dates; this one has them, --date ignored"));
    return t;
  }
  if (o.date)
    return io::daysFromCivil((*o.date)[0], (*o.date)[1], (*o.date)[2]) * kUsPerDay +
           std::llround(firstTod.value_or(0) * 1e6);
  warnings.push_back(
      io::oneLine(name + ": no RMC or ZDA sentence with a date: times of day on an unknown date, shown "
                         "as 1970-01-01 (--date YYYY-MM-DD sets it)"));
  return std::llround(firstTod.value_or(0.0) * 1e6);
}

DayPlacer::DayPlacer(UtcUs first, const Parsed* firstDated)
    : window_{first},
      rollover_(firstDated ? first - utcOf(*dateOf(firstDated->sentence), *timeOfDayOf(firstDated->sentence))
                           : 0) {}

std::optional<UtcUs> DayPlacer::place(const io::nmea::Sentence& s) {
  constexpr std::size_t kRecent = 8;
  const auto tod = timeOfDayOf(s);
  if (!tod) return std::nullopt;
  std::vector<UtcUs> recent(window_.begin(), window_.end());
  const auto mid = recent.begin() + static_cast<std::ptrdiff_t>(recent.size() / 2);
  std::nth_element(recent.begin(), mid, recent.end());
  const UtcUs ref = *mid;
  UtcUs t = 0;
  if (const auto d = dateOf(s)) {
    t = utcOf(*d, *tod) + rollover_;
    const double k = std::round(static_cast<double>(ref - t) / static_cast<double>(kRolloverUs));
    if (k >= 1.0 &&
        std::abs(static_cast<double>(ref - t) - k * static_cast<double>(kRolloverUs)) < 2.0 * 86400e6) {
      t += static_cast<std::int64_t>(k) * kRolloverUs;
      ++rolledOver_;
    }
  } else {
    const UtcUs inDay = static_cast<UtcUs>(std::llround(*tod * 1e6));
    const double day = std::round(static_cast<double>(ref - inDay) / static_cast<double>(kUsPerDay));
    t = static_cast<UtcUs>(day) * kUsPerDay + inDay;
  }
  window_.push_back(t);
  if (window_.size() > kRecent) window_.pop_front();
  return t;
}

void DayPlacer::warn(const std::string& name, std::vector<std::string>& warnings) const {
  if (rollover_ != 0 || rolledOver_ > 0)
    warnings.push_back(
        io::oneLine(name +
                    ": dates 1024 weeks (or a multiple) early, a GPS week roll-over, "
                    "corrected" +
                    (rolledOver_ > 0 ? " in " + std::to_string(rolledOver_) + " sentences" : std::string())));
}

}  // namespace detail

namespace {

/// Parses every line, counting what is skipped. Throws when the file holds no sentence we read, or a
/// DTM names a datum other than WGS-84.
std::vector<Parsed> parseNmea(const std::string& text, const std::string& name, ReplayStats& st) {
  std::vector<Parsed> out;
  std::optional<std::pair<int, std::string>> firstBad;
  std::string why;
  for (const Line& l : linesOf(text)) {
    why.clear();
    if (auto p = detail::parseLine(l.text, l.number, name, st, &why)) {
      out.push_back(std::move(*p));
    } else if (!why.empty() && !firstBad) {
      firstBad.emplace(l.number, why);
    }
  }
  if (out.empty())
    throw io::InputError(name, firstBad ? firstBad->first : 0, "",
                         "no NMEA 0183 sentence Reckoner reads (RMC, GGA, GNS, GLL, VTG, THS, HDT, HDG, HDM, "
                         "VHW, VBW, ZDA, ...)" +
                             (firstBad ? "; the first line is " + firstBad->second : std::string()));
  return out;
}

/// The UTC of each timed sentence (nullopt for the untimed). A dated sentence (RMC with its date, ZDA)
/// is placed by its own date, unless it lies a whole number of 1024-week roll-overs before the others
/// (a receiver with the week-number bug: corrected); the others on the day that puts them nearest the
/// median of the last eight times, so that midnight is crossed and a lone wrong date misleads nothing.
std::vector<std::optional<UtcUs>> timesOf(const std::vector<Parsed>& ps, const std::string& name,
                                          const NmeaOptions& o, std::vector<std::string>& warnings) {
  const auto dated = std::find_if(ps.begin(), ps.end(), [](const Parsed& p) { return dateOf(p.sentence); });
  const Parsed* firstDated = dated == ps.end() ? nullptr : &*dated;
  std::optional<double> firstTod;
  for (const Parsed& p : ps)
    if ((firstTod = timeOfDayOf(p.sentence))) break;
  detail::DayPlacer placer(detail::firstDayOf(firstDated, firstTod, name, o, warnings), firstDated);
  std::vector<std::optional<UtcUs>> out;
  out.reserve(ps.size());
  for (const Parsed& p : ps) out.push_back(placer.place(p.sentence));
  placer.warn(name, warnings);
  return out;
}

/// Shifts the times of every source whose clock runs off the reference's by at least
/// options.clockCorrectionS (sources_stats gets every estimate).
void correctClocks(const std::vector<Parsed>& ps, std::vector<std::optional<UtcUs>>& utc,
                   const NmeaOptions& o, std::map<sources::SourceId, SourceStats>& stats,
                   const std::string& name, std::vector<std::string>& warnings) {
  // The reference: the best-ranked position source (first seen among equals).
  const Parsed* ref = nullptr;
  for (const Parsed& p : ps)
    if (p.kind.quantity == Quantity::Position && utc[static_cast<std::size_t>(&p - ps.data())] &&
        (!ref || p.kind.rank < ref->kind.rank))
      ref = &p;
  if (!ref) return;
  std::vector<std::pair<sources::SourceId, UtcUs>> stamps;
  for (std::size_t i = 0; i < ps.size(); ++i)
    if (utc[i]) stamps.emplace_back(ps[i].source, *utc[i]);
  const auto offsets = sources::clockOffsets(stamps, ref->source);
  for (const auto& [source, c] : offsets) {
    SourceStats& s = stats[source];
    s.clockOffsetS = c.offsetS;
    s.clockResolutionS = c.resolutionS;
    if (std::abs(c.offsetS) < o.clockCorrectionS) continue;
    s.clockCorrected = true;
    const auto shift = static_cast<std::int64_t>(std::llround(c.offsetS * 1e6));
    for (std::size_t i = 0; i < ps.size(); ++i)
      if (utc[i] && ps[i].source == source) *utc[i] -= shift;
    char buf[160];
    std::snprintf(buf, sizeof buf, ": %s runs %.1f s (+- %.1f) %s %s; its times are corrected",
                  source.c_str(), std::abs(c.offsetS), c.resolutionS, c.offsetS > 0 ? "ahead of" : "behind",
                  ref->source.c_str());
    warnings.push_back(io::oneLine(name + buf));
  }
}

}  // namespace

std::vector<Epoch> readNmea(const std::string& text, const std::string& name, const NmeaOptions& o,
                            ReplayStats& st, std::vector<SourceStats>& sourcesOut,
                            std::vector<std::string>& warnings) {
  const std::vector<Parsed> ps = parseNmea(text, name, st);
  std::map<sources::SourceId, SourceStats> stats;
  std::vector<sources::SourceId> firstSeen;
  for (const Parsed& p : ps) {
    auto [it, fresh] = stats.try_emplace(p.source);
    if (fresh) {
      it->second.source = p.source;
      it->second.quantity = std::holds_alternative<nm::Rmc>(p.sentence.body) ? "position+velocity"
                            : std::holds_alternative<nm::Vhw>(p.sentence.body)
                                ? "speed_log+heading"
                                : sources::quantityName(p.kind.quantity);
      firstSeen.push_back(p.source);
    }
    ++it->second.sentences;
  }
  std::vector<std::optional<UtcUs>> utc = timesOf(ps, name, o, warnings);
  correctClocks(ps, utc, o, stats, name, warnings);
  std::vector<UtcUs> stamped;
  for (const auto& u : utc)
    if (u) stamped.push_back(*u);
  const std::vector<char> jump = isolatedTimeJumps(stamped, o.time);
  TimedGroups groups;
  std::size_t k = 0;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    if (utc[i]) {
      if (jump[k++]) {
        ++st.timeJumps;  // its untimed followers stay with the group before it
        ++stats[ps[i].source].timeJumps;
        continue;
      }
      groups.utc.push_back(*utc[i]);
      groups.sentences.push_back({i});
    } else if (groups.sentences.empty()) {
      ++st.untimed;
    } else {
      groups.sentences.back().push_back(i);
    }
  }
  std::vector<Epoch> epochs = detail::assembleEpochs(ps, groups, o, st, stats);
  if (st.noVariation > 0)
    warnings.push_back(io::oneLine(name + ": " + std::to_string(st.noVariation) +
                                   " magnetic headings without a magnetic variation (none in HDG or RMC): "
                                   "--variation DEG gives it"));
  sourcesOut.clear();
  for (const auto& id : firstSeen) sourcesOut.push_back(stats[id]);
  return epochs;
}

}  // namespace reckoner::sim::replay_input
