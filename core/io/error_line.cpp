#include "io/error_line.h"

#include <cstdio>

#include "io/utf8.h"

namespace reckoner::io {
namespace {

void appendEscaped(std::string& out, unsigned char c) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "\\x%02X", static_cast<unsigned>(c));
  out += buf;
}

/// Appends the character at s[i] as one line may show it: a well-formed multi-byte UTF-8 sequence or
/// a printable ASCII character as it is, any other byte as \xHH. Returns the bytes consumed.
std::size_t appendVisible(std::string& out, std::string_view s, std::size_t i) {
  const auto c = static_cast<unsigned char>(s[i]);
  const std::size_t n = utf8SequenceLength(s, i);
  if (n > 1) {
    out.append(s.substr(i, n));
    return n;
  }
  if (n == 1 && c >= 0x20 && c != 0x7F)
    out += static_cast<char>(c);
  else
    appendEscaped(out, c);
  return 1;
}

}  // namespace

std::string quoted(std::string_view input, std::size_t maxChars) {
  std::string out = "'";
  std::size_t chars = 0, i = 0;
  while (i < input.size() && chars < maxChars) {
    switch (input[i]) {
      case '\n':
        out += "\\n";
        ++i;
        break;
      case '\r':
        out += "\\r";
        ++i;
        break;
      case '\t':
        out += "\\t";
        ++i;
        break;
      case '\\':
        out += "\\\\";
        ++i;
        break;
      case '\'':
        out += "\\'";
        ++i;
        break;
      default:
        i += appendVisible(out, input, i);
    }
    ++chars;
  }
  out += '\'';
  if (i < input.size()) out += "... (" + std::to_string(input.size()) + " bytes)";
  return out;
}

std::string oneLine(std::string_view message, std::size_t maxChars) {
  std::string out;
  std::size_t chars = 0, i = 0;
  bool space = false;  // a run of white space pending
  while (i < message.size() && chars < maxChars) {
    const auto c = static_cast<unsigned char>(message[i]);
    if (c == '\n' || c == '\r') {
      // A line break ends a sentence of a multi-line message (GDAL's, for one): "; " joins them.
      std::size_t j = i;
      while (j < message.size() &&
             (message[j] == '\n' || message[j] == '\r' || message[j] == ' ' || message[j] == '\t'))
        ++j;
      if (!out.empty() && j < message.size()) {
        out += "; ";
        chars += 2;
      }
      space = false;
      i = j;
      continue;
    }
    if (c == ' ' || c == '\t') {
      space = true;
      ++i;
      continue;
    }
    if (space && !out.empty()) {
      out += ' ';
      ++chars;
    }
    space = false;
    i += appendVisible(out, message, i);
    ++chars;
  }
  if (i < message.size()) out += "...";
  return out;
}

bool stripByteOrderMark(std::string_view& text) {
  if (text.size() >= 3 && static_cast<unsigned char>(text[0]) == 0xEF &&
      static_cast<unsigned char>(text[1]) == 0xBB && static_cast<unsigned char>(text[2]) == 0xBF) {
    text.remove_prefix(3);
    return true;
  }
  return false;
}

}  // namespace reckoner::io
