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
#include "io/text_format.h"

namespace reckoner::sim {
namespace replay_input {
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

std::optional<double> toNumber(std::string_view f) {
  return io::parseFiniteNumber(f);
}

std::string_view trimmed(std::string_view f) {
  while (!f.empty() && (f.front() == ' ' || f.front() == '\t')) f.remove_prefix(1);
  while (!f.empty() && (f.back() == ' ' || f.back() == '\t')) f.remove_suffix(1);
  return f;
}

namespace {
/// Longest target_id label kept from a radar file.
constexpr std::size_t kMaxLabelBytes = 64;

struct PlotHash {
  std::size_t operator()(const Plot& p) const {
    std::size_t h = std::hash<UtcUs>()(p.utc);
    h = h * 1000003u ^ std::hash<double>()(p.rangeM);
    h = h * 1000003u ^ std::hash<double>()(p.bearingRad);
    return h * 1000003u ^ std::hash<int>()(p.tag);
  }
};

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
  const auto utc = io::parseIso8601(f[0]);
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

std::optional<Plot> readRadarRow(std::string_view row, bool withId, std::vector<std::string>& labels,
                                 std::unordered_map<std::string, int>& tagOf, std::string& why) {
  try {
    return readRow(row, withId, labels, tagOf);
  } catch (const BadRow& bad) {
    why = bad.field.empty() ? bad.reason : bad.field + ": " + bad.reason;
    return std::nullopt;
  }
}

}  // namespace replay_input

namespace replay_input {

std::optional<double> rotationPeriodS(const std::vector<Plot>& plots) {
  constexpr TimeUs kMinUs = 300'000, kMaxUs = 30'000'000;
  constexpr double kNearM = 100.0, kNearRad = degToRad(1.5);
  constexpr std::size_t kLookAhead = 256, kMinIntervals = 20;
  std::vector<double> intervals;
  for (std::size_t i = 0; i < plots.size(); ++i) {
    for (std::size_t j = i + 1; j < plots.size() && j <= i + kLookAhead; ++j) {
      const TimeUs dt = plots[j].utc - plots[i].utc;
      if (dt > kMaxUs) break;
      if (dt < kMinUs) continue;
      if (std::abs(plots[j].rangeM - plots[i].rangeM) <= kNearM &&
          std::abs(angleDiff(plots[j].bearingRad, plots[i].bearingRad)) <= kNearRad) {
        intervals.push_back(toSeconds(dt));
        break;
      }
    }
  }
  if (intervals.size() < kMinIntervals) return std::nullopt;
  const auto mid = intervals.begin() + static_cast<std::ptrdiff_t>(intervals.size() / 2);
  std::nth_element(intervals.begin(), mid, intervals.end());
  return *mid;
}

}  // namespace replay_input

}  // namespace reckoner::sim
