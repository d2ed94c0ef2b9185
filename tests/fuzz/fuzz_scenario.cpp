// libFuzzer target: the scenario reader (core/files/scenario_json.h: parseScenario, the JSON codec of
// core/io/json.h under it) on arbitrary text. Checks what the reader promises beyond not crashing: a
// scenario read passes sim::checkScenario; anything else is one io::InputError naming the file, on
// one line, and never another exception; and what was read is written (writeScenario) and read back
// to the same text, so no value the reader accepts is one the writer cannot give back
// (docs/robustness.md, "Fuzzing"; docs/scenarios.md).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "files/scenario_json.h"
#include "io/input_error.h"
#include "sim/scenario.h"

namespace {
void check(bool ok) {
  if (!ok) std::abort();
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const reckoner::sim::Scenario s = reckoner::files::parseScenario(text, "fuzz.json");
    check(reckoner::sim::checkScenario(s).empty());
    const std::string written = reckoner::files::writeScenario(s);
    const reckoner::sim::Scenario back = reckoner::files::parseScenario(written, "back.json");
    check(reckoner::files::writeScenario(back) == written);
  } catch (const reckoner::io::InputError& e) {
    const std::string_view what = e.what();
    check(what.starts_with("fuzz.json"));  // the round trip above never fails
    check(what.find_first_of("\r\n") == std::string_view::npos);
    check(e.file() == "fuzz.json");
  } catch (...) {
    std::abort();
  }
  return 0;
}
