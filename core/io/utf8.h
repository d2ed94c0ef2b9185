#pragma once
// UTF-8 as RFC 3629 defines it: no overlong forms, no surrogates, nothing above U+10FFFF. Readers of
// text formats that promise UTF-8 (JSON) refuse anything else; writers never emit it.
#include <cstddef>
#include <string>
#include <string_view>

namespace reckoner::io {

/// Length (1 to 4) of the well-formed UTF-8 sequence starting at s[i], or 0 if the bytes there are not
/// one. i must be < s.size().
std::size_t utf8SequenceLength(std::string_view s, std::size_t i);

/// Byte offset of the first byte that does not start a well-formed sequence, or npos if s is UTF-8.
std::size_t firstInvalidUtf8(std::string_view s);

/// s with every ill-formed byte replaced by U+FFFD (the replacement character).
std::string validUtf8(std::string_view s);

}  // namespace reckoner::io
