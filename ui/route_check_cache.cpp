#include "ui/route_check_cache.h"

#include <QElapsedTimer>

namespace reckoner::ui {

charts::SafetySettings safetySettingsOf(const charts::MarinerSettings& mariner) {
  charts::SafetySettings s;
  s.safetyContourM = mariner.safetyContourM;
  s.safetyDepthM = mariner.safetyDepthM;
  s.specialAreas = true;
  return s;
}

const charts::ChartHazards& RouteCheckCache::hazards(const std::vector<charts::CellPtr>& cells,
                                                     const charts::SafetySettings& settings) {
  std::vector<const charts::ChartCell*> key;
  key.reserve(cells.size());
  for (const charts::CellPtr& c : cells) key.push_back(c.get());
  const bool same = hazards_ && key == cells_ && settings.safetyContourM == settings_.safetyContourM &&
                    settings.safetyDepthM == settings_.safetyDepthM &&
                    settings.specialAreas == settings_.specialAreas;
  if (!same) {
    QElapsedTimer t;
    t.start();
    hazards_.reset();  // the old one's memory first
    hazards_.emplace(cells, settings);
    cells_ = std::move(key);
    settings_ = settings;
    ++builds_;
    lastBuildMs_ = static_cast<double>(t.nsecsElapsed()) * 1e-6;
  }
  return *hazards_;
}

std::vector<charts::RouteFinding> RouteCheckCache::check(const geo::Route& route,
                                                         const std::vector<charts::CellPtr>& cells,
                                                         const charts::SafetySettings& settings) {
  const charts::ChartHazards& h = hazards(cells, settings);
  if (route.legCount() == 0) return {};
  return charts::checkRoute(route, h);
}

}  // namespace reckoner::ui
