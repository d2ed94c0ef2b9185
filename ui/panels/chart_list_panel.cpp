#include "ui/panels/chart_list_panel.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QVBoxLayout>
#include <algorithm>

namespace reckoner::ui {

namespace {
QTableWidgetItem* item(const QString& text, Qt::Alignment align = Qt::AlignLeft | Qt::AlignVCenter) {
  auto* it = new QTableWidgetItem(text);
  it->setTextAlignment(align);
  it->setFlags(Qt::ItemIsSelectable | Qt::ItemIsEnabled);
  return it;
}
}  // namespace

ChartListPanel::ChartListPanel(QWidget* parent) : QWidget(parent) {
  auto* v = new QVBoxLayout(this);
  v->setContentsMargins(0, 0, 0, 0);
  table_ = new QTableWidget(0, ColumnCount, this);
  table_->setObjectName(QStringLiteral("chartList"));
  table_->setHorizontalHeaderLabels({tr("Cell"), tr("Band"), tr("Scale"), tr("Ed."), tr("Upd."), tr("Issued"),
                                     tr("Upd. date"), tr("Features")});
  table_->horizontalHeaderItem(Edition)->setToolTip(tr("Edition (DSID_EDTN)"));
  table_->horizontalHeaderItem(Update)->setToolTip(tr("Update number applied (DSID_UPDN)"));
  table_->horizontalHeaderItem(Issued)->setToolTip(
      tr("Issue date of the cell or its latest update (DSID_ISDT)"));
  table_->horizontalHeaderItem(Updated)->setToolTip(
      tr("Update application date (DSID_UADT): the updates issued before it are applied"));
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::ExtendedSelection);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->verticalHeader()->hide();
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->setToolTip(
      tr("The open charts, largest scale first; bold: under the cursor. Double click: zoom to it"));
  v->addWidget(table_);
  underCursorLabel_ = new QLabel(this);
  underCursorLabel_->setObjectName(QStringLiteral("chartsUnderCursor"));
  underCursorLabel_->setWordWrap(true);
  v->addWidget(underCursorLabel_);
  auto* buttons = new QHBoxLayout;
  zoom_ = new QPushButton(tr("Zoom to chart"), this);
  zoom_->setObjectName(QStringLiteral("zoomToChart"));
  zoom_->setToolTip(tr("Show all of the selected charts"));
  zoom_->setEnabled(false);
  all_ = new QPushButton(tr("Show all"), this);
  all_->setObjectName(QStringLiteral("showAllCharts"));
  all_->setToolTip(tr("Show every open chart"));
  buttons->addWidget(zoom_);
  buttons->addWidget(all_);
  buttons->addStretch(1);
  v->addLayout(buttons);
  connect(table_, &QTableWidget::itemSelectionChanged, this,
          [this] { zoom_->setEnabled(!selectedCells().empty()); });
  connect(table_, &QTableWidget::cellDoubleClicked, this, [this](int row, int) {
    if (const charts::CellPtr c = cellAt(row)) emit zoomRequested({c});
  });
  connect(zoom_, &QPushButton::clicked, this, [this] {
    if (const auto cells = selectedCells(); !cells.empty()) emit zoomRequested(cells);
  });
  connect(all_, &QPushButton::clicked, this, &ChartListPanel::showAllRequested);
  setUnderCursor({});
}

QString ChartListPanel::scaleText(int compilationScale) {
  if (compilationScale <= 0) return tr("unknown");
  QString digits = QString::number(compilationScale);
  for (int i = static_cast<int>(digits.size()) - 3; i > 0; i -= 3) digits.insert(i, QChar(0x2009));
  return QStringLiteral("1:") + digits;
}

