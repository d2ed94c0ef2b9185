#include "ui/main_window.h"

#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QEventLoop>
#include <QFileDialog>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSortFilterProxyModel>
#include <QStatusBar>
#include <QTabWidget>
#include <QTableView>
#include <QTextBrowser>
#include <QThread>
#include <QToolBar>
#include <QVBoxLayout>
#include <cmath>

#include "charts/s57/s57_loader.h"
#include "common/units.h"
#include "files/scenario_json.h"
#include "resources/embedded.h"
#include "ui/panels/own_ship_panel.h"
#include "ui/panels/sensor_panel.h"
#include "ui/panels/target_table_model.h"
#include "ui/plots/error_plots.h"

namespace reckoner::ui {
namespace {
constexpr int kRepaintMs = 33;  // <= 30 Hz
constexpr int kPlotMs = 500;
constexpr int kMaxRecent = 8;
const QString kBuiltinPrefix = QStringLiteral("builtin:");

QString clockText(double s) {
  const int total = static_cast<int>(std::floor(s));
  return QStringLiteral("%1:%2:%3")
      .arg(total / 3600, 2, 10, QChar('0'))
      .arg(total / 60 % 60, 2, 10, QChar('0'))
      .arg(total % 60, 2, 10, QChar('0'));
}

QString escape(const std::string& s) {
  return QString::fromStdString(s).toHtmlEscaped();
}
}  // namespace

/// One chart load in its thread. Destroying it cancels the load, waits for the thread and removes the
/// progress bar; a result that arrives for a load that is no longer current is dropped (its id).
struct MainWindow::Loading {
  quint64 id = 0;
  std::unique_ptr<QThread> thread;
  std::atomic<bool> cancel{false};
  std::atomic<int> done{0}, total{0};
  std::unique_ptr<QProgressBar> bar;
  QTimer poll;
  ~Loading() {
    cancel = true;
    if (thread) thread->wait();
  }
};

MainWindow::MainWindow(const MainWindowOptions& options, QWidget* parent)
    : QMainWindow(parent), controller_(new SimulationController(this)), view_(new EcdisView(this)) {
  setWindowTitle(QStringLiteral("Reckoner"));
  setObjectName(QStringLiteral("mainWindow"));
  setCentralWidget(view_);
  view_->setObjectName(QStringLiteral("chart"));
  buildDocks();
  buildActions();
  statusBar()->addWidget(cursorLabel_ = new QLabel(this), 1);
  statusBar()->addPermanentWidget(chartLabel_ = new QLabel(this));

  connect(controller_, &SimulationController::frameArrived, this, &MainWindow::onFrame);
  connect(controller_, &SimulationController::failed, this, &MainWindow::reportError);
  connect(controller_, &SimulationController::loaded, this, [this](const sim::Scenario& s) {
    localFrame_.emplace(s.origin.latDeg, s.origin.lonDeg);
    view_->setHistory(&history_, *localFrame_);
    sensors_->setFitted(s);
    firstFrame_ = true;
  });
  connect(view_, &EcdisView::orderRequested, controller_, &SimulationController::orderOwnShip);
  connect(view_, &EcdisView::addTargetRequested, controller_, &SimulationController::addTarget);
  // A target steered from the chart turns at 1 deg/s and changes speed at 0.05 m/s^2, like a ship.
  connect(view_, &EcdisView::steerTargetRequested, this, [this](int target, double course, double speed) {
    controller_->orderTarget(target, course, speed, 0.017453292519943295, 0.05);
  });
  connect(view_, &EcdisView::acquireRequested, controller_, &SimulationController::acquireAt);
  connect(view_, &EcdisView::cancelTrackRequested, controller_, &SimulationController::cancelTrack);
  connect(view_, &EcdisView::trackSelected, this, &MainWindow::selectTrack);
  connect(view_, &EcdisView::pickRequested, this, &MainWindow::showPick);
  connect(view_, &ChartView::picked, this, &MainWindow::showPickedFeatures);
  connect(view_, &EcdisView::cursorReadout, cursorLabel_, &QLabel::setText);
  connect(view_, &ChartView::renderFinished, this, [this](double ms) {
    chartLabel_->setText(tr("%1 cells · 1:%2 · render %3 ms")
                             .arg(view_->cells().size())
                             .arg(std::round(view_->viewport().scaleDenominator()), 0, 'f', 0)
                             .arg(ms, 0, 'f', 1));
  });

  repaintTimer_.setInterval(kRepaintMs);
  connect(&repaintTimer_, &QTimer::timeout, this, &MainWindow::repaintTick);
  repaintTimer_.start();
  plotTimer_.setInterval(kPlotMs);
  connect(&plotTimer_, &QTimer::timeout, this, &MainWindow::refreshPlots);
  plotTimer_.start();

  readSettings();
  QSettings settings;
  QString scenario = QString::fromStdString(options.scenarioPath);
  QString enc = QString::fromStdString(options.encPath);
  if (options.restoreSession) {
    if (scenario.isEmpty()) scenario = settings.value(QStringLiteral("session/scenario")).toString();
    if (enc.isEmpty()) enc = settings.value(QStringLiteral("session/enc")).toString();
  }
  if (scenario.isEmpty() || !openScenario(scenario))
    openScenario(kBuiltinPrefix + QString::fromLatin1(resources::kDefaultScenario.data(),
                                                      int(resources::kDefaultScenario.size())));
  openCharts(enc.isEmpty() ? QString::fromLatin1(charts::kDefaultChartPath.data(),
                                                 int(charts::kDefaultChartPath.size()))
                           : enc);
}

MainWindow::~MainWindow() = default;

void MainWindow::buildDocks() {
  const auto dock = [this](const QString& title, const QString& name, QWidget* w, Qt::DockWidgetArea area) {
    auto* d = new QDockWidget(title, this);
    d->setObjectName(name);
    d->setWidget(w);
    addDockWidget(area, d);
    return d;
  };
  ownPanel_ = new OwnShipPanel(this);
  sensors_ = new SensorPanel(this);
  dock(tr("Own ship"), QStringLiteral("ownShipDock"), ownPanel_, Qt::RightDockWidgetArea);
  dock(tr("Sensors"), QStringLiteral("sensorDock"), sensors_, Qt::RightDockWidgetArea);
  connect(sensors_, &SensorPanel::sensorToggled, controller_, &SimulationController::setSensorPower);
  connect(sensors_, &SensorPanel::radarToggled, controller_, &SimulationController::setRadarPower);
  connect(sensors_, &SensorPanel::speedlogModeChosen, controller_, &SimulationController::setSpeedlogMode);
  connect(sensors_, &SensorPanel::drLimitChanged, controller_, &SimulationController::setDrLimit);

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

  auto* alarms = new QWidget(this);
  auto* av = new QVBoxLayout(alarms);
  alarmList_ = new QListWidget(alarms);
  alarmList_->setObjectName(QStringLiteral("alarms"));
  auto* ack = new QPushButton(tr("Acknowledge all"), alarms);
  ack->setObjectName(QStringLiteral("acknowledge"));
  connect(ack, &QPushButton::clicked, this, [this] {
    history_.acknowledgeAll();
    updateAlarms();
  });
  av->addWidget(alarmList_);
  av->addWidget(ack);
  dock(tr("Alarms"), QStringLiteral("alarmDock"), alarms, Qt::BottomDockWidgetArea);

  pick_ = new QTextBrowser(this);
  pick_->setObjectName(QStringLiteral("pickReport"));
  dock(tr("Pick report"), QStringLiteral("pickDock"), pick_, Qt::BottomDockWidgetArea);
}

void MainWindow::buildActions() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  file->addAction(tr("Open scenario…"), QKeySequence::Open, this, [this] {
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open scenario"), {}, tr("Scenarios (*.json)"));
    if (!path.isEmpty()) openScenario(path);
  });
  file->addAction(tr("Save scenario as…"), QKeySequence::SaveAs, this, [this] {
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Save scenario"), {}, tr("Scenarios (*.json)"));
    if (!path.isEmpty()) saveScenario(path);
  });
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
  file->addAction(tr("Embedded default chart"), this, [this] {
    openCharts(QString::fromLatin1(charts::kDefaultChartPath.data(), int(charts::kDefaultChartPath.size())));
  });
  recentMenu_ = file->addMenu(tr("Recent files"));
  file->addSeparator();
  for (ErrorPlots* plots : {ownPlots_, targetPlots_}) {
    const QString who = plots == ownPlots_ ? tr("own-ship") : tr("target");
    const QString stem = plots == ownPlots_ ? QStringLiteral("ownship") : QStringLiteral("target");
    file->addAction(tr("Export %1 plots (PNG)…").arg(who), this, [this, plots, stem] {
      const QString p =
          QFileDialog::getSaveFileName(this, tr("Export plots"), stem + ".png", tr("PNG (*.png)"));
      if (!p.isEmpty() && !plots->exportPng(p)) reportError(tr("%1: cannot write the image").arg(p));
    });
    file->addAction(tr("Export %1 plot data (CSV)…").arg(who), this, [this, plots, stem] {
      const QString p =
          QFileDialog::getSaveFileName(this, tr("Export plot data"), stem + ".csv", tr("CSV (*.csv)"));
      if (!p.isEmpty() && !plots->exportCsv(p)) reportError(tr("%1: cannot write the file").arg(p));
    });
  }
  file->addSeparator();
  file->addAction(tr("Quit"), QKeySequence::Quit, this, &QWidget::close);

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
  connect(runAction_, &QAction::triggered, this,
          [this] { setRate(history_.latest().running ? 0.0 : lastRunRate_); });
  QAction* step = sim->addAction(tr("Step"));
  step->setShortcut(QKeySequence(Qt::Key_Period));
  connect(step, &QAction::triggered, controller_, &SimulationController::stepOnce);
  rateBox_ = new QComboBox(this);
  rateBox_->setObjectName(QStringLiteral("rate"));
  for (double r : {1.0, 2.0, 5.0, 10.0, 30.0, 100.0}) rateBox_->addItem(QStringLiteral("%1x").arg(r), r);
  rateBox_->addItem(tr("max"), -1.0);
  rateBox_->setCurrentIndex(3);
  connect(rateBox_, &QComboBox::activated, this, [this](int i) {
    lastRunRate_ = rateBox_->itemData(i).toDouble();
    if (history_.latest().running) setRate(lastRunRate_);
  });
  sim->addWidget(rateBox_);
  alarmBanner_ = new QLabel(this);
  alarmBanner_->setObjectName(QStringLiteral("alarmBanner"));
  alarmBanner_->setStyleSheet(
      QStringLiteral("QLabel { background: #c62828; color: white; font-weight: bold; padding: 2px 8px; }"));
  alarmBanner_->hide();
  sim->addWidget(alarmBanner_);

