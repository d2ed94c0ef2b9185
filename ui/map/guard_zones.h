#pragma once
// Guard (acquisition) zones on the chart: ring sectors around own ship in true bearings (MSC.192(79)'s
// acquisition zones; a new target inside one raises GUARD ZONE, docs/alerts.md). Their outline in widget
// pixels, which edge of which zone a point is on, and the editing: drag the inner or outer arc to change
// a range, a side to change a bearing, or the middle to turn the whole sector; the context menu adds a
// zone at the point and deletes one. EcdisView owns an editor and draws what it shows; the zones it
// emits go to the engine, which records them in the scenario (acquisition_zone_changes).
#include <QPainterPath>
#include <QPointF>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "tracking/initiator.h"

namespace reckoner::ui {

/// Own ship's polar frame on screen: range (true metres) and true bearing to widget pixels and back.
struct PolarMap {
  std::function<QPointF(double rangeM, double trueBearingRad)> toWidget;
  std::function<std::pair<double, double>(QPointF)> fromWidget;  ///< (range m, true bearing rad)
  double pxPerMetre = 1.0;
};

enum class ZoneEdge { None, Inner, Outer, From, To, Inside };

struct ZoneHit {
  int zone = -1;  ///< index, -1: none
  ZoneEdge edge = ZoneEdge::None;
};

/// Whether the sector is a whole ring (equal bearings).
[[nodiscard]] bool wholeRing(const track::AcquisitionZone& z);
/// The zone's outline (closed), its arcs sampled every 2 degrees at most.
[[nodiscard]] QPainterPath zoneOutline(const track::AcquisitionZone& z, const PolarMap& m);
/// The edge of a zone within tolPx of p (arcs before sides; the last zone drawn first), else the
/// zone p is inside, else none.
[[nodiscard]] ZoneHit hitZone(const std::vector<track::AcquisitionZone>& zones, QPointF p, const PolarMap& m,
                              double tolPx = 6.0);
/// z with `edge` moved to the point (rangeM, bearingRad); the ranges stay at least minSpanM apart and
/// the inner one at 0 or more. Inside: the sector turned by the bearing moved since `grabBearingRad`.
[[nodiscard]] track::AcquisitionZone movedZone(track::AcquisitionZone z, ZoneEdge edge, double rangeM,
                                               double bearingRad, double grabBearingRad, double minSpanM);
/// A new zone at a point: 45 degrees wide centred on its bearing, from 0.8 to 1.2 times its range (at
/// least minSpanM deep).
[[nodiscard]] track::AcquisitionZone zoneAt(double rangeM, double bearingRad, double minSpanM);

class GuardZoneEditor {
 public:
  /// Starts dragging the zone edge under p (false: none there; the press is not the editor's).
  bool press(const std::vector<track::AcquisitionZone>& zones, QPointF p, const PolarMap& m);
  /// While dragging: the zones as they would be (true: the editor used the move).
  bool move(QPointF p, const PolarMap& m);
  /// Ends the drag: the zones to apply (nullopt: no drag).
  std::optional<std::vector<track::AcquisitionZone>> release(QPointF p, const PolarMap& m);
  [[nodiscard]] bool dragging() const { return drag_.has_value(); }
  /// The zones being dragged (shown instead of the frame's while dragging).
  [[nodiscard]] const std::vector<track::AcquisitionZone>* preview() const {
    return drag_ ? &drag_->zones : nullptr;
  }

 private:
  struct Drag {
    std::vector<track::AcquisitionZone> zones;
    track::AcquisitionZone start;
    int zone = -1;
    ZoneEdge edge = ZoneEdge::None;
    double grabBearingRad = 0.0;
  };
  std::optional<Drag> drag_;
};

}  // namespace reckoner::ui
