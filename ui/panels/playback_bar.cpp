#include "ui/panels/playback_bar.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QToolButton>
#include <algorithm>
#include <cmath>

#include "io/iso8601.h"

namespace reckoner::ui {
namespace {
constexpr double kMarginPx = 6.0;
/// A jump lands this long (stream time) after the alert was raised, so it is on screen.
constexpr UtcUs kJumpAfterUs = kMicrosPerSecond;

QString hms(UtcUs utc) {
  return QString::fromStdString(io::formatIso8601(utc)).mid(11, 8);
}

QString span(UtcUs us) {
  const long long s = us / kMicrosPerSecond;
  return QStringLiteral("%1:%2:%3")
      .arg(s / 3600, 2, 10, QChar('0'))
      .arg(s / 60 % 60, 2, 10, QChar('0'))
      .arg(s % 60, 2, 10, QChar('0'));
}

QColor priorityColour(const std::string& priority) {
  if (priority == "alarm") return {220, 30, 30};
  if (priority == "warning") return {240, 130, 0};
  return {200, 170, 0};
}
}  // namespace

// ---- timeline ------------------------------------------------------------------------------------

PlaybackTimeline::PlaybackTimeline(QWidget* parent) : QWidget(parent) {
  setMinimumWidth(200);
  setCursor(Qt::PointingHandCursor);
  setToolTip(tr("The record from its first to its last input; marks: alerts raised. Click or drag to seek"));
}

void PlaybackTimeline::setState(const LiveFrame::Playback& p) {
  state_ = p;
  update();
}

UtcUs PlaybackTimeline::utcAt(double x) const {
  const double w = std::max(1.0, width() - 2.0 * kMarginPx);
  const double f = std::clamp((x - kMarginPx) / w, 0.0, 1.0);
  return state_.first + static_cast<UtcUs>(std::llround(f * static_cast<double>(state_.last - state_.first)));
}

double PlaybackTimeline::xOf(UtcUs utc) const {
  const double w = std::max(1.0, width() - 2.0 * kMarginPx);
  const double length = std::max<double>(1.0, static_cast<double>(state_.last - state_.first));
  return kMarginPx + w * std::clamp(static_cast<double>(utc - state_.first) / length, 0.0, 1.0);
}

void PlaybackTimeline::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  const double mid = height() / 2.0;
  const QColor text = palette().color(QPalette::WindowText);
  p.setPen(QPen(palette().color(QPalette::Mid), 4.0, Qt::SolidLine, Qt::RoundCap));
  p.drawLine(QPointF(kMarginPx, mid), QPointF(width() - kMarginPx, mid));
  const UtcUs clock = dragging_.value_or(state_.clock);
  p.setPen(QPen(palette().color(QPalette::Highlight), 4.0, Qt::SolidLine, Qt::RoundCap));
  p.drawLine(QPointF(kMarginPx, mid), QPointF(xOf(clock), mid));
  if (state_.alerts)
    for (const files::RecordedAlert& a : *state_.alerts) {
      if (a.event != "raised") continue;
      const double x = xOf(state_.receiveTimeOf(a.utc));
      p.setPen(QPen(priorityColour(a.priority), 2.0));
      p.drawLine(QPointF(x, 2.0), QPointF(x, mid - 3.0));
    }
  p.setPen(QPen(text, 1.5));
  p.setBrush(palette().color(QPalette::Base));
  p.drawEllipse(QPointF(xOf(clock), mid), 6.0, 6.0);
}

void PlaybackTimeline::mousePressEvent(QMouseEvent* e) {
  if (e->button() != Qt::LeftButton) return;
  dragging_ = utcAt(e->position().x());
  update();
}

void PlaybackTimeline::mouseMoveEvent(QMouseEvent* e) {
  if (!dragging_) return;
  dragging_ = utcAt(e->position().x());
  update();
}

void PlaybackTimeline::mouseReleaseEvent(QMouseEvent* e) {
  if (!dragging_ || e->button() != Qt::LeftButton) return;
  const UtcUs to = utcAt(e->position().x());
  dragging_.reset();
  emit seekRequested(static_cast<qint64>(to));
  update();
}

// ---- bar -----------------------------------------------------------------------------------------