QString ChartListPanel::dateText(const std::string& yyyymmdd) {
  QString d = QString::fromStdString(yyyymmdd);
  if (d.size() != 8 ||
      !std::all_of(yyyymmdd.begin(), yyyymmdd.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return d;
  return QStringLiteral("%1-%2-%3").arg(d.left(4), d.mid(4, 2), d.right(2));
}

void ChartListPanel::setCells(const std::vector<charts::CellPtr>& cells) {
  cells_.clear();
  for (const charts::CellPtr& c : cells)
    if (c) cells_.push_back(c);
  std::stable_sort(cells_.begin(), cells_.end(), [](const charts::CellPtr& a, const charts::CellPtr& b) {
    const int sa = a->info().compilationScale > 0 ? a->info().compilationScale : 1 << 30;
    const int sb = b->info().compilationScale > 0 ? b->info().compilationScale : 1 << 30;
    return sa != sb ? sa < sb : a->info().name < b->info().name;
  });
  table_->clearContents();
  table_->setRowCount(static_cast<int>(cells_.size()));
  const Qt::Alignment right = Qt::AlignRight | Qt::AlignVCenter;
  for (int r = 0; r < static_cast<int>(cells_.size()); ++r) {
    const charts::CellInfo& info = cells_[static_cast<std::size_t>(r)]->info();
    const charts::UsageBand band = charts::usageBand(info);
    table_->setItem(r, Name, item(QString::fromStdString(info.name)));
    table_->item(r, Name)->setToolTip(QString::fromStdString(info.path));
    table_->setItem(
        r, Band,
        item(band == charts::UsageBand::Unknown
                 ? tr("?")
                 : QStringLiteral("%1 %2").arg(static_cast<int>(band)).arg(tr(charts::usageBandName(band)))));
    table_->setItem(r, Scale, item(scaleText(info.compilationScale), right));
    table_->setItem(r, Edition, item(QString::fromStdString(info.edition), right));
    table_->setItem(r, Update, item(QString::number(info.updateNumber), right));
    table_->setItem(r, Issued, item(dateText(info.issueDate)));
    table_->setItem(r, Updated, item(dateText(info.updateDate)));
    table_->setItem(r, Features,
                    item(QString::number(cells_[static_cast<std::size_t>(r)]->features().size()), right));
  }
  under_.clear();
  setUnderCursor({});
}

void ChartListPanel::markRow(int row, bool under) {
  for (int c = 0; c < ColumnCount; ++c) {
    QTableWidgetItem* it = table_->item(row, c);
    if (!it) continue;
    QFont f = it->font();
    f.setBold(under);
    it->setFont(f);
    // Amber blended into the list's own base colour (35%), so that it stays dim at dusk and night.
    const QColor base = table_->palette().color(QPalette::Base);
    const auto mix = [](int b, int amber) { return static_cast<int>(0.65 * b + 0.35 * amber); };
    const QColor tint(mix(base.red(), 255), mix(base.green(), 193), mix(base.blue(), 7));
    it->setBackground(under ? QBrush(tint) : QBrush());
  }
}

void ChartListPanel::setUnderCursor(const std::vector<charts::CellPtr>& cells) {
  under_ = cells;
  QStringList names;
  for (const charts::CellPtr& c : cells)
    names << QStringLiteral("%1 (%2)").arg(QString::fromStdString(c->info().name),
                                           scaleText(c->info().compilationScale));
  underCursorLabel_->setText(names.isEmpty()
                                 ? tr("Under the cursor: no chart")
                                 : tr("Under the cursor: %1").arg(names.join(QStringLiteral(", "))));
  for (int r = 0; r < table_->rowCount(); ++r) markRow(r, rowUnderCursor(r));
}

bool ChartListPanel::rowUnderCursor(int row) const {
  const charts::CellPtr c = cellAt(row);
  return c && std::find(under_.begin(), under_.end(), c) != under_.end();
}

charts::CellPtr ChartListPanel::cellAt(int row) const {
  return row >= 0 && row < static_cast<int>(cells_.size()) ? cells_[static_cast<std::size_t>(row)] : nullptr;
}

std::vector<charts::CellPtr> ChartListPanel::selectedCells() const {
  std::vector<charts::CellPtr> out;
  for (int r = 0; r < table_->rowCount(); ++r)
    if (table_->item(r, Name) && table_->item(r, Name)->isSelected()) out.push_back(cellAt(r));
  return out;
}

}  // namespace reckoner::ui