  // Display: palette, category, safety contour, orientation, vectors.
  QToolBar* display = addToolBar(tr("Display"));
  display->setObjectName(QStringLiteral("displayToolbar"));
  auto* palette = new QComboBox(this);
  palette->setObjectName(QStringLiteral("palette"));
  palette->addItems({tr("Day"), tr("Dusk"), tr("Night")});
  connect(palette, &QComboBox::activated, this,
          [this](int i) { setPalette(static_cast<charts::Palette>(i)); });
  display->addWidget(palette);
  auto* category = new QComboBox(this);
  category->setObjectName(QStringLiteral("category"));
  category->addItems({tr("Base"), tr("Standard"), tr("All")});
  category->setCurrentIndex(1);
  connect(category, &QComboBox::activated, this, [this](int i) {
    charts::MarinerSettings s = view_->settings();
    s.category = static_cast<charts::DisplayCategory>(i);
    view_->setSettings(s);
  });
  display->addWidget(category);
  auto* safety = new QDoubleSpinBox(this);
  safety->setObjectName(QStringLiteral("safetyContour"));
  safety->setPrefix(tr("Safety "));
  safety->setSuffix(QStringLiteral(" m"));
  safety->setRange(0.0, 200.0);
  safety->setValue(view_->settings().safetyContourM);
  connect(safety, &QDoubleSpinBox::valueChanged, this, [this](double v) {
    charts::MarinerSettings s = view_->settings();
    s.safetyContourM = v;
    s.safetyDepthM = v;
    view_->setSettings(s);
  });
  display->addWidget(safety);
  QAction* courseUp = display->addAction(tr("Course up"));
  courseUp->setCheckable(true);
  connect(courseUp, &QAction::toggled, this, [this](bool on) {
    OverlaySettings s = view_->overlay();
    s.courseUp = on;
    view_->setOverlay(s);
  });
  QAction* relative = display->addAction(tr("Relative vectors"));
  relative->setCheckable(true);
  connect(relative, &QAction::toggled, this, [this](bool on) {
    OverlaySettings s = view_->overlay();
    s.relativeVectors = on;
    view_->setOverlay(s);
  });
  auto* minutes = new QDoubleSpinBox(this);
  minutes->setObjectName(QStringLiteral("vectorMinutes"));
  minutes->setRange(1.0, 60.0);
  minutes->setDecimals(0);
  minutes->setSuffix(tr(" min vectors"));
  minutes->setValue(view_->overlay().vectorMinutes);
  connect(minutes, &QDoubleSpinBox::valueChanged, this, [this](double v) {
    OverlaySettings s = view_->overlay();
    s.vectorMinutes = v;
    view_->setOverlay(s);
  });
  display->addWidget(minutes);
  display->addAction(tr("Centre own ship"), this, [this] { view_->centreOnOwnShip(); });

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

