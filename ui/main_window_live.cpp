// MainWindow's Live mode (docs/gui.md, "Live"): the window's connections (a conn::ConnectionHub whose
// sources are saved in QSettings under connections/), the Connections dialog, the data monitor dock,
// the status-bar indicator, the AIS target dock, and the switch between the simulation and the live
// run (SimulationController::startLive / stopLive).
#include <QActionGroup>
#include <QDockWidget>
#include <QHeaderView>
#include <QInputDialog>
#include <QLineEdit>
#include <QMenuBar>
#include <QSettings>
#include <QSortFilterProxyModel>
#include <QStatusBar>
#include <QTableView>
#include <QTextBrowser>
#include <QToolBar>
#include <algorithm>

#include "common/units.h"
#include "connections/nmea_destination.h"
#include "files/scenario_json.h"
#include "io/text_format.h"
#include "resources/embedded.h"
#include "ui/main_window.h"
#include "ui/panels/ais_table_model.h"
#include "ui/panels/connection_indicator.h"
#include "ui/panels/connections_dialog.h"
#include "ui/panels/data_monitor.h"
#include "ui/panels/sensor_panel.h"

namespace reckoner::ui {

void MainWindow::buildLive() {
  hub_ = new conn::ConnectionHub(this);
  QSettings settings;
  QStringList errors;
  for (const conn::SourceConfig& c : loadConnections(settings, &errors)) {
    try {
      hub_->add(c);
    } catch (const std::invalid_argument& e) {
      errors
          << QStringLiteral("%1: connections: %2").arg(settings.fileName(), QString::fromStdString(e.what()));
    }
  }
  if (!errors.isEmpty()) reportError(errors.join(QLatin1Char('\n')));
  indicator_ = new ConnectionIndicator(*hub_, this);
  indicator_->setObjectName(QStringLiteral("connectionIndicator"));
  statusBar()->addPermanentWidget(indicator_);

  aisModel_ = new AisTableModel(this);
  aisProxy_ = new QSortFilterProxyModel(this);
  aisProxy_->setSourceModel(aisModel_);
  aisProxy_->setSortRole(Qt::UserRole);
  aisTable_ = new QTableView(this);
  aisTable_->setObjectName(QStringLiteral("aisTable"));
  aisTable_->setModel(aisProxy_);
  aisTable_->setSortingEnabled(true);
  aisTable_->sortByColumn(AisTableModel::Range, Qt::AscendingOrder);
  aisTable_->setSelectionBehavior(QAbstractItemView::SelectRows);
  aisTable_->setSelectionMode(QAbstractItemView::SingleSelection);
  aisTable_->verticalHeader()->hide();
  // Fixed widths: ResizeToContents would measure all 2000 rows at every refresh of the table.
  aisTable_->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
  aisTable_->horizontalHeader()->setDefaultSectionSize(90);
  aisTable_->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
  aisTable_->setToolTip(tr("AIS targets (Live mode); double-click activates or puts to sleep"));
  addScrollDock(tr("AIS"), QStringLiteral("aisDock"), aisTable_, Qt::BottomDockWidgetArea);
  connect(aisTable_->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
          [this](const QModelIndex& current) {
            if (!current.isValid()) return;
            const std::uint32_t mmsi = aisModel_->mmsiAt(aisProxy_->mapToSource(current).row());
            controller_->selectAis(mmsi);
            if (const LiveFrame& live = history_.latest(); live.aisTargets)
              for (const track::AisTarget& t : *live.aisTargets)
                if (t.mmsi == mmsi) pick_->setPlainText(aisPickReport(t));
          });
  connect(aisTable_, &QTableView::doubleClicked, this, [this](const QModelIndex& index) {
    const int row = aisProxy_->mapToSource(index).row();
    const LiveFrame& live = history_.latest();
    if (!live.aisTargets) return;
    const std::uint32_t mmsi = aisModel_->mmsiAt(row);
    const auto it = std::find_if(live.aisTargets->begin(), live.aisTargets->end(),
                                 [mmsi](const track::AisTarget& t) { return t.mmsi == mmsi; });
    if (it != live.aisTargets->end()) controller_->activateAis(mmsi, !it->activated);
  });
  monitor_ = new DataMonitor(*hub_, this);
  monitor_->setObjectName(QStringLiteral("dataMonitor"));
  addScrollDock(tr("Data monitor"), QStringLiteral("monitorDock"), monitor_, Qt::BottomDockWidgetArea);
}

void MainWindow::buildLiveMenu() {
  QMenu* live = menuBar()->addMenu(tr("&Live"));
  liveAction_ = live->addAction(tr("Live mode"));
  liveAction_->setObjectName(QStringLiteral("liveMode"));
  liveAction_->setCheckable(true);
  liveAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_L));
  liveAction_->setToolTip(
      tr("Run the filters and trackers on the connections' sentences instead of the simulation"));
  connect(liveAction_, &QAction::toggled, this, [this](bool on) {
    if (on)
      startLive();
    else
      stopLive();
  });
  live->addAction(tr("Connections…"), this, [this] {
    QSettings settings;
    ConnectionsDialog dialog(*hub_, &settings, this);
    dialog.exec();
  });
  live->addAction(tr("NMEA output…"), this, &MainWindow::askLiveNmeaOut);
  live->addSeparator();
  buildPlayback(live);
  live->addSeparator();
  for (const char* name : {"monitorDock", "aisDock"})
    if (auto* d = findChild<QDockWidget*>(QString::fromLatin1(name))) live->addAction(d->toggleViewAction());
}

