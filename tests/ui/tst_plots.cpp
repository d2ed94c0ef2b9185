// The error plots as a new user met them (issue 18): round tick values, a time axis in mm:ss that stays
// right after a scenario reload, units in every axis title, a NEES axis that never goes below 0,
// estimate and truth told apart by colour and style in the day and night palettes, and a PNG export of
// the charts alone at the size the user chose. The tick labels are read from what the chart views
// draw (their scenes' text items), not from what the code meant to set.
#include <QAreaSeries>
#include <QCategoryAxis>
#include <QChart>
#include <QChartView>
#include <QDockWidget>
#include <QGraphicsScene>
#include <QGraphicsTextItem>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QRegularExpression>
#include <QScrollArea>
#include <QSpinBox>
#include <QTabWidget>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <array>
#include <memory>
#include <set>

#include "main_window_test_helpers.h"
#include "resources/embedded.h"
#include "support/compare_near.h"
#include "ui/panels/target_table_model.h"
#include "ui/plots/axis_ticks.h"
#include "ui/plots/error_plots.h"
#include "ui/plots/png_export_dialog.h"

using namespace reckoner;
using namespace reckoner::ui;
using namespace reckoner::ui::test;

namespace {

constexpr int kRadarHeadingQuantity = 11;

/// The time steps a time axis may use (seconds), before whole days.
const std::set<double> kTimeSteps{10, 15, 30, 60, 120, 300, 600, 900, 1800, 3600, 7200, 10800, 21600, 43200};

/// Whether step is 1, 2, 2.5 or 5 times a power of ten.
bool isNiceStep(double step) {
  if (!(step > 0.0) || !std::isfinite(step)) return false;
  const double m = step / std::pow(10.0, std::floor(std::log10(step) + 1e-12));
  constexpr std::array<double, 5> kNice{1.0, 2.0, 2.5, 5.0, 10.0};
  return std::any_of(kNice.begin(), kNice.end(), [m](double n) { return std::abs(m - n) < 1e-9; });
}

/// The fewest digits after the point that write every multiple of step exactly.
int digitsFor(double step) {
  for (int d = 0; d < 12; ++d) {
    const double scaled = step * std::pow(10.0, d);
    if (std::abs(scaled - std::round(scaled)) < 1e-6) return d;
  }
  return 12;
}

/// Seconds of "mm:ss" or "h:mm:ss"; -1 when the text is neither.
double parseClock(const QString& text) {
  static const QRegularExpression mmss(QStringLiteral("^(\\d{2,}):([0-5]\\d)$"));
  static const QRegularExpression hmmss(QStringLiteral("^(\\d+):([0-5]\\d):([0-5]\\d)$"));
  if (const auto m = mmss.match(text); m.hasMatch())
    return m.captured(1).toInt() * 60.0 + m.captured(2).toInt();
  if (const auto m = hmmss.match(text); m.hasMatch())
    return m.captured(1).toInt() * 3600.0 + m.captured(2).toInt() * 60.0 + m.captured(3).toInt();
  return -1.0;
}

/// The tick labels a chart view draws now, from its scene: the texts without letters below the plot
/// area (the time axis, left to right) and left of it (the value axis, bottom to top).
struct ShownLabels {
  QStringList time, value;
};
ShownLabels shownLabels(const QChartView* view) {
  const QRectF area = view->chart()->mapRectToScene(view->chart()->plotArea());
  std::vector<std::pair<double, QString>> time, value;
  static const QRegularExpression letter(QStringLiteral("[A-Za-z(]"));
  for (QGraphicsItem* item : view->scene()->items()) {
    const auto* t = dynamic_cast<QGraphicsTextItem*>(item);
    if (!t || !t->isVisible() || t->toPlainText().isEmpty() || t->toPlainText().contains(letter)) continue;
    const QRectF r = t->sceneBoundingRect();
    const QPointF c = r.center();
    if (r.top() >= area.bottom() - 1 && c.x() > area.left() - 40 && c.x() < area.right() + 40)
      time.emplace_back(c.x(), t->toPlainText());
    else if (r.right() <= area.left() + 1 && c.y() > area.top() - 20 && c.y() < area.bottom() + 20)
      value.emplace_back(-c.y(), t->toPlainText());
  }
  ShownLabels out;
  std::sort(time.begin(), time.end());
  std::sort(value.begin(), value.end());
  for (const auto& [pos, text] : time) out.time << text;
  for (const auto& [pos, text] : value) out.value << text;
  return out;
}

/// Whether the view draws `text` whole (not elided to "...").
bool drawsText(const QChartView* view, const QString& text) {
  const QList<QGraphicsItem*> items = view->scene()->items();
  return std::any_of(items.begin(), items.end(), [&](const QGraphicsItem* item) {
    const auto* t = dynamic_cast<const QGraphicsTextItem*>(item);
    return t && t->isVisible() && t->toPlainText() == text;
  });
}

/// Whether every chart of `plots` draws the labels its axes hold now (the layout has run).
bool drawn(const ErrorPlots& plots) {
  for (int c = 0; c < PlotCharts::kCharts; ++c) {
    const auto chart = static_cast<PlotCharts::Chart>(c);
    const ShownLabels shown = shownLabels(plots.chartView(chart));
    if (shown.time != plots.charts().timeAxis(chart)->categoriesLabels() ||
        shown.value != plots.charts().valueAxis(chart)->categoriesLabels())
      return false;
    for (const QCategoryAxis* axis : {plots.charts().timeAxis(chart), plots.charts().valueAxis(chart)})
      if (!drawsText(plots.chartView(chart), axis->titleText())) return false;
  }
  return true;
}

/// Whether the charts of `plots` draw what their axes hold and handling the events waiting now leaves
/// their plot areas as they are (no refit or layout is still to come).
bool laidOut(const ErrorPlots& plots) {
  std::vector<QRectF> areas;
  areas.reserve(PlotCharts::kCharts);
  for (int c = 0; c < PlotCharts::kCharts; ++c)
    areas.push_back(plots.charts().chart(static_cast<PlotCharts::Chart>(c))->plotArea());
  QCoreApplication::sendPostedEvents();
  QCoreApplication::processEvents();
  for (int c = 0; c < PlotCharts::kCharts; ++c)
    if (plots.charts().chart(static_cast<PlotCharts::Chart>(c))->plotArea() != areas[std::size_t(c)])
      return false;
  return drawn(plots);
}

/// What the charts of `plots` draw and hold, for a failure's message.
QString describe(const ErrorPlots& plots) {
  QString text;
  for (int c = 0; c < PlotCharts::kCharts; ++c) {
    const auto chart = static_cast<PlotCharts::Chart>(c);
    const ShownLabels shown = shownLabels(plots.chartView(chart));
    QCategoryAxis* time = plots.charts().timeAxis(chart);
    QCategoryAxis* value = plots.charts().valueAxis(chart);
    text +=
        QStringLiteral("\nchart %1 draws time [%2] values [%3], holds time [%4] values [%5]; titles %6 %7")
            .arg(c)
            .arg(shown.time.join(' '), shown.value.join(' '), time->categoriesLabels().join(' '),
                 value->categoriesLabels().join(' '),
                 drawsText(plots.chartView(chart), time->titleText()) ? "drawn" : "NOT drawn whole",
                 drawsText(plots.chartView(chart), value->titleText()) ? "drawn" : "NOT drawn whole");
  }
  return text;
}

/// The time labels are mm:ss (or h:mm:ss), at least `least` of them, evenly on an allowed step.
void verifyTimeLabels(const QStringList& labels, qsizetype least = 3) {
  QVERIFY2(labels.size() >= least && labels.size() >= 2, qPrintable(labels.join(' ')));
  std::vector<double> s;
  for (const QString& l : labels) {
    s.push_back(parseClock(l));
    QVERIFY2(s.back() >= 0.0, qPrintable(QStringLiteral("'%1' of: %2").arg(l, labels.join(' '))));
  }
  const double step = s[1] - s[0];
  QVERIFY2(kTimeSteps.count(step) == 1, qPrintable(labels.join(' ')));
  for (std::size_t i = 1; i < s.size(); ++i) QVERIFY2(s[i] - s[i - 1] == step, qPrintable(labels.join(' ')));
  const bool hours = s.back() >= 3600.0;
  for (const QString& l : labels) QCOMPARE(l.count(':'), hours ? 2 : 1);  // one form along an axis
}

/// The value labels are numbers evenly on a nice step, written with just the digits that step needs.
void verifyValueLabels(const QStringList& labels) {
  QVERIFY2(labels.size() >= 3, qPrintable(labels.join(' ')));
  std::vector<double> v;
  for (const QString& l : labels) {
    bool ok = false;
    v.push_back(l.toDouble(&ok));
    QVERIFY2(ok, qPrintable(QStringLiteral("'%1' of: %2").arg(l, labels.join(' '))));
  }
  const double step = v[1] - v[0];
  QVERIFY2(isNiceStep(step), qPrintable(labels.join(' ')));
  const int digits = digitsFor(step);
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i > 0) RK_COMPARE_NEAR(v[i] - v[i - 1], step, 1e-9 * step);
    RK_COMPARE_NEAR(v[i] / step, std::round(v[i] / step), 1e-6);  // a multiple of the step
    const QString& l = labels[static_cast<qsizetype>(i)];
    const qsizetype point = l.indexOf('.');
    QCOMPARE(point < 0 ? 0 : l.size() - point - 1, qsizetype(digits));
    QVERIFY2(!l.startsWith(QStringLiteral("-0")) || v[i] != 0.0, qPrintable(l));
  }
}

