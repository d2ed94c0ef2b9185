// MainWindow's docks, menus and toolbars: what the user can do, connected to the window's state
// (main_window.cpp), the chart view and the simulation controller.
#include <QActionGroup>
#include <QComboBox>
#include <QCoreApplication>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHeaderView>
#include <QListWidget>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QSortFilterProxyModel>
#include <QTabWidget>
#include <QTableView>
#include <QTextBrowser>
#include <QToolBar>
#include <QVBoxLayout>
#include <cmath>

#include "charts/s57/s57_loader.h"
#include "common/library_versions.h"
#include "common/units.h"
#include "files/scenario_json.h"
#include "resources/embedded.h"
#include "ui/main_window.h"
#include "ui/map/range_scale.h"
#include "ui/panels/alert_panel.h"
#include "ui/panels/mariner_settings_dialog.h"
#include "ui/panels/own_ship_panel.h"
#include "ui/panels/sensor_panel.h"
#include "ui/panels/target_table_model.h"
#include "ui/plots/error_plots.h"
#include "ui/plots/png_export_dialog.h"

namespace reckoner::ui {
namespace {
/// Changes the chart's overlay settings through `edit(OverlaySettings&)`.
template <class F>
void editOverlay(EcdisView* view, F&& edit) {
  OverlaySettings s = view->overlay();
  edit(s);
  view->setOverlay(s);
}

QString defaultChartPath() {
  return QString::fromLatin1(charts::kDefaultChartPath.data(), int(charts::kDefaultChartPath.size()));
}
}  // namespace

QDockWidget* MainWindow::addScrollDock(const QString& title, const QString& name, QWidget* w,
                                       Qt::DockWidgetArea area) {
  // Every dock scrolls, so that none sets the window's minimum size (it fits a 1024 x 768 screen).
  auto* d = new QDockWidget(title, this);
  d->setObjectName(name);
  auto* scroll = new QScrollArea(d);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setWidget(w);
  d->setWidget(scroll);
  addDockWidget(area, d);
  return d;
}

void MainWindow::buildDocks() {
  const auto dock = [this](const QString& title, const QString& name, QWidget* w, Qt::DockWidgetArea area) {
    return addScrollDock(title, name, w, area);
  };
  ownPanel_ = new OwnShipPanel(this);
  sensors_ = new SensorPanel(this);
  dock(tr("Own ship"), QStringLiteral("ownShipDock"), ownPanel_, Qt::RightDockWidgetArea);
  dock(tr("Sensors"), QStringLiteral("sensorDock"), sensors_, Qt::RightDockWidgetArea);
  connect(sensors_, &SensorPanel::sensorToggled, controller_, &SimulationController::setSensorPower);
  connect(sensors_, &SensorPanel::radarToggled, controller_, &SimulationController::setRadarPower);
  connect(sensors_, &SensorPanel::speedlogModeChosen, controller_, &SimulationController::setSpeedlogMode);
  connect(sensors_, &SensorPanel::drLimitChanged, controller_, &SimulationController::setDrLimit);
  connect(sensors_, &SensorPanel::drLimitChanged, this,
          [](double m) { QSettings().setValue(QStringLiteral("alerts/drLimitM"), m); });
  connect(sensors_, &SensorPanel::discrepancyLimitChanged, controller_,
          &SimulationController::setDiscrepancyLimit);
  connect(sensors_, &SensorPanel::discrepancyLimitChanged, this,
          [](double m) { QSettings().setValue(QStringLiteral("alerts/discrepancyLimitM"), m); });

  model_ = new TargetTableModel(this);
  proxy_ = new QSortFilterProxyModel(this);
  proxy_->setSourceModel(model_);
  proxy_->setSortRole(Qt::UserRole);
  table_ = new QTableView(this);
  table_->setObjectName(QStringLiteral("targetTable"));
  table_->setModel(proxy_);
  table_->setSortingEnabled(true);
  table_->sortByColumn(TargetTableModel::Range, Qt::AscendingOrder);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::SingleSelection);
  table_->verticalHeader()->hide();
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  dock(tr("Targets"), QStringLiteral("targetDock"), table_, Qt::BottomDockWidgetArea);
  connect(table_->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
          [this](const QModelIndex& current) {
            if (!current.isValid()) return;
            const int id = model_->trackIdAt(proxy_->mapToSource(current).row());
            if (id >= 0) view_->setSelectedTrack(id);
          });

