#pragma once
// ISO 8601 UTC timestamps as the project's files write them ("2024-05-01T12:00:01.250000Z") and the
// civil calendar behind them (proleptic Gregorian, days since 1970-01-01).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "common/time.h"

namespace reckoner::io {

inline constexpr std::int64_t kUsPerDay = 86400LL * 1000000LL;

/// "2024-05-01T12:00:01.250Z" -> UTC; nullopt when malformed (Z required).
std::optional<UtcUs> parseIso8601(std::string_view s);
/// UTC -> "2024-05-01T12:00:01.250000Z".
std::string formatIso8601(UtcUs t);
/// Days since 1970-01-01 of a civil date.
std::int64_t daysFromCivil(int year, int month, int day);

}  // namespace reckoner::io