double colourDistance(QColor a, QColor b) {
  return std::abs(a.red() - b.red()) + std::abs(a.green() - b.green()) + std::abs(a.blue() - b.blue());
}

QLineSeries* seriesNamed(QChart* chart, const QString& name) {
  for (QAbstractSeries* s : chart->series())
    if (s->name() == name) return qobject_cast<QLineSeries*>(s);
  return nullptr;
}

/// Presses OK on the plot export size dialog once it is up, after setting its size (or reads its size
/// and cancels when `read` is given).
void answerSizeDialog(QSize set, QSize* read) {
  QTimer::singleShot(0, qApp, [set, read] {
    QWidget* dialog = QApplication::activeModalWidget();
    if (!dialog || dialog->objectName() != QStringLiteral("plotExportSize")) {
      answerSizeDialog(set, read);
      return;
    }
    auto* width = dialog->findChild<QSpinBox*>(QStringLiteral("width"));
    auto* height = dialog->findChild<QSpinBox*>(QStringLiteral("height"));
    if (read) {
      *read = QSize(width->value(), height->value());
      QMetaObject::invokeMethod(dialog, "reject");
      return;
    }
    width->setValue(set.width());
    height->setValue(set.height());
    QMetaObject::invokeMethod(dialog, "accept");
  });
}

