#include "ui/panels/alert_sound.h"

#include <QtEndian>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>

#if RECKONER_HAVE_MULTIMEDIA
#include <QAudioDevice>
#include <QAudioFormat>
#include <QAudioSink>
#include <QBuffer>
#include <QMediaDevices>
#endif

namespace reckoner::ui {

AlertSoundPattern alertSoundPattern(const std::vector<alerts::Alert>& alerts) {
  AlertSoundPattern p = AlertSoundPattern::Silent;
  for (const alerts::Alert& a : alerts) {
    if (!a.audible()) continue;
    if (a.priority == alerts::Priority::Alarm) return AlertSoundPattern::Alarm;
    p = AlertSoundPattern::Warning;
  }
  return p;
}

AlertSoundTiming alertSoundTiming(AlertSoundPattern p) {
  switch (p) {
    case AlertSoundPattern::Silent:
      return {};
    case AlertSoundPattern::Warning:
      return {2, 150, 100, 30000, 660.0};
    case AlertSoundPattern::Alarm:
      return {3, 150, 100, 2000, 880.0};
  }
  return {};
}

QByteArray renderAlertBurst(AlertSoundPattern p, int sampleRate) {
  const AlertSoundTiming t = alertSoundTiming(p);
  if (t.tones == 0 || sampleRate <= 0) return {};
  const int toneSamples = t.toneMs * sampleRate / 1000;
  const int gapSamples = t.gapMs * sampleRate / 1000;
  const int ramp = std::max(1, 5 * sampleRate / 1000);
  const int total = t.tones * toneSamples + (t.tones - 1) * gapSamples;
  QByteArray pcm(2 * static_cast<qsizetype>(total), '\0');
  auto* out = reinterpret_cast<uchar*>(pcm.data());
  const double w = 2.0 * std::numbers::pi * t.frequencyHz / sampleRate;
  for (int k = 0; k < t.tones; ++k) {
    const int start = k * (toneSamples + gapSamples);
    for (int i = 0; i < toneSamples; ++i) {
      const double envelope = std::min({1.0, double(i) / ramp, double(toneSamples - 1 - i) / ramp});
      const auto v = static_cast<qint16>(std::lround(0.5 * 32767.0 * envelope * std::sin(w * i)));
      qToLittleEndian(v, out + 2 * static_cast<std::ptrdiff_t>(start + i));
    }
  }
  return pcm;
}

struct AlertSound::Output {
#if RECKONER_HAVE_MULTIMEDIA
  std::unique_ptr<QAudioSink> sink;
  QBuffer buffer;
  QByteArray pcm;
  int sampleRate = 0;
#endif
};

AlertSound::AlertSound(bool enabled, QObject* parent) : QObject(parent) {
#if RECKONER_HAVE_MULTIMEDIA
  if (enabled) {
    const QAudioDevice device = QMediaDevices::defaultAudioOutput();
    if (!device.isNull()) {
      QAudioFormat format;
      format.setSampleRate(22050);
      format.setChannelCount(1);
      format.setSampleFormat(QAudioFormat::Int16);
      if (device.isFormatSupported(format)) {
        out_ = std::make_unique<Output>();
        out_->sampleRate = format.sampleRate();
        out_->sink = std::make_unique<QAudioSink>(device, format);
      }
    }
  }
#else
  (void)enabled;
#endif
  connect(&repeat_, &QTimer::timeout, this, &AlertSound::burst);
}

AlertSound::~AlertSound() = default;

bool AlertSound::canPlay() const {
  return out_ != nullptr;
}

void AlertSound::update(const std::vector<alerts::Alert>& alerts) {
  const AlertSoundPattern p = alertSoundPattern(alerts);
  if (p == pattern_) return;
  pattern_ = p;
  repeat_.stop();
#if RECKONER_HAVE_MULTIMEDIA
  if (out_) out_->sink->stop();
#endif
  if (p == AlertSoundPattern::Silent) return;
  repeat_.start(alertSoundTiming(p).repeatMs);
  burst();
}

void AlertSound::burst() {
  ++bursts_;
#if RECKONER_HAVE_MULTIMEDIA
  if (!out_) return;
  out_->sink->stop();
  out_->buffer.close();
  out_->pcm = renderAlertBurst(pattern_, out_->sampleRate);
  out_->buffer.setBuffer(&out_->pcm);
  out_->buffer.open(QIODevice::ReadOnly);
  out_->sink->start(&out_->buffer);
#endif
}

}  // namespace reckoner::ui