  auto* plots = new QTabWidget(this);
  plots->setObjectName(QStringLiteral("plots"));
  ownPlots_ = new ErrorPlots(ErrorPlots::Subject::OwnShip, plots);
  targetPlots_ = new ErrorPlots(ErrorPlots::Subject::Target, plots);
  ownPlots_->setHistory(&history_);
  targetPlots_->setHistory(&history_);
  plots->addTab(ownPlots_, tr("Own ship"));
  plots->addTab(targetPlots_, tr("Selected target"));
  dock(tr("Plots"), QStringLiteral("plotDock"), plots, Qt::LeftDockWidgetArea);

  alertPanel_ = new AlertPanel(this);
  connect(alertPanel_, &AlertPanel::acknowledgeRequested, controller_,
          &SimulationController::acknowledgeAlert);
  connect(alertPanel_, &AlertPanel::silenceRequested, controller_, &SimulationController::silenceAlerts);
  dock(tr("Alerts"), QStringLiteral("alarmDock"), alertPanel_, Qt::BottomDockWidgetArea);

  pick_ = new QTextBrowser(this);
  pick_->setObjectName(QStringLiteral("pickReport"));
  dock(tr("Pick report"), QStringLiteral("pickDock"), pick_, Qt::BottomDockWidgetArea);
  buildChartDock();
  buildRouteDock();
  buildVoyageDock();
  buildLive();
  arrangeDocks();
}

void MainWindow::arrangeDocks() {
  // Chart first: one column on the right, own ship / sensors / plots tabbed above alerts / targets /
  // pick report / charts, so the chart keeps some 60% of the window at 1024 x 768. The operator may move and
  // float the docks; the arrangement is remembered (writeSettings).
  const auto d = [this](const char* name) { return findChild<QDockWidget*>(QString::fromLatin1(name)); };
  QDockWidget *own = d("ownShipDock"), *alerts = d("alarmDock");
  for (const char* name : {"ownShipDock", "sensorDock", "plotDock", "routeDock", "voyageDock", "alarmDock",
                           "targetDock", "aisDock", "pickDock", "chartDock", "monitorDock"})
    addDockWidget(Qt::RightDockWidgetArea, d(name));
  splitDockWidget(own, alerts, Qt::Vertical);
  tabifyDockWidget(own, d("sensorDock"));
  tabifyDockWidget(own, d("plotDock"));
  tabifyDockWidget(own, d("routeDock"));
  tabifyDockWidget(own, d("voyageDock"));
  tabifyDockWidget(alerts, d("targetDock"));
  tabifyDockWidget(alerts, d("pickDock"));
  tabifyDockWidget(alerts, d("chartDock"));
  tabifyDockWidget(alerts, d("aisDock"));
  tabifyDockWidget(alerts, d("monitorDock"));
  own->raise();
  alerts->raise();
}

void MainWindow::buildActions() {
  buildFileMenu();
  buildSimulationToolbar();
  buildDisplayToolbar();
  buildTrackingMenu();
  buildViewMenu();
  buildHelpMenu();
  buildRadarMenu();
  buildLiveMenu();
  buildRouteMenu();
}

