// libFuzzer target: the AIS decoder (core/io/ais.h) on arbitrary bytes, split into lines as a stream
// delivers them. Checks what the decoder promises beyond not crashing: bounded partials, counts that
// add up, and decoded values inside their fields' ranges (docs/robustness.md, "Fuzzing").
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "io/ais.h"

namespace {
void check(bool ok) {
  if (!ok) std::abort();
}

void checkMessage(const reckoner::io::AisMessage& m) {
  check(m.type >= 1 && m.type <= 27);
  if (m.latDeg) check(std::isfinite(*m.latDeg) && std::abs(*m.latDeg) <= 90.0);
  if (m.lonDeg) check(std::isfinite(*m.lonDeg) && std::abs(*m.lonDeg) <= 180.0);
  if (m.sogKn) check(*m.sogKn >= 0.0 && *m.sogKn < 102.3);
  if (m.cogDeg) check(*m.cogDeg >= 0.0 && *m.cogDeg < 360.0);
  if (m.headingDeg) check(*m.headingDeg >= 0 && *m.headingDeg < 360);
  if (m.rotDegMin) check(std::isfinite(*m.rotDegMin) && std::abs(*m.rotDegMin) <= 720.1);
  if (m.navStatus) check(*m.navStatus >= 0 && *m.navStatus <= 15);
  for (const auto* s : {&m.name, &m.callsign, &m.destination, &m.vendor, &m.text})
    for (const char c : *s) check(c >= 32 && c < 127);
  check(m.text.size() <= 161);
  if (m.second) check(*m.second >= 0 && *m.second <= 59);
  if (m.positionNotFix) check(*m.positionNotFix >= 61 && *m.positionNotFix <= 63);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  reckoner::io::AisDecoder decoder(reckoner::io::AisDecoder::Limits{8, 60.0, 4});
  std::string_view rest(reinterpret_cast<const char*>(data), size);
  double t = 0.0;
  while (!rest.empty()) {
    const auto nl = rest.find('\n');
    const std::string_view line = rest.substr(0, nl);
    rest.remove_prefix(nl == std::string_view::npos ? rest.size() : nl + 1);
    t += 1.0;
    if (const auto m = decoder.feed(line, t)) checkMessage(*m);
    check(decoder.partialsInFlight() <= 4);
  }
  const auto& c = decoder.counters();
  check(c.decoded + c.rejected() <= c.lines);
  return 0;
}
