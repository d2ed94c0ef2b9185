#pragma once
// The playback bar (docs/gui.md, "Playback"): play and pause, the speed, the timeline of the record with
// a mark at every alert raised (in its priority's colour) and the clock's place on it (a click or a
// drag seeks), jumps to the previous and next alert, the clock, and the end of the playback.
#include <QWidget>
#include <vector>

#include "common/time.h"
#include "files/voyage_record.h"
#include "ui/bridge/live_frame.h"

class QComboBox;
class QLabel;
class QToolButton;

namespace reckoner::ui {

/// The record's span with its alert marks and the clock; click or drag to seek.
class PlaybackTimeline : public QWidget {
  Q_OBJECT
 public:
  explicit PlaybackTimeline(QWidget* parent = nullptr);
  void setState(const LiveFrame::Playback& p);
  [[nodiscard]] QSize sizeHint() const override { return {400, 26}; }
  /// The UTC at a widget x (within the span).
  [[nodiscard]] UtcUs utcAt(double x) const;
  [[nodiscard]] double xOf(UtcUs utc) const;

 signals:
  void seekRequested(qint64 utc);

 protected:
  void paintEvent(QPaintEvent*) override;
  void mousePressEvent(QMouseEvent* e) override;
  void mouseMoveEvent(QMouseEvent* e) override;
  void mouseReleaseEvent(QMouseEvent* e) override;

 private:
  LiveFrame::Playback state_;
  std::optional<UtcUs> dragging_;  ///< where the drag is (the clock shown there until released)
};

class PlaybackBar : public QWidget {
  Q_OBJECT
 public:
  explicit PlaybackBar(QWidget* parent = nullptr);
  void setState(const LiveFrame::Playback& p);
  [[nodiscard]] PlaybackTimeline* timeline() const { return timeline_; }
  /// The raised alerts' times of the record, in order (the jumps).
  [[nodiscard]] static std::vector<UtcUs> alertTimes(const LiveFrame::Playback& p);

 signals:
  void rateRequested(double rate);
  void seekRequested(qint64 utc);
  void closeRequested();

 private:
  void jump(int direction);
  LiveFrame::Playback state_;
  QToolButton *play_, *previous_, *next_, *close_;
  QComboBox* speed_;
  PlaybackTimeline* timeline_;
  QLabel* clock_;
};

}  // namespace reckoner::ui
