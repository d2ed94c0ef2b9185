#pragma once
// Draws chart cells into a QImage with the portrayal table, colour table and mariner's settings:
// coarse cells first and finer ones over their own coverage (the largest scale wins where cells
// overlap), areas, lines and points by display priority, display category and SCAMIN honoured, cell
// boundaries and an overscale indication. Safe to call from a worker thread (QImage, not QPixmap).
#include <QImage>
#include <vector>

#include "charts/model/chart_model.h"
#include "charts/portrayal/portrayal.h"
#include "charts/render/viewport.h"

namespace reckoner::charts {

struct RenderStats {
  int cellsDrawn = 0;
  int featuresDrawn = 0;
  double overscale = 1.0;  ///< compilation scale / display scale of the finest cell drawn (> 1: overscale)
};

RenderStats renderChart(QImage& image, const std::vector<CellPtr>& cells, const Viewport& view,
                        const MarinerSettings& settings, const PortrayalTable& table = defaultPortrayal(),
                        const ColourTable& colours = defaultColours());

}  // namespace reckoner::charts
