#include "ui/plots/plot_charts.h"

#include <QAreaSeries>
#include <QCategoryAxis>
#include <QChart>
#include <QGuiApplication>
#include <QLegend>
#include <QLineSeries>
#include <QPen>
#include <algorithm>
#include <cmath>

namespace reckoner::ui {
namespace {

// Pixels a tick interval needs: a time label ("00:00", "1:00:00") with room between, a value label's
// height with room between.
constexpr double kPxPerTimeInterval = 55.0;
constexpr double kPxPerValueInterval = 30.0;
constexpr int kMaxTimeIntervals = 12, kMaxValueIntervals = 10;

struct Colours {
  QColor background, text, grid, axisLine;
};

Colours coloursOf(PlotStyle style) {
  switch (style) {
    case PlotStyle::Dark:  // dim enough for a bridge at night, like the window's dusk and night palettes
      return {QColor(18, 18, 22), QColor(185, 180, 165), QColor(58, 58, 64), QColor(110, 110, 115)};
    case PlotStyle::Report:
      return {QColor(Qt::white), QColor(Qt::black), QColor(215, 215, 215), QColor(90, 90, 90)};
    case PlotStyle::Day:
      break;
  }
  return {QColor(Qt::white), QColor(30, 30, 30), QColor(225, 225, 225), QColor(120, 120, 120)};
}

/// The axis's categories made the ticks: one label at each tick (a first zero-width category puts a
/// label at the axis's start).
void setTicks(QCategoryAxis* axis, const std::vector<std::string>& labels, const AxisTicks& t) {
  for (const QString& label : axis->categoriesLabels()) axis->remove(label);
  axis->setStartValue(t.min);
  for (int i = 0; i < static_cast<int>(labels.size()); ++i)
    axis->append(QString::fromStdString(labels[static_cast<std::size_t>(i)]),
                 i == t.intervals ? t.max : t.at(i));
  axis->setRange(t.min, t.max);
}

QFont scaledFont(QFont f, double scale, bool bold) {
  if (f.pointSizeF() > 0)
    f.setPointSizeF(f.pointSizeF() * scale);
  else
    f.setPixelSize(std::max(1, static_cast<int>(std::lround(f.pixelSize() * scale))));
  f.setBold(bold);
  return f;
}

QList<QPointF> level(const DataRange& time, double value) {
  if (time.empty()) return {};
  return {QPointF(time.lo, value), QPointF(time.hi, value)};
}

}  // namespace

PlotCharts::PlotCharts() {
  for (int c = 0; c < kCharts; ++c) {
    auto* chart = new QChart;
    chart->legend()->setAlignment(Qt::AlignTop);
    chart->setMargins(QMargins(4, 0, 20, 2));  // room for the last time label, centred on the end
    chart->setBackgroundRoundness(0);
    auto* time = new QCategoryAxis;
    auto* value = new QCategoryAxis;
    for (QCategoryAxis* a : {time, value}) a->setLabelsPosition(QCategoryAxis::AxisLabelsPositionOnValue);
    chart->addAxis(time, Qt::AlignBottom);
    chart->addAxis(value, Qt::AlignLeft);
    charts_[static_cast<std::size_t>(c)] = chart;
    axes_[static_cast<std::size_t>(c)] = {time, value, {}, {}, false};
  }
  const QColor blue(20, 110, 220), lightBlue(100, 175, 255);
  // Bands first, lines over them; the truth last, thin and dashed over the estimate.
  estBand_ = addBand(Value, tr("estimate ±2 sd"), QColor(20, 110, 220, 45), QColor(100, 175, 255, 55));
  // A wide, light estimate: where it lies on the truth, the truth's black (night: white) dashes show on it.
  est_ = addLine(Value, tr("estimate"),
                 {nullptr, QColor(70, 150, 240), QColor(50, 130, 250), 3.4, Qt::SolidLine});
  truth_ =
      addLine(Value, tr("truth"), {nullptr, QColor(Qt::black), QColor(240, 240, 240), 1.3, Qt::DashLine});
  sdBand_ = addBand(Error, tr("±2 sd"), QColor(230, 120, 0, 55), QColor(255, 150, 60, 60));
  error_ = addLine(Error, tr("error (estimate − truth)"), {nullptr, blue, lightBlue, 2.0, Qt::SolidLine});
  neesBand_ = addBand(Nees, tr("95% chi-square band"), QColor(0, 150, 0, 50), QColor(90, 200, 90, 55));
  nees_ = addLine(Nees, tr("NEES"), {nullptr, blue, lightBlue, 2.0, Qt::SolidLine});
  setStyle(PlotStyle::Day);
  applyFonts();
  show(PlotData{});
}

QLineSeries* PlotCharts::addLine(Chart c, const QString& name, const Line& look) {
  auto* s = new QLineSeries;
  s->setName(name);
  charts_[c]->addSeries(s);
  s->attachAxis(axes_[c].time);
  s->attachAxis(axes_[c].value);
  Line l = look;
  l.series = s;
  lines_.push_back(l);
  return s;
}

QAreaSeries* PlotCharts::addBand(Chart c, const QString& name, QColor day, QColor dark) {
  auto* upper = new QLineSeries;
  auto* lower = new QLineSeries;
  auto* band = new QAreaSeries(upper, lower);
  upper->setParent(band);  // the area series uses its boundaries but does not own them
  lower->setParent(band);
  band->setName(name);
  charts_[c]->addSeries(band);
  band->attachAxis(axes_[c].time);
  band->attachAxis(axes_[c].value);
  bands_.push_back({band, day, dark});
  return band;
}

void PlotCharts::setStyle(PlotStyle style) {
  style_ = style;
  const Colours k = coloursOf(style);
  const bool dark = style == PlotStyle::Dark;
  for (QChart* chart : charts_) {
    chart->setBackgroundBrush(k.background);
    chart->setBackgroundPen(Qt::NoPen);
    chart->setPlotAreaBackgroundVisible(false);
    chart->setTitleBrush(k.text);
    chart->legend()->setLabelColor(k.text);
  }
  for (const Axes& a : axes_)
    for (QCategoryAxis* axis : {a.time, a.value}) {
      axis->setLabelsColor(k.text);
      axis->setTitleBrush(k.text);
      axis->setGridLineColor(k.grid);
      axis->setLinePenColor(k.axisLine);
    }
  for (const Line& l : lines_) l.series->setPen(QPen(dark ? l.dark : l.day, l.widthPx, l.style));
  for (const Band& b : bands_) {
    const QColor fill = dark ? b.dark : b.day;
    QColor edge = fill;
    edge.setAlpha(std::min(255, 3 * fill.alpha()));
    b.series->setBrush(fill);
    b.series->setPen(QPen(edge, 1.0));
  }
}

void PlotCharts::setFontScale(double scale) {
  fontScale_ = std::clamp(scale, 0.5, 4.0);
  applyFonts();
}

void PlotCharts::setTitlesVisible(bool visible) {
  titlesVisible_ = visible;
  for (int c = 0; c < kCharts; ++c)
    charts_[static_cast<std::size_t>(c)]->setTitle(visible ? titles_[static_cast<std::size_t>(c)]
                                                           : QString());
}

void PlotCharts::applyFonts() {
  const QFont base = QGuiApplication::font();
  const QFont title = scaledFont(base, fontScale_, true), text = scaledFont(base, 0.9 * fontScale_, false);
  const QFont axisTitle = scaledFont(base, 0.8 * fontScale_, false);  // a rotated title has the plot's height
  for (QChart* chart : charts_) {
    chart->setTitleFont(title);
    chart->legend()->setFont(text);
  }
  for (const Axes& a : axes_)
    for (QCategoryAxis* axis : {a.time, a.value}) {
      axis->setLabelsFont(text);
      axis->setTitleFont(axisTitle);
    }
}

void PlotCharts::show(const PlotData& d) {
  est_->replace(d.est);
  truth_->replace(d.truth);
  estBand_->upperSeries()->replace(d.estHi);
  estBand_->lowerSeries()->replace(d.estLo);
  error_->replace(d.error);
  sdBand_->upperSeries()->replace(d.sdHi);
  sdBand_->lowerSeries()->replace(d.sdLo);
  nees_->replace(d.nees);
  timeRange_ = {};
  for (auto& r : valueRange_) r = {};
  const auto add = [this](Chart c, const QList<QPointF>& points) {
    for (const QPointF& p : points) {
      timeRange_.add(p.x());
      valueRange_[c].add(p.y());
    }
  };
  for (const QList<QPointF>* s : {&d.est, &d.estLo, &d.estHi, &d.truth}) add(Value, *s);
  for (const QList<QPointF>* s : {&d.error, &d.sdLo, &d.sdHi}) add(Error, *s);
  add(Nees, d.nees);
  // NEES is non-negative: its axis starts at 0 and holds the band whenever the band is drawn.
  const bool band = !d.nees.isEmpty();
  neesBand_->upperSeries()->replace(band ? level(timeRange_, d.neesBandHi) : QList<QPointF>{});
  neesBand_->lowerSeries()->replace(band ? level(timeRange_, d.neesBandLo) : QList<QPointF>{});
  valueRange_[Nees].add(0.0);
  valueRange_[Nees].add(band ? d.neesBandHi : 1.0);

  const QString unit = d.unit.isEmpty() ? tr("dimensionless") : d.unit;
  titles_[Value] = d.title.isEmpty() ? tr("Estimate and truth") : tr("%1: estimate and truth").arg(d.title);
  titles_[Error] = tr("Error and ±2 sd");
  titles_[Nees] = d.neesDof > 0 ? tr("NEES (%1 dof) and its 95% chi-square band").arg(d.neesDof, 0, 'f', 0)
                                : tr("NEES and its 95% chi-square band");
  setTitlesVisible(titlesVisible_);
  nees_->setName(d.neesDof > 0 ? tr("NEES (%1 dof)").arg(d.neesDof, 0, 'f', 0) : tr("NEES"));
  axes_[Value].value->setTitleText(tr("%1 (%2)").arg(d.axisName.isEmpty() ? tr("value") : d.axisName, unit));
  axes_[Error].value->setTitleText(tr("error (%1)").arg(unit));
  axes_[Nees].value->setTitleText(tr("NEES (dimensionless)"));
  fit();
}

bool PlotCharts::fit() {
  double width = 1e9;
  for (const QChart* chart : charts_) width = std::min(width, chart->plotArea().width());
  const int nx = std::clamp(static_cast<int>(width / kPxPerTimeInterval), 2, kMaxTimeIntervals);
  const AxisTicks x = ui::timeTicks(timeRange_.lo, timeRange_.hi, nx);
  bool changed = false;
  for (int c = 0; c < kCharts; ++c) {
    Axes& a = axes_[static_cast<std::size_t>(c)];
    const double height = charts_[static_cast<std::size_t>(c)]->plotArea().height();
    const int ny = std::clamp(static_cast<int>(height / kPxPerValueInterval), 2, kMaxValueIntervals);
    const DataRange& r = valueRange_[static_cast<std::size_t>(c)];
    const AxisTicks y = niceTicks(r.lo, r.hi, ny);
    if (!a.fitted || !(x == a.timeTicks)) {
      setTicks(a.time, clockLabels(x), x);
      a.time->setTitleText(clockNeedsHours(x.max) ? tr("time (h:mm:ss)") : tr("time (mm:ss)"));
      a.timeTicks = x;
      changed = true;
    }
    if (!a.fitted || !(y == a.valueTicks)) {
      setTicks(a.value, tickLabels(y), y);
      a.valueTicks = y;
      changed = true;
    }
    a.fitted = true;
  }
  return changed;
}

}  // namespace reckoner::ui