void MainWindow::buildFileMenu() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  file->addAction(tr("Open scenario…"), QKeySequence::Open, this, [this] {
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open scenario"), {}, tr("Scenarios (*.json)"));
    if (!path.isEmpty()) openScenario(path);
  });
  QMenu* builtins = file->addMenu(tr("Open built-in scenario"));
  builtins->setObjectName(QStringLiteral("builtinScenarios"));
  for (const resources::EmbeddedFile& f : resources::scenarios()) {
    const QString name = QString::fromUtf8(f.name.data(), static_cast<qsizetype>(f.name.size()));
    QString title = name;
    try {
      title +=
          QStringLiteral("  —  ") +
          QString::fromStdString(files::parseScenario(f.text, std::string("builtin:").append(f.name)).name);
    } catch (const io::InputError&) {  // tst_scenario_json keeps every built-in valid; show the name only
    }
    QAction* a =
        builtins->addAction(title, this, [this, name] { openScenario(QStringLiteral("builtin:") + name); });
    a->setData(name);
  }
  file->addAction(tr("Save scenario"), QKeySequence::Save, this, [this] { save(); });
  file->addAction(tr("Save scenario as…"), QKeySequence::SaveAs, this, [this] { saveAs(); });
  file->addSeparator();
  file->addAction(tr("Open ENC cell…"), this, [this] {
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open ENC cell"), {}, tr("S-57 cells (*.000)"));
    if (!path.isEmpty()) openCharts(path);
  });
  file->addAction(tr("Open ENC folder…"), this, [this] {
    const QString path = QFileDialog::getExistingDirectory(this, tr("Open ENC folder"));
    if (!path.isEmpty()) openCharts(path);
  });
  file->addAction(tr("Embedded default chart"), this, [this] { openCharts(defaultChartPath()); });
  recentMenu_ = file->addMenu(tr("Recent files"));
  file->addSeparator();
  for (ErrorPlots* plots : {ownPlots_, targetPlots_}) {
    const QString who = plots == ownPlots_ ? tr("own-ship") : tr("target");
    const QString stem = plots == ownPlots_ ? QStringLiteral("ownship") : QStringLiteral("target");
    file->addAction(tr("Export %1 plots (PNG)…").arg(who), this, [this, plots, stem] {
      const std::optional<QSize> size = askPlotExportSize(this);  // the charts alone, at this size
      if (!size) return;
      const QString p =
          QFileDialog::getSaveFileName(this, tr("Export plots"), stem + ".png", tr("PNG (*.png)"));
      if (!p.isEmpty() && !plots->exportPng(p, *size)) reportError(tr("%1: cannot write the image").arg(p));
    });
    file->addAction(tr("Export %1 plot data (CSV)…").arg(who), this, [this, plots, stem] {
      const QString p =
          QFileDialog::getSaveFileName(this, tr("Export plot data"), stem + ".csv", tr("CSV (*.csv)"));
      if (!p.isEmpty() && !plots->exportCsv(p)) reportError(tr("%1: cannot write the file").arg(p));
    });
  }
  file->addSeparator();
  file->addAction(tr("Quit"), QKeySequence::Quit, this, &QWidget::close);
}

void MainWindow::buildSimulationToolbar() {
  // Simulation: toolbar with the clock, run/pause, step and the rate.
  QToolBar* sim = addToolBar(tr("Simulation"));
  sim->setObjectName(QStringLiteral("simulationToolbar"));
  clock_ = new QLabel(this);
  clock_->setObjectName(QStringLiteral("clock"));
  clock_->setMinimumWidth(260);
  QFont mono = clock_->font();
  mono.setFamily(QStringLiteral("monospace"));
  mono.setBold(true);
  clock_->setFont(mono);
  sim->addWidget(clock_);
  runAction_ = sim->addAction(tr("Run"));
  runAction_->setObjectName(QStringLiteral("run"));
  runAction_->setShortcut(Qt::Key_Space);
  runAction_->setShortcutContext(Qt::WindowShortcut);
  runAction_->setToolTip(tr("Run the simulation at the chosen rate, or pause it (Space)"));
  connect(runAction_, &QAction::triggered, this,
          [this] { setRate(history_.latest().running ? 0.0 : lastRunRate_); });
  QAction* step = sim->addAction(tr("Step"));
  step->setShortcut(QKeySequence(Qt::Key_Period));
  step->setToolTip(tr("Advance one step of the scenario and pause (.)"));
  connect(step, &QAction::triggered, controller_, &SimulationController::stepOnce);
  simulationActions_ = {runAction_, step};
  rateBox_ = new QComboBox(this);
  rateBox_->setObjectName(QStringLiteral("rate"));
  rateBox_->setToolTip(
      tr("Simulated seconds per wall second while running (max: as fast as possible); the "
         "clock shows the rate achieved"));
  for (double r : {1.0, 2.0, 5.0, 10.0, 30.0, 100.0}) rateBox_->addItem(QStringLiteral("%1x").arg(r), r);
  rateBox_->addItem(tr("max"), -1.0);
  rateBox_->setCurrentIndex(3);
  connect(rateBox_, &QComboBox::activated, this, [this](int i) {
    lastRunRate_ = rateBox_->itemData(i).toDouble();
    if (history_.latest().running) setRate(lastRunRate_);
  });
  sim->addWidget(rateBox_);
  simulationControls_ = {rateBox_, sensors_};
  alarmBanner_ = new QLabel(this);
  alarmBanner_->setObjectName(QStringLiteral("alarmBanner"));
  alarmBanner_->setStyleSheet(
      QStringLiteral("QLabel { background: #c62828; color: white; font-weight: bold; padding: 2px 8px; }"));
  // A widget in a toolbar is shown and hidden through its action (QWidget::hide() is undone by the
  // toolbar's layout).
  alarmBannerAction_ = sim->addWidget(alarmBanner_);
  alarmBannerAction_->setVisible(false);
}