  QMenu* viewMenu = menuBar()->addMenu(tr("&View"));
  {
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
      connect(a, &QAction::triggered, this, [this, i] {
        OverlaySettings s = view_->overlay();
        s.seed002Shown = i;
        view_->setOverlay(s);
      });
    }
  }
  const auto toggle = [&](const QString& name, bool OverlaySettings::*member) {
    addOverlayToggle(viewMenu, name, member);
  };
  toggle(tr("Truth"), &OverlaySettings::showTruth);
  toggle(tr("Covariance ellipses (95%)"), &OverlaySettings::showEllipses);
  toggle(tr("Raw radar plots"), &OverlaySettings::showPlots);
  toggle(tr("Past track"), &OverlaySettings::showPastTrack);
  toggle(tr("Follow own ship"), &OverlaySettings::followOwnShip);
  QAction* rings = viewMenu->addAction(tr("Range rings"));
  rings->setCheckable(true);
  rings->setChecked(view_->overlay().ringSpacingNm > 0.0);
  connect(rings, &QAction::toggled, this, [this](bool on) {
    OverlaySettings s = view_->overlay();
    s.ringSpacingNm = on ? 0.5 : 0.0;
    view_->setOverlay(s);
  });
  viewMenu->addSeparator();
  for (QDockWidget* d : findChildren<QDockWidget*>()) viewMenu->addAction(d->toggleViewAction());
  buildRadarMenu();
}

