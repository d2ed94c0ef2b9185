#include "ui/plots/error_plots.h"

#include <QChart>
#include <QChartView>
#include <QCoreApplication>
#include <QFile>
#include <QGraphicsLayout>
#include <QGraphicsScene>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QScrollArea>
#include <QTextStream>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "common/angles.h"
#include "estimation/chi_square.h"
#include "ui/plots/png_export_dialog.h"

namespace reckoner::ui {
namespace {
constexpr std::size_t kMaxPoints = 1500;
constexpr int kMinChartHeightPx = 220;

struct Quantity {
  const char* name;
  const char* unit;  ///< "" for none
  const char* axis;  ///< the value axis's name, before its unit
};
const Quantity kOwnQuantities[] = {
    {"Position x (east)", "m", "x east"},
    {"Position y (north)", "m", "y north"},
    {"Velocity x over ground", "m/s", "v east"},
    {"Velocity y over ground", "m/s", "v north"},
    {"Current x", "m/s", "current east"},
    {"Current y", "m/s", "current north"},
    {"Loran-C error x", "m", "Loran-C x"},
    {"Loran-C error y", "m", "Loran-C y"},
    {"Speedlog error", "m/s", "log error"},
    // Seed 004's radar fixes (matched pictures) against the truth at their time; NEES of 3 dof.
    {"Radar fix x (east)", "m", "fix x"},
    {"Radar fix y (north)", "m", "fix y"},
    {"Radar fix heading (grid)", "deg", "fix heading"},
    {"Radar echo residual (rms, in sd)", "sd", "residual"},
};
constexpr int kFirstRadarQuantity = 9;
constexpr int kRadarHeadingQuantity = 11;
const Quantity kTargetQuantities[] = {
    {"Target position x (east)", "m", "x east"},
    {"Target position y (north)", "m", "y north"},
    {"Target velocity x", "m/s", "v east"},
    {"Target velocity y", "m/s", "v north"},
};

/// Calls f for the samples (with a member tS, in time order) from time t0 on, every stride-th one when
/// decimating so that about kMaxPoints remain; the last sample is always included.
template <class Sample, class F>
void forWindow(const std::vector<Sample>& samples, double t0, bool decimate, F&& f) {
  auto it = std::lower_bound(samples.begin(), samples.end(), t0,
                             [](const Sample& s, double t) { return s.tS < t; });
  const std::size_t n = static_cast<std::size_t>(samples.end() - it);
  const std::size_t stride = decimate ? std::max<std::size_t>(1, (n + kMaxPoints - 1) / kMaxPoints) : 1;
  for (std::size_t i = 0; i < n; i += stride) f(it[static_cast<std::ptrdiff_t>(i)]);
  if (n > 0 && (n - 1) % stride != 0) f(samples.back());
}

/// One sample's value of a plotted quantity: estimate, truth (NaN: none) and standard deviation.
struct Estimate {
  double est, truth, sd;
};

Estimate radarFixQuantity(const RadarFixSample& s, int q) {
  switch (q) {
    case 0:
      return {s.x, s.trueX, s.sdX};
    case 1:
      return {s.y, s.trueY, s.sdY};
    case 2:
      return {s.headingDeg, s.trueHeadingDeg, s.sdHeadingDeg};
    default:
      return {s.rmsResidual, std::nan(""), std::nan("")};
  }
}

Estimate ownQuantity(const OwnSample& s, int q) {
  switch (q) {
    case 0:
      return {s.estPos[0], s.truePos[0], s.sdPos[0]};
    case 1:
      return {s.estPos[1], s.truePos[1], s.sdPos[1]};
    case 2:
      return {s.estVel[0], s.trueVel[0], s.sdVel[0]};
    case 3:
      return {s.estVel[1], s.trueVel[1], s.sdVel[1]};
    case 4:
      return {s.estCurrent[0], s.trueCurrent[0], s.sdCurrent[0]};
    case 5:
      return {s.estCurrent[1], s.trueCurrent[1], s.sdCurrent[1]};
    case 6:
      return {s.estLoran[0], s.trueLoran[0], s.sdLoran[0]};
    case 7:
      return {s.estLoran[1], s.trueLoran[1], s.sdLoran[1]};
    default:
      return {s.estLogBias, s.trueLogBias, s.sdLogBias};
  }
}

Estimate trackQuantity(const TrackSample& s, int q) {
  const double nan = std::nan("");
  switch (q) {
    case 0:
      return {s.estPos[0], s.hasTruth ? s.truePos[0] : nan, s.sdPos[0]};
    case 1:
      return {s.estPos[1], s.hasTruth ? s.truePos[1] : nan, s.sdPos[1]};
    case 2:
      return {s.estVel[0], s.hasTruth ? s.trueVel[0] : nan, s.sdVel[0]};
    default:
      return {s.estVel[1], s.hasTruth ? s.trueVel[1] : nan, s.sdVel[1]};
  }
}

}  // namespace

ErrorPlots::ErrorPlots(Subject subject, QWidget* parent) : QWidget(parent), subject_(subject) {
  auto* v = new QVBoxLayout(this);
  auto* bar = new QHBoxLayout;
  quantity_ = new QComboBox(this);
  quantity_->setObjectName(QStringLiteral("quantity"));
  if (subject == Subject::OwnShip)
    for (const auto& q : kOwnQuantities) quantity_->addItem(QString::fromUtf8(q.name));
  else
    for (const auto& q : kTargetQuantities) quantity_->addItem(QString::fromUtf8(q.name));
  window_ = new QComboBox(this);
  window_->setObjectName(QStringLiteral("window"));
  window_->addItem(tr("Last 5 min"), 300.0);
  window_->addItem(tr("Last 30 min"), 1800.0);
  window_->addItem(tr("Whole run"), 0.0);
  window_->setCurrentIndex(2);
  bar->addWidget(new QLabel(subject == Subject::OwnShip ? tr("Own ship") : tr("Selected target"), this));
  bar->addWidget(quantity_, 1);
  bar->addWidget(window_);
  v->addLayout(bar);
  // The charts keep a height their axes can be read at; a short dock scrolls them.
  auto* scroll = new QScrollArea(this);
  scroll->setObjectName(QStringLiteral("plotScroll"));
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  auto* stack = new QWidget(scroll);
  auto* column = new QVBoxLayout(stack);
  column->setContentsMargins(0, 0, 0, 0);
  column->setSpacing(2);
  charts_.setTitlesVisible(false);
  for (int c = 0; c < PlotCharts::kCharts; ++c) {
    QChart* chart = charts_.chart(static_cast<PlotCharts::Chart>(c));
    auto* view = new QChartView(chart, stack);  // owns the chart
    view->setRenderHint(QPainter::Antialiasing);
    view->setMinimumHeight(kMinChartHeightPx);
    column->addWidget(view, 1);
    views_[static_cast<std::size_t>(c)] = view;
    // A new plot area (a resize, new labels) may hold more or fewer ticks: fit again once laid out.
    connect(
        chart, &QChart::plotAreaChanged, this, [this] { charts_.fit(); }, Qt::QueuedConnection);
  }
  scroll->setWidget(stack);
  v->addWidget(scroll, 1);
  connect(quantity_, &QComboBox::currentIndexChanged, this, &ErrorPlots::refresh);
  connect(window_, &QComboBox::currentIndexChanged, this, &ErrorPlots::refresh);
}

void ErrorPlots::setDark(bool dark) {
  charts_.setStyle(dark ? PlotStyle::Dark : PlotStyle::Day);
}

void ErrorPlots::setTrack(std::optional<int> trackId) {
  track_ = trackId;
  refresh();
}

std::vector<ErrorPlots::Row> ErrorPlots::rows(std::vector<double>* nees, bool decimate) const {
  std::vector<Row> out;
  if (!history_ || history_->empty()) return out;
  const double window = window_->currentData().toDouble();
  const int q = quantity_->currentIndex();
  // Calls forWindow over the window's samples, adding each one's row and NEES.
  const auto walk = [&](const auto& samples, auto&& quantityOf, auto&& neesOf) {
    const double t0 = window > 0.0 && !samples.empty() ? samples.back().tS - window : -1e300;
    forWindow(samples, t0, decimate, [&](const auto& s) {
      const Estimate v = quantityOf(s);
      out.push_back({s.tS, v.est, v.truth, v.sd});
      if (nees) nees->push_back(neesOf(s));
    });
  };
  if (subject_ == Subject::OwnShip && q >= kFirstRadarQuantity)
    walk(
        history_->radarFixes(),
        [&](const RadarFixSample& s) { return radarFixQuantity(s, q - kFirstRadarQuantity); },
        [](const RadarFixSample& s) { return s.nees; });
  else if (subject_ == Subject::OwnShip)
    walk(
        history_->own(), [&](const OwnSample& s) { return ownQuantity(s, q); },
        [](const OwnSample& s) { return s.nees; });
  else if (track_)
    walk(
        history_->track(*track_), [&](const TrackSample& s) { return trackQuantity(s, q); },
        [](const TrackSample& s) { return s.hasTruth ? s.positionVelocityNees4 : std::nan(""); });
  return out;
}

double ErrorPlots::errorOf(const Row& r) const {
  const double e = r.est - r.truth;
  const bool angle = subject_ == Subject::OwnShip && quantity_->currentIndex() == kRadarHeadingQuantity;
  return angle ? radToDeg(wrapPi(degToRad(e))) : e;
}

PlotData ErrorPlots::plotData(const std::vector<Row>& samples, const std::vector<double>& nees) const {
  PlotData d;
  const int q = std::max(0, quantity_->currentIndex());
  const Quantity& quantity = subject_ == Subject::OwnShip ? kOwnQuantities[q] : kTargetQuantities[q];
  d.title = quantity_->currentText();
  d.axisName = QString::fromUtf8(quantity.axis);
  d.unit = QString::fromUtf8(quantity.unit);
  d.neesDof = subject_ == Subject::Target ? 4.0 : q >= kFirstRadarQuantity ? 3.0 : 11.0;
  d.neesBandLo = est::chiSquareQuantile(0.025, d.neesDof);
  d.neesBandHi = est::chiSquareQuantile(0.975, d.neesDof);
  d.est.reserve(static_cast<qsizetype>(samples.size()));
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const Row& r = samples[i];
    d.est << QPointF(r.t, r.est);
    if (std::isfinite(r.truth)) {
      d.truth << QPointF(r.t, r.truth);
      d.error << QPointF(r.t, errorOf(r));
    }
    if (std::isfinite(r.sd)) {
      d.estLo << QPointF(r.t, r.est - 2.0 * r.sd);
      d.estHi << QPointF(r.t, r.est + 2.0 * r.sd);
      d.sdLo << QPointF(r.t, -2.0 * r.sd);
      d.sdHi << QPointF(r.t, 2.0 * r.sd);
    }
    if (std::isfinite(nees[i])) d.nees << QPointF(r.t, nees[i]);
  }
  return d;
}

