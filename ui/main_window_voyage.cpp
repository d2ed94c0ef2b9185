// The voyage in the window (docs/gui.md "Route monitoring"): the active route of the library goes to
// the simulation (and to a live run), where own ship is monitored against it and, with Route > Follow
// route, steered along it by the autopilot; the charts shown and the mariner's safety contour go with
// it for the anti-grounding look-ahead. The Voyage dock shows the monitoring; the chart the look-ahead
// area (EcdisView::paintLookAhead).
#include <QAction>
#include <QDockWidget>
#include <QMenu>
#include <QMenuBar>
#include <QSignalBlocker>
#include <QStatusBar>

#include "ui/common/route_text.h"
#include "ui/main_window.h"
#include "ui/panels/voyage_panel.h"
#include "ui/route_check_cache.h"
#include "ui/route_library.h"

namespace reckoner::ui {

void MainWindow::buildVoyageDock() {
  voyagePanel_ = new VoyagePanel(this);
  addScrollDock(tr("Voyage"), QStringLiteral("voyageDock"), voyagePanel_, Qt::RightDockWidgetArea);
}

void MainWindow::buildVoyageActions(QMenu* routeMenu) {
  followRouteAction_ = new QAction(tr("Follow route (track control)"), this);
  followRouteAction_->setObjectName(QStringLiteral("followRouteAction"));
  followRouteAction_->setCheckable(true);
  followRouteAction_->setToolTip(
      tr("Own ship's autopilot steers along the active route (simulation); a helm order takes it off"));
  routeMenu->addAction(followRouteAction_);
  connect(followRouteAction_, &QAction::toggled, this, [this] { sendActiveRoute(); });
  connect(routes_, &RouteLibrary::activeRouteChanged, this, [this] { sendActiveRoute(); });
  const auto sendSafety = [this] { controller_->setSafety(safetySettingsOf(view_->settings())); };
  connect(view_, &ChartView::settingsChanged, this, sendSafety);
  sendSafety();
  // A scenario with a voyage route of its own: the route joins the library (unsaved) as the active
  // one, unless the library has an active route, which then replaces it.
  connect(controller_, &SimulationController::loaded, this, [this](const sim::Scenario& s) {
    const QSignalBlocker block(followRouteAction_);
    if (routes_->activeRoute()) {
      sendActiveRoute();
      return;
    }
    followRouteAction_->setChecked(s.voyage.followRoute);
    if (!s.voyage.route) return;
    for (int i = 0; i < routes_->count(); ++i)
      if (routes_->at(i).route == *s.voyage.route) {
        routes_->setActive(i);
        return;
      }
    routes_->setActive(routes_->add(*s.voyage.route));
  });
}

void MainWindow::sendActiveRoute() {
  const geo::Route* r = routes_->activeRoute();
  std::optional<geo::Route> route;
  if (r && r->legCount() >= 1) {
    if (const auto problems = r->problems(); problems.empty())
      route = *r;
    else
      statusBar()->showMessage(
          tr("The active route is not monitored: %1").arg(QString::fromStdString(problems.front())), 10000);
  }
  controller_->setVoyageRoute(route, route && followRouteAction_->isChecked());
}

void MainWindow::showVoyage(const LiveFrame& live) {
  voyagePanel_->setFrame(live);
  // The simulation ended track control (a helm order took the ship): the menu follows. Only that
  // change: a frame sent before an operator's toggle arrived must not undo it.
  if (lastFollowing_ && !live.followingRoute && followRouteAction_->isChecked()) {
    const QSignalBlocker block(followRouteAction_);
    followRouteAction_->setChecked(false);
  }
  lastFollowing_ = live.followingRoute;
}

}  // namespace reckoner::ui