/// Pixels of `image` within 60 (sum over channels) of `colour`.
int pixelsNear(const QImage& image, QColor colour) {
  int n = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) n += colourDistance(image.pixelColor(x, y), colour) < 60 ? 1 : 0;
  return n;
}

}  // namespace

class TestPlots : public QObject {
  Q_OBJECT
  std::unique_ptr<MainWindow> w_;

  /// Shows `plots` in the plot dock and waits until its charts draw what their axes hold.
  void showPlots(ErrorPlots* plots) {
    w_->findChild<QDockWidget*>(QStringLiteral("plotDock"))->raise();
    w_->findChild<QTabWidget*>(QStringLiteral("plots"))->setCurrentWidget(plots);
    plots->refresh();
    QTRY_VERIFY2_WITH_TIMEOUT(laidOut(*plots), qPrintable(describe(*plots)), kTimeoutMs);
  }

  /// Screenshots of `plots` as the panel shows them (NAME-panel) and of its three charts whole
  /// (NAME-charts: the panel scrolls them when the dock is short). A first grab lays the panel out for
  /// its scroll bar; the shots wait until the charts have followed.
  static void shoot(ErrorPlots* plots, const QString& name) {
    QWidget* stack = plots->findChild<QScrollArea*>(QStringLiteral("plotScroll"))->widget();
    for (QWidget* widget : {static_cast<QWidget*>(plots), stack}) {
      (void)widget->grab();
      QTRY_VERIFY2_WITH_TIMEOUT(laidOut(*plots), qPrintable(describe(*plots)), kTimeoutMs);
      saveShot(*widget, name + (widget == plots ? QStringLiteral("-panel") : QStringLiteral("-charts")));
    }
  }

