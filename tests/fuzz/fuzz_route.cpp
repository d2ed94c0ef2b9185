// libFuzzer target: the route file readers (core/io/route_files.h) on arbitrary bytes, as RTZ and as
// GPX. Checks what the readers promise beyond not crashing: only io::InputError is thrown; a route read
// is valid (no problems(), at most kMaxRouteWaypoints waypoints, positions in range, schedules naming
// its waypoints); and it is written as RTZ and read back unchanged (docs/robustness.md, "Fuzzing";
// docs/routes.md, "Route files").
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <set>
#include <string>
#include <string_view>

#include "io/input_error.h"
#include "io/route_files.h"

namespace {
void check(bool ok) {
  if (!ok) std::abort();
}

void checkRoute(const reckoner::geo::Route& r) {
  check(r.problems().empty());
  check(r.waypoints.size() >= 2 && r.waypoints.size() <= reckoner::io::kMaxRouteWaypoints);
  check(r.schedules.size() <= reckoner::io::kMaxRouteSchedules);
  std::set<int> ids;
  for (const auto& w : r.waypoints) {
    check(std::abs(w.position.latDeg) <= 90.0 && std::abs(w.position.lonDeg) <= 180.0);
    ids.insert(w.id);
  }
  for (const auto& s : r.schedules)
    for (const auto* list : {&s.manual, &s.calculated})
      for (const auto& e : *list) check(ids.count(e.waypointId) == 1);
  // Whatever was read is written, and reads back the same.
  const std::string text = reckoner::io::writeRtz(r);
  check(reckoner::io::readRtz(text, "again.rtz") == r);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    checkRoute(reckoner::io::readRtz(text, "fuzz.rtz"));
  } catch (const reckoner::io::InputError&) {
  }
  try {
    checkRoute(reckoner::io::readGpxRoute(text, "fuzz.gpx", static_cast<int>(size % 3)));
  } catch (const reckoner::io::InputError&) {
  }
  return 0;
}
