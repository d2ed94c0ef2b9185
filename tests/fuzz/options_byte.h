// The input of a text reader's fuzz target with its options in front: a first byte below 0x20 (never
// the start of a line of text) holds option bits and the rest is the text; any other first byte
// starts the text itself, with no options (docs/robustness.md, "Fuzzing": fuzz_nmea_epochs and
// fuzz_radar_csv).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace reckoner::fuzz {

struct OptionsAndText {
  std::uint8_t flags = 0;  // 0 when the input has no options byte
  std::string text;
};

inline OptionsAndText splitOptionsByte(const std::uint8_t* data, std::size_t size) {
  const bool hasOptions = size > 0 && data[0] < 0x20;
  const std::size_t skip = hasOptions ? 1 : 0;
  return {hasOptions ? data[0] : std::uint8_t{0},
          std::string(reinterpret_cast<const char*>(data) + skip, size - skip)};
}

}  // namespace reckoner::fuzz