  /// Every chart of `plots`: round values, mm:ss time, units in the titles, NEES from 0 over its band.
  void verifyCharts(ErrorPlots* plots, const QString& unit) {
    const PlotCharts& charts = plots->charts();
    for (int c = 0; c < PlotCharts::kCharts; ++c) {
      const auto chart = static_cast<PlotCharts::Chart>(c);
      const ShownLabels shown = shownLabels(plots->chartView(chart));
      verifyTimeLabels(shown.time);
      verifyValueLabels(shown.value);
      QVERIFY(QStringList({"time (mm:ss)", "time (h:mm:ss)"}).contains(charts.timeAxis(chart)->titleText()));
      // Both titles drawn whole: the unit is not elided away.
      for (const QCategoryAxis* axis : {charts.timeAxis(chart), charts.valueAxis(chart)})
        QVERIFY2(drawsText(plots->chartView(chart), axis->titleText()), qPrintable(axis->titleText()));
    }
    QVERIFY2(charts.valueAxis(PlotCharts::Value)->titleText().endsWith(QStringLiteral(" (%1)").arg(unit)),
             qPrintable(charts.valueAxis(PlotCharts::Value)->titleText()));
    QCOMPARE(charts.valueAxis(PlotCharts::Error)->titleText(), QStringLiteral("error (%1)").arg(unit));
    QCOMPARE(charts.valueAxis(PlotCharts::Nees)->titleText(), QStringLiteral("NEES (dimensionless)"));
    // NEES is never negative: its axis starts at 0 and holds the whole chi-square band.
    const QStringList nees = shownLabels(plots->chartView(PlotCharts::Nees)).value;
    QCOMPARE(nees.front().toDouble(), 0.0);
    QCOMPARE(charts.valueTicks(PlotCharts::Nees).min, 0.0);
    for (QAbstractSeries* s : charts.chart(PlotCharts::Nees)->series())
      if (auto* band = qobject_cast<QAreaSeries*>(s))
        for (const QPointF& p : band->upperSeries()->points())
          QVERIFY(p.y() <= charts.valueTicks(PlotCharts::Nees).max);
  }

 private slots:
  void initTestCase() { isolateFromTheUser("tst_plots"); }

