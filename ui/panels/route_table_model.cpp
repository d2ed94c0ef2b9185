#include "ui/panels/route_table_model.h"

#include <cmath>

#include "common/units.h"
#include "io/text_format.h"
#include "ui/common/route_text.h"

namespace reckoner::ui {
namespace {

const QString kNone = QStringLiteral("–");

QString fieldName(int column) {
  switch (column) {
    case RouteTableModel::Name:
      return QStringLiteral("name");
    case RouteTableModel::Latitude:
      return QStringLiteral("latitude");
    case RouteTableModel::Longitude:
      return QStringLiteral("longitude");
    case RouteTableModel::Radius:
      return QStringLiteral("turn radius");
    case RouteTableModel::PortXtl:
      return QStringLiteral("port cross-track limit");
    case RouteTableModel::StarboardXtl:
      return QStringLiteral("starboard cross-track limit");
    case RouteTableModel::Speed:
      return QStringLiteral("planned speed");
    case RouteTableModel::Geometry:
      return QStringLiteral("leg geometry");
    default:
      return {};
  }
}

std::optional<geo::LegGeometry> geometryOf(const QString& typed) {
  const QString t = typed.trimmed().toLower();
  for (const char* s : {"rhumb line", "rhumb", "rl", "loxodrome"})
    if (t == QLatin1String(s)) return geo::LegGeometry::RhumbLine;
  for (const char* s : {"great circle", "gc", "orthodrome"})
    if (t == QLatin1String(s)) return geo::LegGeometry::GreatCircle;
  return std::nullopt;
}

}  // namespace

RouteTableModel::RouteTableModel(QObject* parent) : QAbstractTableModel(parent) {}

void RouteTableModel::setRoute(const geo::Route* route) {
  if (route && hasRoute_ && route->waypoints.size() == route_.waypoints.size()) {
    // The same rows: their cells change (an editor being closed and the selection stay valid).
    route_ = *route;
    if (rowCount() > 0) emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
    return;
  }
  beginResetModel();
  hasRoute_ = route != nullptr;
  route_ = route ? *route : geo::Route{};
  endResetModel();
}

void RouteTableModel::setUnits(const DisplayUnits& units) {
  units_ = units;
  if (rowCount() > 0) emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
  emit headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
}

int RouteTableModel::rowCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : static_cast<int>(route_.waypoints.size());
}

int RouteTableModel::columnCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : ColumnCount;
}

QString RouteTableModel::geometryText(geo::LegGeometry g) {
  return g == geo::LegGeometry::GreatCircle ? tr("Great circle") : tr("Rhumb line");
}

QString RouteTableModel::text(int row, int column) const {
  const auto k = static_cast<std::size_t>(row);
  const geo::Waypoint& w = route_.waypoints[k];
  const auto nm = [this](double v) { return formatDistance(nmToMetres(v), units_, 2, false); };
  switch (column) {
    case Name:
      return QString::fromStdString(w.name);
    case Latitude:
      return QString::fromStdString(io::formatLatitude(w.position.latDeg));
    case Longitude:
      return QString::fromStdString(io::formatLongitude(w.position.lonDeg));
    case Course:
      return hasLeg(row) ? formatBearing(geo::legStartCourseRad(route_, k)) : kNone;
    case Distance:
      return hasLeg(row) ? formatDistance(geo::legLengthM(route_, k), units_, 2, false) : kNone;
    case Radius:
      return hasTurn(row) ? nm(route_.turnRadiusNm(k)) : kNone;
    case PortXtl:
      return hasLeg(row) ? nm(w.leg.portXtlNm) : kNone;
    case StarboardXtl:
      return hasLeg(row) ? nm(w.leg.starboardXtlNm) : kNone;
    case Speed:
      if (!hasLeg(row) || !w.leg.plannedSpeedKn) return kNone;
      return formatSpeed(knotsToMps(*w.leg.plannedSpeedKn), units_, 1, false);
    case Geometry:
      return hasLeg(row) ? geometryText(w.leg.geometry) : kNone;
    default:
      return {};
  }
}

QVariant RouteTableModel::data(const QModelIndex& index, int role) const {
  if (!index.isValid() || index.row() >= rowCount()) return {};
  const int row = index.row(), column = index.column();
  if (role == Qt::DisplayRole) return text(row, column);
  if (role == Qt::EditRole) {
    const QString t = text(row, column);
    return t == kNone ? QString() : t;
  }
  if (role == Qt::TextAlignmentRole && column >= Course && column <= Speed)
    return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
  if (role == Qt::ToolTipRole && column == Radius && hasTurn(row) &&
      !route_.waypoints[static_cast<std::size_t>(row)].turnRadiusNm)
    return tr("The route's default turn radius (type a value to set this waypoint's own)");
  if (role == Qt::ToolTipRole && column == Course) return tr("True course at the start of the leg to here");
  return {};
}

