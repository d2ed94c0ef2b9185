#pragma once
// The chart list (docs/gui.md, "Charts"): every open cell with its name, usage band, compilation scale,
// edition, update number, issue date and update application date, feature count, the largest scale first; the
// cells under the chart's cursor in bold on a tinted row, and named below the list. A double click or
// "Zoom to chart" asks to show the selected cells, "Show all" every open cell. The panel only shows
// and asks: the window connects it to the chart view.
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QWidget>
#include <vector>

#include "charts/model/chart_model.h"

namespace reckoner::ui {

class ChartListPanel : public QWidget {
  Q_OBJECT
 public:
  enum Column { Name, Band, Scale, Edition, Update, Issued, Updated, Features, ColumnCount };
  explicit ChartListPanel(QWidget* parent = nullptr);

  /// The open cells (the list is rebuilt; the selection is cleared).
  void setCells(const std::vector<charts::CellPtr>& cells);
  /// The cells under the chart's cursor, highlighted.
  void setUnderCursor(const std::vector<charts::CellPtr>& cells);
  /// The cells of the selected rows (in list order).
  [[nodiscard]] std::vector<charts::CellPtr> selectedCells() const;
  /// The cell of a row, in list order.
  [[nodiscard]] charts::CellPtr cellAt(int row) const;
  /// Whether a row is highlighted as under the cursor.
  [[nodiscard]] bool rowUnderCursor(int row) const;
  [[nodiscard]] QTableWidget* table() const { return table_; }
  [[nodiscard]] QPushButton* zoomButton() const { return zoom_; }
  [[nodiscard]] QLabel* underCursorLabel() const { return underCursorLabel_; }

  /// "1:15 000" (a thin space between thousands).
  [[nodiscard]] static QString scaleText(int compilationScale);
  /// "2023-05-12" from S-57's "20230512"; anything else as it is.
  [[nodiscard]] static QString dateText(const std::string& yyyymmdd);

 signals:
  void zoomRequested(const std::vector<reckoner::charts::CellPtr>& cells);
  void showAllRequested();

 private:
  void markRow(int row, bool under);

  QTableWidget* table_;
  QPushButton* zoom_;
  QPushButton* all_;
  QLabel* underCursorLabel_;
  std::vector<charts::CellPtr> cells_;  ///< in list order
  std::vector<charts::CellPtr> under_;
};

}  // namespace reckoner::ui
