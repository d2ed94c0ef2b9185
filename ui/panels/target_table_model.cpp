#include "ui/panels/target_table_model.h"

#include <QBrush>
#include <QColor>
#include <algorithm>

#include "common/angles.h"
#include "common/units.h"

namespace reckoner::ui {

void TargetTableModel::setTracks(const std::vector<sim::TrackSnapshot>& tracks) {
  const bool sameRows = tracks.size() == tracks_.size() &&
                        std::equal(tracks.begin(), tracks.end(), tracks_.begin(),
                                   [](const auto& a, const auto& b) { return a.trackId == b.trackId; });
  if (sameRows) {
    tracks_ = tracks;
    if (!tracks_.empty()) emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
    return;
  }
  beginResetModel();
  tracks_ = tracks;
  endResetModel();
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
      return QString::number(metresToNm(k.rangeM), 'f', 2);
    case Bearing:
      return QString::number(radToDeg(k.trueBearingRad), 'f', 1);
    case Course:
      return t.status == track::TrackStatus::Tentative ? QString()
                                                       : QString::number(radToDeg(k.trueCourseRad), 'f', 1);
    case Speed:
      return t.status == track::TrackStatus::Tentative ? QString()
                                                       : QString::number(k.speedMps / kMpsPerKnot, 'f', 1);
    case Cpa:
      return cpaKnown ? QString::number(metresToNm(k.cpa.cpaM), 'f', 2) : QString();
    case Tcpa:
      return cpaKnown ? QString::number(k.cpa.tcpaS / 60.0, 'f', 1) : QString();
    case SdCpa:
      return cpaKnown ? QString::number(metresToNm(k.cpa.sdCpaM), 'f', 2) : QString();
    case SdTcpa:
      return cpaKnown ? QString::number(k.cpa.sdTcpaS / 60.0, 'f', 1) : QString();
    default:
      return {};
  }
}

QVariant TargetTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
  if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
  static const char* const kNames[] = {"Track",    "Status",    "Filter",     "Range NM",
                                       "Brg °T",   "Course °T", "Speed kn",   "CPA NM",
                                       "TCPA min", "sd CPA NM", "sd TCPA min"};
  return section >= 0 && section < ColumnCount ? QString::fromUtf8(kNames[section]) : QVariant();
}

}  // namespace reckoner::ui