  void niceTicksCoverTheDataWithRoundSteps() {
    // The data: ticks on hundreds, no "830.9".
    const AxisTicks t = niceTicks(-10.1, 830.9, 10);
    QCOMPARE(t.min, -100.0);
    QCOMPARE(t.max, 900.0);
    QCOMPARE(t.step, 100.0);
    QCOMPARE(t.intervals, 10);
    QCOMPARE(tickLabels(t).front(), std::string("-100"));
    QCOMPARE(tickLabels(t).back(), std::string("900"));
    QCOMPARE(tickLabels(t)[1], std::string("0"));
    const AxisTicks five = niceTicks(-10.1, 830.9, 5);  // 200 would take 6 intervals from -200 to 1000
    QCOMPARE(five.step, 250.0);
    QCOMPARE(five.min, -250.0);
    QCOMPARE(five.max, 1000.0);
    // Over ranges of every size and place: the data covered, few enough nice intervals, no more than
    // the next smaller step would have needed, labels exact with the digits the step needs.
    for (const double lo : {-1234.5, -3.3, -0.004, 0.0, 0.02, 7.0, 830.9, 52000.0})
      for (const double span : {0.001, 0.37, 1.0, 9.99, 144.0, 5000.0, 2.2e6})
        for (int n = 2; n <= 10; ++n) {
          const QString what = QStringLiteral("[%1, %2] in %3").arg(lo).arg(lo + span).arg(n);
          const reckoner::test::NearContext context(what);
          const AxisTicks k = niceTicks(lo, lo + span, n);
          QVERIFY2(k.min <= lo && k.max >= lo + span, qPrintable(what));
          QVERIFY2(k.intervals >= 1 && k.intervals <= n, qPrintable(what));
          QVERIFY2(isNiceStep(k.step), qPrintable(what));
          RK_COMPARE_NEAR((k.max - k.min) / k.step, double(k.intervals), 1e-6);
          if (n >= 4) QVERIFY2(k.step <= 2.0 * span * 1.06 / (n - 2) * (1 + 1e-9), qPrintable(what));
          QCOMPARE(k.decimals, digitsFor(k.step));
          if (lo >= 0.0) QVERIFY2(k.min >= 0.0, qPrintable(what));  // a margin never crosses 0
          const std::vector<std::string> labels = tickLabels(k);
          QCOMPARE(std::set<std::string>(labels.begin(), labels.end()).size(), labels.size());
          for (int i = 0; i <= k.intervals; ++i)
            RK_COMPARE_NEAR(std::stod(labels[static_cast<std::size_t>(i)]), k.min + i * k.step,
                            1e-9 * std::max(k.step, std::abs(k.min + i * k.step)));
        }
    // Steps of 2.5 take one digit more than their power of ten.
    QCOMPARE(niceTicks(0.0, 10.0, 4, 0.0).step, 2.5);
    QCOMPARE(tickLabels(niceTicks(0.0, 10.0, 4, 0.0))[1], std::string("2.5"));
    QCOMPARE(niceTicks(0.0, 1.0, 4, 0.0).decimals, 2);    // 0.25
    QCOMPARE(niceTicks(0.0, 100.0, 4, 0.0).decimals, 0);  // 25
    QCOMPARE(tickLabel(-0.0001, 2), std::string("0.00"));
    QCOMPARE(tickLabel(-0.25, 2), std::string("-0.25"));
  }

  void niceTicksOfDegenerateData() {
    // All equal: around the value.
    const AxisTicks equal = niceTicks(5.0, 5.0, 5);
    QVERIFY(equal.min < 5.0 && equal.max > 5.0);
    QVERIFY(isNiceStep(equal.step));
    // All zero: -1 to 1.
    const AxisTicks zero = niceTicks(0.0, 0.0, 4);
    QCOMPARE(zero.min, -1.0);
    QCOMPARE(zero.max, 1.0);
    // No finite sample: 0 to 1. NaN and infinities are left out of a range.
    for (const double bad : {std::nan(""), std::numeric_limits<double>::infinity()}) {
      const AxisTicks none = niceTicks(bad, bad, 4);
      QCOMPARE(none.min, 0.0);
      QCOMPARE(none.max, 1.0);
    }
    DataRange r;
    QVERIFY(r.empty());
    const AxisTicks empty = niceTicks(r.lo, r.hi, 4);
    QCOMPARE(empty.min, 0.0);
    QCOMPARE(empty.max, 1.0);
    for (const double v : {std::nan(""), 3.0, std::numeric_limits<double>::infinity(), -2.0,
                           -std::numeric_limits<double>::infinity()})
      r.add(v);
    QCOMPARE(r.lo, -2.0);
    QCOMPARE(r.hi, 3.0);
    // A non-positive range stays at or below 0.
    QCOMPARE(niceTicks(-30.0, -0.5, 6).max, 0.0);
  }

