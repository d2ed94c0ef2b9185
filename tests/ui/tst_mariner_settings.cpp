// The mariner's settings a new user found forgotten on restart or tied together (issue 18, section 3):
// shallow, safety and deep contours and the safety depth are separate, as S-52 has them, checked for
// order, and kept with the display category and the dead-reckoning limit across runs of the window;
// and at dusk and night every widget follows the dark palette (no bright selection, banner or tooltip).
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QTableView>
#include <QTest>
#include <QToolTip>

#include "main_window_test_helpers.h"
#include "ui/panels/alert_panel.h"
#include "ui/panels/mariner_settings_dialog.h"
#include "ui/panels/sensor_panel.h"

using namespace reckoner;
using namespace reckoner::ui;
using namespace reckoner::ui::test;

class TestMarinerSettings : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() { isolateFromTheUser("tst_mariner_settings"); }

  void contoursOutOfOrderOrNotDepthsAreRefusedByName() {
    charts::MarinerSettings s;
    QVERIFY(marinerSettingsProblem(s).isEmpty());
    s.shallowContourM = 12.0;  // deeper than the 10 m safety contour
    QVERIFY2(marinerSettingsProblem(s).contains(QStringLiteral("Shallow contour 12 m")),
             qPrintable(marinerSettingsProblem(s)));
    s = {};
    s.deepContourM = 5.0;
    QVERIFY(marinerSettingsProblem(s).contains(QStringLiteral("deep contour 5 m")));
    s = {};
    s.safetyDepthM = std::nan("");
    QVERIFY(marinerSettingsProblem(s).contains(QStringLiteral("Safety depth")));
    s = {};
    s.safetyContourM = -1.0;
    QVERIFY(marinerSettingsProblem(s).contains(QStringLiteral("Safety contour")));
    // The dialog refuses them too: its OK button is off while a value is out of order.
    MarinerSettingsDialog dialog(charts::MarinerSettings{});
    auto* shallow = dialog.findChild<QDoubleSpinBox*>(QStringLiteral("shallowContour"));
    shallow->setValue(20.0);
    QVERIFY(!dialog.findChild<QLabel*>(QStringLiteral("problem"))->text().isEmpty());
    shallow->setValue(3.0);
    QVERIFY(dialog.findChild<QLabel*>(QStringLiteral("problem"))->text().isEmpty());
    QCOMPARE(dialog.settings().shallowContourM, 3.0);
  }

  void safetyContourAndSafetyDepthAreSeparateAndKeptAcrossRuns() {
    charts::MarinerSettings chosen;
    chosen.shallowContourM = 3.0;
    chosen.safetyContourM = 12.0;
    chosen.deepContourM = 40.0;
    chosen.safetyDepthM = 8.0;
    chosen.category = charts::DisplayCategory::Other;
    chosen.fourShades = false;
    {
      MainWindow w(freshOptions());
      showAndWait(w);
      QVERIFY(w.setMarinerSettings(chosen));
      w.sensorPanel()->setDrLimit(400.0);
      // The toolbar's safety contour changes the contour alone, within shallow..deep.
      auto* safety = w.findChild<QDoubleSpinBox*>(QStringLiteral("safetyContour"));
      QCOMPARE(safety->minimum(), 3.0);
      QCOMPARE(safety->maximum(), 40.0);
      safety->setValue(15.0);
      QCOMPARE(w.chart()->settings().safetyContourM, 15.0);
      QCOMPARE(w.chart()->settings().safetyDepthM, 8.0);
      chosen.safetyContourM = 15.0;
      // Settings out of order are refused with the reason, and change nothing.
      charts::MarinerSettings wrong = chosen;
      wrong.deepContourM = 1.0;
      QVERIFY(!w.setMarinerSettings(wrong));
      QVERIFY(w.lastError().contains(QStringLiteral("deep contour")));
      QCOMPARE(w.chart()->settings().deepContourM, 40.0);
      w.close();
    }
    MainWindow again(freshOptions());
    showAndWait(again);
    const charts::MarinerSettings s = again.chart()->settings();
    QCOMPARE(s.shallowContourM, chosen.shallowContourM);
    QCOMPARE(s.safetyContourM, chosen.safetyContourM);
    QCOMPARE(s.deepContourM, chosen.deepContourM);
    QCOMPARE(s.safetyDepthM, chosen.safetyDepthM);
    QCOMPARE(s.category, chosen.category);
    QCOMPARE(s.fourShades, chosen.fourShades);
    QCOMPARE(again.findChild<QComboBox*>(QStringLiteral("category"))->currentIndex(), 2);
    QCOMPARE(again.findChild<QDoubleSpinBox*>(QStringLiteral("safetyContour"))->value(), 15.0);
    QCOMPARE(again.sensorPanel()->drLimit(), 400.0);
    saveWindowShot(again, QStringLiteral("mariner_settings_kept"));
  }

  void atNightNoWidgetStaysBright() {
    MainWindow w(freshOptions());
    showAndWait(w);
    w.targetTable()->selectRow(0);
    w.setPalette(charts::Palette::Night);
    // The roles widgets paint large areas with are all dark: selection, tooltip, base, buttons.
    const QPalette pal = w.targetTable()->palette();
    for (const QPalette::ColorRole r : {QPalette::Highlight, QPalette::ToolTipBase, QPalette::Base,
                                        QPalette::Window, QPalette::Button, QPalette::AlternateBase}) {
      QVERIFY2(
          pal.color(r).lightness() < 80,
          qPrintable(
              QStringLiteral("role %1 lightness %2").arg(static_cast<int>(r)).arg(pal.color(r).lightness())));
    }
    QVERIFY(QToolTip::palette().color(QPalette::ToolTipBase).lightness() < 80);
    // The alert colours dim: an alarm at night is no brighter than a third of the day's.
    for (const auto p : {alerts::Priority::Alarm, alerts::Priority::Warning, alerts::Priority::Caution}) {
      const int day = alertColour(p).value();
      const int night = alertColour(p, charts::Palette::Night).value();
      QVERIFY2(night * 3 <= day + 3, qPrintable(QStringLiteral("%1 -> %2").arg(day).arg(night)));
      QVERIFY(alertLabelStyle(p, charts::Palette::Night, 2)
                  .contains(alertColour(p, charts::Palette::Night).name()));
    }
    // Back to day: the system's palette again.
    w.setPalette(charts::Palette::Day);
    QCOMPARE(w.targetTable()->palette().color(QPalette::Highlight),
             QApplication::palette().color(QPalette::Highlight));
  }
};

QTEST_MAIN(TestMarinerSettings)
#include "tst_mariner_settings.moc"
