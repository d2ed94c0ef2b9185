#pragma once
// Renders the chart in a worker thread for a ChartView (WorkerThread<ChartRenderWorker>): requests go
// in as queued calls of render() carrying a snapshot of the view (viewport, settings, cells: values and
// shared read-only cells), images come back through rendered() with what the render drew (its
// RenderStats: overscale, where its notes went, the texts written). Latest request wins (LatestRequest):
// a newer request cancels the render in progress and makes the older queued ones skip, so the view
// never waits for a render it no longer needs.
#include <QImage>
#include <QObject>
#include <vector>

#include "charts/render/chart_renderer.h"
#include "ui/bridge/latest_request.h"

namespace reckoner::ui {

struct ChartRenderRequest {
  std::vector<charts::CellPtr> cells;
  charts::Viewport view{{0.0, 0.0}, 10000, 16, 16};
  charts::MarinerSettings settings;
  quint64 generation = 0;  ///< from requests().issue()
};

class ChartRenderWorker : public QObject {
  Q_OBJECT
 public:
  ChartRenderWorker() = default;
  /// Thread-safe: the GUI thread numbers each request here before posting it.
  [[nodiscard]] LatestRequest& requests() { return requests_; }

  /// In the worker's thread: renders the request unless a newer one has been issued.
  void render(const reckoner::ui::ChartRenderRequest& request);

 signals:
  void rendered(QImage image, reckoner::charts::Viewport view, quint64 generation, double milliseconds,
                reckoner::charts::RenderStats stats);

 private:
  charts::ChartRenderer renderer_;  // keeps the prepared (projected) cells between renders
  LatestRequest requests_;
};

}  // namespace reckoner::ui

Q_DECLARE_METATYPE(reckoner::charts::Viewport)
Q_DECLARE_METATYPE(reckoner::charts::RenderStats)
