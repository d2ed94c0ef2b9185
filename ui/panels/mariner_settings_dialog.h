#pragma once
// The mariner's chart settings as S-52 separates them: shallow, safety and deep contours, the safety
// depth (soundings at or above it drawn bold), two or four depth shades, display category, text and
// contour labels, SCAMIN. A dialog to edit them (Chart > Mariner settings), their check (the contours
// in order, every value a depth a chart can hold), and their place in QSettings ("chart/..."), so that
// they survive a restart. The palette is the display's (display/palette), not kept here.
#include <QDialog>
#include <QSettings>
#include <QString>

#include "charts/portrayal/portrayal.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QDialogButtonBox;

namespace reckoner::ui {

/// The deepest contour or depth the settings accept (m); deeper than any charted contour.
inline constexpr double kMaxSettingDepthM = 1000.0;

/// Empty when s is usable, else what is wrong, naming the setting ("Shallow contour 12 m is deeper than
/// the safety contour 10 m").
QString marinerSettingsProblem(const charts::MarinerSettings& s);

/// The settings saved under "chart/", each absent or invalid value taken from defaults (the palette
/// always from defaults). A saved set that fails marinerSettingsProblem is ignored as a whole.
charts::MarinerSettings loadMarinerSettings(const QSettings& settings,
                                            const charts::MarinerSettings& defaults);
void saveMarinerSettings(QSettings& settings, const charts::MarinerSettings& s);

class MarinerSettingsDialog : public QDialog {
  Q_OBJECT
 public:
  explicit MarinerSettingsDialog(const charts::MarinerSettings& current, QWidget* parent = nullptr);
  /// What the dialog shows now (the palette of the settings it was opened with).
  [[nodiscard]] charts::MarinerSettings settings() const;
  /// Shows the dialog's values (tests set them through the widgets' object names too).
  void setSettings(const charts::MarinerSettings& s);

 private:
  void check();

  charts::Palette palette_;
  QDoubleSpinBox* shallow_;
  QDoubleSpinBox* safety_;
  QDoubleSpinBox* deep_;
  QDoubleSpinBox* safetyDepth_;
  QComboBox* category_;
  QCheckBox* fourShades_;
  QCheckBox* showText_;
  QCheckBox* contourLabels_;
  QCheckBox* scamin_;
  QLabel* problem_;
  QDialogButtonBox* buttons_;
};

}  // namespace reckoner::ui
