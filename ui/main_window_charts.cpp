// MainWindow's chart management (docs/gui.md, "Charts"): the chart list dock, the chart items of the
// View menu (outlines, show all charts, centre on own ship) and what the view does when the charts a
// user opened arrive.
#include <QAction>
#include <QDockWidget>
#include <QMenu>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QStatusBar>
#include <cmath>

#include "charts/render/chart_extent.h"
#include "ui/main_window.h"
#include "ui/panels/chart_list_panel.h"

namespace reckoner::ui {

void MainWindow::buildChartDock() {
  chartList_ = new ChartListPanel(this);
  auto* d = new QDockWidget(tr("Charts"), this);
  d->setObjectName(QStringLiteral("chartDock"));
  auto* scroll = new QScrollArea(d);  // as every dock: it never sets the window's minimum size
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setWidget(chartList_);
  d->setWidget(scroll);
  addDockWidget(Qt::RightDockWidgetArea, d);
  // Zooming to a chart moves the view away from own ship: following it would take the view back.
  const auto show = [this](const std::vector<charts::CellPtr>& cells) {
    if (!view_->zoomToCells(cells) || !view_->overlay().followOwnShip) return;
    OverlaySettings s = view_->overlay();
    s.followOwnShip = false;
    view_->setOverlay(s);
  };
  connect(chartList_, &ChartListPanel::zoomRequested, this, show);
  connect(chartList_, &ChartListPanel::showAllRequested, this, [this, show] { show(view_->cells()); });
  connect(view_, &ChartView::cellsUnderCursorChanged, chartList_, &ChartListPanel::setUnderCursor);
}

QAction* MainWindow::centreOwnShipAction() {
  // The display modes' action (C, R: centres own ship and follows it again), also on Home.
  QAction* a = displayAction("centreOwnShip");
  if (!a->shortcuts().contains(QKeySequence(Qt::Key_Home)))
    a->setShortcuts(a->shortcuts() << QKeySequence(Qt::Key_Home));
  return a;
}

void MainWindow::buildChartViewActions(QMenu* viewMenu) {
  viewMenu->addAction(centreOwnShipAction());
  viewMenu->addSeparator();
  QAction* outlines = viewMenu->addAction(tr("Chart outlines and names"));
  outlines->setObjectName(QStringLiteral("chartOutlines"));
  outlines->setCheckable(true);
  outlines->setChecked(view_->showOutlines());
  outlines->setToolTip(tr("Each open chart's coverage outlined, with its name at a corner"));
  connect(outlines, &QAction::toggled, view_, &ChartView::setShowOutlines);
  viewMenu->addAction(tr("Show all charts"), this, [this] { emit chartList_->showAllRequested(); })
      ->setObjectName(QStringLiteral("showAllChartsAction"));
}

void MainWindow::showArrivedCharts(const std::vector<charts::CellPtr>& cells, const QString& failures) {
  const int n = static_cast<int>(cells.size());
  QStringList names;
  for (const charts::CellPtr& c : cells)
    if (names.size() < 3) names << QString::fromStdString(c->info().name);
  if (n > 3) names << QStringLiteral("…");
  QString message;
  if (!charts::cellsAt(cells, view_->viewport().centre()).empty()) {
    message = tr("%1 chart(s) open (%2); the view is on them").arg(n).arg(names.join(QStringLiteral(", ")));
  } else {
    view_->zoomToCells(cells);
    message = tr("Showing the %1 chart(s) opened (%2)").arg(n).arg(names.join(QStringLiteral(", ")));
    if (view_->overlay().followOwnShip) {
      // Following own ship would take the view straight back at the next frame.
      OverlaySettings s = view_->overlay();
      s.followOwnShip = false;
      view_->setOverlay(s);
      message += tr(" · Follow own ship is off: View ▸ Centre on own ship (Home) goes back");
    }
  }
  if (!failures.isEmpty()) message += tr(" · not loaded: %1").arg(failures);
  statusBar()->showMessage(message, 30000);
  if (auto* d = findChild<QDockWidget*>(QStringLiteral("chartDock"))) d->raise();
}

void MainWindow::showChartStatus(double renderMs) {
  const double overscale = view_->lastRenderStats().overscale;
  chartLabel_->setText(
      tr("%1 cells · 1:%2%3 · render %4 ms")
          .arg(view_->cells().size())
          .arg(std::round(view_->viewport().scaleDenominator()), 0, 'f', 0)
          .arg(overscale > 1.0 + 1e-9 ? tr(" · overscale x%1").arg(overscale, 0, 'f', 1) : QString())
          .arg(renderMs, 0, 'f', 1));
}

}  // namespace reckoner::ui