  void timeTicksAreRoundMinutesAndSeconds() {
    // Just after a reload: one second of data shows the first minute, every 15 s (not "1 1 2 2 2").
    const AxisTicks reload = timeTicks(1.0, 2.0, 5);
    QCOMPARE(clockLabels(reload), (std::vector<std::string>{"00:00", "00:15", "00:30", "00:45", "01:00"}));
    const AxisTicks run = timeTicks(0.0, 140.0, 6);
    QCOMPARE(run.step, 30.0);
    QCOMPARE(run.max, 150.0);
    const AxisTicks long_ = timeTicks(0.0, 5400.0, 8);
    QCOMPARE(long_.step, 900.0);
    QCOMPARE(clockLabels(long_).front(), std::string("0:00:00"));
    QCOMPARE(clockLabels(long_).back(), std::string("1:30:00"));
    for (const double t0 : {0.0, 17.0, 333.3, 3599.0, 86000.0})
      for (const double span : {0.0, 1.0, 59.0, 300.0, 1800.0, 7000.0, 90000.0, 2e6})
        for (int n = 2; n <= 12; ++n) {
          const QString what = QStringLiteral("[%1, %2] in %3").arg(t0).arg(t0 + span).arg(n);
          const AxisTicks k = timeTicks(t0, t0 + span, n);
          QVERIFY2(k.min <= t0 && k.max >= t0 + span && k.max - k.min >= 60.0, qPrintable(what));
          QVERIFY2(k.intervals >= 1 && k.intervals <= n, qPrintable(what));
          QVERIFY2(kTimeSteps.count(k.step) == 1 || std::fmod(k.step, 86400.0) == 0.0, qPrintable(what));
          QVERIFY2(std::fmod(k.min, k.step) == 0.0, qPrintable(what));
          QStringList labels;
          for (const std::string& l : clockLabels(k)) labels << QString::fromStdString(l);
          if (k.step < 86400.0) verifyTimeLabels(labels, 2);
          QCOMPARE(QSet<QString>(labels.begin(), labels.end()).size(), labels.size());
        }
    QCOMPARE(clockLabel(59.6, false), std::string("01:00"));
    QCOMPARE(clockLabel(600.0, false), std::string("10:00"));
    QCOMPARE(clockLabel(3725.0, true), std::string("1:02:05"));
    QCOMPARE(clockLabel(-75.0, false), std::string("-01:15"));
  }

  void runTheDefaultScenario() {
    w_ = std::make_unique<MainWindow>(freshOptions());
    showAndWait(*w_);
    runUntil(*w_, 300.0);
    QTRY_VERIFY_WITH_TIMEOUT(w_->ownPlots()->pointCount() > 300, kTimeoutMs);
  }

  void ownShipPlotsHaveRoundTicksUnitsAndNeesFromZero() {
    QVERIFY(w_);
    ErrorPlots* plots = w_->ownPlots();
    const QStringList units{"m", "m", "m/s", "m/s", "m/s", "m/s", "m", "m", "m/s", "m", "m", "deg", "sd"};
    QCOMPARE(plots->quantityBox()->count(), units.size());
    for (int q = 0; q < plots->quantityBox()->count(); ++q) {
      plots->quantityBox()->setCurrentIndex(q);
      showPlots(plots);
      qInfo("%s: time %s; values %s", qPrintable(plots->quantityBox()->currentText()),
            qPrintable(shownLabels(plots->chartView(PlotCharts::Value)).time.join(' ')),
            qPrintable(shownLabels(plots->chartView(PlotCharts::Value)).value.join(' ')));
      verifyCharts(plots, units[q]);
      if (QTest::currentTestFailed()) qWarning("quantity %d", q);
    }
    plots->quantityBox()->setCurrentIndex(kRadarHeadingQuantity);
    showPlots(plots);
    shoot(plots, QStringLiteral("plots-own-ship-radar-heading"));
  }

