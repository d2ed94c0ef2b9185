// The voyage record in the window: Live ▸ Record the live run… (LiveWorker's recorder) and playback of a
// record (docs/gui.md, "Playback"; docs/recorder.md): Live ▸ Play back
// a record… runs the record through the live worker (LiveWorker::startPlayback) as Live mode runs the
// connections, so the chart, the targets, the tables, the alerts and the plots follow it; the playback
// bar at the bottom plays, pauses, sets the speed, seeks on the timeline and jumps to the alerts.
#include <QAction>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QStatusBar>
#include <QToolBar>

#include "ui/main_window.h"
#include "ui/panels/playback_bar.h"

namespace reckoner::ui {

void MainWindow::buildPlayback(QMenu* liveMenu) {
  recordLiveAction_ = liveMenu->addAction(tr("Record the live run…"));
  recordLiveAction_->setObjectName(QStringLiteral("recordLiveAction"));
  recordLiveAction_->setCheckable(true);
  recordLiveAction_->setToolTip(
      tr("Record the next live run (every line, the estimates, the alerts, your actions "
         "and the charts) to a new voyage record"));
  connect(recordLiveAction_, &QAction::triggered, this, [this](bool on) {
    if (!on) {
      setLiveRecordPath({});
      return;
    }
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Record the live run to"), {}, tr("Voyage records (*.sqlite)"));
    setLiveRecordPath(path);
  });
  QAction* open = liveMenu->addAction(tr("Play back a record…"), this, [this] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Play back a voyage record"), {},
                                                      tr("Voyage records (*.sqlite);;All files (*)"));
    if (!path.isEmpty()) startPlayback(path);
  });
  open->setObjectName(QStringLiteral("playbackOpenAction"));
  playbackBar_ = new PlaybackBar(this);
  playbackBar_->setObjectName(QStringLiteral("playbackBar"));
  playbackBar_->setToolTip(
      tr("Playback of a voyage record: play, pause, speed, the timeline with its alerts, "
         "the jumps to them"));
  playbackToolbar_ = new QToolBar(tr("Playback"), this);
  playbackToolbar_->setObjectName(QStringLiteral("playbackToolbar"));
  playbackToolbar_->addWidget(playbackBar_);
  playbackToolbar_->setMovable(false);
  addToolBar(Qt::BottomToolBarArea, playbackToolbar_);
  playbackToolbar_->hide();
  connect(playbackBar_, &PlaybackBar::rateRequested, controller_, &SimulationController::setPlaybackRate);
  connect(playbackBar_, &PlaybackBar::seekRequested, controller_,
          [this](qint64 utc) { controller_->seekPlayback(static_cast<UtcUs>(utc)); });
  connect(playbackBar_, &PlaybackBar::closeRequested, this, &MainWindow::stopLive);
}

bool MainWindow::startPlayback(const QString& path) {
  if (!QFileInfo::exists(path)) {
    reportError(tr("%1: no such file").arg(path));
    return false;
  }
  if (controller_->isLive()) stopLive();
  history_.clear();
  localFrame_.reset();
  firstFrame_ = true;
  view_->setSelectedTrack(std::nullopt);
  controller_->startPlayback(path);
  for (QWidget* w : simulationControls_) w->setEnabled(false);
  for (QAction* a : simulationActions_) a->setEnabled(false);
  playbackToolbar_->show();
  setWindowTitle(tr("Playback %1 — Reckoner").arg(QFileInfo(path).fileName()));
  statusBar()->showMessage(tr("Playback of %1: paused at its start; Play or the timeline").arg(path), 10000);
  updateClock();
  return true;
}

bool MainWindow::setLiveRecordPath(const QString& path) {
  const bool on = !path.isEmpty();
  if (on && QFileInfo::exists(path)) {
    reportError(tr("%1: a voyage record is never written over: choose a new file").arg(path));
    recordLiveAction_->setChecked(false);
    return false;
  }
  controller_->setLiveRecordPath(path);
  recordLiveAction_->setChecked(on);
  recordLiveAction_->setText(on ? tr("Record the live run… (%1)").arg(QFileInfo(path).fileName())
                                : tr("Record the live run…"));
  if (on)
    statusBar()->showMessage(controller_->isLive() && !controller_->isPlayback()
                                 ? tr("The next live run is recorded to %1 (this one is not)").arg(path)
                                 : tr("The next live run is recorded to %1").arg(path),
                             8000);
  return true;
}

bool MainWindow::isPlayback() const {
  return controller_->isPlayback();
}

void MainWindow::showPlayback(const LiveFrame& live) {
  if (live.playback) playbackBar_->setState(*live.playback);
}

}  // namespace reckoner::ui
