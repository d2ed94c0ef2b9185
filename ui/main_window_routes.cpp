// Routes in the window (docs/gui.md "Routes"; MSC.232(82) 11.3): the Route menu and toolbar toggle,
// the Route dock (RoutePanel), the route library (RouteLibrary: the routes of a directory of RTZ files,
// one shown and edited, one active) and the route on the chart (RouteOverlay). Every edit, from the
// chart or the table, goes through the library (undo with Ctrl+Z); a route check follows 300 ms after
// the last edit, and whenever the charts or the safety settings change.
#include <QAction>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QPainter>
#include <QPixmap>
#include <QSignalBlocker>
#include <QStatusBar>
#include <QToolBar>
#include <QUndoStack>
#include <algorithm>
#include <cmath>
#include <set>

#include "common/angles.h"
#include "common/units.h"
#include "io/text_format.h"
#include "ui/main_window.h"
#include "ui/panels/route_panel.h"
#include "ui/route_library.h"

namespace reckoner::ui {
namespace {
constexpr int kRouteCheckDelayMs = 300;

/// The toolbar's Route edit toggle: a leg between two waypoints, in the route colour (small: the
/// toolbar row is full).
QIcon routeEditIcon() {
  QPixmap pm(24, 24);
  pm.fill(Qt::transparent);
  QPainter p(&pm);
  p.setRenderHint(QPainter::Antialiasing);
  const QColor orange(240, 130, 0);
  p.setPen(QPen(orange, 2.5, Qt::DashLine, Qt::FlatCap));
  p.drawLine(QPointF(6, 18), QPointF(18, 6));
  p.setPen(QPen(orange, 2.0));
  p.setBrush(Qt::white);
  p.drawEllipse(QPointF(5.5, 18.5), 3.5, 3.5);
  p.drawEllipse(QPointF(18.5, 5.5), 3.5, 3.5);
  return QIcon(pm);
}

QString positionText(const charts::LatLon& p) {
  return QString::fromStdString(io::formatLatitude(p.latDeg) + ' ' + io::formatLongitude(p.lonDeg));
}
}  // namespace

void MainWindow::buildRouteDock() {
  routes_ = new RouteLibrary(this);
  routePanel_ = new RoutePanel(this);
  addScrollDock(tr("Route"), QStringLiteral("routeDock"), routePanel_, Qt::RightDockWidgetArea);
  routeCheckTimer_.setSingleShot(true);
  routeCheckTimer_.setInterval(kRouteCheckDelayMs);
  connect(&routeCheckTimer_, &QTimer::timeout, this, &MainWindow::checkRoute);
}

void MainWindow::buildRouteMenu() {
  QMenu* menu = menuBar()->addMenu(tr("&Route"));
  menu->setObjectName(QStringLiteral("routeMenu"));
  routeEditAction_ = menu->addAction(tr("Edit route"));
  routeEditAction_->setObjectName(QStringLiteral("routeEdit"));
  routeEditAction_->setCheckable(true);
  routeEditAction_->setIcon(routeEditIcon());
  routeEditAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_E));
  routeEditAction_->setToolTip(
      tr("Route edit: a click on the chart adds a waypoint, a drag moves one, the right button inserts, "
         "deletes and renames; Esc ends (Ctrl+E)"));
  connect(routeEditAction_, &QAction::toggled, this, &MainWindow::setRouteEditing);
  const auto add = [&](const QString& text, const char* name, auto slot) {
    QAction* a = menu->addAction(text, this, slot);
    a->setObjectName(QString::fromLatin1(name));
    return a;
  };
  add(tr("New route"), "routeNewAction", [this] { routes_->newRoute(); });
  add(tr("Import route (RTZ, GPX)…"), "routeImportAction", [this] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Import route"), {},
                                                      tr("Routes (*.rtz *.gpx *.RTZ *.GPX);;All files (*)"));
    if (!path.isEmpty()) importRoute(path);
  });
  add(tr("Save route"), "routeSaveAction", [this] { saveRoute(); });
  add(tr("Export route as RTZ…"), "routeExportAction", [this] { askExportRoute(); });
  add(tr("Delete route…"), "routeDeleteAction", [this] { askDeleteRoute(); });
  routeActivateAction_ = add(tr("Activate route"), "routeActivateAction",
                             [this](bool on) { routes_->setActive(on ? routes_->current() : -1); });
  routeActivateAction_->setCheckable(true);
  buildVoyageActions(menu);
  menu->addSeparator();
  add(tr("Check route"), "routeCheckAction", [this] {
    checkRoute();
    statusBar()->showMessage(routePanel_->checkSummary()->text(), 10000);
  });
  menu->addSeparator();
  QAction* undo = routes_->undoStack()->createUndoAction(this, tr("Undo route edit"));
  undo->setObjectName(QStringLiteral("routeUndo"));
  undo->setShortcut(QKeySequence::Undo);
  QAction* redo = routes_->undoStack()->createRedoAction(this, tr("Redo route edit"));
  redo->setObjectName(QStringLiteral("routeRedo"));
  redo->setShortcut(QKeySequence::Redo);
  menu->addAction(undo);
  menu->addAction(redo);

  QToolBar* bar = addToolBar(tr("Route"));
  bar->setObjectName(QStringLiteral("routeToolbar"));
  bar->setToolButtonStyle(Qt::ToolButtonIconOnly);
  bar->addAction(routeEditAction_);
  connectRoutes();
  if (const QStringList failures = routes_->load(RouteLibrary::defaultDirectory()); !failures.isEmpty())
    reportError(tr("Route library: not read: %1").arg(failures.join(QLatin1Char('\n'))));
}

