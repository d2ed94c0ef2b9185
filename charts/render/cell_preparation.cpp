// Preparing a cell for drawing: Mercator geometry and the features in drawing order (prepared_cell.h).
#include <algorithm>
#include <utility>

#include "charts/render/prepared_cell.h"

namespace reckoner::charts {

PreparedCell::PreparedCell(CellPtr cell, const PortrayalTable& table) : cell_(std::move(cell)) {
  const auto& features = cell_->features();
  std::vector<std::pair<int, PreparedItem>> ordered;
  ordered.reserve(features.size());
  for (const auto& f : features) {
    if (f.objectClass == "M_COVR") {
      const auto catcov = f.number("CATCOV");
      if (f.geometry.primitive == Primitive::Area && (!catcov || *catcov == 1)) {
        PreparedItem cov;
        addGeometry(f.geometry, cov);
        cov.f = &f;
        coverage_.push_back(cov);
      }
    }
    if (f.objectClass == "DEPCNT")
      if (const auto v = f.number("VALDCO")) contourValues_.push_back(*v);
    const PortrayalRule* r = table.find(f.objectClass, f.geometry.primitive);
    if (!r || f.geometry.parts.empty()) continue;
    PreparedItem it;
    it.f = &f;
    it.rule = r;
    if (const auto s = f.number("SCAMIN"); s && *s > 0) it.scamin = *s;
    addGeometry(f.geometry, it);
    const int layer = f.geometry.primitive == Primitive::Area   ? 0
                      : f.geometry.primitive == Primitive::Line ? 1
                                                                : 2;
    ordered.emplace_back(r->priority * 3 + layer, it);
  }
  std::stable_sort(ordered.begin(), ordered.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  items_.reserve(ordered.size());
  for (auto& [order, it] : ordered) items_.push_back(it);
}

PartSpan appendMercator(std::vector<MercatorPoint>& points, const std::vector<LatLon>& part) {
  PartSpan span;
  span.first = static_cast<std::uint32_t>(points.size());
  span.count = static_cast<std::uint32_t>(part.size());
  span.lo = {1e9, 1e9};
  span.hi = {-1e9, -1e9};
  for (const auto& ll : part) {
    const MercatorPoint m = toMercator(ll);
    points.push_back(m);
    span.lo = {std::min(span.lo.x, m.x), std::min(span.lo.y, m.y)};
    span.hi = {std::max(span.hi.x, m.x), std::max(span.hi.y, m.y)};
  }
  return span;
}

void PreparedCell::addGeometry(const Geometry& g, PreparedItem& it) {
  it.firstPart = static_cast<std::uint32_t>(parts_.size());
  it.lo = {1e9, 1e9};
  it.hi = {-1e9, -1e9};
  for (const auto& part : g.parts) {
    const PartSpan span = appendMercator(points_, part);
    it.lo = {std::min(it.lo.x, span.lo.x), std::min(it.lo.y, span.lo.y)};
    it.hi = {std::max(it.hi.x, span.hi.x), std::max(it.hi.y, span.hi.y)};
    parts_.push_back(span);
  }
  it.partCount = static_cast<std::uint32_t>(g.parts.size());
}

}  // namespace reckoner::charts
