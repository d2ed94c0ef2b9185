#pragma once
// The three charts of the error plots as one set: estimate and truth with the estimate's ±2 sd band,
// the error with the ±2 sd band, the NEES with its 95% chi-square band. Axes have round ticks fitted to
// the data and to each chart's plot area in pixels (ui/plots/axis_ticks.h), time in mm:ss, units in
// every axis title; estimate and truth differ in colour and style (estimate a solid colour, truth a thin
// dashed black, or near white on the dark style), the bands lighter fills. The widget shows one set in
// chart views; the PNG export renders a second one, in the report style, at the size asked for.
#include <QColor>
#include <QCoreApplication>
#include <QList>
#include <QPointF>
#include <QString>
#include <array>
#include <vector>

#include "ui/plots/axis_ticks.h"

QT_BEGIN_NAMESPACE
class QChart;
class QLineSeries;
class QAreaSeries;
class QCategoryAxis;
QT_END_NAMESPACE

namespace reckoner::ui {

/// What one refresh plots: times in seconds since the scenario's start, values in the quantity's unit.
struct PlotData {
  QString title;     ///< the quantity ("Position x (east)"), maybe with its subject before it
  QString axisName;  ///< the quantity on its axis ("x east")
  QString unit;      ///< "m", "m/s", "deg", ...
  double neesDof = 0.0;
  QList<QPointF> est, estLo, estHi, truth;  ///< estimate, estimate -+ 2 sd, truth
  QList<QPointF> error, sdLo, sdHi;         ///< estimate - truth, -+ 2 sd
  QList<QPointF> nees;
  double neesBandLo = 0.0, neesBandHi = 0.0;  ///< the 95% chi-square band of one NEES sample
};

/// Day: the day palette. Dark: dusk and night (a dim dark background, light text). Report: white
/// background and black text whatever the window's palette (the PNG export).
enum class PlotStyle { Day, Dark, Report };

class PlotCharts {
  Q_DECLARE_TR_FUNCTIONS(PlotCharts)

 public:
  enum Chart { Value = 0, Error = 1, Nees = 2 };
  static constexpr int kCharts = 3;

  /// New charts, owned by whoever takes them (a QChartView or a QGraphicsScene).
  PlotCharts();

  [[nodiscard]] QChart* chart(Chart c) const { return charts_[c]; }
  [[nodiscard]] QCategoryAxis* timeAxis(Chart c) const { return axes_[c].time; }
  [[nodiscard]] QCategoryAxis* valueAxis(Chart c) const { return axes_[c].value; }
  /// The ticks each axis shows now (tests).
  [[nodiscard]] const AxisTicks& timeTicks(Chart c) const { return axes_[c].timeTicks; }
  [[nodiscard]] const AxisTicks& valueTicks(Chart c) const { return axes_[c].valueTicks; }

  void setStyle(PlotStyle style);
  /// Scales every font (the export at a large size); 1 is the application's font.
  void setFontScale(double scale);
  /// The charts' titles (the quantity, the NEES's degrees of freedom) drawn or not: the export draws
  /// them; the panel, short of height, leaves them to its combo box and the legends.
  void setTitlesVisible(bool visible);
  /// Replaces every series' points and the titles, then fits the axes.
  void show(const PlotData& data);
  /// Fits the axes to the data and to the plot areas now (the time axes alike, to the narrowest);
  /// whether any tick changed. A change moves the plot areas at the next layout, which may want a
  /// second fit; the fit settles there (the value axes' labels change the widths, not the heights).
  bool fit();

 private:
  struct Axes {
    QCategoryAxis *time = nullptr, *value = nullptr;
    AxisTicks timeTicks{}, valueTicks{};
    bool fitted = false;
  };
  struct Line {
    QLineSeries* series;
    QColor day, dark;
    double widthPx;
    Qt::PenStyle style;
  };
  struct Band {
    QAreaSeries* series;
    QColor day, dark;  ///< the fill (the border is the same colour, more opaque)
  };
  QLineSeries* addLine(Chart c, const QString& name, const Line& look);
  QAreaSeries* addBand(Chart c, const QString& name, QColor day, QColor dark);
  void applyFonts();

  std::array<QChart*, kCharts> charts_{};
  std::array<Axes, kCharts> axes_{};
  std::vector<Line> lines_;
  std::vector<Band> bands_;
  QLineSeries *est_, *truth_, *error_, *nees_;
  QAreaSeries *estBand_, *sdBand_, *neesBand_;
  std::array<DataRange, kCharts> valueRange_{};  ///< the NEES chart's includes 0 and its band
  DataRange timeRange_{};
  std::array<QString, kCharts> titles_{};
  bool titlesVisible_ = true;
  PlotStyle style_ = PlotStyle::Day;
  double fontScale_ = 1.0;
};

}  // namespace reckoner::ui
