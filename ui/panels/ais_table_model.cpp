#include "ui/panels/ais_table_model.h"

#include <QBrush>
#include <QColor>
#include <QStringList>
#include <algorithm>

#include "common/angles.h"
#include "common/units.h"

namespace reckoner::ui {

void AisTableModel::setTargets(const std::vector<track::AisTarget>& targets) {
  const bool sameRows = targets.size() == targets_.size() &&
                        std::equal(targets.begin(), targets.end(), targets_.begin(),
                                   [](const auto& a, const auto& b) { return a.mmsi == b.mmsi; });
  if (sameRows) {
    targets_ = targets;
    if (!targets_.empty()) emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
    return;
  }
  beginResetModel();
  targets_ = targets;
  endResetModel();
}

void AisTableModel::setUnits(const DisplayUnits& units) {
  if (units == units_) return;
  units_ = units;
  emit headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
  if (!targets_.empty()) emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
}

std::uint32_t AisTableModel::mmsiAt(int row) const {
  return row >= 0 && row < rowCount() ? targets_[static_cast<std::size_t>(row)].mmsi : 0;
}

int AisTableModel::rowOf(std::uint32_t mmsi) const {
  for (std::size_t i = 0; i < targets_.size(); ++i)
    if (targets_[i].mmsi == mmsi) return static_cast<int>(i);
  return -1;
}

QString AisTableModel::statusText(const track::AisTarget& t) {
  QStringList s;
  if (t.device != track::AisDevice::None)
    s << QStringLiteral("%1 %2").arg(QString::fromLatin1(track::aisDeviceName(t.device)),
                                     t.deviceTest ? QStringLiteral("test") : QStringLiteral("ACTIVE"));
  if (t.lost)
    s << QStringLiteral("lost");
  else if (t.dangerous)
    s << QStringLiteral("dangerous");
  s << (t.activated ? QStringLiteral("activated") : QStringLiteral("sleeping"));
  if (t.selected) s << QStringLiteral("selected");
  return s.join(QStringLiteral(", "));
}

int AisTableModel::rowCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : static_cast<int>(targets_.size());
}

int AisTableModel::columnCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : ColumnCount;
}

QVariant AisTableModel::data(const QModelIndex& index, int role) const {
  if (!index.isValid() || index.row() >= rowCount()) return {};
  const track::AisTarget& t = targets_[static_cast<std::size_t>(index.row())];
  const int c = index.column();
  if (role == Qt::UserRole) {  // sort key: numbers by value, absent values last
    switch (c) {
      case Mmsi:
        return static_cast<qulonglong>(t.mmsi);
      case Range:
        return t.rangeValid ? t.rangeM : 1e30;
      case Bearing:
        return t.rangeValid ? t.bearingRad : 1e30;
      case Sog:
        return t.sogKn.value_or(1e30);
      case Cog:
        return t.cogDeg.value_or(1e30);
      case Cpa:
        return t.cpaValid ? t.cpa.cpaM : 1e30;
      case Tcpa:
        return t.cpaValid ? t.cpa.tcpaS : 1e30;
      default:
        return data(index, Qt::DisplayRole);
    }
  }
  if (role == Qt::ForegroundRole && (t.dangerous || t.distress()) && !t.lost)
    return QBrush(QColor(200, 0, 0));
  if (role == Qt::TextAlignmentRole && c != Name && c != Status && c != Class)
    return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
  if (role != Qt::DisplayRole) return {};
  switch (c) {
    case Mmsi:
      return QString::number(t.mmsi);
    case Name:
      return QString::fromStdString(t.info.name);
    case Class:
      return t.device != track::AisDevice::None ? QString::fromLatin1(track::aisDeviceName(t.device))
                                                : QString::fromLatin1(track::aisClassName(t.cls));
    case Range:
      return t.rangeValid ? formatDistance(t.rangeM, units_) : QString();
    case Bearing:
      return t.rangeValid ? formatBearing(t.bearingRad) : QString();
    case Sog:
      return t.sogKn ? formatSpeed(knotsToMps(*t.sogKn), units_) : QString();
    case Cog:
      return t.cogDeg ? formatBearing(degToRad(*t.cogDeg)) : QString();
    case Cpa:
      return t.cpaValid ? formatDistance(t.cpa.cpaM, units_) : QString();
    case Tcpa:
      return t.cpaValid ? QStringLiteral("%1 min").arg(t.cpa.tcpaS / 60.0, 0, 'f', 1) : QString();
    case Status:
      return statusText(t);
    default:
      return {};
  }
}

QVariant AisTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
  if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
  switch (section) {
    case Mmsi:
      return QStringLiteral("MMSI");
    case Name:
      return QStringLiteral("Name");
    case Class:
      return QStringLiteral("Class");
    case Range:
      return QStringLiteral("Range (%1)").arg(unitName(units_.distance));
    case Bearing:
      return QStringLiteral("Bearing");
    case Sog:
      return QStringLiteral("SOG (%1)").arg(unitName(units_.speed));
    case Cog:
      return QStringLiteral("COG");
    case Cpa:
      return QStringLiteral("CPA (%1)").arg(unitName(units_.distance));
    case Tcpa:
      return QStringLiteral("TCPA");
    case Status:
      return QStringLiteral("Status");
    default:
      return {};
  }
}

}  // namespace reckoner::ui
