#include "files/own_ship_output.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "estimation/update_report.h"
#include "files/track_output.h"
#include "io/input_error.h"
#include "io/json.h"
#include "sim/simulation_engine.h"

// The file formats are written with the codecs of io/: their names unqualified here.
using namespace reckoner::io;

namespace reckoner::files {

std::string ownShipCsvHeader() {
  return "t_s,true_x_m,true_y_m,true_vx_mps,true_vy_mps,est_x_m,est_y_m,est_vx_mps,est_vy_mps,"
         "sd_x_m,sd_y_m,sd_vx_mps,sd_vy_mps,est_lat_deg,est_lon_deg,nees,sensors,rows";
}

std::string ownShipCsvLine(const sim::OwnShipRow& r) {
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "%.6f,%.3f,%.3f,%.4f,%.4f,%.3f,%.3f,%.4f,%.4f,%.4f,%.4f,%.5f,%.5f,%.9f,%.9f,%.4f,%s,%d",
                toSeconds(r.timeUs), r.trueXM, r.trueYM, r.trueVxMps, r.trueVyMps, r.estXM, r.estYM,
                r.estVxMps, r.estVyMps, r.sdXM, r.sdYM, r.sdVxMps, r.sdVyMps, r.estLatDeg, r.estLonDeg,
                r.nees, sim::sensorLabel(r.sensors).c_str(), r.rowsApplied);
  return buf;
}

void writeOwnShipCsv(const std::string& path, std::span<const sim::OwnShipRow> rows) {
  std::string text = ownShipCsvHeader() + "\n";
  text.reserve(rows.size() * 200);
  for (const auto& r : rows) text += ownShipCsvLine(r) + "\n";
  writeTextFile(path, text);
}

namespace {

void phaseHeader(JsonWriter& w, const metrics::Phase& p) {
  w.key("index").value(p.index);
  w.key("label").value(p.label);
  w.key("kind").value(metrics::kindName(p.kind));
  w.key("start_s").value(toSeconds(p.startUs));
  w.key("end_s").value(toSeconds(p.endUs));
}

void phaseFigures(JsonWriter& w, const metrics::PhaseStats& s) {
  w.key("steps").value(s.steps);
  w.key("rmse_position_m").value(s.rmsePositionM, 6);
  w.key("rmse_velocity_mps").value(s.rmseVelocityMps, 6);
  w.key("mean_nees").value(s.meanNees, 6);
  w.key("max_position_error_m").value(s.maxPositionErrorM, 6);
  w.key("fraction_within_3sd").value(s.fractionWithin3Sd, 6);
  w.key("sd_position_start_m").value(s.sdPositionStartM, 6);
  w.key("sd_position_end_m").value(s.sdPositionEndM, 6);
}

void scenarioHeader(JsonWriter& w, const sim::Scenario& s) {
  w.key("scenario").value(s.name);
  w.key("duration_s").value(toSeconds(s.durationUs));
  w.key("step_s").value(toSeconds(s.stepUs));
  w.key("state_dim").value(nav::neesDof(sim::drkfConfigFor(s).process));
}

}  // namespace

std::string runSummaryJson(const sim::Scenario& s, const sim::RunResult& run,
                           const std::vector<metrics::PhaseStats>& phases) {
  JsonWriter w;
  w.beginObject();
  scenarioHeader(w, s);
  w.key("seed").value(run.seed);
  w.key("steps").value(static_cast<std::int64_t>(run.rows.size()));
  w.key("wall_time_s").value(run.wallTimeS, 4);
  w.key("phases").beginArray();
  for (const auto& p : phases) {
    w.beginObject();
    phaseHeader(w, p.phase);
    phaseFigures(w, p);
    w.endObject();
  }
  w.endArray();
  w.key("updates").beginObject();
  for (int b = 0; b < nav::kDrkfBlockCount; ++b) {
    w.key(nav::blockName(static_cast<nav::DrkfBlock>(b))).beginObject();
    const auto& counts = run.counters.byStatus[static_cast<std::size_t>(b)];
    for (std::size_t k = 0; k < counts.size(); ++k)
      if (counts[k] > 0)
        w.key(est::statusName(static_cast<est::UpdateStatus>(k))).value(static_cast<std::int64_t>(counts[k]));
    w.endObject();
  }
  w.endObject();
  w.key("predict_failures").value(static_cast<std::int64_t>(run.counters.predictFailures));
  w.key("stale_samples").value(static_cast<std::int64_t>(run.counters.staleSamples));
  w.key("overflow_samples").value(static_cast<std::int64_t>(run.counters.overflowSamples));
  writeFilterResets(w, "filter_resets", run.counters.resets);
  if (s.radar.fitted)
    writeTrackingSummary(w, metrics::summariseTracking(run.trackRows, run.targetRows), run.trackCounters);
  w.endObject();
  return w.str();
}

std::string monteCarloSummaryJson(const sim::Scenario& s, const metrics::MonteCarloSummary& m,
                                  std::uint64_t baseSeed, int threads, double wallTimeS) {
  JsonWriter w;
  w.beginObject();
  scenarioHeader(w, s);
  w.key("runs").value(m.runs);
  w.key("first_seed").value(baseSeed);
  w.key("threads").value(threads);
  w.key("wall_time_s").value(wallTimeS, 4);
  w.key("confidence").value(m.confidence);
  w.key("nees_bounds").beginArray().value(m.bounds.lower, 6).value(m.bounds.upper, 6).endArray();
  w.key("all_phases_inside").value(m.allPhasesInside);
  w.key("phases").beginArray();
  for (const auto& p : m.phases) {
    w.beginObject();
    phaseHeader(w, p.stats.phase);
    phaseFigures(w, p.stats);
    w.key("max_mean_nees").value(p.maxMeanNees, 6);
    w.key("fraction_steps_inside").value(p.fractionStepsInside, 6);
    w.key("inside").value(p.inside);
    w.endObject();
  }
  w.endArray();
  w.key("per_time").beginObject();
  w.key("t_s").numberArray(m.series.timeS, 10);
  w.key("rmse_position_m").numberArray(m.series.rmsePositionM, 6);
  w.key("rmse_velocity_mps").numberArray(m.series.rmseVelocityMps, 6);
  w.key("mean_nees").numberArray(m.series.meanNees, 6);
  w.key("rms_sd_position_m").numberArray(m.series.rmsSdPositionM, 6);
  std::vector<double> inside;
  for (double v : m.series.meanNees) inside.push_back(m.bounds.contains(v) ? 1.0 : 0.0);
  w.key("inside").numberArray(inside, 1);
  w.endObject();
  w.endObject();
  return w.str();
}

void writeMonteCarloCsv(const std::string& path, const metrics::MonteCarloSummary& m) {
  std::string text =
      "t_s,rmse_position_m,rmse_velocity_mps,mean_nees,nees_lower,nees_upper,rms_sd_position_m\n";
  char buf[256];
  const auto& s = m.series;
  for (std::size_t k = 0; k < s.timeS.size(); ++k) {
    std::snprintf(buf, sizeof buf, "%.6f,%.4f,%.5f,%.4f,%.4f,%.4f,%.4f\n", s.timeS[k], s.rmsePositionM[k],
                  s.rmseVelocityMps[k], s.meanNees[k], m.bounds.lower, m.bounds.upper, s.rmsSdPositionM[k]);
    text += buf;
  }
  writeTextFile(path, text);
}

}  // namespace reckoner::files
