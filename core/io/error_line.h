#pragma once
// The one formatter of error lines (docs/outputs.md, "Errors"). Every message that reaches a user
// about bad input is one line: the file, the line or field where known, the problem, and at most
// kMaxQuotedChars characters of the offending input, escaped so that a terminal shows exactly what
// was there (control characters, bytes that are not UTF-8, quotes and backslashes).
#include <cstddef>
#include <string>
#include <string_view>

namespace reckoner::io {

/// Most characters of input an error line quotes.
inline constexpr std::size_t kMaxQuotedChars = 200;
/// Longest message part of an error line (after the file and field), however it was composed.
inline constexpr std::size_t kMaxMessageChars = 600;

/// Input as it may appear in an error line, in single quotes: printable ASCII and valid UTF-8 as is;
/// \n, \r, \t, \\, \' and every other control character or invalid byte as an escape (\xNN); cut
/// after maxChars characters with "... (N bytes)" saying how long it was.
std::string quoted(std::string_view input, std::size_t maxChars = kMaxQuotedChars);

/// A message made safe for one line: line breaks become "; ", runs of white space collapse, other
/// control characters and invalid UTF-8 bytes are escaped, and the text is cut at maxChars.
std::string oneLine(std::string_view message, std::size_t maxChars = kMaxMessageChars);

/// Drops a UTF-8 byte-order mark at the start of a text (editors on Windows write one); returns true
/// if there was one.
bool stripByteOrderMark(std::string_view& text);

}  // namespace reckoner::io
