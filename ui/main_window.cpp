#include "ui/main_window.h"

#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QEventLoop>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QMessageBox>
#include <QProgressBar>
#include <QSettings>
#include <QSignalBlocker>
#include <QSortFilterProxyModel>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTableView>
#include <QTextBrowser>
#include <QTextStream>
#include <QToolTip>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "charts/s57/s57_loader.h"
#include "common/angles.h"
#include "common/units.h"
#include "files/scenario_json.h"
#include "io/text_format.h"
#include "resources/embedded.h"
#include "ui/panels/alert_panel.h"
#include "ui/panels/alert_sound.h"
#include "ui/panels/chart_list_panel.h"
#include "ui/panels/mariner_settings_dialog.h"
#include "ui/panels/message_bar.h"
#include "ui/panels/own_ship_panel.h"
#include "ui/panels/sensor_panel.h"
#include "ui/panels/target_table_model.h"
#include "ui/panels/widget_palette.h"
#include "ui/plots/error_plots.h"

namespace reckoner::ui {
namespace {

constexpr int kRepaintMs = 33;  // <= 30 Hz
constexpr int kPlotMs = 500;
constexpr int kMaxRecent = 8;
const QString kBuiltinPrefix = QStringLiteral("builtin:");
constexpr int kDockStateVersion = 5;  // 4: the AIS and data monitor docks; 5: the route dock

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

MainWindow::MainWindow(const MainWindowOptions& options, QWidget* parent)
    : QMainWindow(parent),
      controller_(new SimulationController(this)),
      view_(new EcdisView(this)),
      options_(options) {
  setWindowTitle(QStringLiteral("Reckoner"));
  setObjectName(QStringLiteral("mainWindow"));
  buildCentre();
  view_->setObjectName(QStringLiteral("chart"));
  sound_ =
      new AlertSound(options.sound && QGuiApplication::platformName() != QLatin1String("offscreen"), this);
  buildDocks();
  buildActions();
  // The cursor readout is a permanent widget: messages take the bar's left part and neither hides the
  // other.
  statusBar()->addPermanentWidget(cursorLabel_ = new QLabel(this));
  cursorLabel_->setObjectName(QStringLiteral("cursorReadout"));
  statusBar()->addPermanentWidget(chartLabel_ = new QLabel(this));
  chartProgress_ = new QProgressBar(this);  // in the status bar while charts load
  chartProgress_->hide();
  chartProgress_->setMaximumWidth(200);
  chartProgress_->setFormat(tr("charts %v/%m"));
  const QString logDir = QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation);
  if (!logDir.isEmpty() && QDir().mkpath(logDir))
    alertLogPath_ = QDir(logDir).filePath(QStringLiteral("alerts.log"));

