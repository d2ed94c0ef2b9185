#include "radar/radar_image.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>

#include "common/angles.h"

namespace reckoner::radar {

double SweepPose::timeOffsetS(double azRad) const {
  return periodS * wrapTwoPi(azRad) / kTwoPi;
}

double RadarImageParams::azStepRad() const {
  return kTwoPi / azimuths;
}

namespace {

// ---- The radar picture (simulator) ----

/// Azimuth index a taken into [0, azimuths).
int wrapAzimuth(int a, int azimuths) {
  return (a % azimuths + azimuths) % azimuths;
}

/// The echo a beam along one azimuth returns: the range of its first contour (land behind it) and
/// the targets it meets before that (discs, their near side), in metres from own ship.
struct Beam {
  double landM = -1.0;                           ///< -1: no land
  std::vector<std::pair<double, double>> spans;  ///< target echoes [from, to]
};

/// One beam cast from `originM` towards grid azimuth `gridAzRad` against the contours and the targets.
Beam castBeam(const Coastline& coast, const std::vector<RadarTarget>& targets, const est::Vec<2>& originM,
              double gridAzRad, double maxRangeM) {
  Beam b;
  if (const auto hit = coast.firstHit(originM, gridAzRad, maxRangeM)) b.landM = *hit;
  const est::Vec<2> u(std::sin(gridAzRad), std::cos(gridAzRad));
  for (const auto& t : targets) {
    const est::Vec<2> w = t.position - originM;
    const double along = w.dot(u), across2 = w.squaredNorm() - along * along;
    if (along <= 0.0 || across2 > t.radiusM * t.radiusM) continue;
    const double near = along - std::sqrt(t.radiusM * t.radiusM - across2);
    if (b.landM >= 0.0 && near > b.landM) continue;  // behind the land: shadowed
    b.spans.emplace_back(near, near + 2.0 * std::sqrt(t.radiusM * t.radiusM - across2));
  }
  return b;
}

/// The beams of one sweep, each from own ship's pose at its own time, with the sensor's errors. The
/// bearing error turns the direction the beam really looks in away from the azimuth it is drawn at (so
/// each azimuth shows exactly one beam: no two returns compete for one azimuth, which would bias the
/// shore inwards), and the range error shifts all its echoes. Two normal draws per beam, in azimuth
/// order: bearing, then range.
std::vector<Beam> castSweep(const Coastline& coast, const std::vector<RadarTarget>& targets,
                            const SweepPose& pose, const RadarImageParams& p, Rng& rng) {
  const double step = p.azStepRad();
  std::vector<Beam> beams(static_cast<std::size_t>(p.azimuths));
  for (int a = 0; a < p.azimuths; ++a) {
    const double az = step * a;
    const double dt = pose.timeOffsetS(az);
    const est::Vec<2> o = pose.positionAt(dt);
    const double gridAz = pose.headingAt(dt) + az + rng.normal(0.0, p.bearingSdRad);
    const double rangeErrorM = rng.normal(0.0, p.rangeSdM);
    Beam& b = beams[static_cast<std::size_t>(a)];
    b = castBeam(coast, targets, o, gridAz, p.maxRangeM);
    if (b.landM >= 0.0) b.landM += rangeErrorM;
    for (auto& [from, to] : b.spans) {
      from += rangeErrorM;
      to += rangeErrorM;
    }
  }
  return beams;
}

/// Draws echoes into the picture: an echo at [fromM, toM] lights its bins blurred by the pulse. Land
/// marks only unlit bins; a target's echo is drawn over the land's (a ship alongside a quay).
struct EchoPainter {
  PolarImage& img;
  int pulseBins;
  void light(int az, double fromM, double toM, BinSource src) const {
    const int a = wrapAzimuth(az, img.azimuths);
    const int r0 = std::max(0, static_cast<int>(std::floor(fromM / img.binM)));
    const int r1 = std::min(img.rangeBins - 1, static_cast<int>(std::floor(toM / img.binM)) + pulseBins - 1);
    auto* row = &img.bins[static_cast<std::size_t>(a) * static_cast<std::size_t>(img.rangeBins)];
    const auto v = static_cast<std::uint8_t>(src);
    for (int r = r0; r <= r1; ++r)
      if (src == BinSource::Target || !row[r]) row[r] = v;
  }
};

/// The beam integrates over its width: a bin shows an echo when at least half of the beams within half
/// a beam width of it see one there (a half-power detection).
struct HalfPowerWindow {
  const std::vector<Beam>& beams;
  int halfBeam;
  [[nodiscard]] const Beam& beam(int a, int k) const {
    return beams[static_cast<std::size_t>(wrapAzimuth(a + k, static_cast<int>(beams.size())))];
  }
  [[nodiscard]] bool halfSee(int count) const { return 2 * count >= 2 * halfBeam + 1; }
  /// The front of the land at azimuth a: the median of the neighbouring beams' ranges, which follows a
  /// sloping shore without the inward bias that "any beam sees it" would give. `window` is scratch.
  std::optional<double> landFrontM(int a, std::vector<double>& window) const {
    window.clear();
    for (int k = -halfBeam; k <= halfBeam; ++k) {
      const double l = beam(a, k).landM;
      if (l >= 0.0) window.push_back(l);
    }
    if (!halfSee(static_cast<int>(window.size()))) return std::nullopt;
    std::nth_element(window.begin(), window.begin() + static_cast<std::ptrdiff_t>(window.size() / 2),
                     window.end());
    return window[window.size() / 2];
  }
  /// The beams of the window at azimuth a that see a target at about `fromM`.
  [[nodiscard]] int targetBeamsNear(int a, double fromM) const {
    int seen = 0;
    for (int j = -halfBeam; j <= halfBeam; ++j)
      for (const auto& sp : beam(a, j).spans) seen += std::abs(sp.first - fromM) < 60.0 ? 1 : 0;
    return seen;
  }
};

/// Each beam lights what lies within half a beam width of its direction: an echo at azimuth a is seen
/// from a - w to a + w, its range blurred by the pulse.
void drawBeams(const std::vector<Beam>& beams, const RadarImageParams& p, PolarImage& img) {
  const HalfPowerWindow window{
      beams, std::max(0, static_cast<int>(std::lround(0.5 * p.beamWidthRad / p.azStepRad())))};
  const EchoPainter painter{img, std::max(1, static_cast<int>(std::lround(p.pulseLengthM / img.binM)))};
  std::vector<double> scratch;
  for (int a = 0; a < p.azimuths; ++a) {
    if (const auto r = window.landFrontM(a, scratch))
      painter.light(a, *r, *r + p.landDepthM, BinSource::Echo);
    // Targets: the same half-power rule on each disc.
    for (int k = -window.halfBeam; k <= window.halfBeam; ++k)
      for (const auto& [from, to] : window.beam(a, k).spans)
        if (window.halfSee(window.targetBeamsNear(a, from))) painter.light(a, from, to, BinSource::Target);
  }
}

/// Receiver noise and sea clutter (clutter only in front of the first echo: the sea). One uniform draw
/// per bin, azimuth-major.
void addNoiseAndClutter(const RadarImageParams& p, Rng& rng, PolarImage& img) {
  for (int a = 0; a < p.azimuths; ++a) {
    auto* row = &img.bins[static_cast<std::size_t>(a) * static_cast<std::size_t>(p.rangeBins)];
    for (int r = 0; r < p.rangeBins; ++r) {
      const double range = (r + 0.5) * img.binM;
      const double pc = p.clutterProbability * std::exp(-range / p.clutterScaleM);
      if (rng.uniform() < p.noiseProbability + pc && !row[r])
        row[r] = static_cast<std::uint8_t>(BinSource::Noise);
    }
  }
}

// ---- Echo extraction (the paper's preprocessing) ----

/// Lit bins [r0, r1] along the beam at azimuth az.
struct Run {
  int az, r0, r1;
  [[nodiscard]] int bins() const { return r1 - r0 + 1; }
};

/// The runs of every beam, azimuth by azimuth, each beam's sorted by range.
struct BeamRuns {
  std::vector<Run> runs;
  std::vector<std::size_t> rowStart;  ///< the runs of azimuth a are [rowStart[a], rowStart[a + 1])
};

BeamRuns beamRuns(const PolarImage& image) {
  const int A = image.azimuths, R = image.rangeBins;
  BeamRuns out;
  out.rowStart.assign(static_cast<std::size_t>(A) + 1, 0);
  for (int a = 0; a < A; ++a) {
    out.rowStart[static_cast<std::size_t>(a)] = out.runs.size();
    const std::uint8_t* row = &image.bins[static_cast<std::size_t>(a) * static_cast<std::size_t>(R)];
    for (int r = 0; r < R; ++r) {
      if (!row[r]) continue;
      const int r0 = r;
      while (r + 1 < R && row[r + 1]) ++r;
      out.runs.push_back({a, r0, r});
    }
  }
  out.rowStart[static_cast<std::size_t>(A)] = out.runs.size();
  return out;
}

/// Radar objects: the connected sets of runs (runs of neighbouring azimuths that overlap in range;
/// azimuth wraps), found by union-find over the runs. Each object is named by its smallest run index.
struct RadarObjects {
  std::vector<std::uint32_t> rootOf;  ///< per run: its object
  std::vector<int> area;              ///< per object (at its root's index): its area in bins
};

RadarObjects radarObjects(const BeamRuns& br) {
  const auto& runs = br.runs;
  const auto A = static_cast<int>(br.rowStart.size()) - 1;
  std::vector<std::uint32_t> parent(runs.size());
  for (std::uint32_t i = 0; i < parent.size(); ++i) parent[i] = i;
  const auto find = [&parent](std::uint32_t i) {
    while (parent[i] != i) {
      parent[i] = parent[parent[i]];
      i = parent[i];
    }
    return i;
  };
  for (int a = 0; a < A; ++a) {
    const int an = (a + 1) % A;
    std::size_t i = br.rowStart[static_cast<std::size_t>(a)], j = br.rowStart[static_cast<std::size_t>(an)];
    const std::size_t iEnd = br.rowStart[static_cast<std::size_t>(a) + 1],
                      jEnd = br.rowStart[static_cast<std::size_t>(an) + 1];
    while (i < iEnd && j < jEnd) {  // two sorted lists of runs: join the overlapping pairs
      if (runs[i].r1 >= runs[j].r0 && runs[j].r1 >= runs[i].r0) {
        const std::uint32_t x = find(static_cast<std::uint32_t>(i)), y = find(static_cast<std::uint32_t>(j));
        if (x != y) parent[std::max(x, y)] = std::min(x, y);
      }
      if (runs[i].r1 < runs[j].r1)
        ++i;
      else
        ++j;
    }
  }
  RadarObjects out;
  out.rootOf.resize(runs.size());
  out.area.assign(runs.size(), 0);
  for (std::uint32_t i = 0; i < runs.size(); ++i) {
    out.rootOf[i] = find(i);
    out.area[out.rootOf[i]] += runs[i].bins();
  }
  return out;
}

/// One point of an object's front contour: its nearest bin on one beam, and what lit that run.
struct Front {
  std::uint32_t root;
  int az, r;
  std::uint8_t src;
};

/// What lit most of a run's bins (a noise bin just in front of the land joins the land's run).
std::uint8_t runSource(const PolarImage& image, const Run& run) {
  std::array<int, 4> n{};
  const std::uint8_t* row =
      &image.bins[static_cast<std::size_t>(run.az) * static_cast<std::size_t>(image.rangeBins)];
  for (int r = run.r0; r <= run.r1; ++r) ++n[std::min<std::size_t>(row[r], 3)];
  return static_cast<std::uint8_t>(std::max_element(n.begin() + 1, n.end()) - n.begin());
}

/// The front contour: the first run of each object on each beam faces own ship (a second object behind
/// a gap on the same beam is a front too). Small objects are noise; runs shorter than a pulse are not
/// fronts.
std::vector<Front> frontContour(const PolarImage& image, const BeamRuns& br, const RadarObjects& objects,
                                const EchoExtractionParams& params) {
  const auto longEnough = [&](std::size_t k) { return br.runs[k].bins() >= params.minFrontRunBins; };
  std::vector<Front> front;
  for (std::size_t a = 0; a + 1 < br.rowStart.size(); ++a) {
    std::uint32_t last = UINT32_MAX;
    for (std::size_t i = br.rowStart[a]; i < br.rowStart[a + 1]; ++i) {
      const std::uint32_t root = objects.rootOf[i];
      if (objects.area[root] < params.minObjectArea || root == last || !longEnough(i)) continue;
      bool seen = false;  // an earlier front-worthy run of the same object on this beam (around a gap)
      for (std::size_t k = br.rowStart[a]; k < i && !seen; ++k)
        seen = longEnough(k) && objects.rootOf[k] == root;
      if (!seen) front.push_back({root, br.runs[i].az, br.runs[i].r0, runSource(image, br.runs[i])});
      last = root;
    }
  }
  return front;
}

/// Aggregate: contour points of the same object at neighbouring azimuths, k at a time, k chosen for
/// about targetPoints in all; each group gives its mean range and azimuth.
std::vector<EchoPoint> aggregateFront(std::vector<Front> front, const RadarObjects& objects,
                                      const PolarImage& image, double azStepRad, int targetPoints) {
  std::stable_sort(front.begin(), front.end(), [](const Front& x, const Front& y) {
    return x.root != y.root ? x.root < y.root : x.az < y.az;
  });
  const auto k = static_cast<std::size_t>(
      std::max(1.0, std::ceil(static_cast<double>(front.size()) / std::max(1, targetPoints))));
  std::vector<EchoPoint> out;
  std::vector<std::uint32_t> roots;
  std::size_t i = 0;
  while (i < front.size()) {
    std::size_t j = i;
    double sumR = 0.0, sumS = 0.0, sumC = 0.0;
    std::array<int, 4> bySource{};
    while (j < front.size() && j - i < k && front[j].root == front[i].root &&
           (j == i || front[j].az - front[j - 1].az <= 2)) {
      ++bySource[std::min<std::size_t>(front[j].src, 3)];
      sumR += (front[j].r + 0.5) * image.binM;
      sumS += std::sin(front[j].az * azStepRad);
      sumC += std::cos(front[j].az * azStepRad);
      ++j;
    }
    const auto n = static_cast<double>(j - i);
    const auto it = std::find(roots.begin(), roots.end(), front[i].root);
    const int obj = static_cast<int>(it - roots.begin());
    if (it == roots.end()) roots.push_back(front[i].root);
    const auto src =
        static_cast<BinSource>(std::max_element(bySource.begin() + 1, bySource.end()) - bySource.begin());
    out.push_back({sumR / n, wrapTwoPi(std::atan2(sumS, sumC)), obj, objects.area[front[i].root], src});
    i = j;
  }
  return out;
}

}  // namespace

PolarImage simulateRadarImage(const Coastline& coast, const std::vector<RadarTarget>& targets,
                              const SweepPose& pose, const RadarImageParams& p, Rng& rng) {
  PolarImage img;
  img.azimuths = p.azimuths;
  img.rangeBins = p.rangeBins;
  img.binM = p.binM();
  img.bins.assign(static_cast<std::size_t>(p.azimuths) * static_cast<std::size_t>(p.rangeBins), 0);
  const std::vector<Beam> beams = castSweep(coast, targets, pose, p, rng);
  drawBeams(beams, p, img);
  addNoiseAndClutter(p, rng, img);
  return img;
}

std::vector<EchoPoint> extractEchoes(const PolarImage& image, double azStepRad,
                                     const EchoExtractionParams& params) {
  if (image.azimuths <= 0 || image.rangeBins <= 0) return {};
  const BeamRuns runs = beamRuns(image);            // runs of lit bins along each beam
  const RadarObjects objects = radarObjects(runs);  // segmentation into radar objects
  std::vector<Front> front = frontContour(image, runs, objects, params);
  if (front.empty()) return {};
  return aggregateFront(std::move(front), objects, image, azStepRad, params.targetPoints);  // echo points
}

}  // namespace reckoner::radar
