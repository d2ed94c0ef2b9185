// The scenario reader's shared helpers (scenario_fields.h).
#include "files/scenario_fields.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>

#include "common/angles.h"
#include "common/units.h"
#include "io/json.h"
#include "io/text_file.h"
#include "sim/scenario_limits.h"

// The file formats are written with the codecs of io/: their names unqualified here.
using namespace reckoner::io;

namespace reckoner::files::scenario_detail {

TimeUs timeField(Fields& f, std::string_view key, TimeUs durationUs) {
  const JsonValue& v = f.require(key);
  const double s = f.checkedNumber(v, f.pathOf(key), Fields::Check::NonNegative);
  if (s > toSeconds(durationUs))
    f.fail(v, f.pathOf(key), "time " + formatNumber(s) + " s lies beyond duration_s");
  return fromSeconds(s);
}

/// The line of the value at a checkScenario path ("sensors.gps.schedule[1].t_s"): the deepest value
/// of the path the file has.
int lineOfPath(const JsonValue& root, std::string_view path) {
  const JsonValue* at = &root;
  std::size_t i = 0;
  while (i < path.size() && at) {
    if (path[i] == '.' && ++i == path.size()) break;
    if (path[i] == '[') {
      const std::size_t close = path.find(']', i);
      if (close == std::string_view::npos || !at->isArray()) break;
      std::size_t k = 0;
      const auto [p, ec] = std::from_chars(path.data() + i + 1, path.data() + close, k);
      if (ec != std::errc() || k >= at->array.size()) break;
      at = &at->array[k];
      i = close + 1;
      continue;
    }
    const std::size_t end = std::min(path.find('.', i), path.find('[', i));
    const JsonValue* next = at->isObject() ? at->find(path.substr(i, end - i)) : nullptr;
    if (!next) break;
    at = next;
    i = end == std::string_view::npos ? path.size() : end;
  }
  return at ? at->line : root.line;
}

/// Gauss-Markov block given by its variance (Table I's units) or sigma, plus beta.
est::GaussMarkov gaussMarkov(Fields& f, std::string_view varianceKey, std::string_view sigmaKey) {
  est::GaussMarkov gm;
  const JsonValue* var = f.get(varianceKey);
  const JsonValue* sig = f.get(sigmaKey);
  if (var && sig)
    f.fail(*sig, f.pathOf(sigmaKey),
           "give either " + std::string(varianceKey) + " or " + std::string(sigmaKey) + ", not both");
  if (!var && !sig) f.fail(f.json(), f.pathOf(varianceKey), "required field is missing");
  gm.sigma = var ? std::sqrt(f.checkedNumber(*var, f.pathOf(varianceKey), Fields::Check::NonNegative))
                 : f.checkedNumber(*sig, f.pathOf(sigmaKey), Fields::Check::NonNegative);
  gm.betaPerS = f.number("beta_per_s", Fields::Check::Positive);
  return gm;
}

/// A sensor's "schedule": [{"t_s": .., "on": bool, ("mode": ..)}]; onMode handles "mode" if given.
void readPowerSchedule(Fields& sensor, StepSchedule<bool>& power, TimeUs durationUs,
                       const std::function<void(Fields&, TimeUs)>& onMode) {
  const JsonValue* sched = sensor.get("schedule");
  if (!sched) return;
  const std::string path = sensor.pathOf("schedule");
  if (!sched->isArray()) sensor.fail(*sched, path, "must be an array of {\"t_s\": ..., \"on\": ...} entries");
  TimeUs last = -1;
  bool lastOn = power.initial();
  for (std::size_t i = 0; i < sched->array.size(); ++i) {
    Fields e(sensor.file(), sched->array[i], path + "[" + std::to_string(i) + "]");
    const TimeUs t = timeField(e, "t_s", durationUs);
    if (t <= last) e.fail(*e.get("t_s"), e.pathOf("t_s"), "schedule times must increase");
    last = t;
    const JsonValue* on = e.get("on");
    const JsonValue* mode = onMode ? e.get("mode") : nullptr;
    if (!on && !mode)
      e.fail(sched->array[i], e.pathOf("on"),
             onMode ? "entry needs \"on\" or \"mode\"" : "required field is missing");
    if (on) lastOn = e.boolean(*on, e.pathOf("on"));
    power.addChange(t, lastOn);
    if (mode) onMode(e, t);
    e.finish();
  }
}

SpeedlogMode speedlogMode(const Fields& f, const JsonValue& v, const std::string& path) {
  return valueOf(kSpeedlogModes, f, v, path);
}

}  // namespace reckoner::files::scenario_detail