bool MainWindow::startLive() {
  if (controller_->isLive()) return true;
  if (hub_->sources().empty()) {
    reportError(tr("Live mode needs a connection: add one in Live > Connections…"));
    const QSignalBlocker block(liveAction_);
    liveAction_->setChecked(false);
    return false;
  }
  sim::LiveOptions o;
  const resources::EmbeddedFile* defaults = resources::findScenario(resources::kDefaultScenario);
  o.replay = sim::recordedDataOptions(files::parseScenario(defaults->text, "builtin:default"));
  o.name = "live";
  o.reorderHorizonS = 1.0;
  const auto sources = hub_->sources();
  o.radar = std::any_of(sources.begin(), sources.end(),
                        [](const conn::SourceConfig& c) { return c.role == conn::Role::Radar; });
  sim::LiveWatchSettings w;
  w.alerts = sim::alertFeedSettingsFor(o.replay.settings);
  QSettings settings;
  if (settings.contains(QStringLiteral("tracking/cpaNm"))) {
    w.alerts.cpa.cpaM = nmToMetres(settings.value(QStringLiteral("tracking/cpaNm")).toDouble());
    w.alerts.cpa.tcpaS = 60.0 * settings.value(QStringLiteral("tracking/tcpaMin")).toDouble();
  }
  w.alerts.drLimitM = sensors_->drLimit();
  w.alerts.positionDiscrepancyM = sensors_->discrepancyLimit();
  w.ais.cpaLimitM = w.alerts.cpa.cpaM;
  w.ais.tcpaLimitS = w.alerts.cpa.tcpaS;
  history_.clear();
  localFrame_.reset();
  firstFrame_ = true;
  view_->setSelectedTrack(std::nullopt);
  hub_->start();
  controller_->startLive(hub_, o, w);
  controller_->setLiveNmeaOut(settings.value(QStringLiteral("live/nmeaOut")).toString());
  {
    const QSignalBlocker block(liveAction_);
    liveAction_->setChecked(true);
  }
  for (QWidget* w2 : simulationControls_) w2->setEnabled(false);
  for (QAction* a : simulationActions_) a->setEnabled(false);
  if (auto* d = findChild<QDockWidget*>(QStringLiteral("aisDock"))) d->raise();
  setWindowTitle(tr("Live — Reckoner"));
  statusBar()->showMessage(tr("Live: waiting for a position fix from the connections"), 10000);
  updateClock();
  return true;
}

