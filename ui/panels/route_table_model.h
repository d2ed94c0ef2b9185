#pragma once
// The route table (docs/gui.md "Routes"): one row per waypoint with its name, position, the leg that
// arrives at it (course at its start, length, cross-track limits to port and starboard, planned speed,
// rhumb line or great circle) and its turn radius; distances and speeds in the display units. Cells
// are edited in place: a typed value is checked (a position as the window writes it or in degrees, a
// number in its range, a route still usable) and either proposed as the whole edited route
// (editRequested; the window applies it through its route library, with undo) or refused with a
// message naming the waypoint and the field (refused). The model never changes the route itself.
#include <QAbstractTableModel>

#include "geo/route.h"
#include "ui/common/display_units.h"

namespace reckoner::ui {

class RouteTableModel : public QAbstractTableModel {
  Q_OBJECT
 public:
  enum Column {
    Name,
    Latitude,
    Longitude,
    Course,    ///< of the leg arriving here, at its start (read only)
    Distance,  ///< the leg's length (read only)
    Radius,    ///< the turn radius here (empty: the route's default)
    PortXtl,
    StarboardXtl,
    Speed,     ///< planned (empty: none)
    Geometry,  ///< rhumb line or great circle
    ColumnCount
  };
  /// Largest cross-track limit and turn radius taken, NM, and planned speed, kn.
  static constexpr double kMaxXtlNm = 10.0, kMaxRadiusNm = 10.0, kMaxSpeedKn = 60.0;

  explicit RouteTableModel(QObject* parent = nullptr);
  /// The route shown (none: no rows).
  void setRoute(const geo::Route* route);
  [[nodiscard]] const geo::Route& route() const { return route_; }
  void setUnits(const DisplayUnits& units);

  [[nodiscard]] int rowCount(const QModelIndex& parent = {}) const override;
  [[nodiscard]] int columnCount(const QModelIndex& parent = {}) const override;
  [[nodiscard]] QVariant data(const QModelIndex& index, int role) const override;
  [[nodiscard]] QVariant headerData(int section, Qt::Orientation orientation, int role) const override;
  [[nodiscard]] Qt::ItemFlags flags(const QModelIndex& index) const override;
  /// Checks the value typed; proposes the edited route (true) or refuses it with a message (false).
  bool setData(const QModelIndex& index, const QVariant& value, int role) override;

  /// "Rhumb line" / "Great circle".
  [[nodiscard]] static QString geometryText(geo::LegGeometry g);

 signals:
  void editRequested(const reckoner::geo::Route& after, const QString& what);
  void refused(const QString& message);

 private:
  [[nodiscard]] QString text(int row, int column) const;
  [[nodiscard]] bool hasLeg(int row) const { return row > 0; }
  [[nodiscard]] bool hasTurn(int row) const { return row > 0 && row + 1 < rowCount(); }
  /// The edited route for a typed value, or the reason it is refused.
  [[nodiscard]] std::pair<std::optional<geo::Route>, QString> edited(int row, int column,
                                                                     const QString& typed) const;
  /// A distance typed in the display unit, as NM in [0, maxNm].
  [[nodiscard]] std::optional<double> distanceNm(const QString& typed, double maxNm, QString& why) const;

  geo::Route route_;
  bool hasRoute_ = false;
  DisplayUnits units_;
};

}  // namespace reckoner::ui