  void targetPlotsHaveRoundTicksUnitsAndNeesFromZero() {
    QVERIFY(w_);
    QTableView* table = w_->targetTable();
    QTRY_VERIFY_WITH_TIMEOUT(table->model()->rowCount() > 0, kTimeoutMs);
    // The row of the track with the most sweeps on a true target.
    int best = -1, bestRow = 0;
    for (int row = 0; row < table->model()->rowCount(); ++row) {
      const int id = table->model()->index(row, TargetTableModel::Id).data(Qt::UserRole).toInt();
      const auto& samples = w_->history().track(id);
      const int n =
          int(std::count_if(samples.begin(), samples.end(), [](const TrackSample& t) { return t.hasTruth; }));
      if (n > best) {
        best = n;
        bestRow = row;
      }
    }
    QVERIFY2(best > 20, qPrintable(QString::number(best)));
    table->selectRow(bestRow);
    table->setCurrentIndex(table->model()->index(bestRow, 0));
    QTRY_VERIFY_WITH_TIMEOUT(w_->chart()->selectedTrack().has_value(), kTimeoutMs);
    ErrorPlots* plots = w_->targetPlots();
    plots->refresh();
    QVERIFY2(plots->pointCount() > 60, qPrintable(QString::number(plots->pointCount())));
    const QStringList units{"m", "m", "m/s", "m/s"};
    for (int q = 0; q < plots->quantityBox()->count(); ++q) {
      plots->quantityBox()->setCurrentIndex(q);
      showPlots(plots);
      verifyCharts(plots, units[q]);
    }
    shoot(plots, QStringLiteral("plots-target-day"));
  }

  void estimateAndTruthDifferInColourAndStyleDayAndNight() {
    QVERIFY(w_);
    ErrorPlots* plots = w_->ownPlots();
    plots->quantityBox()->setCurrentIndex(0);
    for (const charts::Palette palette : {charts::Palette::Day, charts::Palette::Night}) {
      w_->setPalette(palette);
      showPlots(plots);
      QChart* chart = plots->charts().chart(PlotCharts::Value);
      QLineSeries* est = seriesNamed(chart, QStringLiteral("estimate"));
      QLineSeries* truth = seriesNamed(chart, QStringLiteral("truth"));
      QVERIFY(est && truth);
      QVERIFY(est->count() > 100 && truth->count() > 100);
      // Different colour and style; both far from the background.
      const QColor background = chart->backgroundBrush().color();
      qInfo("palette %d: estimate %s, truth %s, background %s", int(palette),
            qPrintable(est->pen().color().name()), qPrintable(truth->pen().color().name()),
            qPrintable(background.name()));
      QVERIFY(colourDistance(est->pen().color(), truth->pen().color()) > 150);
      QCOMPARE(est->pen().style(), Qt::SolidLine);
      QCOMPARE(truth->pen().style(), Qt::DashLine);
      QVERIFY(est->pen().widthF() > truth->pen().widthF());
      QVERIFY(colourDistance(est->pen().color(), background) > 200);
      QVERIFY(colourDistance(truth->pen().color(), background) > 300);
      QVERIFY(colourDistance(chart->titleBrush().color(), background) > 250);
      // The legend names both (and the band).
      QVERIFY(chart->legend()->isVisible());
      QStringList legend;
      for (QLegendMarker* m : chart->legend()->markers())
        if (m->isVisible()) legend << m->label();
      QVERIFY2(legend.contains(QStringLiteral("estimate")) && legend.contains(QStringLiteral("truth")) &&
                   legend.contains(QStringLiteral("estimate ±2 sd")),
               qPrintable(legend.join(", ")));
      verifyCharts(plots, QStringLiteral("m"));
      const QString name = palette == charts::Palette::Day ? QStringLiteral("day") : QStringLiteral("night");
      shoot(plots, QStringLiteral("plots-own-ship-%1").arg(name));
    }
    QVERIFY(plots->charts().chart(PlotCharts::Value)->backgroundBrush().color().lightness() < 40);  // night
    w_->setPalette(charts::Palette::Day);
  }

