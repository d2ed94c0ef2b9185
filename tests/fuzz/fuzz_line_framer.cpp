// libFuzzer target for io::LineFramer (docs/robustness.md, "Fuzzing"): the input is cut into chunks at
// places the input itself chooses, fed to a framer with a small limit and to one with the default, and
// every line out is checked: no terminator in it, only text bytes, no longer than the limit; the
// framer never holds more than its limit; the lines of any chunking equal those of the whole input.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "io/line_framer.h"

namespace {

void check(bool ok) {
  if (!ok) std::abort();
}

void checkLines(const std::vector<std::string>& lines, std::size_t max) {
  for (const std::string& l : lines) {
    check(!l.empty() && l.size() <= max);
    for (const char c : l) {
      const auto u = static_cast<unsigned char>(c);
      check((u >= 0x20 && u <= 0x7e) || u == '\t');
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  // The first byte picks the small limit (1..64) and the chunk sizes' seed.
  const std::size_t smallMax = 1 + (data[0] % 64);
  const std::string_view all(reinterpret_cast<const char*>(data + 1), size - 1);

  reckoner::io::LineFramer whole(smallMax);
  std::vector<std::string> wholeLines;
  whole.feed(all, wholeLines);
  checkLines(wholeLines, smallMax);
  check(whole.buffered() <= smallMax);

  reckoner::io::LineFramer chunked(smallMax);
  std::vector<std::string> chunkedLines;
  std::size_t pos = 0;
  std::size_t step = 1 + (data[0] >> 6);
  while (pos < all.size()) {
    const std::size_t n = std::min(step, all.size() - pos);
    chunked.feed(all.substr(pos, n), chunkedLines);
    check(chunked.buffered() <= smallMax);
    pos += n;
    step = 1 + (static_cast<unsigned char>(all[pos - 1]) % 17);
  }
  check(chunkedLines == wholeLines);
  const auto& a = whole.counters();
  const auto& b = chunked.counters();
  check(a.lines == b.lines && a.tooLong == b.tooLong && a.binary == b.binary && a.bytes == b.bytes);
  check(a.peakBuffered <= smallMax);

  // The default limit, then the end of the stream: a half line is counted, never delivered.
  reckoner::io::LineFramer big;
  std::vector<std::string> bigLines;
  big.feed(all, bigLines);
  checkLines(bigLines, big.maxLineLength());
  const std::uint64_t partialBefore = big.counters().partial;
  const bool half = big.buffered() > 0;
  big.reset();
  check(big.buffered() == 0);
  check(big.counters().partial == partialBefore + (half ? 1 : 0));
  // A datagram end delivers the last line: as if a newline followed.
  reckoner::io::LineFramer dgram(smallMax);
  std::vector<std::string> dgramLines;
  dgram.feed(all, dgramLines);
  dgram.endOfRecord(dgramLines);
  reckoner::io::LineFramer nl(smallMax);
  std::vector<std::string> nlLines;
  nl.feed(all, nlLines);
  nl.feed("\n", nlLines);
  check(dgramLines == nlLines);
  return 0;
}
