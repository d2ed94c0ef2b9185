#include "ui/panels/alert_panel.h"

#include <QHBoxLayout>
#include <QVBoxLayout>

namespace reckoner::ui {

namespace {

QString timeText(TimeUs t) {
  const long long s = static_cast<long long>(t / kMicrosPerSecond);
  return QStringLiteral("T+%1:%2").arg(s / 60).arg(s % 60, 2, 10, QLatin1Char('0'));
}

bool waits(const alerts::Alert& a) {
  return a.priority != alerts::Priority::Caution &&
         (a.state == alerts::AlertState::Unacknowledged || a.state == alerts::AlertState::Silenced ||
          a.state == alerts::AlertState::Rectified);
}

}  // namespace

QColor alertColour(alerts::Priority p, charts::Palette palette) {
  QColor day = Qt::gray;
  switch (p) {
    case alerts::Priority::Alarm:
      day = QColor(0xc6, 0x28, 0x28);
      break;
    case alerts::Priority::Warning:
      day = QColor(0xef, 0x6c, 0x00);
      break;
    case alerts::Priority::Caution:
      day = QColor(0xf9, 0xa8, 0x25);
      break;
  }
  // Dusk keeps the hue at 70% of the day's brightness; night at a third, like the chart's night
  // table, so that the banner is no brighter than the chart's own reds.
  switch (palette) {
    case charts::Palette::Day:
      return day;
    case charts::Palette::Dusk:
      return day.darker(140);
    case charts::Palette::Night:
      return day.darker(300);
  }
  return day;
}

QString alertLabelStyle(alerts::Priority p, charts::Palette palette, int paddingPx) {
  QString text = p == alerts::Priority::Caution ? QStringLiteral("black") : QStringLiteral("white");
  if (palette == charts::Palette::Night)
    text = QStringLiteral("#a09078");
  else if (palette == charts::Palette::Dusk && p != alerts::Priority::Caution)
    text = QStringLiteral("#d8d8d8");
  return QStringLiteral("QLabel { background: %1; color: %2; font-weight: bold; padding: %3px %4px; }")
      .arg(alertColour(p, palette).name(), text)
      .arg(paddingPx)
      .arg(2 * paddingPx);
}

AlertPanel::AlertPanel(QWidget* parent) : QWidget(parent) {
  auto* v = new QVBoxLayout(this);
  v->setContentsMargins(0, 0, 0, 0);
  tabs_ = new QTabWidget(this);
  list_ = new QListWidget(tabs_);
  list_->setObjectName(QStringLiteral("alerts"));
  list_->setToolTip(
      tr("Alerts now: alarms first, then warnings and cautions; within each, those waiting "
         "for acknowledgement first, newest first"));
  history_ = new QListWidget(tabs_);
  history_->setObjectName(QStringLiteral("alertHistory"));
  history_->setToolTip(tr("Every change of every alert in this run (also written to the alert log file)"));
  tabs_->addTab(list_, tr("Active"));
  tabs_->addTab(history_, tr("History"));
  v->addWidget(tabs_);
  auto* buttons = new QHBoxLayout;
  acknowledge_ = new QPushButton(tr("Acknowledge"), this);
  acknowledge_->setObjectName(QStringLiteral("acknowledge"));
  acknowledge_->setToolTip(
      tr("Acknowledge the selected alert, or the most urgent one waiting. An alert "
         "whose condition still holds stays on the list, steady."));
  silence_ = new QPushButton(tr("Silence 30 s"), this);
  silence_->setObjectName(QStringLiteral("silence"));
  silence_->setToolTip(tr("Silence every audible alert for 30 s; they sound again unless acknowledged"));
  buttons->addWidget(acknowledge_);
  buttons->addWidget(silence_);
  v->addLayout(buttons);
  connect(acknowledge_, &QPushButton::clicked, this, [this] {
    if (const auto id = acknowledgeTarget()) emit acknowledgeRequested(*id);
  });
  connect(silence_, &QPushButton::clicked, this, &AlertPanel::silenceRequested);
  connect(list_, &QListWidget::currentRowChanged, this, [this] { updateButtons(); });
  updateButtons();
}

void AlertPanel::refresh(const SimHistory& h) {
  const auto& alerts = h.alerts();
  std::optional<alerts::AlertId> selected;
  if (const QListWidgetItem* it = list_->currentItem())
    selected = it->data(Qt::UserRole).value<alerts::AlertId>();
  shown_ = alerts;
  anyAudible_ = false;
  list_->clear();
  for (const alerts::Alert& a : alerts) {
    anyAudible_ = anyAudible_ || a.audible();
    QString state = QString::fromLatin1(alerts::stateName(a.state));
    if (a.escalated) state += tr(", escalated");
    auto* item =
        new QListWidgetItem(QStringLiteral("%1  %2  [%3]").arg(timeText(a.raisedUs), alertTitle(a), state));
    item->setToolTip(tr("%1, %2 since %3").arg(alertTitle(a), state, timeText(a.raisedUs)));
    item->setData(Qt::UserRole, QVariant::fromValue(a.id));
    item->setForeground(
        alertColour(a.priority, palette_ == charts::Palette::Night ? charts::Palette::Dusk : palette_));
    QFont f = item->font();
    f.setBold(waits(a));
    item->setFont(f);
    list_->addItem(item);
    if (selected && a.id == *selected) list_->setCurrentItem(item);
  }
  const auto& log = h.alertHistory();
  if (h.alertHistoryCount() < historyShown_) {  // a new run
    history_->clear();
    historyShown_ = 0;
  }
  const std::uint64_t fresh = std::min<std::uint64_t>(h.alertHistoryCount() - historyShown_, log.size());
  for (std::size_t k = log.size() - static_cast<std::size_t>(fresh); k < log.size(); ++k)
    history_->addItem(alertLogLine(log[k]));
  historyShown_ = h.alertHistoryCount();
  while (history_->count() > static_cast<int>(SimHistory::kAlertHistoryLimit)) delete history_->takeItem(0);
  updateButtons();
}

std::optional<alerts::AlertId> AlertPanel::acknowledgeTarget() const {
  if (const QListWidgetItem* it = list_->currentItem()) {
    const auto id = it->data(Qt::UserRole).value<alerts::AlertId>();
    for (const auto& a : shown_)
      if (a.id == id && waits(a)) return id;
    return std::nullopt;
  }
  for (const auto& a : shown_)  // most urgent first
    if (waits(a)) return a.id;
  return std::nullopt;
}

void AlertPanel::updateButtons() {
  acknowledge_->setEnabled(acknowledgeTarget().has_value());
  silence_->setEnabled(anyAudible_);
}

}  // namespace reckoner::ui
