#include "charts/route/chart_safety.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/angles.h"
#include "estimation/chi_square.h"

namespace reckoner::charts {
namespace {

constexpr double kSphereRadiusM = 6378137.0;  // the spherical Mercator of the chart (viewport.h)
constexpr double kMinHalfWidthM = 0.01;       // a path of no width is checked as a centimetre's strip
constexpr double kMinGroundingRadiusM = 5.0;

bool isArea(HazardKind k) {
  return k == HazardKind::SafetyContour || k == HazardKind::Land || k == HazardKind::Prohibited;
}

/// Grid to Mercator about each step's mean: m(p) = m0 + J (p - p0).
struct StepMap {
  MercatorPoint m0;
  geo::GridPoint p0;
  double j[2][2] = {{0, 0}, {0, 0}};
  double mPerUnit = 1.0;  // ground metres per Mercator unit here
  [[nodiscard]] MercatorPoint operator()(const geo::GridPoint& p) const {
    const double dx = p.xM - p0.xM, dy = p.yM - p0.yM;
    return {m0.x + j[0][0] * dx + j[0][1] * dy, m0.y + j[1][0] * dx + j[1][1] * dy};
  }
};

MercatorPoint mercatorOf(const geo::LocalFrame& frame, const geo::GridPoint& p) {
  const geo::GeoPoint g = frame.toGeodetic(p);
  return toMercator({g.latDeg, g.lonDeg});
}

StepMap stepMap(const geo::LocalFrame& frame, const geo::GridPoint& p0) {
  StepMap s;
  s.p0 = p0;
  s.m0 = mercatorOf(frame, p0);
  const MercatorPoint ex = mercatorOf(frame, {p0.xM + 1.0, p0.yM});
  const MercatorPoint ey = mercatorOf(frame, {p0.xM, p0.yM + 1.0});
  s.j[0][0] = ex.x - s.m0.x, s.j[1][0] = ex.y - s.m0.y;
  s.j[0][1] = ey.x - s.m0.x, s.j[1][1] = ey.y - s.m0.y;
  s.mPerUnit = 1.0 / std::hypot(s.j[0][0], s.j[1][0]);
  return s;
}

/// The quadrilateral about segment a-b, halfWidth Mercator units to each side.
std::array<MercatorPoint, 4> strip(MercatorPoint a, MercatorPoint b, double halfWidth) {
  double nx = a.y - b.y, ny = b.x - a.x;
  const double len = std::hypot(nx, ny);
  if (len > 0.0) {
    nx *= halfWidth / len, ny *= halfWidth / len;
  } else {
    nx = halfWidth, ny = 0.0;  // a path standing still: a square about the point
    a.x -= halfWidth, b.x += halfWidth;
  }
  return {{{a.x - nx, a.y - ny}, {a.x + nx, a.y + ny}, {b.x + nx, b.y + ny}, {b.x - nx, b.y - ny}}};
}

std::vector<MercatorPoint> convexHull(std::vector<MercatorPoint> pts) {
  std::sort(pts.begin(), pts.end(),
            [](const auto& a, const auto& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  if (pts.size() < 3) return pts;
  const auto cross = [](const MercatorPoint& o, const MercatorPoint& a, const MercatorPoint& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  std::vector<MercatorPoint> h(2 * pts.size());
  std::size_t k = 0;
  for (const auto& p : pts) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p) <= 0) --k;
    h[k++] = p;
  }
  for (std::size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(h[k - 2], h[k - 1], pts[i]) <= 0) --k;
    h[k++] = pts[i];
  }
  h.resize(k - 1);
  return h;
}

/// The 95% position ellipses at every step, their hull.
std::vector<MercatorPoint> lookAheadArea(const nav::LookAheadPrediction& p,
                                         const std::vector<StepMap>& maps) {
  static const double k95 = std::sqrt(est::chiSquareQuantile(0.95, 2.0));
  std::vector<MercatorPoint> pts;
  for (std::size_t k = 0; k < p.timesS.size(); ++k) {
    const Eigen::SelfAdjointEigenSolver<est::Mat<2>> eig(p.covariance[k]);
    const est::Vec<2> r = eig.eigenvalues().cwiseMax(0.0).cwiseSqrt() * k95;
    for (int a = 0; a < 16; ++a) {
      const double th = kTwoPi * a / 16.0;
      const est::Vec<2> d = eig.eigenvectors() * est::Vec<2>(r[0] * std::cos(th), r[1] * std::sin(th));
      pts.push_back(maps[k]({p.mean[k].xM + d[0], p.mean[k].yM + d[1]}));
    }
  }
  return convexHull(std::move(pts));
}

/// What one sampled path meets first.
struct PathOutcome {
  std::optional<std::uint32_t> areaHazard, danger;
  double crossingS = 0.0;
};

class PathFollower {
 public:
  PathFollower(const ChartHazards& hazards, const AntiGroundingSettings& s, std::vector<std::uint8_t> skip)
      : hazards_(hazards), settings_(s), skip_(std::move(skip)) {}

