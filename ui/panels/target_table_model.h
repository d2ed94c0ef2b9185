#pragma once
// The ARPA target table: one row per track of the latest frame (id, status, range, bearing, true course
// and speed, CPA and TCPA with their standard deviations), in the display units. Range, bearing, CPA and
// TCPA are from own ship's CCRP: the tracker's figures are from the point the DRKF estimates (the
// ship's centre), so with the CCRP elsewhere in the hull they are worked again here by the tracker's
// own function (track::kinematicsOf) with own ship's position moved to the CCRP. Refreshed as a whole at
// the repaint rate; a QSortFilterProxyModel sorts it (numbers sort by value: Qt::UserRole).
#include <QAbstractTableModel>
#include <vector>

#include "sim/simulation_engine.h"
#include "ui/common/display_units.h"

namespace reckoner::ui {

class TargetTableModel : public QAbstractTableModel {
  Q_OBJECT
 public:
  enum Column { Id, Status, Filter, Range, Bearing, Course, Speed, Cpa, Tcpa, SdCpa, SdTcpa, ColumnCount };

  using QAbstractTableModel::QAbstractTableModel;

  void setTracks(const std::vector<sim::TrackSnapshot>& tracks);
  void setUnits(const DisplayUnits& units);
  [[nodiscard]] const DisplayUnits& units() const { return units_; }
  /// The CCRP's offset from the DRKF's estimated position (grid metres) and the grid convergence at
  /// own ship: the range, bearing and CPA shown are from there.
  void setCcrpOffset(double dxM, double dyM, double convergenceRad);
  [[nodiscard]] int trackIdAt(int row) const;
  [[nodiscard]] int rowOf(int trackId) const;

  int rowCount(const QModelIndex& parent = {}) const override;
  int columnCount(const QModelIndex& parent = {}) const override;
  QVariant data(const QModelIndex& index, int role) const override;
  QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

 private:
  /// The tracks as shown: the frame's (raw_) with their kinematics from the CCRP.
  void refreshKinematics();
  std::vector<sim::TrackSnapshot> raw_, tracks_;
  DisplayUnits units_;
  double ccrpDxM_ = 0.0, ccrpDyM_ = 0.0, convergenceRad_ = 0.0;
};

}  // namespace reckoner::ui
