#include "ui/bridge/chart_render_worker.h"

#include <chrono>

namespace reckoner::ui {

void ChartRenderWorker::render(const ChartRenderRequest& request) {
  if (!requests_.begin(request.generation)) return;  // a newer view is already queued
  const auto t0 = std::chrono::steady_clock::now();
  QImage image(request.view.width(), request.view.height(), QImage::Format_ARGB32_Premultiplied);
  renderer_.retainOnly(request.cells);
  charts::RenderStats stats =
      renderer_.render(image, request.cells, request.view, request.settings, requests_.cancelFlag());
  if (stats.cancelled) return;
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  emit rendered(std::move(image), request.view, request.generation, ms, std::move(stats));
}

}  // namespace reckoner::ui
