#pragma once
// The chart on screen: a QWidget that shows the S-57 chart in a Mercator view with centre, scale and
// rotation, rendered by a ChartRenderWorker in its own thread. Between renders it shows the last image
// moved to the current view (drawFromCache), so dragging and wheel zooming answer at once; a finished
// render replaces it. Mouse: drag pans, the wheel zooms about the cursor, a click without a drag
// reports the features there (pick report). Zooming keeps to the limits of charts/render/chart_extent.h
// (in: x8 overscale of the best cell at the centre, 1:2000 off the charts; out: the world's width).
// Over the chart it draws each open cell's coverage outline with its name (a toggle), bolder for the
// cells under the cursor; overlays (own ship, targets) paint on top in subclasses or paintOverlay().
#include <QImage>
#include <QWidget>
#include <optional>
#include <vector>

#include "charts/pick/pick_report.h"
#include "charts/render/chart_renderer.h"
#include "ui/bridge/chart_render_worker.h"
#include "ui/bridge/worker_thread.h"

QT_BEGIN_NAMESPACE
class QMenu;
QT_END_NAMESPACE

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
  /// Centre, scale 1:N and rotation (the bearing pointing up). The scale keeps to the zoom limits at the
  /// new centre (largestScale(), smallestScale()): a request past one stops there, except that a view
  /// already past it (it was moved onto a coarser chart or off the charts) keeps its scale.
  void setView(charts::LatLon centre, double scaleDenominator, double rotationRad = 0.0);
  [[nodiscard]] charts::Viewport viewport() const;
  /// Zoom by a factor (> 1 zooms in) keeping the chart point under `anchor` (widget pixels) fixed.
  void zoomAbout(double factor, QPointF anchor);
  /// Pan by a screen displacement (the chart moves with the mouse).
  void panBy(QPointF deltaPx);
  /// The zoom limits (1:N) for a view centred at `centre`: in (the smallest N) and out (the largest).
  [[nodiscard]] double largestScale(charts::LatLon centre) const;
  [[nodiscard]] double smallestScale(charts::LatLon centre) const;

  /// Shows the combined coverage of `cells` (M_COVR CATCOV 1, else their extent): centred on it, at
  /// the scale that holds it inside a margin, within the zoom limits. False when there is nothing.
  bool zoomToCells(const std::vector<charts::CellPtr>& cells);
  /// The open cells whose coverage holds widget point p, the largest scale first.
  [[nodiscard]] std::vector<charts::CellPtr> cellsAt(QPointF p) const;
  /// The cells under the mouse cursor now (as cellsUnderCursor last said).
  [[nodiscard]] const std::vector<charts::CellPtr>& cellsUnderCursor() const { return underCursor_; }
  /// Coverage outlines with the cells' names (on by default).
  void setShowOutlines(bool on);
  [[nodiscard]] bool showOutlines() const { return showOutlines_; }
  /// Adds "Zoom to chart NAME" for each open cell at widget point `at` and "Show all charts" to a menu.
  void addChartActions(QMenu* menu, QPointF at);

  /// The last finished render and the time it took (tests, status bar).
  [[nodiscard]] const QImage& renderedImage() const { return image_; }
  [[nodiscard]] double lastRenderMs() const { return lastRenderMs_; }
  /// What the last finished render drew: its overscale and the box of its note, the texts written.
  [[nodiscard]] const charts::RenderStats& lastRenderStats() const { return lastStats_; }
  [[nodiscard]] quint64 renderedGeneration() const { return imageGeneration_; }
  [[nodiscard]] quint64 requestedGeneration() const { return render_.worker()->requests().latest(); }

 signals:
  void viewChanged(const reckoner::charts::Viewport& view);
  void cursorMoved(reckoner::charts::LatLon position);
  /// The cells under the cursor changed (largest scale first; empty when the cursor left them).
  void cellsUnderCursorChanged(const std::vector<reckoner::charts::CellPtr>& cells);
  void picked(const std::vector<reckoner::charts::PickedFeature>& features, reckoner::charts::LatLon where);
  void renderFinished(double milliseconds);
  /// The open cells were replaced (setCells), or the mariner's settings changed (setSettings).
  void cellsChanged();
  void settingsChanged(const reckoner::charts::MarinerSettings& settings);

 protected:
  void paintEvent(QPaintEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void leaveEvent(QEvent* event) override;
  /// Hook for overlays, painted over the chart at every repaint.
  virtual void paintOverlay(QPainter& painter, const charts::Viewport& view);
  /// Hook for a left click without a drag at widget point `at`: true when a subclass took it (then no
  /// pick report follows).
  virtual bool chartClicked(QPointF /*at*/) { return false; }

 private:
  /// A cell's coverage rings projected once to Mercator, for the outlines.
  struct Outline {
    charts::CellPtr cell;
    std::vector<std::vector<charts::MercatorPoint>> rings;
    charts::MercatorPoint lo, hi;
  };
  /// The 1:N setView and zoomAbout use for a request at `centre` (the rule of setView).
  [[nodiscard]] double allowedScale(charts::LatLon centre, double requested) const;
  void requestRender();
  void onRendered(const QImage& image, const charts::Viewport& view, quint64 generation, double ms,
                  const charts::RenderStats& stats);
  void paintOutlines(QPainter& p, const charts::Viewport& view);
  void setUnderCursor(std::vector<charts::CellPtr> cells);

  std::vector<charts::CellPtr> cells_;
  std::vector<Outline> outlines_;
  std::vector<charts::CellPtr> underCursor_;
  std::optional<QPointF> cursorAt_;  ///< the mouse on the widget, while it is there
  bool showOutlines_ = true;
  charts::MarinerSettings settings_;
  charts::LatLon centre_{49.5, -29.5};
  double scale_ = 20000;
  double rotation_ = 0;
  WorkerThread<ChartRenderWorker> render_{QStringLiteral("chart-render")};
  QImage image_;
  std::optional<charts::Viewport> imageView_;
  quint64 imageGeneration_ = 0;
  double lastRenderMs_ = 0;
  charts::RenderStats lastStats_;
  std::optional<QPointF> pressAt_, lastMouse_;
  bool dragged_ = false;
};

}  // namespace reckoner::ui
