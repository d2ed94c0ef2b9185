#pragma once
// Estimate-vs-truth plots (the only Qt Charts code): for own ship a chosen quantity's estimate and
// truth against time (seed 000 figures 1 and 4), its error with the +-2 sd band from the covariance
// (figures 2 and 5) and the NEES with its chi-square band; the same for the selected target. A rolling
// window or the whole run. Series are rebuilt from SimHistory in one replace() per refresh (never a
// point at a time), decimated to at most ~1500 points. Export: PNG of the plots, CSV of the
// current quantity and window at full resolution.
#include <QComboBox>
#include <QWidget>
#include <optional>

#include "ui/bridge/sim_history.h"

QT_BEGIN_NAMESPACE
class QChart;
class QChartView;
class QLineSeries;
class QAreaSeries;
class QValueAxis;
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

  /// Dark chart theme for the dusk and night palettes.
  void setDark(bool dark);
  /// Number of points in the estimate, error and NEES series (tests).
  [[nodiscard]] int pointCount() const;
  bool exportPng(const QString& path) const;
  bool exportCsv(const QString& path) const;
  [[nodiscard]] QComboBox* quantityBox() const { return quantity_; }
  [[nodiscard]] QComboBox* windowBox() const { return window_; }

 private:
  struct Row {
    double t, est, truth, sd;
  };
  /// The rows of the current quantity and window; decimated to about kMaxPoints for display.
  [[nodiscard]] std::vector<Row> rows(std::vector<double>* nees, bool decimate) const;
  /// The rows of one kind of subject: quantity q (of that kind), window in s (0: the whole run).
  [[nodiscard]] std::vector<Row> radarFixRows(int q, double window, std::vector<double>* nees,
                                              bool decimate) const;
  [[nodiscard]] std::vector<Row> ownRows(int q, double window, std::vector<double>* nees,
                                         bool decimate) const;
  [[nodiscard]] std::vector<Row> trackRows(int q, double window, std::vector<double>* nees,
                                           bool decimate) const;
  QChartView* makeChart(const QString& title, QChart*& chart);

  Subject subject_;
  const SimHistory* history_ = nullptr;
  std::optional<int> track_;
  QComboBox* quantity_;
  QComboBox* window_;
  QChart *valueChart_ = nullptr, *errorChart_ = nullptr, *neesChart_ = nullptr;
  QChartView *valueView_ = nullptr, *errorView_ = nullptr, *neesView_ = nullptr;
  QLineSeries *est_, *truth_, *error_, *plus2_, *minus2_, *nees_, *neesLo_, *neesHi_;
  std::vector<std::pair<QLineSeries*, QPen>> pens_;  // re-applied after a theme change
};

}  // namespace reckoner::ui