void MainWindow::buildRangeBox(QToolBar* bar) {
  auto* range = new QComboBox(this);
  range->setObjectName(QStringLiteral("range"));
  range->setToolTip(
      tr("Range: from own ship to the nearest edge of the chart, with its range rings (keys + "
         "and -)"));
  for (const RangeScale& r : kRangeScales) range->addItem(tr("%1 NM").arg(r.rangeNm), r.rangeNm);
  connect(range, &QComboBox::activated, this,
          [this, range](int i) { view_->setRangeNm(range->itemData(i).toDouble()); });
  // The box follows the view: a standard range, or (after zooming with the wheel) the range shown.
  connect(view_, &ChartView::viewChanged, range, [range](const charts::Viewport& v) {
    const double nm = displayedRangeNm(v);
    const int i = standardRangeIndex(nm);
    range->setPlaceholderText(tr("%1 NM").arg(nm, 0, 'g', 3));
    range->setCurrentIndex(i);
  });
  bar->addWidget(range);
}

void MainWindow::buildDisplayToolbar() {
  // Display: range, palette, category, safety contour, and the display modes (main_window_display.cpp).
  QToolBar* display = addToolBar(tr("Display"));
  display->setObjectName(QStringLiteral("displayToolbar"));
  buildRangeBox(display);
  auto* palette = new QComboBox(this);
  palette->setObjectName(QStringLiteral("palette"));
  palette->setToolTip(
      tr("S-52 colour table for the light on the bridge: day, dusk or night (the whole "
         "window follows)"));
  palette->addItems({tr("Day"), tr("Dusk"), tr("Night")});
  connect(palette, &QComboBox::activated, this,
          [this](int i) { setPalette(static_cast<charts::Palette>(i)); });
  display->addWidget(palette);
  categoryBox_ = new QComboBox(this);
  categoryBox_->setObjectName(QStringLiteral("category"));
  categoryBox_->addItems({tr("Base"), tr("Standard"), tr("All")});
  categoryBox_->setToolTip(tr("S-52 display category (Chart > Mariner settings for the rest)"));
  connect(categoryBox_, &QComboBox::activated, this, [this](int i) {
    charts::MarinerSettings s = view_->settings();
    s.category = static_cast<charts::DisplayCategory>(i);
    setMarinerSettings(s);
  });
  display->addWidget(categoryBox_);
  safetyBox_ = new QDoubleSpinBox(this);
  safetyBox_->setObjectName(QStringLiteral("safetyContour"));
  safetyBox_->setPrefix(tr("Safety "));
  safetyBox_->setSuffix(QStringLiteral(" m"));
  safetyBox_->setToolTip(
      tr("Safety contour, between the shallow and the deep contour (Chart > Mariner settings sets those "
         "and the safety depth)"));
  connect(safetyBox_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
    charts::MarinerSettings s = view_->settings();
    s.safetyContourM = v;
    setMarinerSettings(s);
  });
  display->addWidget(safetyBox_);
  showMarinerSettings(view_->settings());
  buildDisplayModes(display);
}

