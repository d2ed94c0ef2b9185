#include "files/record_playback.h"

#include <algorithm>

#include "io/input_error.h"

namespace reckoner::files {
namespace {
constexpr std::size_t kPage = 4096;  // inputs read at a time
}

RecordPlayback::RecordPlayback(const std::string& path)
    : rec_(path), options_(rec_.liveOptions()), alerts_(rec_.alerts()) {
  const auto span = rec_.inputSpan();
  if (!span) throw io::InputError(path, 0, "inputs", "the record holds no input to play back");
  span_ = *span;
  position_ = span_.first;
}

bool RecordPlayback::fillBatch() {
  // A batch is whole once an input of the next batch is ahead of it, or the record has ended.
  while (!exhausted_ && (ahead_.empty() || ahead_.back().batch == ahead_.front().batch)) {
    std::vector<RecordedInput> page = rec_.inputs(lastSeq_, kPage);
    if (page.empty()) {
      exhausted_ = true;
      break;
    }
    lastSeq_ = page.back().seq;
    for (RecordedInput& in : page) ahead_.push_back(std::move(in));
  }
  return !ahead_.empty();
}

bool RecordPlayback::atEnd() {
  return !fillBatch();
}

std::size_t RecordPlayback::feedTo(
    UtcUs utc, const std::function<void(std::int64_t batch, std::span<const InputLine>)>& feed,
    std::size_t maxBatches) {
  std::size_t fed = 0;
  std::vector<InputLine> lines;
  while (fed < maxBatches && fillBatch()) {
    const std::int64_t batch = ahead_.front().batch;
    std::size_t n = 0;
    while (n < ahead_.size() && ahead_[n].batch == batch) ++n;
    const UtcUs at = ahead_[n - 1].receivedUtc;  // the batch went to the engine with its last line
    if (at > utc) break;
    lines.clear();
    for (std::size_t i = 0; i < n; ++i) {
      lines.push_back(std::move(static_cast<InputLine&>(ahead_.front())));
      ahead_.pop_front();
    }
    position_ = std::max(position_, at);
    feed(batch, lines);
    ++fed;
  }
  return fed;
}

void RecordPlayback::rewind() {
  ahead_.clear();
  lastSeq_ = 0;
  exhausted_ = false;
  position_ = span_.first;
}

}  // namespace reckoner::files
