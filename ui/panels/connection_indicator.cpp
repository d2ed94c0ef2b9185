#include "ui/panels/connection_indicator.h"

#include <QPainter>
#include <QTimer>

#include "ui/panels/connections_dialog.h"

namespace reckoner::ui {

namespace {
constexpr int kPad = 6;  ///< pixels around and between the entries
int dotSize(const QFontMetrics& fm) {
  return fm.height() * 2 / 3;
}
}  // namespace

IndicatorLight indicatorLight(const conn::SourceStatus& s, UtcUs nowUtc) {
  switch (s.state) {
    case conn::State::Connected: {
      const bool heard = s.lastSeenUtc && static_cast<double>(nowUtc - *s.lastSeenUtc) / 1e6 <= kSilentAfterS;
      return heard ? IndicatorLight::Green : IndicatorLight::Amber;
    }
    case conn::State::Connecting:
    case conn::State::WaitingRetry:
      return IndicatorLight::Amber;
    case conn::State::Error:
      return IndicatorLight::Red;
    case conn::State::Stopped:
    case conn::State::Finished:
    case conn::State::Disabled:
      return IndicatorLight::Grey;
  }
  return IndicatorLight::Grey;
}

QColor indicatorColour(IndicatorLight light) {
  switch (light) {
    case IndicatorLight::Green:
      return {0x1e, 0xa0, 0x3c};
    case IndicatorLight::Amber:
      return {0xe6, 0xa0, 0x00};
    case IndicatorLight::Red:
      return {0xd0, 0x20, 0x20};
    case IndicatorLight::Grey:
      return {0x90, 0x90, 0x90};
  }
  return {0x90, 0x90, 0x90};
}

const char* indicatorLightName(IndicatorLight light) {
  switch (light) {
    case IndicatorLight::Green:
      return "green";
    case IndicatorLight::Amber:
      return "amber";
    case IndicatorLight::Red:
      return "red";
    case IndicatorLight::Grey:
      return "grey";
  }
  return "grey";
}

ConnectionIndicator::ConnectionIndicator(conn::ConnectionHub& hub, QWidget* parent)
    : QWidget(parent), hub_(hub), timer_(new QTimer(this)) {
  connect(timer_, &QTimer::timeout, this, &ConnectionIndicator::refresh);
  refresh();
  timer_->start(1000);
}

void ConnectionIndicator::refresh() {
  const UtcUs now = systemUtcUs();
  std::vector<Entry> entries;
  QStringList tips;
  for (const conn::SourceStatus& s : hub_.status()) {
    Entry e;
    e.name = QString::fromStdString(s.name);
    e.light = indicatorLight(s, now);
    e.text = QStringLiteral("%1 %2/s").arg(e.name, QString::number(s.sentencesPerSecond, 'f', 1));
    QString tip = QStringLiteral("%1: %2").arg(e.name, QString::fromLatin1(conn::stateName(s.state)));
    if (s.state == conn::State::Connected && e.light == IndicatorLight::Amber) tip += tr(", silent");
    if (!s.lastError.empty()) tip += QStringLiteral(" (%1)").arg(QString::fromStdString(s.lastError));
    tips.append(tip);
    entries.push_back(std::move(e));
  }
  const bool resized = entries.size() != entries_.size() ||
                       !std::equal(entries.begin(), entries.end(), entries_.begin(),
                                   [](const Entry& a, const Entry& b) { return a.text == b.text; });
  entries_ = std::move(entries);
  setToolTip(tips.isEmpty() ? tr("No connections") : tips.join('\n'));
  if (resized) updateGeometry();
  update();
}

QSize ConnectionIndicator::sizeHint() const {
  const QFontMetrics fm = fontMetrics();
  int w = kPad;
  for (const Entry& e : entries_) w += dotSize(fm) + kPad / 2 + fm.horizontalAdvance(e.text) + kPad;
  if (entries_.empty()) w += fm.horizontalAdvance(tr("No connections")) + kPad;
  return {w, fm.height() + kPad};
}

void ConnectionIndicator::paintEvent(QPaintEvent* /*event*/) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  const QFontMetrics fm = fontMetrics();
  const int d = dotSize(fm);
  int x = kPad;
  if (entries_.empty()) {
    p.setPen(palette().color(QPalette::PlaceholderText));
    p.drawText(QRect(x, 0, width() - x, height()), Qt::AlignVCenter | Qt::AlignLeft, tr("No connections"));
    return;
  }
  for (const Entry& e : entries_) {
    const QColor c = indicatorColour(e.light);
    p.setPen(c.darker(140));
    p.setBrush(c);
    p.drawEllipse(QRect(x, (height() - d) / 2, d, d));
    x += d + kPad / 2;
    const int tw = fm.horizontalAdvance(e.text);
    p.setPen(palette().color(QPalette::WindowText));
    p.drawText(QRect(x, 0, tw + 1, height()), Qt::AlignVCenter | Qt::AlignLeft, e.text);
    x += tw + kPad;
  }
}

}  // namespace reckoner::ui
