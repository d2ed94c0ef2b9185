#pragma once
// Renders the chart in a worker thread for a ChartView: requests go in as queued calls carrying a
// snapshot of the view (viewport, settings, cells: values and shared read-only cells), images come
// back as queued signals. A newer request cancels the render in progress and supersedes queued ones,
// so the view never waits for a render it no longer needs.
#include <QImage>
#include <QObject>
#include <atomic>
#include <memory>
#include <vector>

#include "charts/render/chart_renderer.h"

namespace reckoner::ui {

struct ChartRenderRequest {
  std::vector<charts::CellPtr> cells;
  charts::Viewport view{{0.0, 0.0}, 10000, 16, 16};
  charts::MarinerSettings settings;
  quint64 generation = 0;
};

class ChartRenderWorker : public QObject {
  Q_OBJECT
 public:
  ChartRenderWorker() = default;
  /// Called from the GUI thread before queueing request `generation`: makes the render in progress
  /// stop and the older queued ones skip.
  void supersede(quint64 generation) {
    latest_.store(generation);
    cancel_.store(true);
  }

 public slots:
  void render(const reckoner::ui::ChartRenderRequest& request);

 signals:
  void rendered(QImage image, reckoner::charts::Viewport view, quint64 generation, double milliseconds);

 private:
  charts::ChartRenderer renderer_;  // keeps the prepared (projected) cells between renders
  std::atomic<quint64> latest_{0};
  std::atomic<bool> cancel_{false};
};

}  // namespace reckoner::ui

Q_DECLARE_METATYPE(reckoner::ui::ChartRenderRequest)
Q_DECLARE_METATYPE(reckoner::charts::Viewport)