void MainWindow::buildTrackingMenu() {
  // Tracking: the filter of ARPA tracks started from now on (recorded in the scenario).
  QMenu* tracking = menuBar()->addMenu(tr("&Tracking"));
  QMenu* filterMenu = tracking->addMenu(tr("Filter for new tracks"));
  filterMenu->setObjectName(QStringLiteral("trackerKindMenu"));
  auto* kinds = new QActionGroup(this);
  for (int i = 0; i < track::kTrackerKindCount; ++i) {
    const auto kind = static_cast<track::TrackerKind>(i);
    QAction* a = filterMenu->addAction(QString::fromLatin1(track::trackerKindLabel(kind)));
    a->setObjectName(QStringLiteral("trackerKind_%1").arg(QString::fromLatin1(track::trackerKindName(kind))));
    a->setCheckable(true);
    a->setData(i);
    kinds->addAction(a);
    trackerKindActions_.push_back(a);
    connect(a, &QAction::triggered, this, [this, kind] { controller_->setTrackerKind(kind); });
  }
  tracking->addAction(tr("CPA/TCPA limits…"), this, &MainWindow::askCpaLimits)
      ->setObjectName(QStringLiteral("cpaLimits"));
  autoAcquireAction_ = tracking->addAction(tr("Automatic acquisition"));
  autoAcquireAction_->setObjectName(QStringLiteral("autoAcquire"));
  autoAcquireAction_->setCheckable(true);
  autoAcquireAction_->setChecked(true);
  autoAcquireAction_->setToolTip(
      tr("New echoes in the acquisition zones start tracks by themselves; off, "
         "only the operator acquires (right button: Acquire plot here)"));
  connect(autoAcquireAction_, &QAction::triggered, controller_, &SimulationController::setAutoAcquire);
  buildTrialActions(tracking);
}

void MainWindow::askCpaLimits() {
  QDialog dialog(this);
  dialog.setWindowTitle(tr("CPA/TCPA limits"));
  auto* form = new QFormLayout(&dialog);
  auto* cpa = new QDoubleSpinBox(&dialog);
  cpa->setRange(0.1, 6.0);
  cpa->setSingleStep(0.1);
  cpa->setSuffix(tr(" NM"));
  auto* tcpa = new QDoubleSpinBox(&dialog);
  tcpa->setRange(1.0, 60.0);
  tcpa->setDecimals(0);
  tcpa->setSuffix(tr(" min"));
  QSettings settings;
  cpa->setValue(
      settings.value(QStringLiteral("tracking/cpaNm"), metresToNm(controller_->scenario().tracker.dangerCpaM))
          .toDouble());
  tcpa->setValue(
      settings.value(QStringLiteral("tracking/tcpaMin"), controller_->scenario().tracker.dangerTcpaS / 60.0)
          .toDouble());
  form->addRow(tr("Dangerous when CPA under"), cpa);
  form->addRow(tr("and TCPA under"), tcpa);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
  connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
  form->addRow(buttons);
  if (dialog.exec() == QDialog::Accepted) setCpaLimits(cpa->value(), tcpa->value());
}

QString MainWindow::aboutText() {
  return tr("<h3>Reckoner %1</h3><p>Dead reckoning and target tracking on S-57 charts. Not for navigation: "
            "a research and training tool.</p><p>Qt %2 (built with %3), GDAL %4, GeographicLib %5, Eigen "
            "%6</p>")
      .arg(QCoreApplication::applicationVersion().isEmpty() ? QStringLiteral("(development)")
                                                            : QCoreApplication::applicationVersion(),
           QString::fromLatin1(qVersion()), QStringLiteral(QT_VERSION_STR),
           QString::fromStdString(charts::gdalVersion()), QString::fromStdString(geographicLibVersion()),
           QString::fromStdString(eigenVersion()));
}

