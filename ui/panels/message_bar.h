#pragma once
// A bar above the chart for what went wrong (a file that cannot be read, a chart folder with failures,
// a value refused): the message stays until dismissed or replaced, so that it is not missed the way a
// status-bar line is (it also goes to the status bar and the log). A message that comes again adds a
// count instead of flickering.
#include <QString>
#include <QWidget>

class QLabel;
class QToolButton;

namespace reckoner::ui {

class MessageBar : public QWidget {
  Q_OBJECT
 public:
  explicit MessageBar(QWidget* parent = nullptr);
  /// Shows `message` (the first line bold; several lines allowed).
  void showError(const QString& message);
  void dismiss();
  [[nodiscard]] QString message() const { return message_; }
  [[nodiscard]] int repeats() const { return repeats_; }
  [[nodiscard]] QToolButton* closeButton() const { return close_; }

 private:
  void render();
  QLabel* text_;
  QToolButton* close_;
  QString message_;
  int repeats_ = 0;
};

}  // namespace reckoner::ui
