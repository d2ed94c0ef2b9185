#include "ui/panels/sensor_panel.h"

#include <QFormLayout>
#include <QHBoxLayout>
#include <QSignalBlocker>
#include <QVBoxLayout>
#include <cmath>

namespace reckoner::ui {

SensorPanel::SensorPanel(QWidget* parent) : QWidget(parent) {
  auto* v = new QVBoxLayout(this);
  static const char* const kNames[] = {"GPS", "Loran-C", "Speedlog", "Gyro"};
  static const char* const kObjects[] = {"gps", "loranC", "speedlog", "gyro"};
  for (int i = 0; i < sensors::kOwnShipSensorCount; ++i) {
    auto* b = new QCheckBox(tr(kNames[i]), this);
    b->setObjectName(QString::fromLatin1(kObjects[i]));
    boxes_[static_cast<std::size_t>(i)] = b;
    auto* noise = new QLabel(tr("noise > configured"), this);
    noise->setObjectName(QString::fromLatin1(kObjects[i]) + QStringLiteral("Noise"));
    noise->setStyleSheet(QStringLiteral("QLabel { color: #b36b00; font-weight: bold; }"));
    noise->setToolTip(
        tr("Its innovations over the last 60 updates lie above the 99% chi-square band: "
           "the sensor is noisier than the filter is told (or the ship moves less predictably)."));
    noise->hide();
    noise_[static_cast<std::size_t>(i)] = noise;
    auto* row = new QHBoxLayout;
    row->addWidget(b);
    row->addWidget(noise);
    row->addStretch(1);
    v->addLayout(row);
    const auto id = static_cast<sensors::SensorId>(i);
    connect(b, &QCheckBox::toggled, this, [this, id](bool on) { emit sensorToggled(id, on); });
  }
  logMode_ = new QComboBox(this);
  logMode_->setObjectName(QStringLiteral("speedlogMode"));
  logMode_->addItem(tr("Ground lock (over ground)"));
  logMode_->addItem(tr("Bottom lock (through water)"));
  connect(logMode_, &QComboBox::activated, this, [this](int i) {
    emit speedlogModeChosen(i == 0 ? sensors::SpeedlogMode::GroundLock : sensors::SpeedlogMode::BottomLock);
  });
  v->insertWidget(3, logMode_);
  radar_ = new QCheckBox(tr("Radar"), this);
  radar_->setObjectName(QStringLiteral("radar"));
  connect(radar_, &QCheckBox::toggled, this, &SensorPanel::radarToggled);
  v->addWidget(radar_);
  auto* form = new QFormLayout;
  drLimit_ = new QDoubleSpinBox(this);
  drLimit_->setObjectName(QStringLiteral("drLimit"));
  drLimit_->setRange(10.0, 20000.0);
  drLimit_->setDecimals(0);
  drLimit_->setSuffix(QStringLiteral(" m"));
  drLimit_->setValue(185.0);
  drLimit_->setToolTip(
      tr("An alarm is raised when the 95% radius of the dead-reckoned position grows past this limit "
         "(remembered for the next runs)"));
  connect(drLimit_, &QDoubleSpinBox::valueChanged, this, &SensorPanel::drLimitChanged);
  form->addRow(tr("DR limit (95%)"), drLimit_);
  discrepancy_ = new QDoubleSpinBox(this);
  discrepancy_->setObjectName(QStringLiteral("discrepancyLimit"));
  discrepancy_->setRange(0.0, 20000.0);
  discrepancy_->setDecimals(0);
  discrepancy_->setSuffix(QStringLiteral(" m"));
  discrepancy_->setSpecialValueText(tr("off"));
  discrepancy_->setValue(sim::AlertFeedSettings::kDefaultPositionDiscrepancyM);
  discrepancy_->setToolTip(
      tr("A warning is raised when the GPS (primary) and Loran-C (secondary) fixes are further apart "
         "than this; 0 switches it off (remembered for the next runs)"));
  connect(discrepancy_, &QDoubleSpinBox::valueChanged, this, &SensorPanel::discrepancyLimitChanged);
  form->addRow(tr("GPS/Loran-C discrepancy"), discrepancy_);
  v->addLayout(form);
  v->addStretch(1);
}

double SensorPanel::drLimit() const {
  return drLimit_->value();
}

void SensorPanel::setDrLimit(double metres) {
  if (std::isfinite(metres)) drLimit_->setValue(metres);
}

double SensorPanel::discrepancyLimit() const {
  return discrepancy_->value();
}

void SensorPanel::setDiscrepancyLimit(double metres) {
  if (std::isfinite(metres)) discrepancy_->setValue(metres);
}

void SensorPanel::setFitted(const sim::Scenario& s) {
  const std::array<bool, 4> fitted{s.gps.fitted, s.loran.fitted, s.speedlog.fitted, s.gyro.fitted};
  for (std::size_t i = 0; i < boxes_.size(); ++i) {
    boxes_[i]->setEnabled(fitted[i]);
    if (!fitted[i]) boxes_[i]->setToolTip(tr("not fitted in this scenario"));
  }
  logMode_->setEnabled(s.speedlog.fitted);
  radar_->setEnabled(s.radar.fitted);
}

void SensorPanel::setNoisy(const std::array<bool, nav::kDrkfBlockCount>& noisy) {
  using sensors::SensorId;
  const std::array<bool, sensors::kOwnShipSensorCount> bySensor{
      noisy[nav::kGpsPosition] || noisy[nav::kGpsVelocity], noisy[nav::kLoranPosition], noisy[nav::kSpeedlog],
      noisy[nav::kGyro]};
  for (std::size_t i = 0; i < noise_.size(); ++i) noise_[i]->setVisible(bySensor[i]);
}

void SensorPanel::setStates(const sim::SensorStates& states, bool radarOn) {
  for (std::size_t i = 0; i < boxes_.size(); ++i) {
    const QSignalBlocker block(boxes_[i]);
    boxes_[i]->setChecked(states.on[i]);
  }
  const QSignalBlocker b1(logMode_);
  logMode_->setCurrentIndex(states.speedlogMode == sensors::SpeedlogMode::GroundLock ? 0 : 1);
  const QSignalBlocker b2(radar_);
  radar_->setChecked(radarOn);
}

}  // namespace reckoner::ui
