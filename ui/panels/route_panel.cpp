#include "ui/panels/route_panel.h"

#include <QComboBox>
#include <QGridLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalBlocker>
#include <QStyledItemDelegate>
#include <QTableView>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>

#include "common/units.h"
#include "ui/panels/route_table_model.h"

namespace reckoner::ui {
namespace {

/// The leg geometry column: a choice of two, not a text to type.
class GeometryDelegate : public QStyledItemDelegate {
 public:
  using QStyledItemDelegate::QStyledItemDelegate;
  QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem&, const QModelIndex&) const override {
    auto* box = new QComboBox(parent);
    box->addItems({RouteTableModel::geometryText(geo::LegGeometry::RhumbLine),
                   RouteTableModel::geometryText(geo::LegGeometry::GreatCircle)});
    return box;
  }
  void setEditorData(QWidget* editor, const QModelIndex& index) const override {
    auto* box = static_cast<QComboBox*>(editor);
    box->setCurrentText(index.data(Qt::EditRole).toString());
  }
  void setModelData(QWidget* editor, QAbstractItemModel* model, const QModelIndex& index) const override {
    model->setData(index, static_cast<QComboBox*>(editor)->currentText(), Qt::EditRole);
  }
};

}  // namespace

RoutePanel::RoutePanel(QWidget* parent) : QWidget(parent), model_(new RouteTableModel(this)) {
  auto* column = new QVBoxLayout(this);
  column->addWidget(buildLibraryRow());

  table_ = new QTableView(this);
  table_->setObjectName(QStringLiteral("routeTable"));
  table_->setModel(model_);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::SingleSelection);
  table_->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                          QAbstractItemView::AnyKeyPressed);
  table_->setItemDelegateForColumn(RouteTableModel::Geometry, new GeometryDelegate(table_));
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 8);
  table_->setMinimumHeight(90);
  // Their preferred heights would make the dock scroll (the word-wrapped lines ask the layout for the
  // height at its width): the two tables share what the dock has.
  table_->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Ignored);
  column->addWidget(table_, 1);
  connect(model_, &RouteTableModel::editRequested, this, &RoutePanel::editRequested);
  connect(model_, &RouteTableModel::refused, this, &RoutePanel::refused);
  connect(table_->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
          [this](const QModelIndex& current) {
            if (current.isValid()) emit waypointSelected(current.row());
          });

  totals_ = new QLabel(this);
  totals_->setObjectName(QStringLiteral("routeTotals"));
  totals_->setWordWrap(true);
  column->addWidget(totals_);

  auto* checkRow = new QHBoxLayout;
  QPushButton* check = button(tr("Check route"), QStringLiteral("routeCheck"),
                              tr("Check every leg's corridor against the open charts (also done after each "
                                 "edit)"));
  connect(check, &QPushButton::clicked, this, &RoutePanel::checkRequested);
  checkRow->addWidget(check);
  summary_ = new QLabel(this);
  summary_->setObjectName(QStringLiteral("routeCheckSummary"));
  summary_->setWordWrap(true);
  checkRow->addWidget(summary_, 1);
  column->addLayout(checkRow);

  findings_ = new QTableWidget(0, 5, this);
  findings_->setObjectName(QStringLiteral("routeFindings"));
  findings_->setHorizontalHeaderLabels({tr("Leg"), tr("Kind"), tr("Class"), tr("Depth (m)"), tr("Position")});
  findings_->setSelectionBehavior(QAbstractItemView::SelectRows);
  findings_->setSelectionMode(QAbstractItemView::SingleSelection);
  findings_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  findings_->verticalHeader()->hide();
  findings_->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 8);
  findings_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  findings_->setMinimumHeight(80);
  findings_->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Ignored);
  column->addWidget(findings_, 1);
  connect(findings_, &QTableWidget::currentCellChanged, this, [this](int row, int, int, int) {
    if (row >= 0) emit findingSelected(row);
  });
  setRoute(nullptr);
}

QPushButton* RoutePanel::button(const QString& text, const QString& name, const QString& tip) {
  auto* b = new QPushButton(text, this);
  b->setObjectName(name);
  b->setToolTip(tip);
  return b;
}

QWidget* RoutePanel::buildLibraryRow() {
  auto* box = new QWidget(this);
  auto* grid = new QGridLayout(box);
  grid->setContentsMargins(0, 0, 0, 0);
  routes_ = new QComboBox(box);
  routes_->setObjectName(QStringLiteral("routeList"));
  routes_->setToolTip(tr("The routes of the library; the active one is marked"));
  connect(routes_, &QComboBox::activated, this, &RoutePanel::routeChosen);
  grid->addWidget(routes_, 0, 0, 1, 3);
  QPushButton* fresh =
      button(tr("New"), QStringLiteral("routeNew"), tr("A new empty route (then Route edit)"));
  QPushButton* import =
      button(tr("Import…"), QStringLiteral("routeImport"), tr("Add an RTZ or GPX route file to the library"));
  QPushButton* save = button(tr("Save"), QStringLiteral("routeSave"), tr("Save the route in the library"));
  QPushButton* exportRtz = button(tr("Export…"), QStringLiteral("routeExport"),
                                  tr("Save a copy of the route as an RTZ file anywhere"));
  QPushButton* remove = button(tr("Delete"), QStringLiteral("routeDelete"),
                               tr("Remove the route and its file from the library"));
  activate_ = button(tr("Activate"), QStringLiteral("routeActivate"),
                     tr("Make this the route the ship follows (one route is active at a time)"));
  connect(fresh, &QPushButton::clicked, this, &RoutePanel::newRequested);
  connect(import, &QPushButton::clicked, this, &RoutePanel::importRequested);
  connect(save, &QPushButton::clicked, this, &RoutePanel::saveRequested);
  connect(exportRtz, &QPushButton::clicked, this, &RoutePanel::exportRequested);
  connect(remove, &QPushButton::clicked, this, &RoutePanel::deleteRequested);
  connect(activate_, &QPushButton::clicked, this, [this] { emit activateRequested(!shownActive_); });
  grid->addWidget(activate_, 0, 3);
  grid->addWidget(fresh, 1, 0);
  grid->addWidget(import, 1, 1);
  grid->addWidget(save, 1, 2);
  grid->addWidget(exportRtz, 1, 3);
  grid->addWidget(remove, 2, 3);
  routeButtons_ = {save, exportRtz, remove, activate_};
  name_ = new QLineEdit(box);
  name_->setObjectName(QStringLiteral("routeName"));
  name_->setPlaceholderText(tr("Route name"));
  name_->setToolTip(tr("The route's name (Enter renames it; Ctrl+Z undoes)"));
  connect(name_, &QLineEdit::editingFinished, this, [this] {
    const QString n = name_->text().trimmed();
    if (!n.isEmpty() && n != QString::fromStdString(model_->route().name)) emit renameRouteRequested(n);
  });
  grid->addWidget(name_, 2, 0, 1, 3);
  return box;
}

