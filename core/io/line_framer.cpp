#include "io/line_framer.h"

#include <algorithm>
#include <stdexcept>

namespace reckoner::io {

namespace {

bool isTerminator(char c) {
  return c == '\n' || c == '\r';
}

/// Printable ASCII and TAB: all a sentence, a TAG block or a CSV row is made of.
bool isTextByte(char c) {
  const auto u = static_cast<unsigned char>(c);
  return (u >= 0x20 && u <= 0x7e) || u == '\t';
}

}  // namespace

LineFramer::LineFramer(std::size_t maxLineLength) : max_(maxLineLength) {
  if (max_ == 0) throw std::invalid_argument("LineFramer: maxLineLength must be at least 1");
}

void LineFramer::finishLine(std::vector<std::string>& out) {
  if (discarding_) {
    // counted as too long when it went past the limit
  } else if (binary_) {
    ++counters_.binary;
  } else if (!buf_.empty()) {
    ++counters_.lines;
    out.push_back(buf_);
  }
  buf_.clear();
  inLine_ = discarding_ = binary_ = false;
}

void LineFramer::feed(std::string_view bytes, std::vector<std::string>& out) {
  counters_.bytes += bytes.size();
  std::size_t i = 0;
  while (i < bytes.size()) {
    const char c = bytes[i];
    if (isTerminator(c)) {
      if (inLine_) finishLine(out);
      ++i;
      continue;
    }
    // The run of line bytes up to the next terminator (or the end of this chunk).
    std::size_t end = i;
    while (end < bytes.size() && !isTerminator(bytes[end])) ++end;
    const std::string_view run = bytes.substr(i, end - i);
    inLine_ = true;
    if (!discarding_) {
      if (!binary_ && !std::all_of(run.begin(), run.end(), isTextByte)) binary_ = true;
      if (buf_.size() + run.size() > max_) {
        ++counters_.tooLong;
        discarding_ = true;
        buf_.clear();
        buf_.shrink_to_fit();
      } else if (!binary_) {
        buf_.append(run);
        counters_.peakBuffered = std::max(counters_.peakBuffered, buf_.size());
      } else {
        // A binary line is not kept, only its length, to tell a too-long one.
        buf_.append(run.size(), ' ');
        counters_.peakBuffered = std::max(counters_.peakBuffered, buf_.size());
      }
    }
    i = end;
  }
}

void LineFramer::endOfRecord(std::vector<std::string>& out) {
  if (inLine_) finishLine(out);
}

void LineFramer::reset() {
  if (inLine_ && !discarding_) ++counters_.partial;
  buf_.clear();
  inLine_ = discarding_ = binary_ = false;
}

}  // namespace reckoner::io
