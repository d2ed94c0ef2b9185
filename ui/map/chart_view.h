#pragma once
// The chart on screen: a QWidget that shows the S-57 chart in a Mercator view with centre, scale and
// rotation, rendered by a ChartRenderWorker in its own thread. Between renders it shows the last image
// moved to the current view (drawFromCache), so dragging and wheel zooming answer at once; a finished
// render replaces it. Mouse: drag pans, the wheel zooms about the cursor, a click without a drag
// reports the features there (pick report). Overlays (own ship, targets) paint on top in subclasses
// or through paintOverlay().
#include <QImage>
#include <QWidget>
#include <optional>
#include <vector>

#include "charts/pick/pick_report.h"
#include "charts/render/chart_renderer.h"
#include "ui/bridge/chart_render_worker.h"
#include "ui/bridge/worker_thread.h"

namespace reckoner::ui {

class ChartView : public QWidget {
  Q_OBJECT
 public:
  explicit ChartView(QWidget* parent = nullptr);
  ~ChartView() override;

  void setCells(std::vector<charts::CellPtr> cells);
  [[nodiscard]] const std::vector<charts::CellPtr>& cells() const { return cells_; }
  void setSettings(const charts::MarinerSettings& settings);
  [[nodiscard]] const charts::MarinerSettings& settings() const { return settings_; }
  /// Centre, scale 1:N (clamped to 1:500 .. 1:20 000 000) and rotation (the bearing pointing up).
  void setView(charts::LatLon centre, double scaleDenominator, double rotationRad = 0.0);
  [[nodiscard]] charts::Viewport viewport() const;
  /// Zoom by a factor (> 1 zooms in) keeping the chart point under `anchor` (widget pixels) fixed.
  void zoomAbout(double factor, QPointF anchor);
  /// Pan by a screen displacement (the chart moves with the mouse).
  void panBy(QPointF deltaPx);

  /// The last finished render and the time it took (tests, status bar).
  [[nodiscard]] const QImage& renderedImage() const { return image_; }
  [[nodiscard]] double lastRenderMs() const { return lastRenderMs_; }
  [[nodiscard]] quint64 renderedGeneration() const { return imageGeneration_; }
  [[nodiscard]] quint64 requestedGeneration() const { return render_.worker()->requests().latest(); }

 signals:
  void viewChanged(const reckoner::charts::Viewport& view);
  void cursorMoved(reckoner::charts::LatLon position);
  void picked(const std::vector<reckoner::charts::PickedFeature>& features, reckoner::charts::LatLon where);
  void renderFinished(double milliseconds);

 protected:
  void paintEvent(QPaintEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  /// Hook for overlays, painted over the chart at every repaint.
  virtual void paintOverlay(QPainter& painter, const charts::Viewport& view);

 private:
  void requestRender();
  void onRendered(const QImage& image, const charts::Viewport& view, quint64 generation, double ms);

  std::vector<charts::CellPtr> cells_;
  charts::MarinerSettings settings_;
  charts::LatLon centre_{49.5, -29.5};
  double scale_ = 20000;
  double rotation_ = 0;
  WorkerThread<ChartRenderWorker> render_{QStringLiteral("chart-render")};
  QImage image_;
  std::optional<charts::Viewport> imageView_;
  quint64 imageGeneration_ = 0;
  double lastRenderMs_ = 0;
  std::optional<QPointF> pressAt_, lastMouse_;
  bool dragged_ = false;
};

}  // namespace reckoner::ui
