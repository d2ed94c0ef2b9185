// Defects a new user found in the window (issue 18, section 3), each checked as that user would meet
// it: the built-in scenarios open from the File menu; the cursor's bearing and range far from own ship
// are numbers, not "nan"; the title names the scenario and its file and marks unsaved changes; closing
// with unsaved changes asks first; "Save as" without a suffix writes a .json file.
#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>
#include <QWidgetAction>

#include "main_window_test_helpers.h"
#include "resources/embedded.h"
#include "support/compare_near.h"
#include "ui/map/range_scale.h"
#include "ui/panels/message_bar.h"

using namespace reckoner;
using namespace reckoner::ui;
using namespace reckoner::ui::test;

namespace {

QMenu* builtinMenu(MainWindow& w) {
  return w.menuBar()->findChild<QMenu*>(QStringLiteral("builtinScenarios"));
}

/// Presses `button` on the next modal message box, whenever it appears (checked on each turn of the
/// event loop, so nothing waits on elapsed time).
void answerNextMessageBox(QMessageBox::StandardButton button, bool* asked) {
  QTimer::singleShot(0, qApp, [button, asked] {
    auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
    if (!box) {
      answerNextMessageBox(button, asked);
      return;
    }
    *asked = true;
    box->button(button)->click();
  });
}

}  // namespace