  void pngExportDrawsTheChartsAtTheChosenSize() {
    QVERIFY(w_);
    ErrorPlots* plots = w_->ownPlots();
    plots->quantityBox()->setCurrentIndex(0);
    showPlots(plots);
    QTemporaryDir dir;
    const QColor estimate =
        seriesNamed(plots->charts().chart(PlotCharts::Value), QStringLiteral("estimate"))->pen().color();
    for (const charts::Palette palette : {charts::Palette::Day, charts::Palette::Night}) {
      w_->setPalette(palette);
      const QString path = dir.filePath(QStringLiteral("own-%1.png").arg(int(palette)));
      QVERIFY(plots->exportPng(path, QSize(1200, 800)));
      const QImage image(path);
      QCOMPARE(image.size(), QSize(1200, 800));
      // The report style whatever the palette: white, with the estimate's blue and black text and lines.
      QCOMPARE(image.pixelColor(2, 2), QColor(Qt::white));
      QCOMPARE(image.pixelColor(1197, 797), QColor(Qt::white));
      const int blue = pixelsNear(image, estimate), black = pixelsNear(image, QColor(Qt::black));
      qInfo("export %dx%d: %d estimate pixels, %d black", image.width(), image.height(), blue, black);
      QVERIFY(blue > 1500);
      QVERIFY(black > 1500);
      // Nothing of the panel: the combo boxes' grey frame is nowhere in the first rows.
      for (int x = 0; x < image.width(); ++x) QCOMPARE(image.pixelColor(x, 0), QColor(Qt::white));
      QVERIFY(image.save(QStringLiteral("screenshots/plots-export-1200x800-%1.png")
                             .arg(palette == charts::Palette::Day ? "day" : "night")));
    }
    w_->setPalette(charts::Palette::Day);
    // Another size is that size; the live charts keep theirs.
    const AxisTicks before = plots->charts().timeTicks(PlotCharts::Value);
    QCOMPARE(plots->renderImage(QSize(1600, 1000)).size(), QSize(1600, 1000));
    QCOMPARE(plots->charts().timeTicks(PlotCharts::Value), before);
  }

  void exportSizeIsAskedAndRemembered() {
    QCOMPARE(rememberedPlotExportSize(), QSize(1600, 1000));  // before any export
    answerSizeDialog(QSize(1200, 800), nullptr);
    QCOMPARE(askPlotExportSize(w_.get()), std::optional<QSize>(QSize(1200, 800)));
    QCOMPARE(rememberedPlotExportSize(), QSize(1200, 800));
    QSize shown;
    answerSizeDialog({}, &shown);
    QCOMPARE(askPlotExportSize(w_.get()), std::nullopt);  // cancelled
    QCOMPARE(shown, QSize(1200, 800));                    // the dialog offered the last size
  }

  void theTimeAxisIsRightAfterAReload() {
    QVERIFY(w_);
    ErrorPlots* plots = w_->ownPlots();
    // WHEN the scenario is loaded again and runs a few seconds
    QVERIFY(w_->openScenario(QStringLiteral("builtin:") +
                             QString::fromLatin1(resources::kDefaultScenario.data(),
                                                 qsizetype(resources::kDefaultScenario.size()))));
    QTRY_VERIFY_WITH_TIMEOUT(!w_->history().empty() && simTime(*w_) < 100.0, kTimeoutMs);
    for (const double t : {2.0, 45.0}) {
      runUntil(*w_, t);
      showPlots(plots);
      // THEN the time axis reads whole minutes and seconds on a round step, from 00:00
      const QStringList time = shownLabels(plots->chartView(PlotCharts::Value)).time;
      qInfo("after a reload, at %g s: %s", t, qPrintable(time.join(' ')));
      verifyTimeLabels(time);
      QCOMPARE(time.front(), QStringLiteral("00:00"));
      QVERIFY(parseClock(time.back()) >= std::max(60.0, t));
      verifyCharts(plots, QStringLiteral("m"));
    }
    shoot(plots, QStringLiteral("plots-after-reload"));
  }

  void cleanupTestCase() { w_.reset(); }
};

QTEST_MAIN(TestPlots)
#include "tst_plots.moc"