void MainWindow::connectRoutes() {
  RouteOverlay* overlay = view_->routeOverlay();
  connect(overlay, &RouteOverlay::routeEdited, this, &MainWindow::applyRouteEdit);
  connect(overlay, &RouteOverlay::waypointSelected, routePanel_, &RoutePanel::selectWaypoint);
  connect(overlay, &RouteOverlay::renameRequested, this, [this](int index) {
    if (auto* d = findChild<QDockWidget*>(QStringLiteral("routeDock"))) d->raise();
    routePanel_->editWaypointName(index);
  });
  connect(overlay, &RouteOverlay::editingChanged, routeEditAction_, &QAction::setChecked);
  connect(routePanel_, &RoutePanel::editRequested, this, &MainWindow::applyRouteEdit);
  connect(routePanel_, &RoutePanel::refused, this, &MainWindow::reportError);
  connect(routePanel_, &RoutePanel::waypointSelected, this, &MainWindow::showRouteWaypoint);
  connect(routePanel_, &RoutePanel::findingSelected, this, &MainWindow::showRouteFinding);
  connect(routePanel_, &RoutePanel::routeChosen, routes_, &RouteLibrary::setCurrent);
  connect(routePanel_, &RoutePanel::newRequested, routes_, &RouteLibrary::newRoute);
  connect(routePanel_, &RoutePanel::importRequested, findChild<QAction*>(QStringLiteral("routeImportAction")),
          &QAction::trigger);
  connect(routePanel_, &RoutePanel::saveRequested, this, &MainWindow::saveRoute);
  connect(routePanel_, &RoutePanel::exportRequested, this, &MainWindow::askExportRoute);
  connect(routePanel_, &RoutePanel::deleteRequested, this, &MainWindow::askDeleteRoute);
  connect(routePanel_, &RoutePanel::activateRequested, this,
          [this](bool on) { routes_->setActive(on ? routes_->current() : -1); });
  connect(routePanel_, &RoutePanel::renameRouteRequested, this, [this](const QString& name) {
    if (const geo::Route* r = routes_->currentRoute()) {
      geo::Route after = *r;
      after.name = name.toStdString();
      applyRouteEdit(after, tr("Rename route"));
    }
  });
  connect(routePanel_, &RoutePanel::checkRequested, this, &MainWindow::checkRoute);
  connect(routes_, &RouteLibrary::listChanged, this, [this] {
    routePanel_->setLibrary(routes_->names(), routes_->current(), routes_->active());
    const QSignalBlocker block(routeActivateAction_);
    routeActivateAction_->setChecked(routes_->current() >= 0 && routes_->current() == routes_->active());
    routeActivateAction_->setEnabled(routes_->current() >= 0);
  });
  connect(routes_, &RouteLibrary::currentChanged, this, [this] {
    routeFindings_.clear();
    routeTurns_.clear();
    routeTurnIds_.clear();
    showCurrentRoute();
  });
  connect(routes_, &RouteLibrary::routeChanged, this, [this](int index) {
    if (index == routes_->current()) showCurrentRoute();
  });
  connect(routes_, &RouteLibrary::activeRouteChanged, this, [this] { showCurrentRoute(); });
  // New charts or safety settings: the findings of the route shown are checked again.
  connect(view_, &ChartView::cellsChanged, this, [this] { routeCheckTimer_.start(); });
  connect(view_, &ChartView::settingsChanged, this, [this] { routeCheckTimer_.start(); });
}