class TestWatchOfficer : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() { isolateFromTheUser("tst_watch_officer"); }

  void theChartComesFirstAt1024x768And1920x1080() {
    for (const QSize size : {QSize(1024, 768), QSize(1920, 1080)}) {
      MainWindow w(freshOptions());
      showAndWait(w, size);
      RK_WAIT_VERIFY(settled(w));
      // THEN the window fits the screen, the chart has at least 60% of it
      const QSize least = w.minimumSizeHint().expandedTo(w.minimumSize());
      QVERIFY2(least.width() <= 1024 && least.height() <= 768,
               qPrintable(QString("minimum %1x%2").arg(least.width()).arg(least.height())));
      QCOMPARE(w.size(), size);
      const double share =
          double(w.chart()->width()) * w.chart()->height() / (double(size.width()) * size.height());
      qInfo("%dx%d: chart %dx%d, %.0f%% of the window", size.width(), size.height(), w.chart()->width(),
            w.chart()->height(), 100.0 * share);
      QVERIFY(share >= 0.6);
      // AND own ship and every target of the default scenario are in view
      const sim::SimFrame& f = w.history().latest().frame;
      const QRect inside = w.chart()->rect();
      const auto& x = f.estimate.x;
      QVERIFY(inside.contains(w.chart()->gridToWidget(x[est::drkf::kPosX], x[est::drkf::kPosY]).toPoint()));
      QCOMPARE(f.targets.size(), std::size_t{3});
      for (const auto& t : f.targets)
        QVERIFY(inside.contains(w.chart()->gridToWidget(t.position.xM, t.position.yM).toPoint()));
      saveWindowShot(w, QStringLiteral("window-%1x%2").arg(size.width()).arg(size.height()));
    }
  }

  void rangesAndTheirRingsFromTheBoxAndTheKeys() {
    // The standard ranges and their ring intervals
    QCOMPARE(ringIntervalNm(0.25), 0.05);
    QCOMPARE(ringIntervalNm(3.0), 0.5);
    QCOMPARE(ringIntervalNm(2.3), 0.5);
    QCOMPARE(ringIntervalNm(24.0), 4.0);
    QCOMPARE(ringIntervalNm(48.0), 8.0);
    QCOMPARE(steppedRangeIndex(3.0, 1), 5);
    QCOMPARE(steppedRangeIndex(3.0, -1), 3);
    QCOMPARE(steppedRangeIndex(2.0, 1), 4);
    QCOMPARE(steppedRangeIndex(0.25, -1), 0);
    MainWindow w(freshOptions());
    showAndWait(w);
    auto* box = w.findChild<QComboBox*>(QStringLiteral("range"));
    QVERIFY(box);
    QCOMPARE(box->count(), kRangeScaleCount);
    // WHEN 3 NM is chosen THEN the chart shows 3 NM from own ship to its nearest edge
    box->setCurrentIndex(4);
    emit box->activated(4);
    RK_COMPARE_NEAR(displayedRangeNm(w.chart()->viewport()), 3.0, 1e-6);
    const auto& x = w.history().latest().frame.estimate.x;
    const QPointF own = w.chart()->gridToWidget(x[est::drkf::kPosX], x[est::drkf::kPosY]);
    RK_COMPARE_NEAR(own.x(), w.chart()->width() / 2.0, 1.0);
    RK_COMPARE_NEAR(own.y(), w.chart()->height() / 2.0, 1.0);
    RK_WAIT_VERIFY(settled(w));
    saveWindowShot(w, QStringLiteral("range-3nm"));
    // AND '+' halves it, '-' twice goes to 6 NM, and the box follows
    w.chart()->setFocus();
    QTest::keyClick(w.chart(), Qt::Key_Plus);
    RK_COMPARE_NEAR(displayedRangeNm(w.chart()->viewport()), 1.5, 1e-6);
    QCOMPARE(box->currentIndex(), 3);
    QTest::keyClick(w.chart(), Qt::Key_Minus);
    QTest::keyClick(w.chart(), Qt::Key_Minus);
    RK_COMPARE_NEAR(displayedRangeNm(w.chart()->viewport()), 6.0, 1e-6);
    QCOMPARE(box->currentText(), QStringLiteral("6 NM"));
    // AND a wheel zoom between ranges shows the range in the box without choosing one
    w.chart()->zoomAbout(1.3, QPointF(w.chart()->width() / 2.0, w.chart()->height() / 2.0));
    QCOMPARE(box->currentIndex(), -1);
    QVERIFY2(box->placeholderText().endsWith(QStringLiteral(" NM")), qPrintable(box->placeholderText()));
  }

  void helpHasShortcutsAndAnAboutBoxWithTheLibraries() {
    const QString about = MainWindow::aboutText();
    for (const QString& part :
         {QStringLiteral("Qt ") + QString::fromLatin1(qVersion()), QStringLiteral("GDAL 3."),
          QStringLiteral("GeographicLib "), QStringLiteral("Eigen 3.")})
      QVERIFY2(about.contains(part), qPrintable(about));
    QVERIFY(MainWindow::shortcutsText().contains(QStringLiteral("+ / -")));
    MainWindow w(freshOptions());
    QMenu* help = nullptr;
    for (QAction* a : w.menuBar()->actions())
      if (a->text() == QStringLiteral("&Help")) help = a->menu();
    QVERIFY(help);
    QCOMPARE(help->actions().size(), 2);
  }

  void theOfficerSetsTheCpaLimitsAndTheyAreKept() {
    // The first CPA/TCPA alarm of a run to 900 s: its time and the CPA (NM) its text gives.
    const auto firstCpaAlarm = [](MainWindow& w) -> std::pair<double, double> {
      runUntil(w, 900.0);
      for (const auto& e : w.history().alertHistory())
        if (e.id.kind == alerts::AlertKind::CpaTcpa && e.event == alerts::AlertLogEntry::Event::Raised)
          return {toSeconds(e.timeUs), QString::fromStdString(e.text)
                                           .section(QStringLiteral("CPA "), 1)
                                           .section(' ', 0, 0)
                                           .toDouble()};
      return {-1.0, -1.0};
    };
    // GIVEN the default run: at 1 NM the alarm for target 3 comes at 647 s
    double defaultS = 0.0;
    {
      MainWindow w(freshOptions());
      showAndWait(w);
      defaultS = firstCpaAlarm(w).first;
      QVERIFY(defaultS > 0.0);
    }
    // WHEN the officer sets 0.05 NM within 12 min THEN the alarm comes later, only under 0.05 NM
    double limitedS = 0.0;
    {
      MainWindow w(freshOptions());
      showAndWait(w);
      w.setCpaLimits(0.05, 12.0);
      const auto [t, cpaNm] = firstCpaAlarm(w);
      qInfo("first CPA/TCPA alarm: %.0f s at 1 NM, %.0f s at 0.05 NM (CPA %.2f NM)", defaultS, t, cpaNm);
      QVERIFY(t > defaultS);
      QVERIFY(cpaNm <= 0.05);
      limitedS = t;
    }
    // AND the next window keeps the limits: the same run gives the same alarm
    MainWindow again(freshOptions());
    showAndWait(again);
    QCOMPARE(firstCpaAlarm(again).first, limitedS);
    // AND impossible limits are refused with a message
    again.setCpaLimits(-1.0, 12.0);
    QVERIFY(again.lastError().contains(QStringLiteral("CPA/TCPA limits")));
    QSettings().remove(QStringLiteral("tracking"));
  }

  void everyBuiltInScenarioOpensFromTheFileMenu() {
    MainWindow w(freshOptions());
    showAndWait(w);
    QMenu* menu = builtinMenu(w);
    QVERIFY(menu);
    const auto all = resources::scenarios();
    QCOMPARE(menu->actions().size(), static_cast<qsizetype>(all.size()));
    QAction* busy = nullptr;
    for (QAction* a : menu->actions()) {
      QVERIFY2(a->text().contains(QStringLiteral("  —  ")), qPrintable(a->text()));  // with its title
      if (a->data().toString() == QStringLiteral("busy-harbour")) busy = a;
    }
    QVERIFY(busy);
    busy->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(w.controller()->scenario().targets.size() == 40, kTimeoutMs);
    QVERIFY(w.lastError().isEmpty());
    QVERIFY(w.windowTitle().contains(QStringLiteral("builtin:busy-harbour")));
  }

  void theCursorReadsBearingAndRangeAnywhere() {
    MainWindow w(freshOptions());
    showAndWait(w);
    // GIVEN the view moved half a world away from own ship (outside the grid's zone)
    w.chart()->setView({-33.9, 151.2}, 50000);
    const QString text = w.chart()->cursorText(QPointF(w.chart()->width() / 2.0, w.chart()->height() / 2.0));
    // THEN the readout has a bearing and a range, and no "nan"
    QVERIFY2(!text.contains(QStringLiteral("nan"), Qt::CaseInsensitive), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral(" NM")), qPrintable(text));
    qInfo("cursor at Sydney: %s", qPrintable(text));
  }

  void anErrorStaysAboveTheChartUntilDismissed() {
    MainWindow w(freshOptions());
    showAndWait(w, QSize(1024, 768));
    QVERIFY(!w.messageBar()->isVisible());
    // WHEN a file cannot be opened
    const QString missing = QStringLiteral("/nonexistent/reckoner/harbour.json");
    QVERIFY(!w.openScenario(missing));
    // THEN the bar above the chart says so, naming the file, and stays while the cursor moves
    QVERIFY(w.messageBar()->isVisible());
    QVERIFY2(w.messageBar()->message().contains(missing), qPrintable(w.messageBar()->message()));
    for (int i = 0; i < 5; ++i) QTest::mouseMove(w.chart(), QPoint(100 + 40 * i, 200));
    QVERIFY(w.messageBar()->isVisible());
    QVERIFY(w.statusBar()->currentMessage().contains(missing));
    // AND again: one bar, counted
    QVERIFY(!w.openScenario(missing));
    QCOMPARE(w.messageBar()->repeats(), 2);
    saveWindowShot(w, QStringLiteral("error-message-bar"));
    // AND the chart keeps most of the window meanwhile
    const double share = double(w.chart()->width() * w.chart()->height()) / (w.width() * w.height());
    QVERIFY2(share > 0.55, qPrintable(QString::number(share)));
    QTest::mouseClick(w.messageBar()->closeButton(), Qt::LeftButton);
    QVERIFY(!w.messageBar()->isVisible());
  }

  void everyToolbarControlHasATooltipThatSaysMoreThanItsLabel() {
    MainWindow w(freshOptions());
    showAndWait(w);
    QStringList bare;
    for (QToolBar* bar : w.findChildren<QToolBar*>()) {
      for (QAction* a : bar->actions()) {
        if (a->isSeparator() || !a->isVisible()) continue;
        QString tip = a->toolTip(), text = a->text();
        if (auto* wa = qobject_cast<QWidgetAction*>(a)) {
          if (QWidget* widget = bar->widgetForAction(wa)) {
            if (widget->objectName() == QLatin1String("alarmBanner") || qobject_cast<QLabel*>(widget))
              continue;
            tip = widget->toolTip();
            text = widget->objectName();
          }
        }
        text.remove(QLatin1Char('&'));
        // Qt's default tooltip of an action is its text: that says nothing more than the label.
        if (tip.isEmpty() || tip == text) bare << (text.isEmpty() ? QStringLiteral("(unnamed)") : text);
      }
    }
    QVERIFY2(bare.isEmpty(), qPrintable(QStringLiteral("no tooltip beyond the label: ") + bare.join(", ")));
  }

  void runningOnPastTheEndSaysSo() {
    MainWindow w(freshOptions());
    showAndWait(w);
    runUntil(w, toSeconds(w.controller()->scenario().durationUs));
    QTRY_VERIFY_WITH_TIMEOUT(w.history().latest().finished, kTimeoutMs);
    w.setRate(-1.0);
    QVERIFY2(w.statusBar()->currentMessage().contains(QStringLiteral("running on for 30 more minutes")),
             qPrintable(w.statusBar()->currentMessage()));
    w.setRate(0.0);
  }

  void theTitleShowsTheFileAndUnsavedChangesAndClosingAsks() {
    QTemporaryDir dir;
    MainWindowOptions o = freshOptions();
    o.askToSaveOnClose = true;
    MainWindow w(o);
    showAndWait(w);
    QVERIFY(w.windowTitle().contains(QStringLiteral("builtin:default[*]")));
    QVERIFY(!w.isWindowModified());
    // WHEN the officer gives a helm order THEN the scenario has unsaved changes
    w.controller()->orderOwnShip(1.0, 4.0);
    QTRY_VERIFY_WITH_TIMEOUT(w.isWindowModified(), kTimeoutMs);
    // AND closing asks; Cancel keeps the window open
    bool asked = false;
    answerNextMessageBox(QMessageBox::Cancel, &asked);
    QVERIFY(!w.close());
    QVERIFY(asked);
    QVERIFY(w.isVisible());
    // WHEN saved THEN the title names the file and the mark is gone
    const QString path = dir.filePath(QStringLiteral("voyage.json"));
    QVERIFY(w.saveScenario(path));
    QVERIFY(!w.isWindowModified());
    QVERIFY(w.windowTitle().contains(QStringLiteral("voyage.json[*]")));
    // AND closing without changes does not ask
    asked = false;
    QVERIFY(w.close());
    QVERIFY(!asked);
  }
};

QTEST_MAIN(TestWatchOfficer)
#include "tst_watch_officer.moc"
