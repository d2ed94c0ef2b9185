#include "sim/replay.h"

#include <algorithm>
#include <cmath>

#include "common/angles.h"
#include "io/error_line.h"
#include "io/input_error.h"
#include "sim/replay_input.h"
#include "sim/replay_runner.h"

namespace reckoner::sim {
using replay_runner::chooseOrigin;
using replay_runner::Epoch;
using replay_runner::Plot;
using replay_runner::Runner;
using replay_runner::trackerConfigOf;

ReplayOptions recordedDataOptions(Scenario defaults, SensorProfile profile) {
  ReplayOptions o;
  o.settings = std::move(defaults);
  applySensorProfile(o.settings, profile);
  assumeRadar(o.settings);
  o.sweepFromPlots = true;  // no radar configured: the antenna's rotation as the plots show it
  return o;
}

void assumeRadar(Scenario& s) {
  if (s.radar.fitted) return;
  s.radar.fitted = true;
  s.radar.rangeSdM = 20.0;
  s.radar.bearingSdRad = degToRad(0.5);
}

ReplayResult replay(const std::string& nmeaText, const std::string& nmeaName, const std::string* radarCsv,
                    const std::string& radarName, const ReplayOptions& options) {
  ReplayOptions o = options;  // the sweep period may come from the plots
  ReplayResult res;
  ReplayStats& st = res.stats;
  replay_input::NmeaOptions nmeaOptions;
  nmeaOptions.time = o.time;
  nmeaOptions.date = o.date;
  nmeaOptions.variationDeg = o.variationDeg;
  nmeaOptions.holdS = o.sourceHoldS;
  const std::vector<Epoch> epochs =
      replay_input::readNmea(nmeaText, nmeaName, nmeaOptions, st, res.sources, res.warnings);
  std::vector<Plot> plots;
  if (radarCsv) {
    plots = replay_input::inReplayOrder(
        replay_input::readRadar(*radarCsv, radarName, st, res.targetLabels),
        [](const Plot& p) { return p.utc; }, o.time, st.radarTimeJumps, st.radarReordered);
    st.radarPlots = static_cast<long>(plots.size());
    if (plots.empty()) res.warnings.push_back(io::oneLine(radarName + ": holds no radar plot"));
    if (o.sweepFromPlots) {
      if (const auto period = replay_input::rotationPeriodS(plots);
          period && *period >= 0.5 && *period <= 60.0) {
        o.settings.radar.sweepPeriodS = std::round(*period * 1000.0) / 1000.0;
        res.sweepFromPlots = true;
      }
    }
    res.sweepPeriodS = o.settings.radar.sweepPeriodS;
  }
  const auto firstFix = std::find_if(epochs.begin(), epochs.end(), [](const Epoch& e) { return e.hasFix(); });
  if (firstFix == epochs.end())
    throw io::InputError(nmeaName, 0, "",
                         "no position fix (RMC, GGA or GLL) to start from (" + std::to_string(st.notGnss) +
                             " not GNSS fixes: estimated, manual, simulator; " + std::to_string(st.unusable) +
                             " without a fix; " + std::to_string(st.implausible) + " implausible)");
  res.utc0 = epochs.front().utc;
  res.origin = chooseOrigin(o, *firstFix, nmeaName, res.warnings);
  if (st.reordered > 0)
    res.warnings.push_back(
        io::oneLine(nmeaName + ": " + std::to_string(st.reordered) +
                    " timed sentences were written out of time order; replayed in time order"));
  if (st.timeJumps > 0)
    res.warnings.push_back(
        io::oneLine(nmeaName + ": " + std::to_string(st.timeJumps) +
                    " sentences stamped far from their neighbours were dropped as clock errors"));
  if (radarCsv) {
    track::TrackManagerConfig c = trackerConfigOf(o);
    if (const std::string problem = c.check(); !problem.empty())
      throw io::InputError(o.settingsName.empty() ? "settings" : o.settingsName, 0, "tracker",
                           problem + (o.assumeAssociation ? ""
                                                          : " (replay associates plots by nearest neighbour "
                                                            "unless --assume-association is given)"));
  }
  Runner run(o, res, radarCsv != nullptr);
  std::size_t pi = 0;
  for (const Epoch& e : epochs) {
    for (; pi < plots.size() && plots[pi].utc < e.utc; ++pi) run.plot(plots[pi]);  // plots before this epoch
    run.ownShip(e);
  }
  for (; pi < plots.size(); ++pi) run.plot(plots[pi]);  // against the last own-ship estimate
  run.finish();
  return res;
}

}  // namespace reckoner::sim
