#pragma once
// The ARPA target table: one row per track of the latest frame (id, status, range, bearing, true course
// and speed, CPA and TCPA with their standard deviations). Refreshed as a whole at the repaint rate; a
// QSortFilterProxyModel sorts it (numbers sort by value: Qt::UserRole).
#include <QAbstractTableModel>
#include <vector>

#include "sim/simulation_engine.h"

namespace reckoner::ui {

class TargetTableModel : public QAbstractTableModel {
  Q_OBJECT
 public:
  enum Column { Id, Status, Filter, Range, Bearing, Course, Speed, Cpa, Tcpa, SdCpa, SdTcpa, ColumnCount };

  using QAbstractTableModel::QAbstractTableModel;

  void setTracks(const std::vector<sim::TrackSnapshot>& tracks);
  [[nodiscard]] int trackIdAt(int row) const;
  [[nodiscard]] int rowOf(int trackId) const;

  int rowCount(const QModelIndex& parent = {}) const override;
  int columnCount(const QModelIndex& parent = {}) const override;
  QVariant data(const QModelIndex& index, int role) const override;
  QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

 private:
  std::vector<sim::TrackSnapshot> tracks_;
};

}  // namespace reckoner::ui
