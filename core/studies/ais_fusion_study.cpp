#include "studies/ais_fusion_study.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "common/percentile.h"
#include "estimation/ekf.h"
#include "sim/scenario_run.h"
#include "sim/simulation_engine.h"

namespace reckoner::studies {
namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
namespace tk = est::ttkf;

struct Sample {
  std::optional<ImoErrors> at1, at3;
  double nees3 = std::numeric_limits<double>::quiet_NaN();
};

/// One vessel's scored track in one run: the first track of the vessel, followed by its id.
struct Scored {
  int trackId = -1;
  TimeUs acquiredUs = -1;
};

struct Vessel {
  int targetId = 0;
  std::size_t index = 0;  ///< in the scenario's targets
  std::uint32_t mmsi = 0;
};

struct RunOut {
  long eligible = 0, correct = 0, missed = 0, falseAssociations = 0, swapsNear = 0, swapsFar = 0;
  long associated = 0, dissociated = 0, fused = 0, rejected = 0;
  std::vector<std::array<Sample, kFusionSourceCount>> samples;  ///< per vessel
};

double neesOf(const est::Vec<4>& err, const est::Mat<4>& P) {
  return est::nees<4>(err, P);
}

est::Vec<4> trueTarget(const sim::VesselTruth& t) {
  return {t.position.xM, t.position.yM, t.groundVxMps(), t.groundVyMps()};
}

/// Which of `at` (1 or 3 minutes) falls due at t for a track acquired at acquiredUs.
void scoreAt(Sample& s, TimeUs t, TimeUs acquiredUs, const ImoErrors& e, double nees) {
  if (!s.at1 && t >= acquiredUs + 60 * kMicrosPerSecond) s.at1 = e;
  if (!s.at3 && t >= acquiredUs + 180 * kMicrosPerSecond) {
    s.at3 = e;
    s.nees3 = nees;
  }
}

const sim::TrackSnapshot* followed(const sim::SimFrame& f, const Vessel& v, Scored& sc) {
  for (const auto& t : f.tracks) {
    if (sc.trackId < 0 && t.targetId == v.targetId && t.status == track::TrackStatus::Confirmed) {
      sc.trackId = t.trackId;
      sc.acquiredUs = t.initiatedUs;
      return &t;
    }
    if (t.trackId == sc.trackId) return t.status == track::TrackStatus::Lost ? nullptr : &t;
  }
  return nullptr;
}

/// The AIS-only estimate as a 12-state belief: own ship from the track's own block (the DRKF's), the
/// target from the station's latest report carried to t, uncorrelated.
std::optional<tk::Belief> aisOnly(const sim::SimulationEngine& e, std::uint32_t mmsi, const tk::Belief& track,
                                  TimeUs t) {
  const track::AisObservation* o = e.ais().fusion().latest(mmsi);
  if (!o) return std::nullopt;
  const est::Gaussian<4> g = o->at(t, false);
  tk::Belief b;
  b.x.setZero();
  b.P.setZero();
  b.x.head<6>() = track.x.head<6>();
  b.P.topLeftCorner<6, 6>() = track.P.topLeftCorner<6, 6>();
  b.x.segment<4>(tk::kTgtX) = g.x;
  b.P.block<4, 4>(tk::kTgtX, tk::kTgtX) = g.P;
  b.P(tk::kTgtAx, tk::kTgtAx) = b.P(tk::kTgtAy, tk::kTgtAy) = 1e-4;
  return b;
}

struct AssociationState {
  std::vector<TimeUs> heard, tracked;
  std::vector<int> wrongTag;
  explicit AssociationState(std::size_t n) : heard(n, -1), tracked(n, -1), wrongTag(n, -2) {}
};

void scoreAssociation(const sim::SimFrame& f, const std::vector<Vessel>& vessels,
                      const std::map<int, std::size_t>& indexOfTarget, const FusionStudyOptions& o,
                      AssociationState& st, RunOut& out) {
  const TimeUs t = f.timeUs;
  std::map<int, int> tagOfTrack;
  for (const auto& tr : f.tracks) tagOfTrack[tr.trackId] = tr.targetId;
  std::map<std::uint32_t, int> trackOfMmsi;
  for (const auto& a : f.aisAssociations) trackOfMmsi[a.mmsi] = a.trackId;
  const TimeUs window = fromSeconds(o.associateWindowS);
  for (std::size_t i = 0; i < vessels.size(); ++i) {
    const Vessel& v = vessels[i];
    for (const auto& r : f.aisReceived)
      if (r.sourceTarget == v.targetId && st.heard[i] < 0) st.heard[i] = r.rxUs;
    const bool hasTrack = std::any_of(f.tracks.begin(), f.tracks.end(), [&](const auto& tr) {
      return tr.targetId == v.targetId && tr.status == track::TrackStatus::Confirmed;
    });
    st.tracked[i] = hasTrack ? (st.tracked[i] < 0 ? t : st.tracked[i]) : -1;
    const auto a = trackOfMmsi.find(v.mmsi);
    const int tag = a == trackOfMmsi.end() ? -2 : tagOfTrack[a->second];
    const bool wrong = a != trackOfMmsi.end() && tag != v.targetId;
    if (wrong && tag != st.wrongTag[i]) {  // an association that turned false: a swap
      const auto other = indexOfTarget.find(tag);
      double apartM = kInf;  // clutter's track: no vessel there
      if (other != indexOfTarget.end()) {
        const auto& p = f.targets[v.index].position;
        const auto& q = f.targets[other->second].position;
        apartM = std::hypot(p.xM - q.xM, p.yM - q.yM);
      }
      ++(apartM > o.swapDistanceM ? out.swapsFar : out.swapsNear);
    }
    st.wrongTag[i] = wrong ? tag : -2;
    const bool eligible =
        st.heard[i] >= 0 && t - st.heard[i] >= window && st.tracked[i] >= 0 && t - st.tracked[i] >= window;
    if (!eligible) continue;
    ++out.eligible;
    if (a == trackOfMmsi.end())
      ++out.missed;
    else if (wrong)
      ++out.falseAssociations;
    else
      ++out.correct;
  }
}

void scoreTrack(const sim::SimFrame& f, const sim::SimulationEngine& e, const Vessel& v, Scored& sc,
                Sample& s, Sample* aisSample) {
  const sim::TrackSnapshot* tr = followed(f, v, sc);
  if (!tr) return;
  const bool due1 = !s.at1 && f.timeUs >= sc.acquiredUs + 60 * kMicrosPerSecond;
  const bool due3 = !s.at3 && f.timeUs >= sc.acquiredUs + 180 * kMicrosPerSecond;
  if (!due1 && !due3) return;  // the truth and its projection only when a sample falls due
  const double gamma = e.frame().gridInfo(f.truth.position).convergenceRad;
  const ImoTruth truth = imoTruthOf(f.truth, f.targets[v.index], gamma);
  const est::Vec<4> x = trueTarget(f.targets[v.index]);
  const auto& b = tr->estimate;
  scoreAt(s, f.timeUs, sc.acquiredUs, imoErrorsOf(tr->kinematics, truth),
          neesOf(x - b.x.segment<4>(tk::kTgtX), b.P.block<4, 4>(tk::kTgtX, tk::kTgtX)));
  if (!aisSample) return;
  const auto a = aisOnly(e, v.mmsi, b, f.timeUs);
  if (!a) return;
  const track::TrackKinematics k = track::kinematicsOf(*a, gamma);
  Sample& as = *aisSample;
  if (due1 && !as.at1) as.at1 = imoErrorsOf(k, truth);
  if (due3 && !as.at3) {
    as.at3 = imoErrorsOf(k, truth);
    as.nees3 = neesOf(x - a->x.segment<4>(tk::kTgtX), a->P.block<4, 4>(tk::kTgtX, tk::kTgtX));
  }
}

void run(const sim::Scenario& scenario, std::uint64_t seed, const std::vector<Vessel>& vessels,
         const FusionStudyOptions& o, bool fused, RunOut& out) {
  std::map<int, std::size_t> indexOfTarget;
  for (std::size_t i = 0; i < scenario.targets.size(); ++i) indexOfTarget[scenario.targets[i].id] = i;
  sim::SimulationEngine engine(scenario, seed);
  AssociationState st(vessels.size());
  std::vector<Scored> scored(vessels.size());
  out.samples.resize(vessels.size());
  while (!engine.finished()) {
    const sim::SimFrame f = engine.step();
    if (fused) {
      scoreAssociation(f, vessels, indexOfTarget, o, st, out);
      for (const auto& ev : f.aisEvents)
        ++(ev.kind == track::AisAssociationEvent::Kind::Associated ? out.associated : out.dissociated);
    }
    for (std::size_t i = 0; i < vessels.size(); ++i) {
      auto& s = out.samples[i];
      if (fused)
        scoreTrack(f, engine, vessels[i], scored[i], s[static_cast<int>(FusionSource::Fused)], nullptr);
      else
        scoreTrack(f, engine, vessels[i], scored[i], s[static_cast<int>(FusionSource::RadarOnly)],
                   &s[static_cast<int>(FusionSource::AisOnly)]);
    }
  }
  if (fused) {
    out.fused = engine.ais().fusion().counters().fused;
    out.rejected = engine.ais().fusion().counters().rejected;
  }
}
}  // namespace