QString MainWindow::shortcutsText() {
  return tr(
      "<table>"
      "<tr><td>Space</td><td>run / pause</td></tr>"
      "<tr><td>.</td><td>one step</td></tr>"
      "<tr><td>+ / -</td><td>shorter / longer range</td></tr>"
      "<tr><td>Home</td><td>centre on own ship and follow it</td></tr>"
      "<tr><td>Left / Right</td><td>ordered course -5 / +5 deg (Shift: 1 deg)</td></tr>"
      "<tr><td>Up / Down</td><td>ordered speed +0.5 / -0.5 kn</td></tr>"
      "<tr><td>O</td><td>next orientation: north up, course up, head up</td></tr>"
      "<tr><td>M</td><td>true / relative motion</td></tr>"
      "<tr><td>C or R</td><td>centre own ship and follow it (true-motion reset)</td></tr>"
      "<tr><td>Esc</td><td>cancel adding or steering a target; leave route edit</td></tr>"
      "<tr><td>Ctrl+E</td><td>route edit: click adds, drag moves, right button inserts or deletes</td></tr>"
      "<tr><td>Ctrl+Z / Ctrl+Shift+Z</td><td>undo / redo the last route edit</td></tr>"
      "<tr><td>Delete</td><td>in route edit: delete the selected waypoint</td></tr>"
      "<tr><td>Ctrl+O / Ctrl+S / Ctrl+Shift+S</td><td>open / save / save as</td></tr>"
      "<tr><td>Ctrl+M</td><td>mariner settings (contours, safety depth, category)</td></tr>"
      "<tr><td>Ctrl+Q</td><td>quit (asks to save unsaved changes)</td></tr>"
      "</table>");
}

void MainWindow::buildHelpMenu() {
  QMenu* help = menuBar()->addMenu(tr("&Help"));
  help->addAction(tr("Keyboard shortcuts"), QKeySequence::HelpContents, this,
                  [this] { QMessageBox::information(this, tr("Keyboard shortcuts"), shortcutsText()); });
  help->addAction(tr("About Reckoner"), this,
                  [this] { QMessageBox::about(this, tr("About Reckoner"), aboutText()); });
}

void MainWindow::buildViewMenu() {
  QMenu* viewMenu = menuBar()->addMenu(tr("&View"));
  QAction* mariner = viewMenu->addAction(tr("Mariner settings..."), this, &MainWindow::editMarinerSettings);
  mariner->setObjectName(QStringLiteral("marinerSettings"));
  mariner->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_M));
  mariner->setToolTip(tr("Shallow, safety and deep contours, safety depth, shades, category, text"));
  viewMenu->addSeparator();
  // Seed 002's own-ship filters run beside the DRKF on the same sensors; one can be drawn with it.
  QMenu* alt = viewMenu->addMenu(tr("Also show own ship by"));
  alt->setObjectName(QStringLiteral("seed002Menu"));
  auto* group = new QActionGroup(this);
  const QString names[] = {tr("DRKF only"), tr("Geodetic Kalman filter (seed 002)"),
                           tr("Least squares with dead reckoning (seed 002)")};
  for (int i = 0; i < 3; ++i) {
    QAction* a = alt->addAction(names[i]);
    a->setObjectName(QStringLiteral("seed002_%1").arg(i));
    a->setCheckable(true);
    a->setChecked(i == view_->overlay().seed002Shown);
    group->addAction(a);
    connect(a, &QAction::triggered, this,
            [this, i] { editOverlay(view_, [i](OverlaySettings& s) { s.seed002Shown = i; }); });
  }
  addOverlayToggle(viewMenu, tr("Truth"), &OverlaySettings::showTruth);
  addOverlayToggle(viewMenu, tr("Covariance ellipses (95%)"), &OverlaySettings::showEllipses);
  addOverlayToggle(viewMenu, tr("Raw radar plots"), &OverlaySettings::showPlots);
  addOverlayToggle(viewMenu, tr("Past track"), &OverlaySettings::showPastTrack);
  addOverlayToggle(viewMenu, tr("Range rings"), &OverlaySettings::showRings);
  buildChartViewActions(viewMenu);
  viewMenu->addSeparator();
  buildDisplayMenu(viewMenu);
  viewMenu->addSeparator();
  for (QDockWidget* d : findChildren<QDockWidget*>()) viewMenu->addAction(d->toggleViewAction());
}