  PathOutcome follow(const std::vector<MercatorPoint>& path, const std::vector<StepMap>& maps,
                     const std::vector<double>& timesS) {
    PathOutcome out;
    holding_.clear();
    hazards_.containing(path[0], holding_);
    for (const std::uint32_t h : holding_) {
      if (isArea(hazards_.hazards()[h].kind)) {
        out.areaHazard = h;
        break;
      }
    }
    for (std::size_t k = 0; k + 1 < path.size() && !(out.areaHazard && out.danger); ++k) {
      const double unit = 1.0 / maps[k].mPerUnit;
      const double wide = std::max({settings_.dangerClearanceM, settings_.halfBeamM, kMinHalfWidthM}) * unit;
      contacts_.clear();
      const auto quad = strip(path[k], path[k + 1], wide);
      hazards_.touching(quad, contacts_, skip_);
      bool areaNear = false;
      for (const HazardContact& c : contacts_) {
        const HazardKind kind = hazards_.hazards()[c.hazard].kind;
        if (kind == HazardKind::Danger && !out.danger) out.danger = c.hazard;
        areaNear = areaNear || isArea(kind);
      }
      if (out.areaHazard || !areaNear) continue;
      contacts_.clear();
      const auto thin = strip(path[k], path[k + 1], std::max(settings_.halfBeamM, kMinHalfWidthM) * unit);
      hazards_.touching(thin, contacts_, skip_);
      for (const HazardContact& c : contacts_) {
        if (!isArea(hazards_.hazards()[c.hazard].kind)) continue;
        out.areaHazard = c.hazard;
        // when along the step: the contact's share of the step
        const double len = std::hypot(path[k + 1].x - path[k].x, path[k + 1].y - path[k].y);
        const double f = len > 0.0 ? std::hypot(c.at.x - path[k].x, c.at.y - path[k].y) / len : 0.0;
        out.crossingS = timesS[k] + std::min(1.0, f) * (timesS[k + 1] - timesS[k]);
        break;
      }
    }
    return out;
  }

 private:
  const ChartHazards& hazards_;
  const AntiGroundingSettings& settings_;
  std::vector<std::uint8_t> skip_;
  std::vector<std::uint32_t> holding_;
  std::vector<HazardContact> contacts_;
};

/// The hazards that may matter: those meeting the box of every path point, widened by the clearance.
std::vector<std::uint8_t> candidateMask(const ChartHazards& hazards,
                                        const std::vector<std::vector<MercatorPoint>>& paths,
                                        double marginUnits) {
  double x0 = paths[0][0].x, x1 = x0, y0 = paths[0][0].y, y1 = y0;
  for (const auto& path : paths)
    for (const auto& p : path)
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  x0 -= marginUnits, x1 += marginUnits, y0 -= marginUnits, y1 += marginUnits;
  const std::array<MercatorPoint, 4> box{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}};
  std::vector<HazardContact> contacts;
  hazards.touching(box, contacts);
  std::vector<std::uint32_t> holding;
  hazards.containing({0.5 * (x0 + x1), 0.5 * (y0 + y1)}, holding);
  std::vector<std::uint8_t> skip(hazards.hazards().size(), 1);
  for (const auto& c : contacts) skip[c.hazard] = 0;
  for (const auto h : holding) skip[h] = 0;
  for (std::size_t h = 0; h < skip.size(); ++h) {
    const HazardKind k = hazards.hazards()[h].kind;
    if (!isArea(k) && k != HazardKind::Danger) skip[h] = 1;
  }
  return skip;
}

}  // namespace

std::vector<std::string> AntiGroundingSettings::problems() const {
  std::vector<std::string> out;
  if (!std::isfinite(safety.safetyContourM)) out.emplace_back("safety contour must be finite");
  if (!(draughtM > 0.0 && draughtM < 100.0)) out.emplace_back("draught must be in (0, 100) m");
  if (!(dangerClearanceM >= 0.0 && dangerClearanceM < 10000.0))
    out.emplace_back("danger clearance must be in [0, 10000) m");
  if (!(halfBeamM >= 0.0 && halfBeamM < 100.0)) out.emplace_back("half-beam must be in [0, 100) m");
  return out;
}

AntiGroundingSettings antiGroundingSettingsOf(const sim::VoyageSpec& v) {
  AntiGroundingSettings g;
  g.safety.safetyContourM = v.safetyContourM;
  g.safety.safetyDepthM = v.safetyDepthM;
  g.draughtM = v.draughtM;
  g.dangerClearanceM = v.dangerClearanceM;
  g.halfBeamM = v.halfBeamM;
  return g;
}

ChartSafety::ChartSafety(const std::vector<CellPtr>& cells, const AntiGroundingSettings& settings)
    : settings_(settings),
      hazards_(cells, settings.safety),
      grounding_(cells, SafetySettings{settings.draughtM, settings.draughtM, false}) {
  if (const auto p = settings.problems(); !p.empty()) throw std::invalid_argument(p.front());
}

