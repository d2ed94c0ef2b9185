#pragma once
// Lines out of a byte stream (docs/connections.md, "Framing"): bytes in any chunking, complete lines
// out. A line ends at CR, LF or CRLF (any run of CR and LF ends one line; empty lines are skipped).
// What cannot be a line of NMEA 0183, AIS or a radar CSV row is counted and discarded, never delivered
// and never kept: a line longer than the limit (discarded up to its newline, however long it goes: a
// 10 MB line without a newline keeps at most the limit in memory), a line with a byte outside printable
// ASCII and TAB (NUL, binary garbage, UTF-8), and the half line buffered when the stream ends (reset()).
// Qt-free; one framer per stream, not thread-safe.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace reckoner::io {

struct LineFramerCounters {
  std::uint64_t bytes = 0;       ///< bytes fed
  std::uint64_t lines = 0;       ///< lines delivered
  std::uint64_t tooLong = 0;     ///< lines discarded for being longer than the limit
  std::uint64_t binary = 0;      ///< lines discarded for a byte outside printable ASCII and TAB
  std::uint64_t partial = 0;     ///< half lines discarded at reset() (a disconnect, the end of a file)
  std::size_t peakBuffered = 0;  ///< the most bytes ever held for one unfinished line (<= the limit)
};

class LineFramer {
 public:
  /// 82 characters (IEC 61162-1, with "$" and CR LF) plus room for a TAG block (IEC 61162-450) and
  /// the longest radar CSV rows: lines beyond 1024 characters are no sentence of any source we read.
  static constexpr std::size_t kDefaultMaxLineLength = 1024;

  /// maxLineLength: the longest line delivered, in bytes without its terminator (>= 1).
  explicit LineFramer(std::size_t maxLineLength = kDefaultMaxLineLength);

  /// Feeds bytes; appends each line completed by them to out (without the terminator).
  void feed(std::string_view bytes, std::vector<std::string>& out);
  /// The end of a datagram ends its last line, newline or not (UDP sources send one or more sentences
  /// a datagram, often without the final CR LF): appends the buffered line to out, if any and valid.
  void endOfRecord(std::vector<std::string>& out);
  /// The stream ended (disconnect, end of file): the half line buffered, if any, is discarded and
  /// counted as partial. The framer is then ready for a new stream.
  void reset();

  [[nodiscard]] std::size_t buffered() const { return buf_.size(); }
  [[nodiscard]] std::size_t maxLineLength() const { return max_; }
  [[nodiscard]] const LineFramerCounters& counters() const { return counters_; }

 private:
  void finishLine(std::vector<std::string>& out);

  std::size_t max_;
  std::string buf_;
  bool inLine_ = false;      ///< bytes of an unfinished line have been seen (buffered or discarded)
  bool discarding_ = false;  ///< the unfinished line went past the limit: dropped up to its end
  bool binary_ = false;      ///< the unfinished line holds a byte no sentence has
  LineFramerCounters counters_;
};

}  // namespace reckoner::io