void MainWindow::editMarinerSettings() {
  MarinerSettingsDialog dialog(view_->settings(), this);
  if (dialog.exec() == QDialog::Accepted) setMarinerSettings(dialog.settings());
}

QAction* MainWindow::addOverlayToggle(QMenu* menu, const QString& name, bool OverlaySettings::*member) {
  QAction* a = menu->addAction(name);
  a->setCheckable(true);
  a->setChecked(view_->overlay().*member);
  connect(a, &QAction::toggled, this, [this, member](bool on) {
    editOverlay(view_, [member, on](OverlaySettings& s) { s.*member = on; });
  });
  return a;
}

void MainWindow::buildRadarMenu() {
  // Seed 004: the radar picture matched to the loaded charts, and the radar overlay.
  QMenu* radar = menuBar()->addMenu(tr("&Radar"));
  radar->setObjectName(QStringLiteral("radarMenu"));
  radarMatchAction_ =
      radar->addAction(tr("Match the radar picture to the chart (position and heading fixes)"));
  radarMatchAction_->setObjectName(QStringLiteral("radarMatching"));
  radarMatchAction_->setCheckable(true);
  connect(radarMatchAction_, &QAction::triggered, this,
          [this](bool on) { controller_->setRadarMatching(on); });
  QAction* picture =
      addOverlayToggle(radar, tr("Show the radar picture"), &OverlaySettings::showRadarPicture);
  picture->setObjectName(QStringLiteral("radarPicture"));
  connect(picture, &QAction::toggled, this, [this](bool on) { controller_->setRadarPicturesWanted(on); });
  addOverlayToggle(radar, tr("Show matched echoes and their chart points"), &OverlaySettings::showRadarEchoes)
      ->setObjectName(QStringLiteral("radarEchoes"));
  radar->addSeparator();
  auto* layer = new QActionGroup(this);
  const std::pair<QString, bool> layers[] = {{tr("Radar over the chart"), true},
                                             {tr("Radar under the chart's land (shown on water)"), false}};
  for (const auto& [name, over] : layers) {
    QAction* a = radar->addAction(name);
    a->setObjectName(over ? QStringLiteral("radarOver") : QStringLiteral("radarUnder"));
    a->setCheckable(true);
    a->setChecked(view_->overlay().radarOverChart == over);
    layer->addAction(a);
    connect(a, &QAction::triggered, this, [this, over = over] {
      editOverlay(view_, [over](OverlaySettings& s) { s.radarOverChart = over; });
    });
  }
  QMenu* opacity = radar->addMenu(tr("Radar opacity"));
  auto* opacities = new QActionGroup(this);
  for (const int pct : {25, 40, 60, 80, 100}) {
    QAction* a = opacity->addAction(tr("%1%").arg(pct));
    a->setObjectName(QStringLiteral("radarOpacity%1").arg(pct));
    a->setCheckable(true);
    a->setChecked(std::abs(view_->overlay().radarOpacity * 100.0 - pct) < 1.0);
    opacities->addAction(a);
    connect(a, &QAction::triggered, this,
            [this, pct] { editOverlay(view_, [pct](OverlaySettings& s) { s.radarOpacity = pct / 100.0; }); });
  }
  QMenu* colours = radar->addMenu(tr("Radar colour"));
  auto* colourGroup = new QActionGroup(this);
  for (int i = 0; i < static_cast<int>(std::size(kRadarColours)); ++i) {
    QAction* a = colours->addAction(tr(kRadarColours[i].name));
    a->setCheckable(true);
    a->setChecked(view_->overlay().radarColour == i);
    colourGroup->addAction(a);
    connect(a, &QAction::triggered, this,
            [this, i] { editOverlay(view_, [i](OverlaySettings& s) { s.radarColour = i; }); });
  }
}

}  // namespace reckoner::ui
