#pragma once
// Own-ship panel: estimated and true position, course and speed, the current, the speedlog and Loran-C
// error estimates against the truth, the active sensors, the NIS of each sensor's last update and the
// dead-reckoning indication; at the top the helm order, always shown, and two fields to type one (true
// course in degrees, speed in the display unit; Enter orders it).
#include <QLabel>
#include <QLineEdit>
#include <QWidget>
#include <array>

#include "charts/portrayal/portrayal.h"
#include "common/units.h"
#include "geo/local_frame.h"
#include "ui/bridge/live_frame.h"
#include "ui/common/display_units.h"

namespace reckoner::ui {

class OwnShipPanel : public QWidget {
  Q_OBJECT
 public:
  explicit OwnShipPanel(QWidget* parent = nullptr);
  /// The fastest speed a typed order may ask for (m/s; 40 kn).
  static constexpr double kMaxOrderSpeedMps = 40.0 * kMpsPerKnot;

  void setFrame(const LiveFrame& frame, const geo::LocalFrame& localFrame);
  void setUnits(const DisplayUnits& units);
  /// The helm order now (true course, speed through the water), as the chart shows it.
  void showOrder(double trueCourseRad, double speedMps);
  /// Reads the two fields and emits orderTyped, or says what is wrong (false). An empty field keeps
  /// that part of the present order.
  bool applyTypedOrder();
  [[nodiscard]] QString orderText() const { return order_->text(); }
  [[nodiscard]] QString orderError() const {
    return orderError_->isVisibleTo(this) ? orderError_->text() : QString();
  }
  [[nodiscard]] QLineEdit* courseEdit() const { return courseEdit_; }
  [[nodiscard]] QLineEdit* speedEdit() const { return speedEdit_; }
  /// The dead-reckoning banner (tests read it).
  [[nodiscard]] QString drText() const { return dr_->text(); }
  [[nodiscard]] bool drShown() const { return dr_->isVisibleTo(this); }
  /// The dead-reckoning banner's colours follow the display palette (dim at night).
  void setDisplayPalette(charts::Palette p);

 signals:
  /// An order typed in the panel: true course, speed through the water.
  void orderTyped(double trueCourseRad, double speedMps);

 private:
  /// Truth, error, current, log and Loran-C rows: estimate against truth, or the estimate alone (live).
  void showTruthAndCalibration(const LiveFrame& live, const geo::LocalFrame& frame, double gamma);
  QLabel* add(const QString& name);
  QWidget* buildOrderRow();
  QLabel* dr_;
  QLabel* order_ = nullptr;
  QLabel* orderError_ = nullptr;
  QLabel* speedUnit_ = nullptr;
  QLineEdit* courseEdit_ = nullptr;
  QLineEdit* speedEdit_ = nullptr;
  DisplayUnits units_;
  double orderCourseRad_ = 0.0, orderSpeedMps_ = 0.0;
  QLabel *estPos_, *truePos_, *estCog_, *trueCog_, *heading_, *current_, *log_, *loran_, *sensors_, *error_;
  std::array<QLabel*, 2> seed002_{};  ///< error and 95% semi-major axis of seed 002's two filters
  std::array<QLabel*, 5> nis_{};
  QLabel* radarFix_ = nullptr;
  QWidget* form_;
};

}  // namespace reckoner::ui