const char* fusionSourceName(FusionSource s) {
  switch (s) {
    case FusionSource::Fused:
      return "fused";
    case FusionSource::RadarOnly:
      return "radar only";
    case FusionSource::AisOnly:
      return "AIS only";
  }
  return "?";
}

sim::Scenario withAis(sim::Scenario s, sensors::AisStationClass cls) {
  for (auto& t : s.targets) {
    if (t.ais) continue;
    auto a = sensors::AisTransmitterSpec::defaults(cls);
    a.mmsi = 200000000u + static_cast<std::uint32_t>(t.id);
    a.shipName = t.name;
    if (cls == sensors::AisStationClass::A) {
      a.toBowM = 90, a.toSternM = 30, a.toPortM = 8, a.toStarboardM = 10;
    } else {
      a.toBowM = 7, a.toSternM = 5, a.toPortM = 2, a.toStarboardM = 2;
    }
    t.ais = a;
  }
  return s;
}

FusionStudyResult evaluateFusion(const sim::Scenario& scenario, const FusionStudyOptions& o) {
  std::vector<Vessel> vessels;
  for (std::size_t i = 0; i < scenario.targets.size(); ++i)
    if (scenario.targets[i].ais)
      vessels.push_back({scenario.targets[i].id, i, scenario.targets[i].ais->mmsi});
  if (vessels.empty() || !scenario.radar.fitted)
    throw std::invalid_argument("AIS fusion evaluation: scenario '" + scenario.name +
                                "' needs a radar and a target with AIS");
  if (o.runs <= 0 || o.threads <= 0)
    throw std::invalid_argument("AIS fusion evaluation: runs and threads must be positive");
  sim::Scenario radarOnly = scenario;
  radarOnly.tracker.aisAssociation.fuse = false;
  std::vector<RunOut> fusedRuns(static_cast<std::size_t>(o.runs)), radarRuns(fusedRuns.size());
  parallelRuns(2 * o.runs, o.threads, [&](int k) {
    const auto i = static_cast<std::size_t>(k / 2);
    const std::uint64_t seed = o.seed + i;
    if (k % 2 == 0)
      run(scenario, seed, vessels, o, true, fusedRuns[i]);
    else
      run(radarOnly, seed, vessels, o, false, radarRuns[i]);
  });

  FusionStudyResult r;
  r.scenario = scenario.name;
  r.runs = o.runs;
  r.aisVessels = static_cast<int>(vessels.size());
  std::array<std::array<std::vector<double>, kImoErrorCount>, kFusionSourceCount> e1, e3;
  std::array<std::vector<double>, kFusionSourceCount> nees;
  for (std::size_t i = 0; i < fusedRuns.size(); ++i) {
    const RunOut& f = fusedRuns[i];
    r.eligible += f.eligible;
    r.correct += f.correct;
    r.missed += f.missed;
    r.falseAssociations += f.falseAssociations;
    r.swapsNear += f.swapsNear;
    r.swapsFar += f.swapsFar;
    r.associationEvents += f.associated;
    r.dissociationEvents += f.dissociated;
    r.fusedReports += f.fused;
    r.rejectedReports += f.rejected;
    for (std::size_t v = 0; v < vessels.size(); ++v) {
      std::array<Sample, kFusionSourceCount> s = radarRuns[i].samples[v];
      s[0] = f.samples[v][0];
      // Only where all three have a sample: the same vessels at the same stage.
      const bool all1 = s[0].at1 && s[1].at1 && s[2].at1, all3 = s[0].at3 && s[1].at3 && s[2].at3;
      for (int src = 0; src < kFusionSourceCount; ++src) {
        for (int q = 0; q < kImoErrorCount; ++q) {
          if (all1) e1[src][q].push_back((*s[src].at1)[q]);
          if (all3) e3[src][q].push_back((*s[src].at3)[q]);
        }
        if (all3 && std::isfinite(s[src].nees3)) nees[src].push_back(s[src].nees3);
      }
    }
  }
  for (int src = 0; src < kFusionSourceCount; ++src) {
    FusionAccuracy& a = r.accuracy[src];
    for (int q = 0; q < kImoErrorCount; ++q) {
      a.p95At1[q] = percentile95(e1[src][q], kInf);
      a.p95At3[q] = percentile95(e3[src][q], kInf);
    }
    a.samplesAt1 = static_cast<int>(e1[src][0].size());
    a.samplesAt3 = static_cast<int>(e3[src][0].size());
    double sum = 0.0;
    for (double n : nees[src]) sum += n;
    a.meanNeesAt3 = nees[src].empty() ? 0.0 : sum / static_cast<double>(nees[src].size());
  }
  return r;
}

}  // namespace reckoner::studies
