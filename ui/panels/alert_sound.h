#pragma once
// The audible signal of the alerts (MSC.302(87), IEC 62923-1): an unacknowledged, unsilenced alarm
// sounds three short tones every 2 s, a warning two short tones every 30 s, a caution nothing; the
// signal stops when the alert is acknowledged, silenced or rectified. The tones are made in memory
// (16-bit mono PCM) and played through Qt Multimedia's QAudioSink on the default output device, when
// the program was built with Qt Multimedia and the platform has an output; otherwise, and always when
// the window was opened with sound off (the tests do), nothing plays and the pattern is still decided,
// so that what would sound can be checked.
#include <QByteArray>
#include <QObject>
#include <QTimer>
#include <memory>
#include <vector>

#include "alerts/alert.h"

namespace reckoner::ui {

enum class AlertSoundPattern { Silent, Warning, Alarm };

/// The pattern the alerts call for: the most urgent audible one's.
AlertSoundPattern alertSoundPattern(const std::vector<alerts::Alert>& alerts);

struct AlertSoundTiming {
  int tones = 0;           ///< tones per burst
  int toneMs = 0;          ///< each tone's length
  int gapMs = 0;           ///< silence between the tones of a burst
  int repeatMs = 0;        ///< from one burst's start to the next
  double frequencyHz = 0;  ///< the tone
};
AlertSoundTiming alertSoundTiming(AlertSoundPattern p);

/// One burst of pattern p as 16-bit signed little-endian mono samples at sampleRate (empty: Silent).
/// Each tone is shaped with 5 ms ramps (no clicks).
QByteArray renderAlertBurst(AlertSoundPattern p, int sampleRate);

class AlertSound : public QObject {
  Q_OBJECT
 public:
  /// enabled false: never plays (tests, or no sound wanted).
  explicit AlertSound(bool enabled, QObject* parent = nullptr);
  ~AlertSound() override;
  /// Whether sound can play here: built with Qt Multimedia, an output device present, and enabled.
  [[nodiscard]] bool canPlay() const;
  /// Follows the alerts now (call when they change).
  void update(const std::vector<alerts::Alert>& alerts);
  [[nodiscard]] AlertSoundPattern pattern() const { return pattern_; }
  /// Bursts started since the window opened (counted whether or not sound can play).
  [[nodiscard]] int burstCount() const { return bursts_; }

 private:
  void burst();

  struct Output;
  std::unique_ptr<Output> out_;
  AlertSoundPattern pattern_ = AlertSoundPattern::Silent;
  QTimer repeat_;
  int bursts_ = 0;
};

}  // namespace reckoner::ui
