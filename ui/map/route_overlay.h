#pragma once
// The route on the chart (docs/gui.md "Routes"): the route shown (the library's selected one), the
// active route when it is another, the route check's findings, and route editing with the mouse. This
// class holds the state, the geometry (projected once to Mercator when the route changes, so a repaint
// only maps points) and the input; EcdisView paints it (ecdis_route.cpp) and passes the mouse to it.
// Edits are not applied here: each is proposed as the whole edited route (routeEdited), and the window
// applies it through its route library (with undo), which then shows it here again.
//
// Edit mode (setEditing): a click on the chart appends a waypoint, a drag of a waypoint moves it, the
// context menu inserts a waypoint on a leg and deletes or renames one; Escape leaves the mode.
#include <QObject>
#include <QPointF>
#include <QString>
#include <optional>
#include <vector>

#include "charts/render/viewport.h"
#include "charts/route/route_check.h"
#include "geo/route.h"

QT_BEGIN_NAMESPACE
class QMenu;
QT_END_NAMESPACE

namespace reckoner::ui {

/// A route's geometry in spherical Mercator (drawn in any view through Viewport::mercatorToScreen).
struct RouteGeometry {
  std::vector<charts::MercatorPoint> waypoints;
  /// Index k: the leg arriving at waypoint k along its true geometry (great circles as curves), and
  /// its port and starboard cross-track limits (the route check's corridor edges); k = 0 empty.
  std::vector<std::vector<charts::MercatorPoint>> legs, port, starboard;
  struct Turn {
    std::size_t waypoint = 0;
    charts::MercatorPoint wheelOver;         ///< where the turn as sailed begins (geo::turnFit)
    charts::MercatorPoint direction;         ///< the arriving leg's direction there (Mercator, unit length)
    std::vector<charts::MercatorPoint> arc;  ///< the turn as sailed, tangent to both legs
    bool fits = true;  ///< false: the waypoint's radius has no room, a smaller one is sailed
  };
  std::vector<Turn> turns;
};
/// The geometry of a route (legs with their points at most ~1/256 of the leg or 500 m apart).
[[nodiscard]] RouteGeometry routeGeometry(const geo::Route& route);

class RouteOverlay : public QObject {
  Q_OBJECT
 public:
  explicit RouteOverlay(QObject* parent = nullptr);

  /// The route shown and edited; `active`: it is the route the ship follows (drawn solid).
  void setRoute(const geo::Route& route, bool active);
  void clearRoute();
  /// The active route when it is not the one shown: drawn solid, with waypoints, without the editing
  /// marks. nullopt: none (or it is the one shown).
  void setActiveRoute(const std::optional<geo::Route>& route);
  void setFindings(std::vector<charts::RouteFinding> findings);
  void setSelectedWaypoint(std::optional<std::size_t> index);
  void setSelectedFinding(std::optional<std::size_t> index);
  void setEditing(bool on);

  [[nodiscard]] bool editing() const { return editing_; }
  [[nodiscard]] bool isActive() const { return active_; }
  /// The route as drawn: with a waypoint drag in progress applied.
  [[nodiscard]] const std::optional<geo::Route>& route() const { return shown_; }
  [[nodiscard]] const RouteGeometry& geometry() const { return geometry_; }
  [[nodiscard]] const std::optional<RouteGeometry>& activeGeometry() const { return activeGeometry_; }
  [[nodiscard]] const std::optional<geo::Route>& activeRoute() const { return activeRoute_; }
  [[nodiscard]] const std::vector<charts::RouteFinding>& findings() const { return findings_; }
  [[nodiscard]] std::optional<std::size_t> selectedWaypoint() const { return selectedWaypoint_; }
  [[nodiscard]] std::optional<std::size_t> selectedFinding() const { return selectedFinding_; }

  /// The waypoint drawn nearest widget point p within tolPx, in view v.
  [[nodiscard]] std::optional<std::size_t> waypointAt(QPointF p, const charts::Viewport& v,
                                                      double tolPx = 9.0) const;
  /// The leg (index of the waypoint it arrives at) nearest p within tolPx.
  [[nodiscard]] std::optional<std::size_t> legAt(QPointF p, const charts::Viewport& v,
                                                 double tolPx = 7.0) const;

  // The chart's mouse (EcdisView), widget pixels in view v; true when the overlay took the event.
  /// Left press: on a waypoint selects it, and in edit mode starts dragging it.
  bool press(QPointF p, const charts::Viewport& v);
  bool move(QPointF p, const charts::Viewport& v);
  /// Ends a drag: proposes the moved route (or only selects, when it did not move).
  bool release(QPointF p, const charts::Viewport& v);
  /// A click (no drag) on the chart: in edit mode appends a waypoint there.
  bool click(QPointF p, const charts::Viewport& v);
  /// Escape: leaves edit mode (cancelling a drag). Delete: deletes the selected waypoint.
  bool key(int key);
  /// In edit mode: insert a waypoint on the leg at p, delete or rename the waypoint at p, append one.
  void addContextActions(QMenu* menu, QPointF p, const charts::Viewport& v);

  // The edits the mouse and the menu propose (the route shown, edited).
  [[nodiscard]] geo::Route appended(const geo::GeoPoint& at) const;
  /// A waypoint on the leg arriving at `to`, at the point of the leg nearest `at`.
  [[nodiscard]] geo::Route inserted(std::size_t to, const geo::GeoPoint& at) const;
  [[nodiscard]] geo::Route removed(std::size_t k) const;
  [[nodiscard]] geo::Route moved(std::size_t k, const geo::GeoPoint& at) const;

 signals:
  /// An edit from the chart: the whole route after it, and what was done ("Move WP2").
  void routeEdited(const reckoner::geo::Route& after, const QString& what);
  void waypointSelected(int index);
  /// The context menu's Rename: the window lets the operator type the name (the route table).
  void renameRequested(int index);
  void editingChanged(bool on);
  /// Something drawn changed: repaint.
  void changed();

 private:
  void rebuild();
  struct Drag {
    std::size_t index;
    QPointF from;
    geo::GeoPoint at;
    bool moved = false;
  };
  std::optional<geo::Route> route_;  // as set
  std::optional<geo::Route> shown_;  // as drawn (with the drag)
  RouteGeometry geometry_;
  bool active_ = false;
  std::optional<geo::Route> activeRoute_;
  std::optional<RouteGeometry> activeGeometry_;
  std::vector<charts::RouteFinding> findings_;
  std::optional<std::size_t> selectedWaypoint_, selectedFinding_;
  bool editing_ = false;
  std::optional<Drag> drag_;
};

}  // namespace reckoner::ui