void RoutePanel::setLibrary(const QStringList& names, int current, int active) {
  const QSignalBlocker block(routes_);
  routes_->clear();
  for (int i = 0; i < names.size(); ++i)
    routes_->addItem(i == active ? tr("%1  (active)").arg(names[i]) : names[i]);
  routes_->setCurrentIndex(current);
  shownActive_ = current >= 0 && current == active;
  activate_->setText(shownActive_ ? tr("Deactivate") : tr("Activate"));
}

void RoutePanel::setRoute(const geo::Route* route) {
  const int row = table_->currentIndex().row();
  hasRoute_ = route != nullptr;
  model_->setRoute(route);
  if (row >= 0 && row < model_->rowCount()) table_->selectRow(row);
  for (QPushButton* b : routeButtons_) b->setEnabled(route != nullptr);
  name_->setEnabled(route != nullptr);
  if (!name_->hasFocus()) name_->setText(route ? QString::fromStdString(route->name) : QString());
  totals_->setText(route ? totalsText(*route, units_) : tr("No route: New, Import…, or Route ▸ Edit route"));
}

void RoutePanel::setUnits(const DisplayUnits& units) {
  units_ = units;
  model_->setUnits(units);
  if (hasRoute_) totals_->setText(totalsText(model_->route(), units_));
}

QString RoutePanel::totalsText(const geo::Route& route, const DisplayUnits& units) {
  double totalM = 0.0, timeS = 0.0;
  int withoutSpeed = 0;
  for (std::size_t to = 1; to < route.waypoints.size(); ++to) {
    const double len = geo::legLengthM(route, to);
    totalM += len;
    const auto& kn = route.waypoints[to].leg.plannedSpeedKn;
    if (kn && *kn > 0.0)
      timeS += len / knotsToMps(*kn);
    else
      ++withoutSpeed;
  }
  const auto legs = static_cast<int>(route.legCount());
  QString s = tr("%1 waypoints · total %2").arg(route.waypoints.size()).arg(formatDistance(totalM, units));
  if (legs == 0) return s;
  if (withoutSpeed == legs) return s + tr(" · no planned speeds");
  const auto minutes = static_cast<long>(std::lround(timeS / 60.0));
  s +=
      tr(" · %1 h %2 min at the planned speeds").arg(minutes / 60).arg(minutes % 60, 2, 10, QLatin1Char('0'));
  if (withoutSpeed > 0) s += tr(" (%1 leg(s) without one not counted)").arg(withoutSpeed);
  return s;
}

void RoutePanel::setFindings(const std::vector<RouteFindingRow>& rows, const QString& summary) {
  const QSignalBlocker block(findings_);
  summary_->setText(summary);
  findings_->clearContents();
  findings_->setRowCount(static_cast<int>(rows.size()));
  for (int i = 0; i < static_cast<int>(rows.size()); ++i) {
    const RouteFindingRow& r = rows[static_cast<std::size_t>(i)];
    const QString cells[] = {r.turn ? r.legName : QStringLiteral("%1 %2").arg(r.leg).arg(r.legName), r.kind,
                             r.className, r.depth, r.position};
    for (int c = 0; c < 5; ++c) {
      auto* item = new QTableWidgetItem(cells[c]);
      item->setToolTip(cells[c]);  // the class and a turn's figures are longer than their column
      if (r.dangerous && c == 1) {
        QFont f = item->font();
        f.setBold(true);
        item->setFont(f);
      }
      findings_->setItem(i, c, item);
    }
  }
}

void RoutePanel::selectWaypoint(int index) {
  if (index < 0 || index >= model_->rowCount()) {
    table_->clearSelection();
    return;
  }
  if (table_->currentIndex().row() == index) return;
  const QSignalBlocker block(table_->selectionModel());
  table_->setCurrentIndex(model_->index(index, RouteTableModel::Name));
  table_->selectRow(index);
  table_->scrollTo(model_->index(index, RouteTableModel::Name));
}

void RoutePanel::editWaypointName(int index) {
  if (index < 0 || index >= model_->rowCount()) return;
  const QModelIndex i = model_->index(index, RouteTableModel::Name);
  table_->setCurrentIndex(i);
  table_->edit(i);
}

}  // namespace reckoner::ui
