#pragma once
// Estimate-vs-truth plots (the only Qt Charts code): for own ship a chosen quantity's estimate and
// truth against time (seed 000 figures 1 and 4), its error with the +-2 sd band from the covariance
// (figures 2 and 5) and the NEES with its chi-square band; the same for the selected target. A rolling
// window or the whole run. Series are rebuilt from SimHistory in one replace() per refresh (never a
// point at a time), decimated to at most ~1500 points; the charts themselves are ui/plots/plot_charts.h.
// Export: PNG of the three charts (not the panel) at a size asked for, CSV of the current quantity and
// window at full resolution.
#include <QComboBox>
#include <QImage>
#include <QWidget>
#include <array>
#include <optional>

#include "ui/bridge/sim_history.h"
#include "ui/plots/plot_charts.h"

QT_BEGIN_NAMESPACE
class QChartView;
QT_END_NAMESPACE

namespace reckoner::ui {

class ErrorPlots : public QWidget {
  Q_OBJECT
 public:
  enum class Subject { OwnShip, Target };

  ErrorPlots(Subject subject, QWidget* parent = nullptr);

  void setHistory(const SimHistory* history) { history_ = history; }
  void setTrack(std::optional<int> trackId);
  /// Rebuilds the series from the history (call at a modest rate, e.g. 2 Hz).
  void refresh();

  /// The dark style for the dusk and night palettes (the PNG export keeps the report style).
  void setDark(bool dark);
  /// Number of points in the estimate, error and NEES series (tests).
  [[nodiscard]] int pointCount() const;
  /// The three charts as shown now, stacked, drawn at sizePx (each dimension 200 to 8000 px) in the
  /// report style (white background, black text, whatever the palette), the axes' ticks fitted to
  /// that size, the subject in the first title; without the panel's combo boxes.
  [[nodiscard]] QImage renderImage(QSize sizePx) const;
  /// renderImage(sizePx) written as PNG.
  bool exportPng(const QString& path, QSize sizePx) const;
  bool exportCsv(const QString& path) const;
  [[nodiscard]] QComboBox* quantityBox() const { return quantity_; }
  [[nodiscard]] QComboBox* windowBox() const { return window_; }
  [[nodiscard]] const PlotCharts& charts() const { return charts_; }
  [[nodiscard]] QChartView* chartView(PlotCharts::Chart c) const { return views_[c]; }

 private:
  struct Row {
    double t, est, truth, sd;
  };
  /// The rows of the current quantity and window; decimated to about kMaxPoints for display.
  [[nodiscard]] std::vector<Row> rows(std::vector<double>* nees, bool decimate) const;
  /// What the charts show of the rows.
  [[nodiscard]] PlotData plotData(const std::vector<Row>& samples, const std::vector<double>& nees) const;
  /// estimate - truth, wrapped to (-180, 180] for an angle in degrees.
  [[nodiscard]] double errorOf(const Row& r) const;

  Subject subject_;
  const SimHistory* history_ = nullptr;
  std::optional<int> track_;
  QComboBox* quantity_;
  QComboBox* window_;
  PlotCharts charts_;
  std::array<QChartView*, PlotCharts::kCharts> views_{};
  PlotData shown_;
};

}  // namespace reckoner::ui
