// The trial manoeuvre in the window (docs/gui.md "Trial manoeuvre"): Tracking > Trial manoeuvre (Ctrl+T)
// shows the trial for the ordered course and speed; dragging the ordered-vector handle then proposes a
// trial instead of ordering; Tracking > Trial delay sets when the order would be given. The simulation
// runs on untouched. Also here: which symbol an associated AIS target shows.
#include <QAction>
#include <QInputDialog>
#include <QMenu>

#include "ui/main_window.h"

namespace reckoner::ui {

void MainWindow::buildTrialActions(QMenu* tracking) {
  tracking->addSeparator();
  trialAction_ = tracking->addAction(tr("Trial manoeuvre"));
  trialAction_->setObjectName(QStringLiteral("trialManoeuvre"));
  trialAction_->setCheckable(true);
  trialAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_T));
  trialAction_->setToolTip(
      tr("Show the effect of a proposed course and speed on every target (drag own "
         "ship's vector handle to try one); the run is not changed"));
  connect(trialAction_, &QAction::toggled, this, &MainWindow::setTrialShown);
  tracking
      ->addAction(tr("Trial delay…"), this,
                  [this] {
                    bool ok = false;
                    const double d =
                        QInputDialog::getDouble(this, tr("Trial delay"), tr("Order given after (s)"),
                                                trialDelayS_, 0.0, 3600.0, 0, &ok);
                    if (!ok) return;
                    trialDelayS_ = d;
                    if (trialAction_->isChecked()) setTrialShown(true);
                  })
      ->setObjectName(QStringLiteral("trialDelay"));
  connect(view_, &EcdisView::trialRequested, this, [this](double course, double speed) {
    if (trialAction_->isChecked()) controller_->setTrial(true, course, speed, trialDelayS_);
  });
  addOverlayToggle(tracking, tr("Associated AIS targets: radar symbol"), &OverlaySettings::associatedAsRadar)
      ->setObjectName(QStringLiteral("associatedAsRadar"));
}

void MainWindow::setTrialShown(bool on) {
  view_->setTrialMode(on);
  const auto [course, speed] = view_->orderedCourseSpeed();
  controller_->setTrial(on, course, speed, trialDelayS_);
}

}  // namespace reckoner::ui
