// libFuzzer target: a voyage record's operator actions applied again (core/files/recorded_actions.h) on
// arbitrary text, as a record written by another program (or damaged) may hold them. The input is
// "action\nsubject\nvalue" lines, several actions in a row. Checks what the reader promises beyond not
// crashing: it throws nothing (a bad action is false), and the watch it acts on keeps valid settings
// (validate() accepts them) whatever it was given (docs/robustness.md, "Fuzzing"; docs/recorder.md).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "files/recorded_actions.h"
#include "sim/live_watch.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  reckoner::sim::LiveWatch watch;
  std::size_t at = 0;
  const auto next = [&] {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    std::string field(text.substr(at, end - at));
    at = end < text.size() ? end + 1 : end;
    return field;
  };
  for (int k = 0; k < 64 && at < text.size(); ++k) {
    reckoner::files::OperatorAction a;
    a.afterBatch = k;
    a.action = next();
    a.subject = next();
    a.value = next();
    try {
      (void)reckoner::files::applyOperatorAction(a, watch);
      reckoner::sim::validate(watch.settings());
    } catch (...) {
      std::abort();  // neither the action nor the settings it left may throw
    }
  }
  return 0;
}
