#include "radar/radar_image.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>

#include "common/angles.h"

namespace reckoner::radar {

double SweepPose::timeOffsetS(double azRad) const {
  return periodS * wrapTwoPi(azRad) / kTwoPi;
}

double RadarImageParams::azStepRad() const {
  return kTwoPi / azimuths;
}

PolarImage simulateRadarImage(const Coastline& coast, const std::vector<RadarTarget>& targets,
                              const SweepPose& pose, const RadarImageParams& p, Rng& rng) {
  PolarImage img;
  img.azimuths = p.azimuths;
  img.rangeBins = p.rangeBins;
  img.binM = p.binM();
  img.bins.assign(static_cast<std::size_t>(p.azimuths) * static_cast<std::size_t>(p.rangeBins), 0);
  const double step = p.azStepRad();
  // The echo a beam along each azimuth returns: the range of its first contour (land behind it) and
  // the targets it meets before that (discs, their near side).
  struct Beam {
    double landM = -1.0;
    std::vector<std::pair<double, double>> spans;  ///< target echoes [from, to] in metres
  };
  // The sensor's errors, per beam: the bearing error turns the direction the beam really looks in away
  // from the azimuth it is drawn at (so each azimuth shows exactly one beam: no two returns compete for
  // one azimuth, which would bias the shore inwards), and the range error shifts all its echoes.
  std::vector<Beam> beams(static_cast<std::size_t>(p.azimuths));
  std::vector<double> rangeError(static_cast<std::size_t>(p.azimuths));
  for (int a = 0; a < p.azimuths; ++a) {
    const double az = step * a;
    const double dt = pose.timeOffsetS(az);
    const est::Vec<2> o = pose.positionAt(dt);
    const double gridAz = pose.headingAt(dt) + az + rng.normal(0.0, p.bearingSdRad);
    rangeError[static_cast<std::size_t>(a)] = rng.normal(0.0, p.rangeSdM);
    Beam& b = beams[static_cast<std::size_t>(a)];
    if (const auto hit = coast.firstHit(o, gridAz, p.maxRangeM)) b.landM = *hit;
    const est::Vec<2> u(std::sin(gridAz), std::cos(gridAz));
    for (const auto& t : targets) {
      const est::Vec<2> w = t.position - o;
      const double along = w.dot(u), across2 = w.squaredNorm() - along * along;
      if (along <= 0.0 || across2 > t.radiusM * t.radiusM) continue;
      const double near = along - std::sqrt(t.radiusM * t.radiusM - across2);
      if (b.landM >= 0.0 && near > b.landM) continue;  // behind the land: shadowed
      b.spans.emplace_back(near, near + 2.0 * std::sqrt(t.radiusM * t.radiusM - across2));
    }
  }
  // Each beam lights what lies within half a beam width of its direction: an echo at azimuth a is seen
  // from a - w to a + w, its range blurred by the pulse and jittered by the sensor's errors.
  const int halfBeam = std::max(0, static_cast<int>(std::lround(0.5 * p.beamWidthRad / step)));
  const int pulseBins = std::max(1, static_cast<int>(std::lround(p.pulseLengthM / img.binM)));
  // Land marks only unlit bins; a target's echo is drawn over the land's (a ship alongside a quay).
  const auto light = [&](int az, double fromM, double toM, BinSource src) {
    const int a = ((az % p.azimuths) + p.azimuths) % p.azimuths;
    const int r0 = std::max(0, static_cast<int>(std::floor(fromM / img.binM)));
    const int r1 = std::min(p.rangeBins - 1, static_cast<int>(std::floor(toM / img.binM)) + pulseBins - 1);
    auto* row = &img.bins[static_cast<std::size_t>(a) * static_cast<std::size_t>(p.rangeBins)];
    const auto v = static_cast<std::uint8_t>(src);
    for (int r = r0; r <= r1; ++r)
      if (src == BinSource::Target || !row[r]) row[r] = v;
  };
  std::vector<double> land(static_cast<std::size_t>(p.azimuths), -1.0);
  for (int a = 0; a < p.azimuths; ++a) {
    Beam& b = beams[static_cast<std::size_t>(a)];
    const double dr = rangeError[static_cast<std::size_t>(a)];
    if (b.landM >= 0.0) land[static_cast<std::size_t>(a)] = b.landM + dr;
    for (auto& [from, to] : b.spans) {
      from += dr;
      to += dr;
    }
  }
  // The beam integrates over its width: a bin shows an echo when at least half of the beams within
  // half a beam width of it see one there (a half-power detection). The front of the land at azimuth
  // a is then the median of the neighbouring beams' ranges, which follows a sloping shore without the
  // inward bias that "any beam sees it" would give.
  std::vector<double> window;
  for (int a = 0; a < p.azimuths; ++a) {
    window.clear();
    for (int k = -halfBeam; k <= halfBeam; ++k) {
      const double l = land[static_cast<std::size_t>(((a + k) % p.azimuths + p.azimuths) % p.azimuths)];
      if (l >= 0.0) window.push_back(l);
    }
    if (2 * static_cast<int>(window.size()) >= 2 * halfBeam + 1) {
      std::nth_element(window.begin(), window.begin() + static_cast<std::ptrdiff_t>(window.size() / 2),
                       window.end());
      const double r = window[window.size() / 2];
      light(a, r, r + p.landDepthM, BinSource::Echo);
    }
    // Targets: the same half-power rule on each disc.
    for (int k = -halfBeam; k <= halfBeam; ++k) {
      const Beam& nb = beams[static_cast<std::size_t>(((a + k) % p.azimuths + p.azimuths) % p.azimuths)];
      for (const auto& [from, to] : nb.spans) {
        // Count the beams of the window that see a target at about this range.
        int seen = 0;
        for (int j = -halfBeam; j <= halfBeam; ++j) {
          const Beam& ob = beams[static_cast<std::size_t>(((a + j) % p.azimuths + p.azimuths) % p.azimuths)];
          for (const auto& sp : ob.spans) seen += std::abs(sp.first - from) < 60.0 ? 1 : 0;
        }
        if (2 * seen >= 2 * halfBeam + 1) light(a, from, to, BinSource::Target);
      }
    }
  }
  // Receiver noise and sea clutter (clutter only in front of the first echo: the sea).
  for (int a = 0; a < p.azimuths; ++a) {
    auto* row = &img.bins[static_cast<std::size_t>(a) * static_cast<std::size_t>(p.rangeBins)];
    for (int r = 0; r < p.rangeBins; ++r) {
      const double range = (r + 0.5) * img.binM;
      const double pc = p.clutterProbability * std::exp(-range / p.clutterScaleM);
      if (rng.uniform() < p.noiseProbability + pc && !row[r])
        row[r] = static_cast<std::uint8_t>(BinSource::Noise);
    }
  }
  return img;
}

std::vector<EchoPoint> extractEchoes(const PolarImage& image, double azStepRad,
                                     const EchoExtractionParams& params) {
  const int A = image.azimuths, R = image.rangeBins;
  if (A <= 0 || R <= 0) return {};
  // Runs of lit bins along each beam; radar objects are the connected sets of runs (runs of
  // neighbouring azimuths that overlap in range; azimuth wraps), found by union-find over the runs.
  struct Run {
    int az, r0, r1;  ///< bins [r0, r1]
  };
  std::vector<Run> runs;
  std::vector<std::size_t> rowStart(static_cast<std::size_t>(A) + 1, 0);
  for (int a = 0; a < A; ++a) {
    rowStart[static_cast<std::size_t>(a)] = runs.size();
    const std::uint8_t* row = &image.bins[static_cast<std::size_t>(a) * static_cast<std::size_t>(R)];
    for (int r = 0; r < R; ++r) {
      if (!row[r]) continue;
      const int r0 = r;
      while (r + 1 < R && row[r + 1]) ++r;
      runs.push_back({a, r0, r});
    }
  }
  rowStart[static_cast<std::size_t>(A)] = runs.size();
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
    std::size_t i = rowStart[static_cast<std::size_t>(a)], j = rowStart[static_cast<std::size_t>(an)];
    const std::size_t iEnd = rowStart[static_cast<std::size_t>(a) + 1],
                      jEnd = rowStart[static_cast<std::size_t>(an) + 1];
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
  std::vector<int> area(runs.size(), 0);
  for (std::uint32_t i = 0; i < runs.size(); ++i) area[find(i)] += runs[i].r1 - runs[i].r0 + 1;
  // The front contour: the first run of each object on each beam faces own ship (a second object
  // behind a gap on the same beam is a front too). Runs shorter than a pulse are not fronts.
  struct Front {
    std::uint32_t root;
    int az, r;
    std::uint8_t src;
  };
  std::vector<Front> front;
  // What lit most of a run's bins (a noise bin just in front of the land joins the land's run).
  const auto runSource = [&image, R](int a, const Run& run) {
    std::array<int, 4> n{};
    const std::uint8_t* row = &image.bins[static_cast<std::size_t>(a) * static_cast<std::size_t>(R)];
    for (int r = run.r0; r <= run.r1; ++r) ++n[std::min<std::size_t>(row[r], 3)];
    return static_cast<std::uint8_t>(std::max_element(n.begin() + 1, n.end()) - n.begin());
  };
  for (int a = 0; a < A; ++a) {
    std::uint32_t last = UINT32_MAX;
    for (std::size_t i = rowStart[static_cast<std::size_t>(a)]; i < rowStart[static_cast<std::size_t>(a) + 1];
         ++i) {
      const std::uint32_t root = find(static_cast<std::uint32_t>(i));
      const auto longEnough = [&](std::size_t k) {
        return runs[k].r1 - runs[k].r0 + 1 >= params.minFrontRunBins;
      };
      if (area[root] < params.minObjectArea || root == last || !longEnough(i)) continue;
      bool seen = false;  // an earlier front-worthy run of the same object on this beam (around a gap)
      for (std::size_t k = rowStart[static_cast<std::size_t>(a)]; k < i && !seen; ++k)
        seen = longEnough(k) && find(static_cast<std::uint32_t>(k)) == root;
      if (!seen) front.push_back({root, a, runs[i].r0, runSource(a, runs[i])});
      last = root;
    }
  }
  if (front.empty()) return {};
  // Aggregate: contour points of the same object at neighbouring azimuths, k at a time, k chosen for
  // about targetPoints in all; each group gives its mean range and azimuth.
  std::stable_sort(front.begin(), front.end(), [](const Front& x, const Front& y) {
    return x.root != y.root ? x.root < y.root : x.az < y.az;
  });
  const auto k = static_cast<std::size_t>(
      std::max(1.0, std::ceil(static_cast<double>(front.size()) / std::max(1, params.targetPoints))));
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
    out.push_back({sumR / n, wrapTwoPi(std::atan2(sumS, sumC)), obj, area[front[i].root], src});
    i = j;
  }
  return out;
}

}  // namespace reckoner::radar