  connect(controller_, &SimulationController::frameArrived, this, &MainWindow::onFrame);
  connect(chartLoad_.worker(), &ChartLoadWorker::progress, this, &MainWindow::onChartLoadProgress,
          Qt::QueuedConnection);
  connect(chartLoad_.worker(), &ChartLoadWorker::loaded, this, &MainWindow::onChartsLoaded,
          Qt::QueuedConnection);
  connect(controller_, &SimulationController::failed, this, &MainWindow::reportError);
  connect(controller_, &SimulationController::scenarioEdited, this, [this] { setWindowModified(true); });
  connect(controller_, &SimulationController::loaded, this, [this](const sim::Scenario& s) {
    localFrame_.emplace(s.origin.latDeg, s.origin.lonDeg);
    view_->setHistory(&history_, *localFrame_);
    sensors_->setFitted(s);
    firstFrame_ = true;
    // The operator's remembered limits replace the scenario's (Tracking > CPA/TCPA limits).
    QSettings settings;
    if (settings.contains(QStringLiteral("tracking/cpaNm")))
      controller_->setCpaLimits(nmToMetres(settings.value(QStringLiteral("tracking/cpaNm")).toDouble()),
                                60.0 * settings.value(QStringLiteral("tracking/tcpaMin")).toDouble());
  });
  connect(view_, &EcdisView::orderRequested, controller_, &SimulationController::orderOwnShip);
  connect(view_, &EcdisView::addTargetRequested, controller_, &SimulationController::addTarget);
  // A target steered from the chart turns at 1 deg/s and changes speed at 0.05 m/s^2, like a ship.
  connect(view_, &EcdisView::steerTargetRequested, this, [this](int target, double course, double speed) {
    controller_->orderTarget(target, course, speed, degToRad(1.0), 0.05);
  });
  connect(view_, &EcdisView::acquireRequested, controller_, &SimulationController::acquireAt);
  connect(view_, &EcdisView::zonesEdited, controller_, &SimulationController::setAcquisitionZones);
  connect(view_, &EcdisView::cancelTrackRequested, controller_, &SimulationController::cancelTrack);
  connect(view_, &EcdisView::trackSelected, this, &MainWindow::selectTrack);
  connect(view_, &EcdisView::pickRequested, this, &MainWindow::showPick);
  connect(view_, &ChartView::picked, this, &MainWindow::showPickedFeatures);
  connect(view_, &EcdisView::cursorReadout, cursorLabel_, &QLabel::setText);
  connect(view_, &ChartView::renderFinished, this, &MainWindow::showChartStatus);

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
                           : enc,
             ChartArrival::Stay);  // the first view shows own ship and the targets (onFrame)
}

MainWindow::~MainWindow() {
  controller_->stopLive();
  hub_->stop();
  chartLoad_.worker()->requests().issue();  // stops a load in progress; chartLoad_ then stops the thread
}

