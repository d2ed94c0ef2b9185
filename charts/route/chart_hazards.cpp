#include "charts/route/chart_hazards.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

namespace reckoner::charts {
namespace {

// The areas for which special conditions exist (MSC.232(82) Appendix 5, as S-57 encodes them) other
// than the prohibited and restricted areas: traffic separation schemes and routeing measures,
// anchorages, caution areas, offshore production, seaplane landing, submarine transit lanes, marine
// farms, dumping and incineration grounds.
constexpr std::array<std::string_view, 16> kSpecialAreaClasses = {
    "ACHARE", "CTNARE", "DMPGRD", "DWRTPT", "ICNARE", "ISTZNE", "MARCUL", "OSPARE",
    "PRCARE", "SPLARE", "SUBTLN", "TSEZNE", "TSSCRS", "TSSLPT", "TSSRON", "TWRTPT"};

// RESTRN values (S-57 attribute 131).
constexpr std::int64_t kEntryProhibited = 7, kEntryRestricted = 8, kAreaToBeAvoided = 14;
// WATLEV values: 1 partly submerged at high water, 2 always dry, 4 covers and uncovers.
constexpr std::int64_t kPartlySubmerged = 1, kAlwaysDry = 2, kCoversAndUncovers = 4;

bool contains(const std::vector<std::int64_t>& list, std::int64_t v) {
  return std::find(list.begin(), list.end(), v) != list.end();
}

std::optional<HazardClass> classifyArea(const ChartFeature& f, const SafetySettings& s) {
  const std::string& c = f.objectClass;
  if (c == "DEPARE" || c == "DRGARE") {
    const std::optional<double> drval1 = f.number("DRVAL1");
    // no DRVAL1: depth unknown, so not known to be safe
    if (!drval1 || *drval1 < s.safetyContourM) return HazardClass{HazardKind::SafetyContour, drval1};
    return std::nullopt;
  }
  if (c == "UNSARE") return HazardClass{HazardKind::SafetyContour, std::nullopt};
  if (c == "RESARE") {
    const std::vector<std::int64_t> restrn = f.list("RESTRN");
    if (contains(restrn, kEntryProhibited) || contains(restrn, kAreaToBeAvoided)) {
      return HazardClass{HazardKind::Prohibited, std::nullopt};
    }
    if (contains(restrn, kEntryRestricted)) return HazardClass{HazardKind::Restricted, std::nullopt};
    if (s.specialAreas) return HazardClass{HazardKind::SpecialArea, std::nullopt};
    return std::nullopt;
  }
  if (c == "MIPARE") return HazardClass{HazardKind::Restricted, std::nullopt};
  if (s.specialAreas &&
      std::find(kSpecialAreaClasses.begin(), kSpecialAreaClasses.end(), c) != kSpecialAreaClasses.end()) {
    return HazardClass{HazardKind::SpecialArea, std::nullopt};
  }
  return std::nullopt;
}

/// Twice the signed area of the polygon (positive counter-clockwise).
double signedArea2(std::span<const MercatorPoint> poly) {
  double a = 0.0;
  for (std::size_t i = 0, n = poly.size(); i < n; ++i) {
    const MercatorPoint& p = poly[i];
    const MercatorPoint& q = poly[(i + 1) % n];
    a += p.x * q.y - q.x * p.y;
  }
  return a;
}

/// Cyrus-Beck: the part [t0, t1] of segment a-b inside the convex polygon (winding sign `orient`);
/// false when none.
bool clipToConvex(MercatorPoint a, MercatorPoint b, std::span<const MercatorPoint> poly, double orient,
                  double& t0, double& t1) {
  t0 = 0.0;
  t1 = 1.0;
  const double dx = b.x - a.x, dy = b.y - a.y;
  for (std::size_t i = 0, n = poly.size(); i < n; ++i) {
    const MercatorPoint& v = poly[i];
    const MercatorPoint& w = poly[(i + 1) % n];
    const double ex = w.x - v.x, ey = w.y - v.y;
    const double num = orient * (ex * (a.y - v.y) - ey * (a.x - v.x));  // >= 0: a is inside this edge
    const double den = orient * (ex * dy - ey * dx);
    if (den == 0.0) {
      if (num < 0.0) return false;
      continue;
    }
    const double t = -num / den;
    if (den > 0.0) {
      t0 = std::max(t0, t);
    } else {
      t1 = std::min(t1, t);
    }
    if (t0 > t1) return false;
  }
  return true;
}

}  // namespace

const char* hazardKindName(HazardKind kind) {
  switch (kind) {
    case HazardKind::SafetyContour:
      return "safety_contour";
    case HazardKind::Land:
      return "land";
    case HazardKind::Danger:
      return "danger";
    case HazardKind::Prohibited:
      return "prohibited_area";
    case HazardKind::Restricted:
      return "restricted_area";
    case HazardKind::SpecialArea:
      return "special_area";
  }
  return "unknown";
}

std::optional<HazardClass> classifyHazard(const ChartFeature& f, const SafetySettings& s) {
  const std::string& c = f.objectClass;
  if (c == "LNDARE") return HazardClass{HazardKind::Land, std::nullopt};
  if (c == "WRECKS" || c == "OBSTRN" || c == "UWTROC") {
    const std::optional<double> valsou = f.number("VALSOU");
    const std::optional<double> watlev = f.number("WATLEV");
    const bool dries =
        watlev && (*watlev == kPartlySubmerged || *watlev == kAlwaysDry || *watlev == kCoversAndUncovers);
    if (dries || !valsou || *valsou < s.dangerDepthM()) return HazardClass{HazardKind::Danger, valsou};
    return std::nullopt;
  }
  if (f.geometry.primitive != Primitive::Area) return std::nullopt;
  return classifyArea(f, s);
}

ChartHazards::ChartHazards(std::vector<CellPtr> cells, const SafetySettings& settings)
    : cells_(std::move(cells)), settings_(settings) {
  for (std::size_t ci = 0; ci < cells_.size(); ++ci) {
    for (const ChartFeature& f : cells_[ci]->features()) {
      if (f.geometry.parts.empty()) continue;
      const std::optional<HazardClass> hc = classifyHazard(f, settings_);
      if (!hc) continue;
      const auto index = static_cast<std::uint32_t>(hazards_.size());
      hazards_.push_back({hc->kind, hc->depthM, static_cast<std::uint32_t>(ci), &f});
      addFeature(index, f.geometry);
    }
  }
  if (edges_.empty()) return;
  std::vector<geo::GridBox> boxes;
  boxes.reserve(edges_.size());
  geo::GridBox all{edges_[0].a.x, edges_[0].a.y, edges_[0].a.x, edges_[0].a.y};
  for (const Edge& e : edges_) {
    const geo::GridBox b{std::min(e.a.x, e.b.x), std::min(e.a.y, e.b.y), std::max(e.a.x, e.b.x),
                         std::max(e.a.y, e.b.y)};
    all = {std::min(all.x0, b.x0), std::min(all.y0, b.y0), std::max(all.x1, b.x1), std::max(all.y1, b.y1)};
    boxes.push_back(b);
  }
  // About four edges a cell where they were spread evenly, and no more than 2048 cells across.
  const double w = std::max(all.x1 - all.x0, 1e-9), h = std::max(all.y1 - all.y0, 1e-9);
  const double even = std::sqrt(w * h / std::max(1.0, static_cast<double>(edges_.size()) / 4.0));
  grid_ = geo::GridIndex(std::max(even, std::max(w, h) / 2048.0), boxes);
}

void ChartHazards::addFeature(std::uint32_t hazard, const Geometry& g) {
  const bool area = g.primitive == Primitive::Area;
  for (const auto& part : g.parts) {
    if (g.primitive == Primitive::Point || part.size() == 1) {
      for (const LatLon& p : part) {
        const MercatorPoint m = toMercator(p);
        edges_.push_back({m, m, hazard, false});
      }
      continue;
    }
    for (std::size_t i = 1; i < part.size(); ++i) {
      edges_.push_back({toMercator(part[i - 1]), toMercator(part[i]), hazard, area});
    }
    // rings as GDAL gives them are closed; close one that is not
    if (area && (part.front().latDeg != part.back().latDeg || part.front().lonDeg != part.back().lonDeg)) {
      edges_.push_back({toMercator(part.back()), toMercator(part.front()), hazard, true});
    }
  }
}

void ChartHazards::touching(std::span<const MercatorPoint> poly, std::vector<HazardContact>& out,
                            std::span<const std::uint8_t> skip) const {
  if (grid_.empty() || poly.size() < 3) return;
  const double orient = signedArea2(poly) >= 0.0 ? 1.0 : -1.0;
  double x0 = poly[0].x, x1 = poly[0].x, y0 = poly[0].y, y1 = poly[0].y;
  for (const MercatorPoint& p : poly) {
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  }
  const std::size_t first = out.size();
  const MercatorPoint o = poly[0];
  std::vector<double> bestDist2;
  // An edge in several cells is met once per cell: the same contact again, harmless and cheaper than
  // sorting the candidates to drop the repeats.
  const auto visit = [&](const Edge& e) {
    if (std::max(e.a.x, e.b.x) < x0 || std::min(e.a.x, e.b.x) > x1 || std::max(e.a.y, e.b.y) < y0 ||
        std::min(e.a.y, e.b.y) > y1 || (!skip.empty() && skip[e.hazard] != 0)) {
      return;
    }
    double t0 = 0.0, t1 = 1.0;
    if (!clipToConvex(e.a, e.b, poly, orient, t0, t1)) return;
    // the point of the clipped part nearest poly[0]
    const double dx = e.b.x - e.a.x, dy = e.b.y - e.a.y, len2 = dx * dx + dy * dy;
    const double t = len2 > 0.0 ? std::clamp(((o.x - e.a.x) * dx + (o.y - e.a.y) * dy) / len2, t0, t1) : 0.0;
    const MercatorPoint at{e.a.x + t * dx, e.a.y + t * dy};
    const double d2 = (at.x - o.x) * (at.x - o.x) + (at.y - o.y) * (at.y - o.y);
    std::size_t k = first;
    while (k < out.size() && out[k].hazard != e.hazard) ++k;
    if (k == out.size()) {
      out.push_back({e.hazard, at});
      bestDist2.push_back(d2);
    } else if (d2 < bestDist2[k - first]) {
      out[k].at = at;
      bestDist2[k - first] = d2;
    }
  };
  const std::int64_t ix0 = std::max(grid_.cellOf(x0), grid_.minX()),
                     ix1 = std::min(grid_.cellOf(x1), grid_.maxX());
  const std::int64_t iy0 = std::max(grid_.cellOf(y0), grid_.minY()),
                     iy1 = std::min(grid_.cellOf(y1), grid_.maxY());
  for (std::int64_t iy = iy0; iy <= iy1; ++iy) {
    for (std::int64_t ix = ix0; ix <= ix1; ++ix) {
      for (const std::uint32_t ei : grid_.cell(ix, iy)) visit(edges_[ei]);
    }
  }
}

void ChartHazards::containing(MercatorPoint p, std::vector<std::uint32_t>& out) const {
  if (grid_.empty()) return;
  const std::int64_t iy = grid_.cellOf(p.y);
  if (iy < grid_.minY() || iy > grid_.maxY()) return;
  std::vector<std::uint32_t> crossings;
  for (std::int64_t ix = std::max(grid_.cellOf(p.x), grid_.minX()); ix <= grid_.maxX(); ++ix) {
    for (const std::uint32_t ei : grid_.cell(ix, iy)) {
      const Edge& e = edges_[ei];
      if (!e.area || (e.a.y > p.y) == (e.b.y > p.y)) continue;
      const double x = std::clamp(e.a.x + (p.y - e.a.y) * (e.b.x - e.a.x) / (e.b.y - e.a.y),
                                  std::min(e.a.x, e.b.x), std::max(e.a.x, e.b.x));
      // each crossing once: in the cell that holds it
      if (x < p.x || grid_.cellOf(x) != ix) continue;
      crossings.push_back(e.hazard);
    }
  }
  std::sort(crossings.begin(), crossings.end());
  for (std::size_t i = 0; i < crossings.size();) {
    std::size_t j = i;
    while (j < crossings.size() && crossings[j] == crossings[i]) ++j;
    if ((j - i) % 2 == 1) out.push_back(crossings[i]);
    i = j;
  }
}

}  // namespace reckoner::charts
