#include "sim/replay_input.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <deque>
#include <unordered_map>
#include <unordered_set>

#include "common/angles.h"
#include "common/units.h"
#include "io/error_line.h"
#include "io/input_error.h"
#include "io/nmea.h"

namespace reckoner::sim {
namespace replay_input {
namespace {
namespace nm = io::nmea;
constexpr std::int64_t kUsPerDay = 86400LL * 1000000LL;
/// Longest target_id label kept from a radar file.
constexpr std::size_t kMaxLabelBytes = 64;

struct Line {
  int number;  ///< 1-based
  std::string_view text;
};

std::vector<Line> linesOf(std::string_view text) {
  io::stripByteOrderMark(text);
  std::vector<Line> out;
  std::size_t start = 0;
  int number = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view l = text.substr(start, end - start);
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    out.push_back({++number, l});
    start = end + 1;
  }
  return out;
}

struct PlotHash {
  std::size_t operator()(const Plot& p) const {
    std::size_t h = std::hash<UtcUs>()(p.utc);
    h = h * 1000003u ^ std::hash<double>()(p.rangeM);
    h = h * 1000003u ^ std::hash<double>()(p.bearingRad);
    return h * 1000003u ^ std::hash<int>()(p.tag);
  }
};

std::optional<double> toNumber(std::string_view f) {
  while (!f.empty() && f.front() == ' ') f.remove_prefix(1);
  while (!f.empty() && f.back() == ' ') f.remove_suffix(1);
  if (f.empty()) return std::nullopt;
  double v = 0.0;
  const auto [p, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
  if (ec != std::errc() || p != f.data() + f.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::string_view trimmed(std::string_view f) {
  while (!f.empty() && (f.front() == ' ' || f.front() == '\t')) f.remove_prefix(1);
  while (!f.empty() && (f.back() == ' ' || f.back() == '\t')) f.remove_suffix(1);
  return f;
}

// ---- radar CSV -------------------------------------------------------------------------------------

struct BadRow {
  std::string field, reason;
};

/// Reads one data row; throws BadRow with the field and the reason.
Plot readRow(std::string_view row, bool withId, std::vector<std::string>& labels,
             std::unordered_map<std::string, int>& tagOf) {
  std::vector<std::string_view> f;
  for (std::size_t s = 0;;) {
    const std::size_t c = row.find(',', s);
    f.push_back(row.substr(s, c == std::string_view::npos ? std::string_view::npos : c - s));
    if (c == std::string_view::npos) break;
    s = c + 1;
  }
  const std::size_t want = withId ? 4u : 3u;
  if (f.size() != want)
    throw BadRow{"", "expected " + std::to_string(want) + " fields, got " + std::to_string(f.size()) +
                         " in " + io::quoted(row, 80)};
  const auto utc = parseIso8601(f[0]);
  if (!utc)
    throw BadRow{"utc", "not an ISO 8601 UTC time (2026-01-01T00:00:00.000Z): " + io::quoted(f[0], 40)};
  const auto r = toNumber(f[1]);
  if (!r || *r < 0.0 || *r > kMaxPlausiblePlotRangeM)
    throw BadRow{"range_m", "must be a number in [0, " +
                                std::to_string(static_cast<int>(kMaxPlausiblePlotRangeM)) + "], got " +
                                io::quoted(f[1], 40)};
  const auto b = toNumber(f[2]);
  if (!b || *b < 0.0 || *b > 360.0)
    throw BadRow{"bearing_deg", "must be a number in [0, 360], got " + io::quoted(f[2], 40)};
  int tag = -1;
  if (withId) {
    const std::string_view label = trimmed(f[3]);
    const bool printable = std::all_of(label.begin(), label.end(), [](char c) {
      return static_cast<unsigned char>(c) >= 0x20 && c != 0x7F && c != '"';
    });
    if (label.size() > kMaxLabelBytes || !printable)
      throw BadRow{"target_id", "must be at most " + std::to_string(kMaxLabelBytes) +
                                    " printable characters, got " + io::quoted(label, 80)};
    if (!label.empty()) {
      const auto [it, added] = tagOf.try_emplace(std::string(label), static_cast<int>(labels.size()));
      if (added) labels.emplace_back(label);
      tag = it->second;
    }
  }
  return {*utc, *r, degToRad(*b), tag};
}

// ---- NMEA ------------------------------------------------------------------------------------------

struct Parsed {
  int line;
  nm::Sentence sentence;
};

/// Parses every line, counting what is skipped. Throws when the file holds no sentence we read.
std::vector<Parsed> parseNmea(const std::string& text, const std::string& name, ReplayStats& st) {
  std::vector<Parsed> out;
  std::optional<std::pair<int, std::string>> firstBad;
  for (const Line& l : linesOf(text)) {
    if (!l.text.empty() && l.text.front() == '#') {  // a comment (gpsd's logs open with some)
      ++st.nmeaLines;
      ++st.comments;
      continue;
    }
    auto r = nm::parse(l.text);
    if (r.error == nm::Error::Empty) continue;
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
      default:
        out.push_back({l.number, std::move(*r.sentence)});
        continue;
    }
    if (!firstBad) firstBad.emplace(l.number, std::string(nm::errorName(r.error)) + ": " + r.reason);
  }
  if (out.empty())
    throw io::InputError(name, firstBad ? firstBad->first : 0, "",
                         "no NMEA 0183 sentence Reckoner reads (RMC, GGA, GLL, VTG, HDT, VHW, VBW, ZDA)" +
                             (firstBad ? "; the first line is " + firstBad->second : std::string()));
  return out;
}

std::optional<double> timeOfDayOf(const nm::Sentence& s) {
  std::optional<double> tod;
  std::visit(
      [&](const auto& b) {
        using T = std::decay_t<decltype(b)>;
        if constexpr (std::is_same_v<T, nm::Rmc> || std::is_same_v<T, nm::Gga> || std::is_same_v<T, nm::Zda>)
          tod = b.timeOfDayS;
        else if constexpr (std::is_same_v<T, nm::Gll>)
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

UtcUs medianOf(std::vector<UtcUs> v) {
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

/// The UTC of each timed sentence (nullopt for the untimed). A dated sentence (RMC with its date, ZDA)
/// is placed by its own date; the others on the day that puts them nearest the median of the last
/// eight times, so that midnight is crossed and a lone wrong date misleads nothing else.
std::vector<std::optional<UtcUs>> timesOf(const std::vector<Parsed>& ps, const std::string& name) {
  const auto utcOf = [](const nm::Date& d, double tod) {
    return daysFromCivil(d.year, d.month, d.day) * kUsPerDay + static_cast<UtcUs>(std::llround(tod * 1e6));
  };
  std::vector<UtcUs> recent;
  for (const Parsed& p : ps) {
    const auto d = dateOf(p.sentence);
    if (d) {
      recent.push_back(utcOf(*d, *timeOfDayOf(p.sentence)));
      break;
    }
  }
  if (recent.empty())
    throw io::InputError(name, 0, "", "no RMC or ZDA sentence with a date: the replay needs UTC dates");
  constexpr std::size_t kRecent = 8;
  std::deque<UtcUs> window(recent.begin(), recent.end());
  std::vector<std::optional<UtcUs>> out;
  out.reserve(ps.size());
  for (const Parsed& p : ps) {
    const auto tod = timeOfDayOf(p.sentence);
    if (!tod) {
      out.emplace_back();
      continue;
    }
    UtcUs t = 0;
    if (const auto d = dateOf(p.sentence)) {
      t = utcOf(*d, *tod);
    } else {
      const UtcUs inDay = static_cast<UtcUs>(std::llround(*tod * 1e6));
      const UtcUs ref = medianOf({window.begin(), window.end()});
      const double day = std::round(static_cast<double>(ref - inDay) / static_cast<double>(kUsPerDay));
      t = static_cast<UtcUs>(day) * kUsPerDay + inDay;
    }
    out.emplace_back(t);
    window.push_back(t);
    if (window.size() > kRecent) window.pop_front();
  }
  return out;
}

bool plausibleSpeedKn(double kn) {
  return std::isfinite(kn) && std::abs(kn) <= kMaxPlausibleSpeedKn;
}

enum class Use { Used, Unusable, NotGnss, Implausible };

/// What one sentence adds to its epoch (the first source of each quantity in an epoch wins).
Use apply(const nm::Sentence& s, Epoch& e) {
  return std::visit(
      [&](const auto& b) -> Use {
        using T = std::decay_t<decltype(b)>;
        if constexpr (std::is_same_v<T, nm::Rmc>) {
          if (!b.valid) return Use::Unusable;
          if (!nm::gnssFix(b.mode)) return Use::NotGnss;
          if (b.sogKn && !plausibleSpeedKn(*b.sogKn)) return Use::Implausible;
          if (!e.gps) e.gps = geo::GeoPoint{b.latDeg, b.lonDeg};
          if (b.sogKn && b.cogTrueDeg && !e.gpsVelocity)
            e.gpsVelocity = std::pair{knotsToMps(*b.sogKn), degToRad(*b.cogTrueDeg)};
        } else if constexpr (std::is_same_v<T, nm::Gga>) {
          if (b.quality == 0) return Use::Unusable;
          if (!nm::gnssFix(b.quality)) return Use::NotGnss;
          if (!e.gps) e.gps = geo::GeoPoint{b.latDeg, b.lonDeg};
        } else if constexpr (std::is_same_v<T, nm::Vtg>) {
          if (!b.cogTrueDeg || b.mode == 'N') return Use::Unusable;
          if (!nm::gnssFix(b.mode)) return Use::NotGnss;
          if (!plausibleSpeedKn(b.sogKn)) return Use::Implausible;
          e.gpsVelocity = std::pair{knotsToMps(b.sogKn), degToRad(*b.cogTrueDeg)};
        } else if constexpr (std::is_same_v<T, nm::Gll>) {
          if (!b.valid) return Use::Unusable;
          if (!nm::gnssFix(b.mode)) return Use::NotGnss;
          if (s.talker == "LC")
            e.loran = geo::GeoPoint{b.latDeg, b.lonDeg};
          else if (!e.gps)
            e.gps = geo::GeoPoint{b.latDeg, b.lonDeg};
        } else if constexpr (std::is_same_v<T, nm::Hdt>) {
          e.headingRad = degToRad(b.headingDeg);
        } else if constexpr (std::is_same_v<T, nm::Vhw>) {
          if (!plausibleSpeedKn(b.speedKn)) return Use::Implausible;
          if (!e.log) e.log = std::pair{knotsToMps(b.speedKn), sensors::SpeedlogMode::BottomLock};
        } else if constexpr (std::is_same_v<T, nm::Vbw>) {
          if (b.longGroundKn) {
            const double kn = std::hypot(*b.longGroundKn, *b.transGroundKn);
            if (!plausibleSpeedKn(kn)) return Use::Implausible;
            e.log = std::pair{knotsToMps(kn), sensors::SpeedlogMode::GroundLock};
          } else if (b.longWaterKn) {
            const double kn = std::hypot(*b.longWaterKn, *b.transWaterKn);
            if (!plausibleSpeedKn(kn)) return Use::Implausible;
            if (!e.log) e.log = std::pair{knotsToMps(kn), sensors::SpeedlogMode::BottomLock};
          } else {
            return Use::Unusable;
          }
        }
        // ZDA: time only.
        return Use::Used;
      },
      s.body);
}
}  // namespace

std::vector<Plot> readRadar(const std::string& text, const std::string& name, ReplayStats& st,
                            std::vector<std::string>& labels) {
  const auto ls = linesOf(text);
  if (ls.empty())
    throw io::InputError(name, 1, "header", "empty file; expected 'utc,range_m,bearing_deg[,target_id]'");
  std::string header(ls[0].text);
  header.erase(std::remove(header.begin(), header.end(), ' '), header.end());
  const bool withId = header == "utc,range_m,bearing_deg,target_id";
  if (!withId && header != "utc,range_m,bearing_deg")
    throw io::InputError(
        name, 1, "header",
        "expected 'utc,range_m,bearing_deg[,target_id]', got " + io::quoted(ls[0].text, 120));
  std::vector<Plot> rows;
  std::unordered_map<std::string, int> tagOf;
  std::optional<std::pair<int, BadRow>> firstBad;
  for (std::size_t i = 1; i < ls.size(); ++i) {
    if (trimmed(ls[i].text).empty()) continue;
    ++st.radarLines;
    try {
      rows.push_back(readRow(ls[i].text, withId, labels, tagOf));
    } catch (const BadRow& bad) {
      ++st.radarBad;
      if (!firstBad) firstBad.emplace(ls[i].number, bad);
    }
  }
  if (rows.empty() && firstBad)
    throw io::InputError(name, firstBad->first, firstBad->second.field,
                         "no usable plot in the file; the first bad line: " + firstBad->second.reason);
  // Exact repeats of a plot (one echo written twice) are counted once.
  std::vector<Plot> unique;
  unique.reserve(rows.size());
  std::unordered_set<Plot, PlotHash> seen;
  seen.reserve(rows.size());
  for (const Plot& p : rows) {
    if (seen.insert(p).second)
      unique.push_back(p);
    else
      ++st.radarDuplicates;
  }
  return unique;
}

std::vector<Epoch> readNmea(const std::string& text, const std::string& name, const StreamTimePolicy& policy,
                            ReplayStats& st) {
  const std::vector<Parsed> ps = parseNmea(text, name, st);
  const std::vector<std::optional<UtcUs>> utc = timesOf(ps, name);
  std::vector<UtcUs> stamped;
  for (const auto& u : utc)
    if (u) stamped.push_back(*u);
  const std::vector<char> jump = isolatedTimeJumps(stamped, policy);
  // A group: a timed sentence and the untimed ones after it (they share its time).
  struct Group {
    UtcUs utc;
    std::vector<std::size_t> members;
  };
  std::vector<Group> groups;
  std::size_t k = 0;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    if (utc[i]) {
      if (jump[k++]) {
        ++st.timeJumps;  // its untimed followers stay with the group before it
        continue;
      }
      groups.push_back({*utc[i], {i}});
    } else if (groups.empty()) {
      ++st.untimed;
    } else {
      groups.back().members.push_back(i);
    }
  }
  std::vector<UtcUs> groupTimes;
  groupTimes.reserve(groups.size());
  for (const Group& g : groups) groupTimes.push_back(g.utc);
  std::vector<Epoch> out;
  for (const std::size_t gi : replayOrder(groupTimes, {}, st.reordered)) {
    const Group& g = groups[gi];
    if (out.empty() || out.back().utc != g.utc) out.push_back(Epoch{g.utc, {}, {}, {}, {}, {}});
    for (const std::size_t i : g.members) {
      switch (apply(ps[i].sentence, out.back())) {
        case Use::Used:
          ++st.sentencesUsed;
          break;
        case Use::Unusable:
          ++st.unusable;
          break;
        case Use::NotGnss:
          ++st.notGnss;
          break;
        case Use::Implausible:
          ++st.implausible;
          break;
      }
    }
  }
  std::erase_if(out, [](const Epoch& e) { return e.empty(); });
  return out;
}

}  // namespace replay_input

std::int64_t daysFromCivil(int y, int m, int d) {
  // Count of days from 1970-01-01 (proleptic Gregorian), by years shifted to start in March.
  y -= m <= 2 ? 1 : 0;
  const std::int64_t era = (y >= 0 ? y : y - 399) / 400;
  const std::int64_t yoe = y - era * 400;
  const std::int64_t doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const std::int64_t doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + doe - 719468;
}

std::optional<UtcUs> parseIso8601(std::string_view s) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  if (s.size() < 20 || s[4] != '-' || s[7] != '-' || s[10] != 'T' || s[13] != ':' || s[16] != ':' ||
      s.back() != 'Z')
    return std::nullopt;
  const auto num = [&](std::size_t at, std::size_t n) -> std::optional<int> {
    int v = 0;
    const auto [p, ec] = std::from_chars(s.data() + at, s.data() + at + n, v);
    if (ec != std::errc() || p != s.data() + at + n) return std::nullopt;
    return v;
  };
  const auto y = num(0, 4), mo = num(5, 2), d = num(8, 2), h = num(11, 2), mi = num(14, 2);
  const auto sec = replay_input::toNumber(s.substr(17, s.size() - 18));
  if (!y || !mo || !d || !h || !mi || !sec || *mo < 1 || *mo > 12 || *d < 1 || *d > 31 || *h > 23 ||
      *mi > 59 || *sec < 0.0 || *sec >= 61.0)
    return std::nullopt;
  return daysFromCivil(*y, *mo, *d) * replay_input::kUsPerDay +
         (static_cast<std::int64_t>(*h) * 3600 + *mi * 60) * 1000000LL +
         static_cast<std::int64_t>(std::llround(*sec * 1e6));
}

std::string formatIso8601(UtcUs t) {
  std::int64_t days =
      t >= 0 ? t / replay_input::kUsPerDay : (t - replay_input::kUsPerDay + 1) / replay_input::kUsPerDay;
  std::int64_t us = t - days * replay_input::kUsPerDay;
  // Civil from days (inverse of daysFromCivil).
  days += 719468;
  const std::int64_t era = (days >= 0 ? days : days - 146096) / 146097;
  const std::int64_t doe = days - era * 146097;
  const std::int64_t yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  std::int64_t y = yoe + era * 400;
  const std::int64_t doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const std::int64_t mp = (5 * doy + 2) / 153;
  const std::int64_t d = doy - (153 * mp + 2) / 5 + 1;
  const std::int64_t m = mp < 10 ? mp + 3 : mp - 9;
  y += m <= 2 ? 1 : 0;
  const std::int64_t h = us / 3600000000LL;
  us -= h * 3600000000LL;
  const std::int64_t mi = us / 60000000LL;
  us -= mi * 60000000LL;
  char buf[96];
  std::snprintf(buf, sizeof buf, "%04lld-%02lld-%02lldT%02lld:%02lld:%02lld.%06lldZ",
                static_cast<long long>(y), static_cast<long long>(m), static_cast<long long>(d),
                static_cast<long long>(h), static_cast<long long>(mi), static_cast<long long>(us / 1000000),
                static_cast<long long>(us % 1000000));
  return buf;
}

}  // namespace reckoner::sim
