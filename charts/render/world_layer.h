#pragma once
// The world background under the cells (internal to charts/render; docs/charts.md, "World
// background"): GSHHG's land and water filled in tones of the palette that no ENC uses, their
// shorelines, and a labelled graticule, so that no view is ever blank. A ChartRenderer owns one
// WorldLayer, which projects each shoreline it draws to Mercator once (as cells are) and keeps it.
#include <QColor>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "charts/render/painting.h"
#include "charts/world/gshhg.h"

namespace reckoner::charts {

struct RenderStats;

/// A Shoreline projected once to Mercator: one point array, parts with their Mercator boxes, bins
/// with theirs (longitudes east from 0 to 2 pi, unwrapped: a view shifts them by whole turns).
class PreparedWorld {
 public:
  struct Part {
    std::uint32_t first = 0, count = 0;
    int level = 1;
    MercatorPoint lo, hi;
  };
  struct Bin {
    MercatorPoint lo, hi;
    std::vector<Part> areas, lines;
  };
  explicit PreparedWorld(std::shared_ptr<const world::Shoreline> shoreline);
  [[nodiscard]] const std::vector<Bin>& bins() const { return bins_; }
  [[nodiscard]] const std::vector<MercatorPoint>& points() const { return points_; }

 private:
  Part add(const std::vector<LatLon>& pts, int level);
  std::shared_ptr<const world::Shoreline> shoreline_;  // kept alive: the renderer's cache is keyed by it
  std::vector<Bin> bins_;
  std::vector<MercatorPoint> points_;
};

/// The world background's tones in a palette: mixed from the chart's own tokens towards NODTA, so
/// they follow day, dusk and night but differ from every ENC land and depth shade.
struct WorldColours {
  QColor water, land, shore, grid, text;
};
WorldColours worldColours(const paint::Ctx& c);

class WorldLayer {
 public:
  /// Draws the background of the view in `c` (the whole image): water, the land and shorelines of
  /// the bins in view at the resolution the view's scale asks for (world_data.h) and the graticule.
  /// Fills in the world fields of `stats`; returns the note naming the source, or the problem when
  /// there is no shoreline, for drawNote once the cells are drawn over the background.
  QString draw(paint::Ctx& c, RenderStats& stats);
  /// The note at the bottom right, above the window's scale bar (over the cells).
  static void drawNote(const paint::Ctx& c, const QString& note);

 private:
  const PreparedWorld& preparedOf(const std::shared_ptr<const world::Shoreline>& s);
  std::map<const world::Shoreline*, std::unique_ptr<PreparedWorld>> prepared_;
};

}  // namespace reckoner::charts