void ErrorPlots::refresh() {
  std::vector<double> nees;
  const std::vector<Row> samples = rows(&nees, true);
  shown_ = plotData(samples, nees);
  charts_.show(shown_);
}

int ErrorPlots::pointCount() const {
  return static_cast<int>(shown_.est.size() + shown_.error.size() + shown_.nees.size());
}

QImage ErrorPlots::renderImage(QSize sizePx) const {
  const QSize size = sizePx.expandedTo(QSize(kMinPlotExportPx, kMinPlotExportPx))
                         .boundedTo(QSize(kMaxPlotExportPx, kMaxPlotExportPx));
  QGraphicsScene scene;  // owns the report's charts
  PlotCharts report;
  report.setStyle(PlotStyle::Report);
  report.setTitlesVisible(true);
  // Text a report can read once the picture is scaled to a page: larger with the picture.
  report.setFontScale(std::clamp(std::min(size.width() / 1200.0, size.height() / 800.0), 1.0, 3.0));
  const int h = size.height() / PlotCharts::kCharts;
  for (int c = 0; c < PlotCharts::kCharts; ++c) {
    QChart* chart = report.chart(static_cast<PlotCharts::Chart>(c));
    scene.addItem(chart);
    const int top = c * h, bottom = c + 1 == PlotCharts::kCharts ? size.height() : top + h;
    chart->setGeometry(QRectF(0, top, size.width(), bottom - top));
  }
  PlotData titled = shown_;
  const QString subject = subject_ == Subject::OwnShip ? tr("Own ship")
                          : track_                     ? tr("Track %1").arg(*track_)
                                                       : tr("Selected target");
  titled.title = tr("%1 · %2").arg(subject, titled.title);
  report.show(titled);
  // Lay out, fit the ticks to the plot areas, and again while the new labels move them. The charts'
  // own posted events (their legends' new names) are delivered first; nobody else's.
  for (int pass = 0; pass < 4; ++pass) {
    for (int c = 0; c < PlotCharts::kCharts; ++c) {
      QChart* chart = report.chart(static_cast<PlotCharts::Chart>(c));
      QCoreApplication::sendPostedEvents(chart->legend());
      QCoreApplication::sendPostedEvents(chart);
      chart->layout()->activate();
    }
    if (!report.fit()) break;
  }
  QImage image(size, QImage::Format_ARGB32_Premultiplied);
  image.fill(Qt::white);
  QPainter p(&image);
  p.setRenderHint(QPainter::Antialiasing);
  const QRectF all(QPointF(0, 0), QSizeF(size));
  scene.render(&p, all, all);
  p.end();
  return image;
}

bool ErrorPlots::exportPng(const QString& path, QSize sizePx) const {
  return renderImage(sizePx).save(path, "PNG");
}

bool ErrorPlots::exportCsv(const QString& path) const {
  QFile file(path);
  if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text)) return false;
  QTextStream out(&file);
  std::vector<double> nees;
  const std::vector<Row> samples = rows(&nees, false);
  out << "t_s,estimate,truth,error,sd,nees\n";
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const Row& r = samples[i];
    out << QString::number(r.t, 'f', 3) << ',' << QString::number(r.est, 'g', 10) << ','
        << (std::isfinite(r.truth) ? QString::number(r.truth, 'g', 10) : QString()) << ','
        << (std::isfinite(r.truth) ? QString::number(errorOf(r), 'g', 10) : QString()) << ','
        << QString::number(r.sd, 'g', 10) << ','
        << (std::isfinite(nees[i]) ? QString::number(nees[i], 'g', 8) : QString()) << '\n';
  }
  return out.status() == QTextStream::Ok && file.flush();
}

}  // namespace reckoner::ui
