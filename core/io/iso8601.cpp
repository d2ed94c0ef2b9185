// ISO 8601 UTC timestamps (docs/outputs.md) and the civil calendar (proleptic Gregorian).
#include "io/iso8601.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <system_error>

#include "io/text_format.h"

namespace reckoner::io {

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
  const auto sec = parseFiniteNumber(s.substr(17, s.size() - 18));
  if (!y || !mo || !d || !h || !mi || !sec || *mo < 1 || *mo > 12 || *d < 1 || *d > 31 || *h > 23 ||
      *mi > 59 || *sec < 0.0 || *sec >= 61.0)
    return std::nullopt;
  return io::daysFromCivil(*y, *mo, *d) * kUsPerDay +
         (static_cast<std::int64_t>(*h) * 3600 + static_cast<std::int64_t>(*mi) * 60) * 1000000LL +
         static_cast<std::int64_t>(std::llround(*sec * 1e6));
}

std::string formatIso8601(UtcUs t) {
  std::int64_t days = t >= 0 ? t / kUsPerDay : (t - kUsPerDay + 1) / kUsPerDay;
  std::int64_t us = t - days * kUsPerDay;
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

}  // namespace reckoner::io
