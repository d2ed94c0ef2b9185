#pragma once
// The AIS target table: one row per target of the table (track::AisTargetTable::targets()): MMSI, name,
// class, range, bearing, SOG, COG, CPA, TCPA and status, in the display units. Range, bearing and CPA
// come from the core's table (own ship's reported position); the model only formats them. Numbers sort
// by value (Qt::UserRole) through a QSortFilterProxyModel.
#include <QAbstractTableModel>
#include <vector>

#include "tracking/ais_targets.h"
#include "ui/common/display_units.h"

namespace reckoner::ui {

class AisTableModel : public QAbstractTableModel {
  Q_OBJECT
 public:
  enum Column { Mmsi, Name, Class, Range, Bearing, Sog, Cog, Cpa, Tcpa, Status, ColumnCount };

  using QAbstractTableModel::QAbstractTableModel;

  void setTargets(const std::vector<track::AisTarget>& targets);
  void setUnits(const DisplayUnits& units);
  [[nodiscard]] std::uint32_t mmsiAt(int row) const;
  [[nodiscard]] int rowOf(std::uint32_t mmsi) const;
  /// "dangerous, activated", "lost", "sleeping", with "selected" when it is.
  [[nodiscard]] static QString statusText(const track::AisTarget& t);

  int rowCount(const QModelIndex& parent = {}) const override;
  int columnCount(const QModelIndex& parent = {}) const override;
  QVariant data(const QModelIndex& index, int role) const override;
  QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

 private:
  std::vector<track::AisTarget> targets_;
  DisplayUnits units_;
};

}  // namespace reckoner::ui
