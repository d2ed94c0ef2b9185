#include "ui/panels/message_bar.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QStyle>
#include <QTime>
#include <QToolButton>

namespace reckoner::ui {

MessageBar::MessageBar(QWidget* parent) : QWidget(parent) {
  setObjectName(QStringLiteral("messageBar"));
  setAutoFillBackground(true);
  // The tooltip colours: light yellow by day, dark and dim at dusk and night (widget_palette.h).
  setBackgroundRole(QPalette::ToolTipBase);
  auto* row = new QHBoxLayout(this);
  row->setContentsMargins(8, 4, 4, 4);
  auto* icon = new QLabel(this);
  icon->setPixmap(style()->standardIcon(QStyle::SP_MessageBoxWarning).pixmap(16, 16));
  row->addWidget(icon, 0, Qt::AlignTop);
  text_ = new QLabel(this);
  text_->setObjectName(QStringLiteral("messageText"));
  text_->setWordWrap(true);
  text_->setForegroundRole(QPalette::ToolTipText);
  text_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  row->addWidget(text_, 1);
  close_ = new QToolButton(this);
  close_->setObjectName(QStringLiteral("dismissMessage"));
  close_->setAutoRaise(true);
  close_->setIcon(style()->standardIcon(QStyle::SP_DialogCloseButton));
  close_->setToolTip(tr("Dismiss (the message stays in the log)"));
  connect(close_, &QToolButton::clicked, this, &MessageBar::dismiss);
  row->addWidget(close_, 0, Qt::AlignTop);
  hide();
}

void MessageBar::showError(const QString& message) {
  repeats_ = isVisible() && message == message_ ? repeats_ + 1 : 1;
  message_ = message;
  render();
  show();
}

void MessageBar::dismiss() {
  hide();
  repeats_ = 0;
}

void MessageBar::render() {
  const QStringList lines = message_.split(QLatin1Char('\n'));
  QString html = QStringLiteral("<b>%1</b>").arg(lines.front().toHtmlEscaped());
  for (qsizetype i = 1; i < lines.size() && i < 8; ++i)
    html += QStringLiteral("<br>") + lines[i].toHtmlEscaped();
  if (lines.size() > 8) html += tr("<br>… and %1 more (see the log)").arg(lines.size() - 8);
  if (repeats_ > 1)
    html += tr("  <i>(%1 times, last at %2)</i>").arg(repeats_).arg(QTime::currentTime().toString());
  text_->setText(html);
}

}  // namespace reckoner::ui
