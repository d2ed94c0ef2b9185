#include "metrics/phases.h"

#include <algorithm>

namespace reckoner::metrics {

const char* kindName(PhaseKind k) {
  switch (k) {
    case PhaseKind::Gps:
      return "gps";
    case PhaseKind::LoranC:
      return "loran_c";
    case PhaseKind::DeadReckoning:
      return "dead_reckoning";
  }
  return "unknown";
}

std::vector<Phase> derivePhases(const sim::Scenario& s) {
  std::vector<TimeUs> cuts{0};
  auto collect = [&](const auto& schedule) {
    for (const auto& [t, value] : schedule.changes())
      if (t > 0 && t < s.durationUs) cuts.push_back(t);
  };
  collect(s.gps.power);
  collect(s.loran.power);
  collect(s.speedlog.power);
  collect(s.speedlog.mode);
  collect(s.gyro.power);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());

  using sensors::SensorId;
  std::vector<Phase> phases;
  for (std::size_t i = 0; i < cuts.size(); ++i) {
    const TimeUs start = cuts[i];
    const TimeUs end = i + 1 < cuts.size() ? cuts[i + 1] : s.durationUs;
    const sim::SensorStates st = sim::sensorStatesAt(s, start);
    if (!phases.empty() && phases.back().sensors == st) {
      phases.back().endUs = end;
      continue;
    }
    Phase p;
    p.index = static_cast<int>(phases.size());
    p.startUs = start;
    p.endUs = end;
    p.sensors = st;
    p.kind = st.isOn(SensorId::Gps)      ? PhaseKind::Gps
             : st.isOn(SensorId::LoranC) ? PhaseKind::LoranC
                                         : PhaseKind::DeadReckoning;
    p.label = sim::sensorLabel(st);
    phases.push_back(std::move(p));
  }
  if (!phases.empty()) phases.back().last = true;
  return phases;
}

}  // namespace reckoner::metrics