QVariant RouteTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
  if (role != Qt::DisplayRole) return {};
  if (orientation == Qt::Vertical) return section + 1;
  const QString d = unitName(units_.distance), s = unitName(units_.speed);
  switch (section) {
    case Name:
      return tr("Name");
    case Latitude:
      return tr("Latitude");
    case Longitude:
      return tr("Longitude");
    case Course:
      return tr("Course");
    case Distance:
      return tr("Dist (%1)").arg(d);
    case Radius:
      return tr("Radius (%1)").arg(d);
    case PortXtl:
      return tr("Port XTL (%1)").arg(d);
    case StarboardXtl:
      return tr("Stbd XTL (%1)").arg(d);
    case Speed:
      return tr("Speed (%1)").arg(s);
    case Geometry:
      return tr("Leg");
    default:
      return {};
  }
}

Qt::ItemFlags RouteTableModel::flags(const QModelIndex& index) const {
  if (!index.isValid()) return Qt::NoItemFlags;
  const int row = index.row(), column = index.column();
  Qt::ItemFlags f = Qt::ItemIsSelectable | Qt::ItemIsEnabled;
  const bool editable = column == Name || column == Latitude || column == Longitude ||
                        (column == Radius && hasTurn(row)) ||
                        (hasLeg(row) && column >= PortXtl && column <= Geometry);
  return editable ? f | Qt::ItemIsEditable : f;
}

std::optional<double> RouteTableModel::distanceNm(const QString& typed, double maxNm, QString& why) const {
  const std::optional<double> v = io::parseFiniteNumber(typed.toStdString());
  const double nm = v ? metresToNm(metresFrom(*v, units_.distance)) : 0.0;
  if (!v || nm < 0.0 || nm > maxNm) {
    why = tr("'%1' is not a distance from 0 to %2 %3")
              .arg(typed, formatDistance(nmToMetres(maxNm), units_, 1, false), unitName(units_.distance));
    return std::nullopt;
  }
  return nm;
}

std::pair<std::optional<geo::Route>, QString> RouteTableModel::edited(int row, int column,
                                                                      const QString& typed) const {
  geo::Route r = route_;
  geo::Waypoint& w = r.waypoints[static_cast<std::size_t>(row)];
  QString why;
  switch (column) {
    case Name:
      if (typed.isEmpty()) return {std::nullopt, tr("a waypoint needs a name")};
      w.name = typed.toStdString();
      break;
    case Latitude:
    case Longitude: {
      const ParsedAngle a = column == Latitude ? parseLatitude(typed) : parseLongitude(typed);
      if (!a.deg) return {std::nullopt, a.problem};
      (column == Latitude ? w.position.latDeg : w.position.lonDeg) = *a.deg;
      break;
    }
    case Radius:
      if (typed.isEmpty()) {
        w.turnRadiusNm.reset();  // the route's default
      } else if (const auto nm = distanceNm(typed, kMaxRadiusNm, why)) {
        w.turnRadiusNm = *nm;
      } else {
        return {std::nullopt, why};
      }
      break;
    case PortXtl:
    case StarboardXtl: {
      const auto nm = distanceNm(typed, kMaxXtlNm, why);
      if (!nm) return {std::nullopt, why};
      (column == PortXtl ? w.leg.portXtlNm : w.leg.starboardXtlNm) = *nm;
      break;
    }
    case Speed:
      if (typed.isEmpty()) {
        w.leg.plannedSpeedKn.reset();
      } else {
        const std::optional<double> v = io::parseFiniteNumber(typed.toStdString());
        const double kn = v ? mpsToKnots(mpsFrom(*v, units_.speed)) : 0.0;
        if (!v || kn <= 0.0 || kn > kMaxSpeedKn)
          return {std::nullopt, tr("'%1' is not a speed above 0 and up to %2 %3")
                                    .arg(typed, formatSpeed(knotsToMps(kMaxSpeedKn), units_, 0, false),
                                         unitName(units_.speed))};
        w.leg.plannedSpeedKn = kn;
      }
      break;
    case Geometry: {
      const auto g = geometryOf(typed);
      if (!g) return {std::nullopt, tr("'%1': type Rhumb line (RL) or Great circle (GC)").arg(typed)};
      w.leg.geometry = *g;
      break;
    }
    default:
      return {std::nullopt, tr("this field cannot be edited")};
  }
  if (const QStringList problems = routeEditProblems(r); !problems.isEmpty())
    return {std::nullopt, problems.front()};
  return {r, {}};
}

bool RouteTableModel::setData(const QModelIndex& index, const QVariant& value, int role) {
  if (role != Qt::EditRole || !index.isValid() || index.row() >= rowCount() ||
      !(flags(index) & Qt::ItemIsEditable))
    return false;
  const int row = index.row(), column = index.column();
  const QString typed = value.toString().trimmed();
  // The text shown, given back unchanged, changes nothing (a position is shown to 0.001').
  if (typed == data(index, Qt::EditRole).toString()) return true;
  const QString name = QString::fromStdString(route_.waypoints[static_cast<std::size_t>(row)].name);
  const auto [after, why] = edited(row, column, typed);
  if (!after) {
    emit refused(tr("%1 %2: %3").arg(name, fieldName(column), why));
    return false;
  }
  emit editRequested(*after, tr("Edit %1 %2").arg(name, fieldName(column)));
  return true;
}

}  // namespace reckoner::ui