sim::GroundingOutlook ChartSafety::outlook(const nav::LookAheadPrediction& prediction,
                                           const geo::LocalFrame& frame) const {
  sim::GroundingOutlook out;
  out.timeUs = prediction.t0Us;
  if (!prediction.valid || prediction.paths.empty() || prediction.timesS.size() < 2) return out;
  out.horizonS = prediction.timesS.back();
  std::vector<StepMap> maps;
  for (const auto& m : prediction.mean) maps.push_back(stepMap(frame, m));
  std::vector<std::vector<MercatorPoint>> paths(prediction.paths.size());
  for (std::size_t i = 0; i < paths.size(); ++i)
    for (std::size_t k = 0; k < prediction.timesS.size(); ++k)
      paths[i].push_back(maps[k](prediction.paths[i][k]));
  const double margin = std::max(settings_.dangerClearanceM, settings_.halfBeamM) / maps[0].mPerUnit;
  PathFollower follower(hazards_, settings_, candidateMask(hazards_, paths, margin));
  std::vector<double> crossings;
  std::vector<int> firstHits(hazards_.hazards().size(), 0);
  int dangers = 0;
  for (const auto& path : paths) {
    const PathOutcome o = follower.follow(path, maps, prediction.timesS);
    if (o.areaHazard) {
      crossings.push_back(o.crossingS);
      ++firstHits[*o.areaHazard];
    }
    if (o.danger) {
      ++dangers;
      ++firstHits[*o.danger];
    }
  }
  const auto n = static_cast<double>(paths.size());
  out.crossingProbability = static_cast<double>(crossings.size()) / n;
  out.dangerProbability = dangers / n;
  if (!crossings.empty()) {
    std::nth_element(crossings.begin(), crossings.begin() + static_cast<std::ptrdiff_t>(crossings.size() / 2),
                     crossings.end());
    out.medianCrossingS = crossings[crossings.size() / 2];
  }
  const std::vector<MercatorPoint> area = lookAheadArea(prediction, maps);
  for (const auto& m : area) {
    const LatLon g = fromMercator(m);
    out.area.push_back({g.latDeg, g.lonDeg});
  }
  std::vector<HazardContact> contacts;
  if (area.size() >= 3) hazards_.touching(area, contacts);
  std::vector<std::uint32_t> holding;
  hazards_.containing(paths[0][0], holding);
  for (const auto h : holding)
    if (std::none_of(contacts.begin(), contacts.end(), [h](const HazardContact& c) { return c.hazard == h; }))
      contacts.push_back({h, maps[0].m0});
  for (const HazardContact& c : contacts) {
    const Hazard& h = hazards_.hazards()[c.hazard];
    const LatLon g = fromMercator(c.at);
    out.ahead.push_back({hazardKindName(h.kind),
                         h.feature->objectClass,
                         hazards_.cells()[h.cell]->info().name,
                         h.feature->lnam,
                         {g.latDeg, g.lonDeg},
                         h.depthM,
                         firstHits[c.hazard] / n});
  }
  std::stable_sort(out.ahead.begin(), out.ahead.end(),
                   [](const auto& a, const auto& b) { return a.probability > b.probability; });
  out.valid = true;
  return out;
}

std::optional<sim::Grounding> ChartSafety::grounding(const geo::GeoPoint& p) const {
  if (!std::isfinite(p.latDeg) || !std::isfinite(p.lonDeg)) return std::nullopt;
  const MercatorPoint m = toMercator({p.latDeg, p.lonDeg});
  const auto found = [&](const Hazard& h) {
    char depth[32] = "";
    if (h.depthM) std::snprintf(depth, sizeof depth, " %.1f m", *h.depthM);
    const std::string what = h.kind == HazardKind::Land     ? "land"
                             : h.kind == HazardKind::Danger ? "danger"
                                                            : "depth area";
    return sim::Grounding{what + depth + " (" + h.feature->objectClass + ")", h.feature->objectClass,
                          h.feature->lnam, h.depthM};
  };
  std::vector<std::uint32_t> holding;
  grounding_.containing(m, holding);
  for (const std::uint32_t i : holding) {
    const Hazard& h = grounding_.hazards()[i];
    if (h.kind == HazardKind::Land || (h.kind == HazardKind::SafetyContour && h.depthM)) return found(h);
  }
  const double r =
      std::max(settings_.halfBeamM, kMinGroundingRadiusM) / (kSphereRadiusM * std::cos(degToRad(p.latDeg)));
  const std::array<MercatorPoint, 4> box{
      {{m.x - r, m.y - r}, {m.x + r, m.y - r}, {m.x + r, m.y + r}, {m.x - r, m.y + r}}};
  std::vector<HazardContact> contacts;
  grounding_.touching(box, contacts);
  for (const HazardContact& c : contacts) {
    const Hazard& h = grounding_.hazards()[c.hazard];
    if (h.kind == HazardKind::Danger) return found(h);
  }
  return std::nullopt;
}

}  // namespace reckoner::charts
