#pragma once
// Lines of a recording for tests that cut, damage and reassemble them.
#include <string>
#include <vector>

namespace reckoner::test {

enum class EmptyLines { Keep, Drop };

/// The lines of text (LF or CR LF; the CR dropped).
inline std::vector<std::string> splitLines(const std::string& text, EmptyLines empty = EmptyLines::Keep) {
  std::vector<std::string> out;
  for (std::size_t s = 0; s < text.size();) {
    std::size_t e = text.find('\n', s);
    if (e == std::string::npos) e = text.size();
    std::string l = text.substr(s, e - s);
    if (!l.empty() && l.back() == '\r') l.pop_back();
    if (!l.empty() || empty == EmptyLines::Keep) out.push_back(l);
    s = e + 1;
  }
  return out;
}

/// The lines joined, each ended by CR LF as NMEA 0183 ends them.
inline std::string joinLines(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines) out.append(l).append("\r\n");
  return out;
}

}  // namespace reckoner::test
