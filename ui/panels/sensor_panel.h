#pragma once
// Sensor panel: switch GPS, Loran-C, speedlog, gyro and radar on and off while the simulation runs,
// choose the speedlog's ground or bottom lock, and set the dead-reckoning alarm limit. The boxes follow
// the simulation's own schedule too (a scripted outage unticks the box).
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QWidget>
#include <array>

#include "navigation/drkf.h"
#include "sim/alert_feed.h"
#include "sim/scenario.h"

namespace reckoner::ui {

class SensorPanel : public QWidget {
  Q_OBJECT
 public:
  explicit SensorPanel(QWidget* parent = nullptr);
  /// Which sensors the scenario has (others are disabled).
  void setFitted(const sim::Scenario& s);
  void setStates(const sim::SensorStates& states, bool radarOn);
  /// Marks each sensor whose DRKF innovations are larger than configured (per nav::DrkfBlock, the
  /// engine's windowed NIS test): an amber "noise > configured" beside its box, with a tooltip.
  void setNoisy(const std::array<bool, nav::kDrkfBlockCount>& noisy);
  /// The sensor's noise label (hidden unless flagged).
  [[nodiscard]] QLabel* noiseLabel(sensors::SensorId id) const {
    return noise_[static_cast<std::size_t>(id)];
  }
  [[nodiscard]] QCheckBox* box(sensors::SensorId id) const { return boxes_[static_cast<std::size_t>(id)]; }
  [[nodiscard]] QCheckBox* radarBox() const { return radar_; }
  /// The dead-reckoning alarm limit (95% radius, m), as the operator set it.
  [[nodiscard]] double drLimit() const;
  /// Sets it (clamped to the box's 10 m to 20 km), as if typed: drLimitChanged follows a change.
  void setDrLimit(double metres);
  /// The GPS to Loran-C distance for POSITION DISCREPANCY (m; 0 off), as drLimit.
  [[nodiscard]] double discrepancyLimit() const;
  void setDiscrepancyLimit(double metres);
  [[nodiscard]] QComboBox* logMode() const { return logMode_; }

 signals:
  void sensorToggled(reckoner::sensors::SensorId id, bool on);
  void radarToggled(bool on);
  void speedlogModeChosen(reckoner::sensors::SpeedlogMode mode);
  void drLimitChanged(double metres);
  void discrepancyLimitChanged(double metres);

 private:
  std::array<QCheckBox*, sensors::kOwnShipSensorCount> boxes_{};
  std::array<QLabel*, sensors::kOwnShipSensorCount> noise_{};
  QCheckBox* radar_;
  QComboBox* logMode_;
  QDoubleSpinBox* drLimit_;
  QDoubleSpinBox* discrepancy_;
};

}  // namespace reckoner::ui