QAction* MainWindow::addOverlayToggle(QMenu* menu, const QString& name, bool OverlaySettings::*member) {
  QAction* a = menu->addAction(name);
  a->setCheckable(true);
  a->setChecked(view_->overlay().*member);
  connect(a, &QAction::toggled, this, [this, member](bool on) {
    OverlaySettings s = view_->overlay();
    s.*member = on;
    view_->setOverlay(s);
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
      OverlaySettings s = view_->overlay();
      s.radarOverChart = over;
      view_->setOverlay(s);
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
    connect(a, &QAction::triggered, this, [this, pct] {
      OverlaySettings s = view_->overlay();
      s.radarOpacity = pct / 100.0;
      view_->setOverlay(s);
    });
  }
  QMenu* colours = radar->addMenu(tr("Radar colour"));
  auto* colourGroup = new QActionGroup(this);
  for (int i = 0; i < static_cast<int>(std::size(kRadarColours)); ++i) {
    QAction* a = colours->addAction(tr(kRadarColours[i].name));
    a->setCheckable(true);
    a->setChecked(view_->overlay().radarColour == i);
    colourGroup->addAction(a);
    connect(a, &QAction::triggered, this, [this, i] {
      OverlaySettings s = view_->overlay();
      s.radarColour = i;
      view_->setOverlay(s);
    });
  }
}

bool MainWindow::openScenario(const QString& path) {
  sim::Scenario s;
  try {
    if (path.startsWith(kBuiltinPrefix)) {
      const std::string name = path.mid(kBuiltinPrefix.size()).toStdString();
      const resources::EmbeddedFile* f = resources::findScenario(name);
      if (!f) throw io::InputError(path.toStdString(), 0, "", "no embedded scenario of that name");
      s = io::parseScenario(f->text, path.toStdString());
    } else {
      s = io::loadScenarioFile(path.toStdString());
    }
  } catch (const io::InputError& e) {
    reportError(QString::fromStdString(e.what()));
    return false;
  }
  loadScenario(s, path);
  if (!path.startsWith(kBuiltinPrefix)) addRecent(QStringLiteral("recent/scenarios"), path);
  return true;
}

void MainWindow::loadScenario(const sim::Scenario& scenario, const QString& source) {
  history_.clear();
  scenarioSource_ = source;
  firstFrame_ = true;
  view_->setSelectedTrack(std::nullopt);
  controller_->load(scenario);
  setWindowTitle(QStringLiteral("Reckoner — %1").arg(QString::fromStdString(scenario.name)));
  runAction_->setText(tr("Run"));
}

void MainWindow::openCharts(const QString& path) {
  loading_.reset();  // cancels and waits for a load still running
  loading_ = std::make_unique<Loading>();
  Loading* l = loading_.get();
  l->id = ++chartLoads_;
  l->bar = std::make_unique<QProgressBar>();
  l->bar->setMaximumWidth(200);
  l->bar->setFormat(tr("charts %v/%m"));
  statusBar()->addPermanentWidget(l->bar.get());
  const std::string p = path.toStdString();
  l->thread.reset(QThread::create([this, l, p, path, id = l->id] {
    charts::LoadResult result;
    QString problem;
    try {
      result = charts::loadCharts(
          {p},
          [l](std::size_t done, std::size_t total, const std::string&) {
            l->done = static_cast<int>(done);
            l->total = static_cast<int>(total);
          },
          &l->cancel);
    } catch (const std::exception& e) {
      problem = QString::fromStdString(e.what());
    }
    QMetaObject::invokeMethod(
        this,
        [this, result = std::move(result), problem, path, id] {
          if (!loading_ || loading_->id != id) return;  // superseded by a newer load
          loading_.reset();
          if (!problem.isEmpty()) {
            reportError(problem);
            return;
          }
          QStringList failures;
          for (const auto& f : result.failures)
            failures << QStringLiteral("%1: %2").arg(QString::fromStdString(f.file),
                                                     QString::fromStdString(f.reason));
          if (!failures.isEmpty()) reportError(failures.join(QLatin1Char('\n')));
          if (result.cells.empty()) return;
          view_->setCells(result.cells);
          controller_->setCharts(result.cells);
          chartSource_ = path;
          if (!path.startsWith(kBuiltinPrefix)) addRecent(QStringLiteral("recent/charts"), path);
        },
        Qt::QueuedConnection);
  }));
  connect(&l->poll, &QTimer::timeout, this, [l] {
    l->bar->setMaximum(std::max(1, l->total.load()));
    l->bar->setValue(l->done.load());
  });
  l->poll.start(100);
  l->thread->start();
}

bool MainWindow::saveScenario(const QString& path) {
  std::optional<sim::Scenario> got;
  QEventLoop loop;
  const auto c =
      connect(controller_, &SimulationController::scenarioReady, &loop, [&](const sim::Scenario& s) {
        got = s;
        loop.quit();
      });
  QTimer::singleShot(5000, &loop, &QEventLoop::quit);
  controller_->requestScenario();
  loop.exec();
  disconnect(c);
  if (!got) {
    reportError(tr("%1: the simulation did not answer; nothing written").arg(path));
    return false;
  }
  try {
    io::saveScenarioFile(*got, path.toStdString());
  } catch (const io::InputError& e) {
    reportError(QString::fromStdString(e.what()));
    return false;
  }
  addRecent(QStringLiteral("recent/scenarios"), path);
  scenarioSource_ = path;
  statusBar()->showMessage(tr("Saved %1").arg(path), 5000);
  return true;
}

void MainWindow::setRate(double rate) {
  if (rate != 0.0) lastRunRate_ = rate;
  controller_->setRate(rate);
  runAction_->setText(rate == 0.0 ? tr("Run") : tr("Pause"));
}

void MainWindow::setPalette(charts::Palette palette) {
  charts::MarinerSettings s = view_->settings();
  s.palette = palette;
  view_->setSettings(s);
  QPalette pal = QApplication::palette();
  if (palette != charts::Palette::Day) {
    const bool night = palette == charts::Palette::Night;
    const QColor window = night ? QColor(12, 12, 14) : QColor(40, 40, 48);
    const QColor text = night ? QColor(150, 140, 110) : QColor(215, 215, 215);
    pal.setColor(QPalette::Window, window);
    pal.setColor(QPalette::Base, window.darker(120));
    pal.setColor(QPalette::AlternateBase, window);
    pal.setColor(QPalette::Button, window.lighter(130));
    pal.setColor(QPalette::WindowText, text);
    pal.setColor(QPalette::Text, text);
    pal.setColor(QPalette::ButtonText, text);
  }
  QMainWindow::setPalette(pal);
  for (QWidget* w : findChildren<QWidget*>()) w->setPalette(pal);
  ownPlots_->setDark(palette != charts::Palette::Day);
  targetPlots_->setDark(palette != charts::Palette::Day);
  for (auto* combo : findChildren<QComboBox*>(QStringLiteral("palette")))
    combo->setCurrentIndex(static_cast<int>(palette));
}

void MainWindow::onFrame(const LiveFrame& frame) {
  QElapsedTimer t;
  t.start();
  history_.append(frame);
  frameDirty_ = true;
  plotsDirty_ = true;
  if (!frame.running) QTimer::singleShot(0, this, &MainWindow::refreshPlots);  // paused: show all now
  if (firstFrame_ && localFrame_) {
    firstFrame_ = false;
    view_->centreOnOwnShip();
  }
  guiTimings_.push_back({GuiTiming::Kind::Frame, static_cast<double>(t.nsecsElapsed()) * 1e-6});
}

void MainWindow::repaintTick() {
  if (!frameDirty_) {
    if (!history_.alarms().empty()) view_->update();  // flashing symbols
    return;
  }
  QElapsedTimer t;
  t.start();
  frameDirty_ = false;
  const LiveFrame& live = history_.latest();
  if (localFrame_) ownPanel_->setFrame(live, *localFrame_);
  sensors_->setStates(live.frame.sensors, live.radarOn);
  sensors_->setNoisy(live.frame.noisierThanConfigured);
  for (QAction* a : trackerKindActions_)
    if (a->data().toInt() == static_cast<int>(live.trackerKind) && !a->isChecked()) a->setChecked(true);
  if (radarMatchAction_) {
    radarMatchAction_->setChecked(live.radarMatching);
    radarMatchAction_->setEnabled(live.chartContourSegments > 0 || live.radarMatching);
  }
  const std::optional<int> selected = view_->selectedTrack();
  model_->setTracks(live.frame.tracks);
  if (selected) {
    const int row = model_->rowOf(*selected);
    if (row >= 0) {
      const QModelIndex idx = proxy_->mapFromSource(model_->index(row, 0));
      if (table_->currentIndex().row() != idx.row()) table_->setCurrentIndex(idx);
    }
  }
  updateClock();
  updateAlarms();
  view_->frameUpdated();
  view_->repaint();
  guiTimings_.push_back({GuiTiming::Kind::Repaint, static_cast<double>(t.nsecsElapsed()) * 1e-6});
}

void MainWindow::refreshPlots() {
  if (!plotsDirty_) return;
  QElapsedTimer t;
  t.start();
  plotsDirty_ = false;
  ownPlots_->refresh();
  targetPlots_->refresh();
  guiTimings_.push_back({GuiTiming::Kind::Plots, static_cast<double>(t.nsecsElapsed()) * 1e-6});
}

void MainWindow::updateClock() {
  const LiveFrame& live = history_.latest();
  const double t = toSeconds(live.frame.timeUs);
  QString rate;
  if (live.rate == 0.0)
    rate = live.finished ? tr("END") : tr("PAUSED");
  else if (live.rate < 0.0)
    rate = tr("max (%1x)").arg(live.achievedRate, 0, 'f', 0);
  else
    rate = tr("%1x (%2x)").arg(live.rate, 0, 'f', 0).arg(live.achievedRate, 0, 'f', 0);
  clock_->setText(QStringLiteral("T+%1 / %2  %3").arg(clockText(t), clockText(live.durationS), rate));
  runAction_->setText(live.running ? tr("Pause") : tr("Run"));
}

void MainWindow::updateAlarms() {
  const auto& alarms = history_.alarms();
  alarmList_->clear();
  for (const Alarm& a : alarms)
    alarmList_->addItem(QStringLiteral("%1  at T+%2").arg(a.text(), clockText(a.tS)));
  if (alarms.empty()) {
    alarmBanner_->hide();
  } else {
    alarmBanner_->setText(alarms.begin()->text() +
                          (alarms.size() > 1 ? tr("  (+%1)").arg(alarms.size() - 1) : QString()));
    alarmBanner_->show();
  }
}

void MainWindow::selectTrack(std::optional<int> id) {
  targetPlots_->setTrack(id);
  frameDirty_ = true;
}

void MainWindow::showPick(QPointF at) {
  const charts::Viewport v = view_->viewport();
  const charts::ScreenPoint s{at.x(), at.y()};
  try {
    showPickedFeatures(charts::pickFeatures(view_->cells(), v, s), v.toLatLon(s));
  } catch (const std::exception& e) {
    reportError(QString::fromStdString(e.what()));
  }
}

void MainWindow::showPickedFeatures(const std::vector<charts::PickedFeature>& features,
                                    charts::LatLon where) {
  QString html = tr("<b>%1 features at %2, %3</b>")
                     .arg(features.size())
                     .arg(where.latDeg, 0, 'f', 5)
                     .arg(where.lonDeg, 0, 'f', 5);
  for (const auto& f : features) {
    html += QStringLiteral("<p><b>%1</b> (%2) — %3")
                .arg(escape(f.className), escape(f.objectClass), escape(f.cell));
    html += QStringLiteral("<table>");
    for (const auto& a : f.attributes)
      html += QStringLiteral("<tr><td>%1&nbsp;</td><td>%2</td></tr>").arg(escape(a.name), escape(a.value));
    html += QStringLiteral("</table></p>");
  }
  pick_->setHtml(html);
}

void MainWindow::addRecent(const QString& key, const QString& path) {
  QSettings settings;
  QStringList list = settings.value(key).toStringList();
  list.removeAll(path);
  list.prepend(path);
  while (list.size() > kMaxRecent) list.removeLast();
  settings.setValue(key, list);
  rebuildRecentMenu();
}

void MainWindow::rebuildRecentMenu() {
  recentMenu_->clear();
  QSettings settings;
  for (const QString& p : settings.value(QStringLiteral("recent/scenarios")).toStringList())
    recentMenu_->addAction(tr("Scenario: %1").arg(p), this, [this, p] { openScenario(p); });
  for (const QString& p : settings.value(QStringLiteral("recent/charts")).toStringList())
    recentMenu_->addAction(tr("Chart: %1").arg(p), this, [this, p] { openCharts(p); });
  recentMenu_->setEnabled(!recentMenu_->isEmpty());
}

void MainWindow::readSettings() {
  QSettings settings;
  if (!restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray())) resize(1500, 950);
  restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
  const int palette = settings.value(QStringLiteral("display/palette"), 0).toInt();
  if (palette >= 0 && palette <= 2) setPalette(static_cast<charts::Palette>(palette));
  OverlaySettings o = view_->overlay();
  o.vectorMinutes = std::clamp(
      settings.value(QStringLiteral("display/vectorMinutes"), o.vectorMinutes).toDouble(), 1.0, 60.0);
  o.relativeVectors = settings.value(QStringLiteral("display/relativeVectors"), o.relativeVectors).toBool();
  view_->setOverlay(o);
  const double scale = settings.value(QStringLiteral("display/scale"), 25000.0).toDouble();
  view_->setView(view_->viewport().centre(), std::isfinite(scale) ? scale : 25000.0);
  const int rate = settings.value(QStringLiteral("simulation/rateIndex"), 3).toInt();
  if (rate >= 0 && rate < rateBox_->count()) {
    rateBox_->setCurrentIndex(rate);
    lastRunRate_ = rateBox_->itemData(rate).toDouble();
  }
  rebuildRecentMenu();
}

