#include "charts/model/chart_model.h"

#include <algorithm>
#include <map>

namespace reckoner::charts {

void Bounds::add(const LatLon& p) {
  minLatDeg = std::min(minLatDeg, p.latDeg);
  maxLatDeg = std::max(maxLatDeg, p.latDeg);
  minLonDeg = std::min(minLonDeg, p.lonDeg);
  maxLonDeg = std::max(maxLonDeg, p.lonDeg);
}

void Bounds::add(const Bounds& b) {
  if (b.empty()) return;
  add(LatLon{b.minLatDeg, b.minLonDeg});
  add(LatLon{b.maxLatDeg, b.maxLonDeg});
}

bool Bounds::contains(const LatLon& p) const {
  return p.latDeg >= minLatDeg && p.latDeg <= maxLatDeg && p.lonDeg >= minLonDeg && p.lonDeg <= maxLonDeg;
}

bool Bounds::intersects(const Bounds& b) const {
  return !empty() && !b.empty() && b.minLatDeg <= maxLatDeg && b.maxLatDeg >= minLatDeg &&
         b.minLonDeg <= maxLonDeg && b.maxLonDeg >= minLonDeg;
}

const AttributeValue* ChartFeature::attribute(std::string_view acronym) const {
  for (const auto& a : attributes)
    if (a.acronym == acronym) return &a.value;
  return nullptr;
}

std::optional<double> ChartFeature::number(std::string_view acronym) const {
  const AttributeValue* v = attribute(acronym);
  if (!v) return std::nullopt;
  if (const auto* i = std::get_if<std::int64_t>(v)) return static_cast<double>(*i);
  if (const auto* d = std::get_if<double>(v)) return *d;
  return std::nullopt;
}

std::optional<std::string> ChartFeature::text(std::string_view acronym) const {
  const AttributeValue* v = attribute(acronym);
  if (!v) return std::nullopt;
  if (const auto* s = std::get_if<std::string>(v)) return *s;
  return std::nullopt;
}

std::vector<std::int64_t> ChartFeature::list(std::string_view acronym) const {
  const AttributeValue* v = attribute(acronym);
  if (!v) return {};
  if (const auto* l = std::get_if<std::vector<std::int64_t>>(v)) return *l;
  if (const auto* i = std::get_if<std::int64_t>(v)) return {*i};
  return {};
}

ChartCell::ChartCell(CellInfo info, std::vector<ChartFeature> features)
    : info_(std::move(info)), features_(std::move(features)) {
  for (const auto& f : features_) {
    bounds_.add(f.geometry.bounds);
    if (f.objectClass == "M_COVR" && f.number("CATCOV").value_or(1.0) == 1.0 &&
        f.geometry.primitive == Primitive::Area)
      coverage_.push_back(&f);
  }
  for (const ChartFeature* c : coverage_) coverageBounds_.add(c->geometry.bounds);
  if (coverageBounds_.empty()) coverageBounds_ = bounds_;
}

bool ChartCell::covers(const LatLon& p) const {
  if (coverage_.empty()) return bounds_.contains(p);
  return std::any_of(coverage_.begin(), coverage_.end(),
                     [&p](const ChartFeature* c) { return c->geometry.contains(p); });
}

UsageBand usageBand(const CellInfo& info) {
  int band = info.intendedUsage;
  if ((band < 1 || band > 6) && info.name.size() >= 3 && info.name[2] >= '1' && info.name[2] <= '6')
    band = info.name[2] - '0';
  return band >= 1 && band <= 6 ? static_cast<UsageBand>(band) : UsageBand::Unknown;
}

const char* usageBandName(UsageBand band) {
  switch (band) {
    case UsageBand::Overview:
      return "Overview";
    case UsageBand::General:
      return "General";
    case UsageBand::Coastal:
      return "Coastal";
    case UsageBand::Approach:
      return "Approach";
    case UsageBand::Harbour:
      return "Harbour";
    case UsageBand::Berthing:
      return "Berthing";
    case UsageBand::Unknown:
      break;
  }
  return "Unknown";
}

std::vector<std::pair<std::string, std::size_t>> ChartCell::countsByClass() const {
  std::map<std::string, std::size_t> m;
  for (const auto& f : features_) ++m[f.objectClass];
  return {m.begin(), m.end()};
}

std::size_t ChartCell::soundingCount() const {
  std::size_t n = 0;
  for (const auto& f : features_)
    if (f.objectClass == "SOUNDG") n += f.geometry.depthsM.size();
  return n;
}

bool Geometry::contains(const LatLon& p) const {
  if (primitive != Primitive::Area || !bounds.contains(p)) return false;
  bool in = false;
  for (const auto& ring : parts) {
    if (ring.empty()) continue;
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
      if ((ring[i].latDeg > p.latDeg) != (ring[j].latDeg > p.latDeg) &&
          p.lonDeg < (ring[j].lonDeg - ring[i].lonDeg) * (p.latDeg - ring[i].latDeg) /
                             (ring[j].latDeg - ring[i].latDeg) +
                         ring[i].lonDeg)
        in = !in;
  }
  return in;
}

}  // namespace reckoner::charts
