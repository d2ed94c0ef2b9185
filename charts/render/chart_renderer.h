#pragma once
// Draws chart cells into a QImage with the portrayal table, colour table and mariner's settings:
// over the world background (GSHHG land and water, a graticule; world_layer.h), coarse cells first and finer
// ones over their own coverage (the largest scale wins where cells overlap), areas, lines and points by
// display priority, display category and SCAMIN honoured, cell boundaries and an overscale indication. Safe
// to use from a worker thread (QImage, not QPixmap).
//
// Speed: a ChartRenderer projects each cell once to Mercator and sorts its features by drawing order
// (a PreparedCell, kept while the renderer lives), so a redraw is one affine map per vertex, with
// vertices closer than half a pixel dropped. drawFromCache() shows a rendered image in a moved or
// zoomed view at once (a pan or wheel step) while the worker renders the new view.
#include <QColor>
#include <QImage>
#include <QRectF>
#include <QString>
#include <atomic>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "charts/model/chart_model.h"
#include "charts/portrayal/portrayal.h"
#include "charts/render/viewport.h"

class QPainter;

namespace reckoner::charts {

/// A name or light description written on the chart, and the box it took (image pixels).
struct DrawnText {
  QString text;
  QRectF box;
};

struct RenderStats {
  int cellsDrawn = 0;
  int featuresDrawn = 0;
  /// Compilation scale / display scale (> 1: overscale) of the best cell at the view's centre, or
  /// when no drawn cell covers the centre, of the finest cell drawn.
  double overscale = 1.0;
  QRectF overscaleNote;           ///< where "OVERSCALE xk" was written (bottom centre); empty if not
  bool notForNavigation = false;  ///< a drawn cell says so (DSID_COMT) and the notice is on screen
  bool cancelled = false;         ///< the cancel flag was raised during the render; the image is incomplete
  /// The world background under the cells (docs/charts.md, "World background"): the GSHHG resolution
  /// drawn ('c', 'l' or 'i'; 0 when none or switched off), the bins of it in view, and why the
  /// resolution the view wants is not drawn (the file named), empty when it is.
  char worldResolution = 0;
  int worldBinsDrawn = 0;
  std::string worldProblem;
  std::vector<DrawnText> texts;  ///< every name and light description written, in drawing order
};

class PreparedCell;
class WorldLayer;

class ChartRenderer {
 public:
  explicit ChartRenderer(const PortrayalTable& table = defaultPortrayal(),
                         const ColourTable& colours = defaultColours());
  ~ChartRenderer();
  ChartRenderer(const ChartRenderer&) = delete;
  ChartRenderer& operator=(const ChartRenderer&) = delete;

  /// Renders `cells` into `image` (its size must be the view's). Stops early, with `cancelled` set,
  /// when `cancel` becomes true (a newer view is waiting).
  RenderStats render(QImage& image, const std::vector<CellPtr>& cells, const Viewport& view,
                     const MarinerSettings& settings, const std::atomic<bool>* cancel = nullptr);

  /// Projects and sorts a cell now (otherwise done on its first render).
  void prepare(const CellPtr& cell);
  /// Drops prepared cells that are not in `keep` (after the user closes a chart).
  void retainOnly(const std::vector<CellPtr>& keep);
  [[nodiscard]] std::size_t preparedCount() const { return prepared_.size(); }
  /// The world background (GSHHG land and water, shorelines, graticule) under the cells; on by
  /// default. Off: the plain NODTA background.
  void setWorldBackground(bool on) { worldBackground_ = on; }

 private:
  const PreparedCell& preparedOf(const CellPtr& cell);
  const PortrayalTable& table_;
  const ColourTable& colours_;
  std::map<const ChartCell*, std::unique_ptr<PreparedCell>> prepared_;
  std::unique_ptr<WorldLayer> world_;
  bool worldBackground_ = true;
};

/// One-shot rendering (prepares the cells each time; a view keeps a ChartRenderer instead).
RenderStats renderChart(QImage& image, const std::vector<CellPtr>& cells, const Viewport& view,
                        const MarinerSettings& settings, const PortrayalTable& table = defaultPortrayal(),
                        const ColourTable& colours = defaultColours());

/// Draws `cachedImage`, rendered for `cachedView`, as it appears in the view `now` (shifted by a pan,
/// scaled by a zoom, turned by a rotation), after filling the painter's device with `background`.
void drawFromCache(QPainter& painter, const QImage& cachedImage, const Viewport& cachedView,
                   const Viewport& now, const QColor& background);

}  // namespace reckoner::charts