PlaybackBar::PlaybackBar(QWidget* parent) : QWidget(parent) {
  auto* h = new QHBoxLayout(this);
  h->setContentsMargins(4, 2, 4, 2);
  const auto button = [this, h](const QString& text, const char* name, const QString& tip) {
    auto* b = new QToolButton(this);
    b->setText(text);
    b->setObjectName(QString::fromLatin1(name));
    b->setToolTip(tip);
    h->addWidget(b);
    return b;
  };
  play_ = button(tr("Play"), "playbackPlay", tr("Play or pause the record (Space in the bar)"));
  speed_ = new QComboBox(this);
  speed_->setObjectName(QStringLiteral("playbackSpeed"));
  for (const double r : {1.0, 2.0, 5.0, 10.0, 30.0, 60.0, 300.0})
    speed_->addItem(QStringLiteral("%1x").arg(r), r);
  speed_->addItem(tr("max"), -1.0);
  speed_->setCurrentIndex(3);
  speed_->setToolTip(tr("Playback speed: times the recorded pace"));
  h->addWidget(speed_);
  previous_ = button(QStringLiteral("◀ ") + tr("alert"), "playbackPreviousAlert",
                     tr("Back to the previous alert raised"));
  timeline_ = new PlaybackTimeline(this);
  timeline_->setObjectName(QStringLiteral("playbackTimeline"));
  h->addWidget(timeline_, 1);
  next_ = button(tr("alert") + QStringLiteral(" ▶"), "playbackNextAlert", tr("On to the next alert raised"));
  clock_ = new QLabel(this);
  clock_->setObjectName(QStringLiteral("playbackClock"));
  h->addWidget(clock_);
  close_ = button(tr("End playback"), "playbackClose", tr("End the playback and go back to the simulation"));
  connect(play_, &QToolButton::clicked, this,
          [this] { emit rateRequested(state_.rate != 0.0 ? 0.0 : speed_->currentData().toDouble()); });
  connect(speed_, &QComboBox::activated, this, [this] {
    if (state_.rate != 0.0) emit rateRequested(speed_->currentData().toDouble());
  });
  connect(previous_, &QToolButton::clicked, this, [this] { jump(-1); });
  connect(next_, &QToolButton::clicked, this, [this] { jump(+1); });
  connect(timeline_, &PlaybackTimeline::seekRequested, this, &PlaybackBar::seekRequested);
  connect(close_, &QToolButton::clicked, this, &PlaybackBar::closeRequested);
}

std::vector<UtcUs> PlaybackBar::alertTimes(const LiveFrame::Playback& p) {
  std::vector<UtcUs> out;
  if (p.alerts)
    for (const files::RecordedAlert& a : *p.alerts)
      if (a.event == "raised") out.push_back(p.receiveTimeOf(a.utc + kJumpAfterUs));
  std::sort(out.begin(), out.end());
  return out;
}

void PlaybackBar::jump(int direction) {
  const std::vector<UtcUs> times = alertTimes(state_);
  // The clock at an alert jumped to is on it: the next one is after it, the previous one before it.
  if (direction > 0) {
    const auto it = std::upper_bound(times.begin(), times.end(), state_.clock);
    if (it != times.end()) emit seekRequested(static_cast<qint64>(*it));
  } else {
    const auto it = std::lower_bound(times.begin(), times.end(), state_.clock);
    if (it != times.begin()) emit seekRequested(static_cast<qint64>(*std::prev(it)));
  }
}

void PlaybackBar::setState(const LiveFrame::Playback& p) {
  state_ = p;
  timeline_->setState(p);
  play_->setText(p.rate != 0.0 ? tr("Pause") : tr("Play"));
  play_->setEnabled(!p.atEnd || p.rate != 0.0);
  const std::vector<UtcUs> times = alertTimes(p);
  next_->setEnabled(std::upper_bound(times.begin(), times.end(), p.clock) != times.end());
  previous_->setEnabled(std::lower_bound(times.begin(), times.end(), p.clock) != times.begin());
  clock_->setText(tr("%1 UTC  %2 / %3%4")
                      .arg(hms(p.clock), span(p.clock - p.first), span(p.last - p.first),
                           p.atEnd ? tr("  END") : QString()));
}

}  // namespace reckoner::ui