void MainWindow::setRouteEditing(bool on) {
  if (on && !routes_->currentRoute()) routes_->newRoute();
  view_->routeOverlay()->setEditing(on);
  if (on) {
    if (auto* d = findChild<QDockWidget*>(QStringLiteral("routeDock"))) d->raise();
    view_->setFocus();
    statusBar()->showMessage(tr("Route edit: click to add waypoints; Esc ends"), 8000);
  }
}

void MainWindow::showCurrentRoute() {
  const geo::Route* r = routes_->currentRoute();
  const bool shownActive = r && routes_->current() == routes_->active();
  RouteOverlay* overlay = view_->routeOverlay();
  routePanel_->setRoute(r);
  if (r)
    overlay->setRoute(*r, shownActive);
  else
    overlay->clearRoute();
  const geo::Route* active = routes_->activeRoute();
  overlay->setActiveRoute(active && !shownActive ? std::optional<geo::Route>(*active) : std::nullopt);
  overlay->setFindings(routeFindings_);
  routeCheckTimer_.start();
}

void MainWindow::applyRouteEdit(const geo::Route& after, const QString& what) {
  QString error;
  if (!routes_->edit(after, what, &error)) reportError(error);
}

bool MainWindow::importRoute(const QString& path) {
  QString error;
  const int index = routes_->importFile(path, &error);
  if (!error.isEmpty()) reportError(error);
  if (index < 0) return false;
  statusBar()->showMessage(tr("Imported %1 into the route library").arg(QFileInfo(path).fileName()), 8000);
  return true;
}

bool MainWindow::saveRoute() {
  QString error;
  if (routes_->save(routes_->current(), &error)) {
    statusBar()->showMessage(tr("Saved %1").arg(routes_->at(routes_->current()).path), 8000);
    return true;
  }
  if (!error.isEmpty()) reportError(error);
  return false;
}

void MainWindow::askExportRoute() {
  const geo::Route* r = routes_->currentRoute();
  if (!r) return;
  QString path = QFileDialog::getSaveFileName(this, tr("Export route as RTZ"),
                                              QString::fromStdString(r->name) + QStringLiteral(".rtz"),
                                              tr("RTZ routes (*.rtz)"));
  if (path.isEmpty()) return;
  if (QFileInfo(path).suffix().isEmpty()) path += QStringLiteral(".rtz");
  QString error;
  if (routes_->exportTo(routes_->current(), path, &error))
    statusBar()->showMessage(tr("Exported %1").arg(path), 8000);
  else
    reportError(error);
}

void MainWindow::askDeleteRoute() {
  const geo::Route* r = routes_->currentRoute();
  if (!r) return;
  const auto answer = QMessageBox::question(
      this, tr("Delete route"),
      tr("Delete the route %1 and its file from the library?").arg(QString::fromStdString(r->name)));
  if (answer != QMessageBox::Yes) return;
  QString error;
  if (!routes_->remove(routes_->current(), &error)) reportError(error);
}

