#include "ui/panels/target_table_model.h"

#include <QBrush>
#include <QColor>
#include <algorithm>

#include "common/angles.h"
#include "tracking/cpa.h"

namespace reckoner::ui {

void TargetTableModel::setTracks(const std::vector<sim::TrackSnapshot>& tracks) {
  const bool sameRows = tracks.size() == tracks_.size() &&
                        std::equal(tracks.begin(), tracks.end(), tracks_.begin(),
                                   [](const auto& a, const auto& b) { return a.trackId == b.trackId; });
  if (sameRows) {
    raw_ = tracks;
    refreshKinematics();
    if (!tracks_.empty()) emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
    return;
  }
  beginResetModel();
  raw_ = tracks;
  refreshKinematics();
  endResetModel();
}

void TargetTableModel::refreshKinematics() {
  tracks_ = raw_;
  if (ccrpDxM_ == 0.0 && ccrpDyM_ == 0.0) return;  // the CCRP is the estimated point: the tracker's figures
  for (sim::TrackSnapshot& t : tracks_) {
    est::ttkf::Belief b = t.estimate;
    b.x[est::ttkf::kOwnX] += ccrpDxM_;
    b.x[est::ttkf::kOwnY] += ccrpDyM_;
    t.kinematics = track::kinematicsOf(b, convergenceRad_);
  }
}

void TargetTableModel::setUnits(const DisplayUnits& units) {
  if (units == units_) return;
  units_ = units;
  emit headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
  if (!tracks_.empty()) emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
}

void TargetTableModel::setCcrpOffset(double dxM, double dyM, double convergenceRad) {
  if (dxM == ccrpDxM_ && dyM == ccrpDyM_ && convergenceRad == convergenceRad_) return;
  ccrpDxM_ = dxM;
  ccrpDyM_ = dyM;
  convergenceRad_ = convergenceRad;
  refreshKinematics();
  if (!tracks_.empty()) emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
}

int TargetTableModel::trackIdAt(int row) const {
  return row >= 0 && row < rowCount() ? tracks_[static_cast<std::size_t>(row)].trackId : -1;
}

int TargetTableModel::rowOf(int trackId) const {
  for (std::size_t i = 0; i < tracks_.size(); ++i)
    if (tracks_[i].trackId == trackId) return static_cast<int>(i);
  return -1;
}

int TargetTableModel::rowCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : static_cast<int>(tracks_.size());
}

int TargetTableModel::columnCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : ColumnCount;
}

QVariant TargetTableModel::data(const QModelIndex& index, int role) const {
  if (!index.isValid() || index.row() >= rowCount()) return {};
  const sim::TrackSnapshot& t = tracks_[static_cast<std::size_t>(index.row())];
  const auto& k = t.kinematics;
  const bool cpaKnown = k.cpa.defined && t.status == track::TrackStatus::Confirmed;
  if (role == Qt::UserRole) {  // sort key
    switch (index.column()) {
      case Id:
        return t.trackId;
      case Status:
        return static_cast<int>(t.status) * 2 + (t.dangerous ? 0 : 1);
      case Filter:
        return static_cast<int>(t.kind);
      case Range:
        return k.rangeM;
      case Bearing:
        return k.trueBearingRad;
      case Course:
        return k.trueCourseRad;
      case Speed:
        return k.speedMps;
      case Cpa:
        return cpaKnown ? k.cpa.cpaM : 1e12;
      case Tcpa:
        return cpaKnown ? k.cpa.tcpaS : 1e12;
      case SdCpa:
        return k.cpa.sdCpaM;
      case SdTcpa:
        return k.cpa.sdTcpaS;
      default:
        return {};
    }
  }
  if (role == Qt::ForegroundRole && t.dangerous) return QBrush(QColor(200, 0, 0));
  if (role == Qt::TextAlignmentRole)
    return index.column() == Status || index.column() == Filter ? int(Qt::AlignLeft | Qt::AlignVCenter)
                                                                : int(Qt::AlignRight | Qt::AlignVCenter);
  if (role != Qt::DisplayRole) return {};
  switch (index.column()) {
    case Id:
      return t.trackId;
    case Status: {
      QString s = QString::fromLatin1(track::trackStatusName(t.status));
      if (t.dangerous) s += QStringLiteral(" DANGER");
      if (t.manoeuvring) s += QStringLiteral(" MANOEUVRE");
      if (t.manual) s += QStringLiteral(" (manual)");
      return s;
    }
    case Filter:
      return QString::fromLatin1(track::trackerKindName(t.kind));
    case Range:
      return formatDistance(k.rangeM, units_, 2, false);
    case Bearing:
      return QString::number(radToDeg(k.trueBearingRad), 'f', 1);
    case Course:
      return t.status == track::TrackStatus::Tentative ? QString()
                                                       : QString::number(radToDeg(k.trueCourseRad), 'f', 1);
    case Speed:
      return t.status == track::TrackStatus::Tentative ? QString()
                                                       : formatSpeed(k.speedMps, units_, 1, false);
    case Cpa:
      return cpaKnown ? formatDistance(k.cpa.cpaM, units_, 2, false) : QString();
    case Tcpa:
      return cpaKnown ? QString::number(k.cpa.tcpaS / 60.0, 'f', 1) : QString();
    case SdCpa:
      return cpaKnown ? formatDistance(k.cpa.sdCpaM, units_, 2, false) : QString();
    case SdTcpa:
      return cpaKnown ? QString::number(k.cpa.sdTcpaS / 60.0, 'f', 1) : QString();
    default:
      return {};
  }
}

QVariant TargetTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
  if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
  const QString d = unitName(units_.distance), v = unitName(units_.speed);
  const QString names[] = {
      tr("Track"),    tr("Status"),           tr("Filter"),          tr("Range %1").arg(d),
      tr("Brg °T"),   tr("Course °T"),        tr("Speed %1").arg(v), tr("CPA %1").arg(d),
      tr("TCPA min"), tr("sd CPA %1").arg(d), tr("sd TCPA min")};
  return section >= 0 && section < ColumnCount ? QVariant(names[section]) : QVariant();
}

}  // namespace reckoner::ui