void MainWindow::stopLive() {
  if (!controller_->isLive()) return;
  controller_->stopLive();
  hub_->stop();
  playbackToolbar_->hide();
  {
    const QSignalBlocker block(liveAction_);
    liveAction_->setChecked(false);
  }
  for (QWidget* w : simulationControls_) w->setEnabled(true);
  for (QAction* a : simulationActions_) a->setEnabled(true);
  aisModel_->setTargets({});
  aisShown_.reset();
  // Back to the simulation: the scenario again from its start.
  const QString scenario = scenarioSource_;
  localFrame_.reset();
  if (scenario.isEmpty() || !openScenario(scenario))
    openScenario(QStringLiteral("builtin:") + QString::fromLatin1(resources::kDefaultScenario.data(),
                                                                  int(resources::kDefaultScenario.size())));
}

bool MainWindow::setLiveNmeaOut(const QString& spec) {
  if (!spec.trimmed().isEmpty()) {
    try {
      (void)conn::parseDestination(spec.trimmed().toStdString());
    } catch (const std::invalid_argument& e) {
      reportError(QString::fromStdString(e.what()));
      return false;
    }
  }
  QSettings().setValue(QStringLiteral("live/nmeaOut"), spec.trimmed());
  if (controller_->isLive()) controller_->setLiveNmeaOut(spec.trimmed());
  return true;
}

void MainWindow::askLiveNmeaOut() {
  bool ok = false;
  const QString spec = QInputDialog::getText(
      this, tr("NMEA output"),
      tr("Own ship, tracks and alerts as NMEA 0183 in Live mode, to udp://HOST:PORT (e.g. OpenCPN's\n"
         "udp://127.0.0.1:10110), tcp://:PORT (a server) or a file path; empty: none"),
      QLineEdit::Normal, QSettings().value(QStringLiteral("live/nmeaOut")).toString(), &ok);
  if (ok) setLiveNmeaOut(spec);
}

bool MainWindow::isLive() const {
  return controller_->isLive();
}

void MainWindow::liveFrameArrived(const LiveFrame& frame) {
  if (!frame.liveOrigin) return;
  const geo::GeoPoint& o = *frame.liveOrigin;
  if (!localFrame_ || localFrame_->origin().latDeg != o.latDeg || localFrame_->origin().lonDeg != o.lonDeg) {
    localFrame_.emplace(o.latDeg, o.lonDeg);
    view_->setHistory(&history_, *localFrame_);
    firstFrame_ = true;  // the first view shows own ship and the targets
    statusBar()->showMessage(
        (frame.playback ? tr("Playback: own ship from the record's first position fix, %1")
                        : tr("Live: own ship from the connections' first position fix, %1"))
            .arg(QString::fromStdString(io::formatLatitude(o.latDeg) + " " + io::formatLongitude(o.lonDeg))),
        8000);
  }
}

void MainWindow::refreshAisTable(const LiveFrame& live) {
  // Only while the list is on screen, at most once a second (the table's range and CPA change once a
  // second; a new target resets the model, some 7 ms with 2000 rows sorted).
  if (live.aisTargets == aisShown_ || !aisTable_->isVisible()) return;
  if (aisRefreshed_.isValid() && aisRefreshed_.elapsed() < 1000 && aisShown_) return;
  aisRefreshed_.start();
  aisShown_ = live.aisTargets;
  aisModel_->setTargets(live.aisTargets ? *live.aisTargets : std::vector<track::AisTarget>{});
}

QString MainWindow::liveClockText(const LiveFrame& live) const {
  const UtcUs utc = live.liveUtc0 + live.frame.timeUs;
  const auto sod = static_cast<long long>((utc / kMicrosPerSecond) % 86400);
  QString text = QStringLiteral("%4 %1:%2:%3 UTC")
                     .arg(sod / 3600, 2, 10, QChar('0'))
                     .arg(sod / 60 % 60, 2, 10, QChar('0'))
                     .arg(sod % 60, 2, 10, QChar('0'))
                     .arg(live.playback ? tr("PLAYBACK") : QStringLiteral("LIVE"));
  if (live.frame.deadReckoning.active) text += tr("  DR");
  if (live.aisCounts.targets > 0) text += tr("  AIS %1").arg(live.aisCounts.targets);
  return text;
}

}  // namespace reckoner::ui