void MainWindow::checkRoute() {
  routeCheckTimer_.stop();
  routeFindings_.clear();
  routeTurns_.clear();
  const geo::Route* r = routes_->currentRoute();
  // The turns that do not fit between their legs need no chart (a route being drawn may not be valid yet).
  routeTurnIds_.clear();
  if (r && r->problems().empty()) routeTurns_ = geo::turnsThatDoNotFit(*r);
  for (const geo::TurnFit& t : routeTurns_) routeTurnIds_.push_back(r->waypoints[t.waypoint].id);
  const charts::SafetySettings safety = safetySettingsOf(view_->settings());
  std::vector<RouteFindingRow> rows;
  QString summary;
  if (!r || r->legCount() == 0) {
    summary = tr("Not checked: the route needs two waypoints");
  } else if (view_->cells().empty()) {
    summary = tr("Not checked: no charts open");
  } else {
    routeFindings_ = routeCheck_.check(*r, view_->cells(), safety);
    rows = routeFindingRows(*r);
    std::set<std::size_t> legs;
    int dangerous = 0;
    for (const charts::RouteFinding& f : routeFindings_) {
      legs.insert(f.leg);
      dangerous += charts::isDangerous(f.kind) ? 1 : 0;
    }
    summary = routeFindings_.empty() ? tr("No findings on %1 leg(s)").arg(r->legCount())
                                     : tr("%1 finding(s) on %2 of %3 leg(s), %4 dangerous")
                                           .arg(routeFindings_.size())
                                           .arg(legs.size())
                                           .arg(r->legCount())
                                           .arg(dangerous);
    summary += tr(" · safety contour %1 m, safety depth %2 m")
                   .arg(safety.safetyContourM, 0, 'g', 4)
                   .arg(safety.dangerDepthM(), 0, 'g', 4);
  }
  if (!routeTurns_.empty()) {
    summary += tr(" · %1 turn(s) that do not fit").arg(routeTurns_.size());
    const std::vector<RouteFindingRow> turns = routeTurnRows(*r);
    rows.insert(rows.end(), turns.begin(), turns.end());
  }
  view_->routeOverlay()->setFindings(routeFindings_);
  routePanel_->setFindings(rows, summary);
}

std::vector<RouteFindingRow> MainWindow::routeTurnRows(const geo::Route& route) const {
  std::vector<RouteFindingRow> rows;
  for (const geo::TurnFit& t : routeTurns_) {
    const geo::Waypoint& w = route.waypoints[t.waypoint];
    RouteFindingRow row;
    row.leg = static_cast<int>(t.waypoint);
    row.turn = true;
    row.legName =
        tr("at %1").arg(w.name.empty() ? tr("waypoint %1").arg(w.id) : QString::fromStdString(w.name));
    row.kind = tr("turn does not fit");
    row.className = tr("%1° to %2: radius %3 NM needs %4 NM each side, legs %5 and %6 NM; sailed on %7 NM")
                        .arg(std::abs(radToDeg(t.changeRad)), 0, 'f', 0)
                        .arg(t.changeRad < 0.0 ? tr("port") : tr("starboard"))
                        .arg(metresToNm(t.plannedRadiusM), 0, 'f', 2)
                        .arg(metresToNm(t.plannedWheelOverM), 0, 'f', 2)
                        .arg(metresToNm(t.legBeforeM), 0, 'f', 2)
                        .arg(metresToNm(t.legAfterM), 0, 'f', 2)
                        .arg(metresToNm(t.radiusM), 0, 'f', 2);
    row.depth = QStringLiteral("–");
    row.position = positionText({w.position.latDeg, w.position.lonDeg});
    row.dangerous = false;
    rows.push_back(row);
  }
  return rows;
}

std::vector<RouteFindingRow> MainWindow::routeFindingRows(const geo::Route& route) const {
  std::vector<RouteFindingRow> rows;
  const charts::ChartHazards* hazards = routeCheck_.lastHazards();
  for (const charts::RouteFinding& f : routeFindings_) {
    RouteFindingRow row;
    row.leg = static_cast<int>(f.leg);
    if (f.leg >= 1 && f.leg < route.waypoints.size())
      row.legName = QStringLiteral("%1 – %2").arg(QString::fromStdString(route.waypoints[f.leg - 1].name),
                                                  QString::fromStdString(route.waypoints[f.leg].name));
    row.kind =
        QString::fromLatin1(charts::hazardKindName(f.kind)).replace(QLatin1Char('_'), QLatin1Char(' '));
    row.className = QString::fromStdString(f.objectClass);
    try {
      if (hazards)
        row.className = QStringLiteral("%1 (%2)").arg(
            QString::fromStdString(charts::findingReport(*hazards, f).className), row.className);
    } catch (const std::exception&) {  // no S-57 catalogue: the acronym alone
    }
    row.depth = f.depthM ? QString::number(*f.depthM, 'f', 1) : QStringLiteral("–");
    row.position = positionText(f.position);
    row.dangerous = charts::isDangerous(f.kind);
    rows.push_back(row);
  }
  return rows;
}