bool MainWindow::openScenario(const QString& path) {
  sim::Scenario s;
  try {
    if (path.startsWith(kBuiltinPrefix)) {
      const std::string name = path.mid(kBuiltinPrefix.size()).toStdString();
      const resources::EmbeddedFile* f = resources::findScenario(name);
      if (!f) throw io::InputError(path.toStdString(), 0, "", "no embedded scenario of that name");
      s = files::parseScenario(f->text, path.toStdString());
    } else {
      s = files::loadScenarioFile(path.toStdString());
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
  scenarioName_ = QString::fromStdString(scenario.name);
  setWindowModified(false);
  firstFrame_ = true;
  view_->setSelectedTrack(std::nullopt);
  controller_->load(scenario);
  updateTitle();
  runAction_->setText(tr("Run"));
}

void MainWindow::openCharts(const QString& path, ChartArrival arrival) {
  chartArrival_ = arrival;
  if (!chartsLoading_) {
    statusBar()->addPermanentWidget(chartProgress_);
    chartProgress_->show();
  }
  chartsLoading_ = true;
  chartProgress_->setRange(0, 100);
  chartProgress_->reset();
  chartLoad_.post(&ChartLoadWorker::load, path, chartLoad_.worker()->requests().issue());
}

void MainWindow::onChartLoadProgress(quint64 generation, int done, int total) {
  if (!chartLoad_.worker()->requests().isCurrent(generation)) return;
  chartProgress_->setMaximum(std::max(1, total));
  chartProgress_->setValue(done);
}

void MainWindow::onChartsLoaded(const ChartLoadAnswer& answer) {
  if (!chartLoad_.worker()->requests().isCurrent(answer.generation)) return;  // superseded by a newer load
  chartsLoading_ = false;
  statusBar()->removeWidget(chartProgress_);  // (a hidden widget would still keep the bar's height)
  if (!answer.problem.isEmpty()) {
    reportError(answer.problem);
    return;
  }
  QStringList failures;
  for (const auto& f : answer.result.failures)
    failures << QStringLiteral("%1: %2").arg(QString::fromStdString(f.file),
                                             QString::fromStdString(f.reason));
  if (!failures.isEmpty()) reportError(failures.join(QLatin1Char('\n')));
  if (answer.result.cells.empty()) return;
  view_->setCells(answer.result.cells);
  chartList_->setCells(answer.result.cells);
  if (chartArrival_ == ChartArrival::Show)
    showArrivedCharts(answer.result.cells, failures.isEmpty() ? QString() : failures.front());
  controller_->setCharts(answer.result.cells);
  chartSource_ = answer.path;
  if (!answer.path.startsWith(kBuiltinPrefix)) addRecent(QStringLiteral("recent/charts"), answer.path);
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
    files::saveScenarioFile(*got, path.toStdString());
  } catch (const io::InputError& e) {
    reportError(QString::fromStdString(e.what()));
    return false;
  }
  addRecent(QStringLiteral("recent/scenarios"), path);
  scenarioSource_ = path;
  setWindowModified(false);
  updateTitle();
  statusBar()->showMessage(tr("Saved %1").arg(path), 5000);
  return true;
}

void MainWindow::setCpaLimits(double cpaNm, double tcpaMin) {
  if (!std::isfinite(cpaNm) || !std::isfinite(tcpaMin) || cpaNm <= 0.0 || tcpaMin <= 0.0) {
    reportError(tr("CPA/TCPA limits must be above 0 (got %1 NM, %2 min)").arg(cpaNm).arg(tcpaMin));
    return;
  }
  QSettings settings;
  settings.setValue(QStringLiteral("tracking/cpaNm"), cpaNm);
  settings.setValue(QStringLiteral("tracking/tcpaMin"), tcpaMin);
  controller_->setCpaLimits(nmToMetres(cpaNm), 60.0 * tcpaMin);
  statusBar()->showMessage(tr("Dangerous targets: CPA under %1 NM within %2 min").arg(cpaNm).arg(tcpaMin),
                           8000);
}

bool MainWindow::save() {
  if (scenarioSource_.isEmpty() || scenarioSource_.startsWith(kBuiltinPrefix)) return saveAs();
  return saveScenario(scenarioSource_);
}

bool MainWindow::saveAs() {
  QString path = QFileDialog::getSaveFileName(this, tr("Save scenario"), {}, tr("Scenarios (*.json)"));
  if (path.isEmpty()) return false;
  if (QFileInfo(path).suffix().isEmpty()) path += QStringLiteral(".json");  // else the Open dialog hides it
  return saveScenario(path);
}

void MainWindow::updateTitle() {
  // "[*]" is where Qt shows the unsaved-changes mark (setWindowModified).
  const QString where =
      scenarioSource_.startsWith(kBuiltinPrefix) ? scenarioSource_ : QFileInfo(scenarioSource_).fileName();
  setWindowTitle(QStringLiteral("%1 — %2[*] — Reckoner").arg(scenarioName_, where));
}

void MainWindow::setRate(double rate) {
  if (rate != 0.0) lastRunRate_ = rate;
  const LiveFrame& live = history_.latest();
  if (rate != 0.0 && live.finished)  // the worker runs on for 30 min: say so
    statusBar()->showMessage(tr("The scenario had ended at T+%1; running on for 30 more minutes")
                                 .arg(clockText(toSeconds(live.frame.timeUs))),
                             15000);
  controller_->setRate(rate);
  runAction_->setText(rate == 0.0 ? tr("Run") : tr("Pause"));
}

void MainWindow::onFrame(const LiveFrame& frame) {
  QElapsedTimer t;
  t.start();
  if (frame.restarted) history_.clear();  // a playback's seek back: its run starts again
  history_.append(frame);
  appendAlertLog(frame);
  const bool raised =
      std::any_of(frame.alertLog.begin(), frame.alertLog.end(), [](const alerts::AlertLogEntry& e) {
        return e.event == alerts::AlertLogEntry::Event::Raised ||
               e.event == alerts::AlertLogEntry::Event::Escalated;
      });
  if (raised)  // a new alert brings the Alerts tab forward
    if (auto* d = findChild<QDockWidget*>(QStringLiteral("alarmDock"))) d->raise();
  frameDirty_ = true;
  plotsDirty_ = true;
  if (frame.live) liveFrameArrived(frame);
  if (!frame.running) QTimer::singleShot(0, this, &MainWindow::refreshPlots);  // paused: show all now
  if (firstFrame_ && localFrame_) {
    firstFrame_ = false;
    view_->fitOwnShipAndTargets();
  }
  guiTimings_.push_back({GuiTiming::Kind::Frame, static_cast<double>(t.nsecsElapsed()) * 1e-6});
}

void MainWindow::repaintTick() {
  if (!frameDirty_) {
    if (!history_.alerts().empty()) view_->update();  // flashing symbols
    return;
  }
  QElapsedTimer t;
  t.start();
  frameDirty_ = false;
  const LiveFrame& live = history_.latest();
  if (localFrame_) ownPanel_->setFrame(live, *localFrame_);
  showVoyage(live);
  showPlayback(live);
  sensors_->setStates(live.frame.sensors, live.radarOn);
  sensors_->setNoisy(live.frame.noisierThanConfigured);
  for (QAction* a : trackerKindActions_)
    if (a->data().toInt() == static_cast<int>(live.trackerKind) && !a->isChecked()) a->setChecked(true);
  if (autoAcquireAction_ && autoAcquireAction_->isChecked() != live.autoAcquire)
    autoAcquireAction_->setChecked(live.autoAcquire);
  if (radarMatchAction_) {
    radarMatchAction_->setChecked(live.radarMatching);
    radarMatchAction_->setEnabled(live.chartContourSegments > 0 || live.radarMatching);
  }
  if (live.live) refreshAisTable(live);
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
  if (controller_->isLive()) {
    clock_->setText(live.live ? liveClockText(live) : tr("LIVE  waiting for a position fix"));
    return;
  }
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
  alertPanel_->refresh(history_);
  const auto& alerts = history_.alerts();
  sound_->update(alerts);
  alarmBannerAction_->setVisible(!alerts.empty());
  if (alerts.empty()) return;
  const alerts::Alert& top = alerts.front();
  alarmBanner_->setText(alertTitle(top) +
                        (alerts.size() > 1 ? tr("  (+%1)").arg(alerts.size() - 1) : QString()));
  alarmBanner_->setStyleSheet(alertLabelStyle(top.priority, view_->settings().palette, 2));
  alarmBanner_->setToolTip(tr("The most urgent alert; the Alerts dock lists them all"));
}

void MainWindow::appendAlertLog(const LiveFrame& frame) {
  if (frame.alertLog.empty() || alertLogPath_.isEmpty()) return;
  QFile f(alertLogPath_);
  if (!f.open(QIODevice::Append | QIODevice::Text)) {
    reportError(tr("cannot write the alert log %1: %2").arg(alertLogPath_, f.errorString()));
    alertLogPath_.clear();  // said once
    return;
  }
  QTextStream out(&f);
  for (const auto& e : frame.alertLog) out << scenarioSource_ << "  " << alertLogLine(e) << '\n';
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
  QString html = tr("<b>%1 features at %2 %3</b>")
                     .arg(features.size())
                     .arg(QString::fromStdString(io::formatLatitude(where.latDeg)),
                          QString::fromStdString(io::formatLongitude(where.lonDeg)));
  if (const QString from = view_->fromOwnShipText(where); !from.isEmpty())
    html += tr("<br>%1 from own ship").arg(from.toHtmlEscaped());
  for (const auto& f : features) {
    html += QStringLiteral("<p><b>%1</b> (%2) — %3")
                .arg(escape(f.className), escape(f.objectClass), escape(f.cell));
    html += QStringLiteral("<table>");
    for (const auto& a : f.attributes)
      html += QStringLiteral("<tr><td>%1&nbsp;</td><td>%2</td></tr>").arg(escape(a.name), escape(a.value));
    html += QStringLiteral("</table></p>");
  }
  pick_->setHtml(html);
  if (auto* d = findChild<QDockWidget*>(QStringLiteral("pickDock"))) d->raise();
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
  // Version 2: the chart-first arrangement (arrangeDocks); older saved arrangements are not restored.
  docksSized_ = restoreState(settings.value(QStringLiteral("window/state")).toByteArray(), kDockStateVersion);
  const int palette = settings.value(QStringLiteral("display/palette"), 0).toInt();
  if (palette >= 0 && palette <= 2) setPalette(static_cast<charts::Palette>(palette));
  OverlaySettings o = view_->overlay();
  o.vectorMinutes = std::clamp(
      settings.value(QStringLiteral("display/vectorMinutes"), o.vectorMinutes).toDouble(), 1.0, 60.0);
  o.relativeVectors = settings.value(QStringLiteral("display/relativeVectors"), o.relativeVectors).toBool();
  view_->setOverlay(o);
  charts::MarinerSettings mariner = loadMarinerSettings(settings, view_->settings());
  mariner.palette = view_->settings().palette;
  setMarinerSettings(mariner);
  if (settings.contains(QStringLiteral("alerts/drLimitM")))
    sensors_->setDrLimit(settings.value(QStringLiteral("alerts/drLimitM")).toDouble());
  if (settings.contains(QStringLiteral("alerts/discrepancyLimitM")))
    sensors_->setDiscrepancyLimit(settings.value(QStringLiteral("alerts/discrepancyLimitM")).toDouble());
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
  settings.setValue(QStringLiteral("window/state"), saveState(kDockStateVersion));
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

void MainWindow::showEvent(QShowEvent* event) {
  QMainWindow::showEvent(event);
  if (docksSized_) return;
  docksSized_ = true;
  // The dock column takes 30% of the window's width, between 300 and 440 px: the chart keeps 60% of a
  // 1024 x 768 window and more of larger ones.
  const int column = std::clamp(static_cast<int>(0.3 * width()), 300, 440);
  if (auto* own = findChild<QDockWidget*>(QStringLiteral("ownShipDock")))
    resizeDocks({own}, {column}, Qt::Horizontal);
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (isWindowModified() && options_.askToSaveOnClose) {
    const auto answer = QMessageBox::question(
        this, tr("Unsaved changes"),
        tr("The scenario has changes made while it ran (orders, sensors, targets). Save them?"),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Cancel || (answer == QMessageBox::Save && !save())) {
      event->ignore();
      return;
    }
  }
  if (!confirmUnsavedRoutes()) return event->ignore();  // routes edited and not saved: asks
  writeSettings();
  QMainWindow::closeEvent(event);
}

void MainWindow::buildCentre() {
  // The chart, with the message bar above it (shown only while there is an error to read).
  auto* centre = new QWidget(this);
  auto* column = new QVBoxLayout(centre);
  column->setContentsMargins(0, 0, 0, 0);
  column->setSpacing(0);
  messageBar_ = new MessageBar(centre);
  column->addWidget(messageBar_);
  column->addWidget(view_, 1);
  setCentralWidget(centre);
}

bool MainWindow::setMarinerSettings(const charts::MarinerSettings& s) {
  if (const QString problem = marinerSettingsProblem(s); !problem.isEmpty()) {
    reportError(problem);
    return false;
  }
  view_->setSettings(s);
  QSettings settings;
  saveMarinerSettings(settings, s);
  showMarinerSettings(s);
  return true;
}

void MainWindow::showMarinerSettings(const charts::MarinerSettings& s) {
  const QSignalBlocker blockCategory(categoryBox_);
  const QSignalBlocker blockSafety(safetyBox_);
  categoryBox_->setCurrentIndex(static_cast<int>(s.category));
  safetyBox_->setRange(s.shallowContourM, s.deepContourM);
  safetyBox_->setValue(s.safetyContourM);
}

void MainWindow::reportError(const QString& message) {
  lastError_ = message;
  statusBar()->showMessage(message.section(QLatin1Char('\n'), 0, 0), 15000);
  messageBar_->showError(message);
  qWarning("%s", qPrintable(message));
}

}  // namespace reckoner::ui
