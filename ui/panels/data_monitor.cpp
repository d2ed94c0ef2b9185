#include "ui/panels/data_monitor.h"

#include <QComboBox>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScrollBar>
#include <QTableView>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>

#include "ui/panels/connections_dialog.h"

namespace reckoner::ui {

MonitorModel::MonitorModel(std::size_t maxLines, QObject* parent)
    : QAbstractTableModel(parent), max_(std::max<std::size_t>(1, maxLines)) {}

void MonitorModel::append(const std::vector<conn::MonitorLine>& lines) {
  if (lines.empty()) return;
  // Only the newest max_ of the new lines can stay.
  const std::size_t skip = lines.size() > max_ ? lines.size() - max_ : 0;
  const std::size_t incoming = lines.size() - skip;
  const std::size_t overflow = rows_.size() + incoming > max_ ? rows_.size() + incoming - max_ : 0;
  if (overflow > 0) {
    beginRemoveRows({}, 0, static_cast<int>(overflow) - 1);
    rows_.erase(rows_.begin(), rows_.begin() + static_cast<std::ptrdiff_t>(overflow));
    endRemoveRows();
  }
  const int first = static_cast<int>(rows_.size());
  beginInsertRows({}, first, first + static_cast<int>(incoming) - 1);
  rows_.insert(rows_.end(), lines.begin() + static_cast<std::ptrdiff_t>(skip), lines.end());
  endInsertRows();
}

void MonitorModel::clear() {
  beginResetModel();
  rows_.clear();
  endResetModel();
}

void MonitorModel::setMaxLines(std::size_t n) {
  max_ = std::max<std::size_t>(1, n);
  if (rows_.size() > max_) {
    const auto overflow = rows_.size() - max_;
    beginRemoveRows({}, 0, static_cast<int>(overflow) - 1);
    rows_.erase(rows_.begin(), rows_.begin() + static_cast<std::ptrdiff_t>(overflow));
    endRemoveRows();
  }
}

int MonitorModel::rowCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : static_cast<int>(rows_.size());
}
int MonitorModel::columnCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : ColumnCount;
}

QVariant MonitorModel::data(const QModelIndex& index, int role) const {
  if (!index.isValid() || index.row() >= rowCount()) return {};
  const conn::MonitorLine& l = rows_[static_cast<std::size_t>(index.row())];
  if (role == Qt::ForegroundRole && index.column() == VerdictColumn) {
    switch (l.verdict) {
      case conn::Verdict::BadChecksum:
        return QColor(0xb0, 0x00, 0x00);
      case conn::Verdict::Filtered:
      case conn::Verdict::GpsdJson:
        return QColor(0x70, 0x70, 0x70);
      case conn::Verdict::Delivered:
        return QColor(0x00, 0x70, 0x00);
    }
  }
  if (role != Qt::DisplayRole) return {};
  switch (index.column()) {
    case Source:
      return QString::fromStdString(l.source);
    case Time:
      return utcClockText(l.receivedUtc);
    case VerdictColumn:
      return QString::fromLatin1(conn::verdictName(l.verdict));
    case Line:
      return QString::fromStdString(l.line);
    default:
      return {};
  }
}

QVariant MonitorModel::headerData(int section, Qt::Orientation orientation, int role) const {
  if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
  switch (section) {
    case Source:
      return tr("Source");
    case Time:
      return tr("Received (UTC)");
    case VerdictColumn:
      return tr("Verdict");
    case Line:
      return tr("Line");
    default:
      return {};
  }
}

// ----------------------------------------------------------------------------------------------------

DataMonitor::DataMonitor(conn::ConnectionHub& hub, QWidget* parent)
    : QWidget(parent),
      hub_(hub),
      model_(new MonitorModel(500, this)),
      source_(new QComboBox(this)),
      text_(new QLineEdit(this)),
      pause_(new QPushButton(tr("Pause"), this)),
      table_(new QTableView(this)),
      timer_(new QTimer(this)) {
  source_->addItem(tr("All sources"), QString());
  source_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
  text_->setPlaceholderText(tr("lines containing..."));
  text_->setClearButtonEnabled(true);
  pause_->setCheckable(true);
  table_->setModel(model_);
  table_->verticalHeader()->hide();
  table_->setWordWrap(false);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->verticalHeader()->setDefaultSectionSize(table_->fontMetrics().height() + 4);
  auto* bar = new QHBoxLayout;
  bar->addWidget(new QLabel(tr("Source"), this));
  bar->addWidget(source_);
  bar->addWidget(new QLabel(tr("Text"), this));
  bar->addWidget(text_, 1);
  bar->addWidget(pause_);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(bar);
  layout->addWidget(table_, 1);
  connect(source_, &QComboBox::currentIndexChanged, this, [this] { restart(); });
  connect(text_, &QLineEdit::textChanged, this, [this] { restart(); });
  connect(pause_, &QPushButton::toggled, this, [this](bool on) { setPaused(on); });
  connect(table_->verticalScrollBar(), &QScrollBar::valueChanged, this,
          [this](int v) { follow_ = v == table_->verticalScrollBar()->maximum(); });
  connect(timer_, &QTimer::timeout, this, &DataMonitor::refresh);
  updateSources();
  refresh();
  timer_->start(250);
}

void DataMonitor::updateSources() {
  const QString current = source_->currentData().toString();
  QStringList names;
  for (const auto& c : hub_.sources()) names.append(QString::fromStdString(c.name));
  QStringList shown;
  for (int i = 1; i < source_->count(); ++i) shown.append(source_->itemData(i).toString());
  if (names == shown) return;
  const QSignalBlocker block(source_);
  while (source_->count() > 1) source_->removeItem(1);
  for (const QString& n : names) source_->addItem(n, n);
  const int at = source_->findData(current);
  source_->setCurrentIndex(at < 0 ? 0 : at);
  if (at < 0 && !current.isEmpty()) restart();  // the source shown was removed
}

void DataMonitor::refresh() {
  updateSources();
  if (paused_) return;
  conn::MonitorFilter f;
  f.source = source_->currentData().toString().toStdString();
  f.text = text_->text().toStdString();
  f.afterIndex = lastIndex_;
  const std::vector<conn::MonitorLine> lines = hub_.monitor(f, model_->maxLines());
  if (lines.empty()) return;
  lastIndex_ = lines.back().index;
  model_->append(lines);
  if (follow_) table_->scrollToBottom();
}

void DataMonitor::restart() {
  lastIndex_ = 0;
  model_->clear();
  refresh();
}

void DataMonitor::setSourceFilter(const QString& name) {
  updateSources();
  const int at = source_->findData(name);
  source_->setCurrentIndex(at < 0 ? 0 : at);
}

void DataMonitor::setTextFilter(const QString& text) {
  text_->setText(text);
}

void DataMonitor::setPaused(bool paused) {
  paused_ = paused;
  if (pause_->isChecked() != paused) pause_->setChecked(paused);
  pause_->setText(paused ? tr("Resume") : tr("Pause"));
  if (!paused) refresh();
}

void DataMonitor::setMaxLines(std::size_t n) {
  model_->setMaxLines(n);
}

}  // namespace reckoner::ui
