#pragma once
// The data monitor (docs/connections.md, "The window"): the raw lines the hub saw (ConnectionHub::
// monitor()), each with its source, receive time (UTC), verdict (delivered, filtered, bad checksum,
// gpsd json) and text; filtered by source and by text, paused on request, and bounded: at most
// maxLines() rows, the oldest dropped. A 250 ms timer reads only the lines after the last one shown.
#include <QAbstractTableModel>
#include <QWidget>
#include <cstdint>
#include <deque>

#include "connections/connection_hub.h"

class QComboBox;
class QLineEdit;
class QPushButton;
class QTableView;
class QTimer;

namespace reckoner::ui {

class MonitorModel : public QAbstractTableModel {
  Q_OBJECT
 public:
  enum Column { Source, Time, VerdictColumn, Line, ColumnCount };
  explicit MonitorModel(std::size_t maxLines, QObject* parent = nullptr);

  /// Appends lines (oldest first), dropping the oldest rows beyond maxLines().
  void append(const std::vector<conn::MonitorLine>& lines);
  void clear();
  void setMaxLines(std::size_t n);
  [[nodiscard]] std::size_t maxLines() const { return max_; }
  [[nodiscard]] const conn::MonitorLine& lineAt(int row) const {
    return rows_.at(static_cast<std::size_t>(row));
  }

  int rowCount(const QModelIndex& parent = {}) const override;
  int columnCount(const QModelIndex& parent = {}) const override;
  QVariant data(const QModelIndex& index, int role) const override;
  QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

 private:
  std::deque<conn::MonitorLine> rows_;
  std::size_t max_;
};

class DataMonitor : public QWidget {
  Q_OBJECT
 public:
  explicit DataMonitor(conn::ConnectionHub& hub, QWidget* parent = nullptr);

  /// Reads the lines after the last one read (the timer calls it); nothing while paused.
  void refresh();
  /// Shows only lines of this source (empty: every source).
  void setSourceFilter(const QString& name);
  /// Shows only lines containing this text (empty: every line).
  void setTextFilter(const QString& text);
  void setPaused(bool paused);
  [[nodiscard]] bool paused() const { return paused_; }
  /// At most n rows (>= 1); the oldest go.
  void setMaxLines(std::size_t n);
  [[nodiscard]] MonitorModel* model() const { return model_; }
  [[nodiscard]] QComboBox* sourceCombo() const { return source_; }
  [[nodiscard]] QLineEdit* textEdit() const { return text_; }
  [[nodiscard]] QPushButton* pauseButton() const { return pause_; }

 private:
  /// The filter changed: the rows are read again from the hub's ring.
  void restart();
  void updateSources();

  conn::ConnectionHub& hub_;
  MonitorModel* model_;
  QComboBox* source_;
  QLineEdit* text_;
  QPushButton* pause_;
  QTableView* table_;
  QTimer* timer_;
  std::uint64_t lastIndex_ = 0;  ///< the monitor index of the last line read (0: none)
  bool paused_ = false;
  bool follow_ = true;  ///< scrolled to the bottom: keep the newest line in view
};

}  // namespace reckoner::ui