void MainWindow::stopFollowingOwnShip() {
  if (!view_->overlay().followOwnShip) return;
  OverlaySettings s = view_->overlay();
  s.followOwnShip = false;
  view_->setOverlay(s);
}

void MainWindow::showRouteFinding(int index) {
  // The rows of the findings, then those of the turns that do not fit (at their waypoints, found by id:
  // an edit may have moved them in the 300 ms before the check runs again).
  const auto turn = static_cast<std::size_t>(index) - routeFindings_.size();
  if (index >= 0 && static_cast<std::size_t>(index) >= routeFindings_.size() && turn < routeTurns_.size()) {
    view_->routeOverlay()->setSelectedFinding(std::nullopt);
    const geo::Route* r = routes_->currentRoute();
    if (!r) return;
    const auto& wps = r->waypoints;
    const auto it = std::find_if(wps.begin(), wps.end(),
                                 [&](const geo::Waypoint& w) { return w.id == routeTurnIds_[turn]; });
    if (it == wps.end()) return;
    const auto k = static_cast<int>(it - wps.begin());
    routePanel_->selectWaypoint(k);
    showRouteWaypoint(k);
    return;
  }
  if (index < 0 || index >= static_cast<int>(routeFindings_.size())) return;
  const charts::RouteFinding& f = routeFindings_[static_cast<std::size_t>(index)];
  view_->routeOverlay()->setSelectedFinding(static_cast<std::size_t>(index));
  // Centred on it; following own ship would take the view back at the next frame.
  stopFollowingOwnShip();
  const charts::Viewport v = view_->viewport();
  view_->setView(f.position, v.scaleDenominator(), v.rotationRad());
  std::vector<charts::PickedFeature> report;
  try {
    if (const charts::ChartHazards* h = routeCheck_.lastHazards())
      report.push_back(charts::findingReport(*h, f));
  } catch (const std::exception& e) {
    reportError(QString::fromStdString(e.what()));
  }
  showPickedFeatures(report, f.position);
}

void MainWindow::showRouteWaypoint(int index) {
  const geo::Route* r = routes_->currentRoute();
  if (!r || index < 0 || index >= static_cast<int>(r->waypoints.size())) return;
  view_->routeOverlay()->setSelectedWaypoint(static_cast<std::size_t>(index));
  const geo::GeoPoint& p = r->waypoints[static_cast<std::size_t>(index)].position;
  const charts::Viewport v = view_->viewport();
  const charts::ScreenPoint s = v.toScreen({p.latDeg, p.lonDeg});
  if (s.x >= 0 && s.y >= 0 && s.x <= v.width() && s.y <= v.height()) return;  // on screen: stays
  stopFollowingOwnShip();
  view_->setView({p.latDeg, p.lonDeg}, v.scaleDenominator(), v.rotationRad());
}

bool MainWindow::confirmUnsavedRoutes() {
  QStringList names;
  for (int i = 0; i < routes_->count(); ++i)
    if (routes_->at(i).modified) names << QString::fromStdString(routes_->at(i).route.name);
  if (names.isEmpty() || !options_.askToSaveOnClose) return true;
  const auto answer = QMessageBox::question(
      this, tr("Unsaved routes"), tr("Routes edited and not saved: %1. Save them?").arg(names.join(", ")),
      QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
  if (answer != QMessageBox::Save) return answer == QMessageBox::Discard;
  for (int i = 0; i < routes_->count(); ++i) {
    QString error;
    if (routes_->at(i).modified && !routes_->save(i, &error)) {
      reportError(error);  // one that cannot be saved (fewer than two waypoints): the window stays
      return false;
    }
  }
  return true;
}

}  // namespace reckoner::ui