void MainWindow::writeSettings() {
  QSettings settings;
  settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
  settings.setValue(QStringLiteral("window/state"), saveState());
  settings.setValue(QStringLiteral("display/palette"), static_cast<int>(view_->settings().palette));
  settings.setValue(QStringLiteral("display/vectorMinutes"), view_->overlay().vectorMinutes);
  settings.setValue(QStringLiteral("display/relativeVectors"), view_->overlay().relativeVectors);
  settings.setValue(QStringLiteral("display/scale"), view_->viewport().scaleDenominator());
  settings.setValue(QStringLiteral("simulation/rateIndex"), rateBox_->currentIndex());
  settings.setValue(QStringLiteral("session/scenario"),
                    scenarioSource_.startsWith(kBuiltinPrefix) ? QString() : scenarioSource_);
  settings.setValue(QStringLiteral("session/enc"),
                    chartSource_.startsWith(kBuiltinPrefix) ? QString() : chartSource_);
}

void MainWindow::closeEvent(QCloseEvent* event) {
  writeSettings();
  QMainWindow::closeEvent(event);
}

void MainWindow::reportError(const QString& message) {
  lastError_ = message;
  statusBar()->showMessage(message, 15000);
  qWarning("%s", qPrintable(message));
}

}  // namespace reckoner::ui
