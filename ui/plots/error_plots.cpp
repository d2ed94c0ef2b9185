#include "ui/plots/error_plots.h"

#include <QChart>
#include <QChartView>
#include <QFile>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineSeries>
#include <QPainter>
#include <QTextStream>
#include <QVBoxLayout>
#include <QValueAxis>
#include <algorithm>
#include <cmath>

#include "estimation/chi_square.h"

namespace reckoner::ui {
namespace {
constexpr std::size_t kMaxPoints = 1500;

struct Quantity {
  const char* name;
  const char* unit;
};
const Quantity kOwnQuantities[] = {
    {"Position x (east)", "m"},
    {"Position y (north)", "m"},
    {"Velocity x over ground", "m/s"},
    {"Velocity y over ground", "m/s"},
    {"Current x", "m/s"},
    {"Current y", "m/s"},
    {"Loran-C error x", "m"},
    {"Loran-C error y", "m"},
    {"Speedlog error", "m/s"},
    // Seed 004's radar fixes (matched pictures) against the truth at their time; NEES of 3 dof.
    {"Radar fix x (east)", "m"},
    {"Radar fix y (north)", "m"},
    {"Radar fix heading (grid)", "deg"},
    {"Radar echo residual (rms, in sd)", "sd"},
};
constexpr int kFirstRadarQuantity = 9;
const Quantity kTargetQuantities[] = {
    {"Target position x (east)", "m"},
    {"Target position y (north)", "m"},
    {"Target velocity x", "m/s"},
    {"Target velocity y", "m/s"},
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

void fitAxes(QChart* chart, const std::vector<QLineSeries*>& series) {
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const QLineSeries* s : series)
    for (const QPointF& p : s->points()) {
      if (!std::isfinite(p.y())) continue;
      x0 = std::min(x0, p.x());
      x1 = std::max(x1, p.x());
      y0 = std::min(y0, p.y());
      y1 = std::max(y1, p.y());
    }
  if (x0 > x1) return;
  if (x1 - x0 < 1.0) x1 = x0 + 1.0;
  const double pad = std::max(1e-9, (y1 - y0) * 0.05);
  auto axes = chart->axes();
  for (QAbstractAxis* a : axes) {
    auto* v = qobject_cast<QValueAxis*>(a);
    if (!v) continue;
    if (a->orientation() == Qt::Horizontal)
      v->setRange(x0, x1);
    else
      v->setRange(y0 - pad, y1 + pad);
  }
}

QLineSeries* addSeries(QChart* chart, const QString& name, QColor colour,
                       Qt::PenStyle style = Qt::SolidLine) {
  auto* s = new QLineSeries;
  s->setName(name);
  QPen pen(colour, 1.5, style);
  s->setPen(pen);
  chart->addSeries(s);
  return s;
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
  valueView_ = makeChart(tr("Estimate and truth"), valueChart_);
  errorView_ = makeChart(tr("Error and ±2 sd"), errorChart_);
  neesView_ = makeChart(tr("NEES and 95% chi-square band"), neesChart_);
  v->addWidget(valueView_, 1);
  v->addWidget(errorView_, 1);
  v->addWidget(neesView_, 1);
  est_ = addSeries(valueChart_, tr("estimate"), QColor(0, 90, 200));
  truth_ = addSeries(valueChart_, tr("truth"), QColor(40, 40, 40), Qt::DashLine);
  error_ = addSeries(errorChart_, tr("error"), QColor(0, 90, 200));
  plus2_ = addSeries(errorChart_, tr("+2 sd"), QColor(200, 60, 0), Qt::DashLine);
  minus2_ = addSeries(errorChart_, tr("-2 sd"), QColor(200, 60, 0), Qt::DashLine);
  nees_ = addSeries(neesChart_, tr("NEES"), QColor(0, 90, 200));
  neesLo_ = addSeries(neesChart_, tr("2.5%"), QColor(0, 140, 0), Qt::DashLine);
  neesHi_ = addSeries(neesChart_, tr("97.5%"), QColor(0, 140, 0), Qt::DashLine);
  for (QLineSeries* s : {est_, truth_, error_, plus2_, minus2_, nees_, neesLo_, neesHi_})
    pens_.emplace_back(s, s->pen());
  for (QChart* c : {valueChart_, errorChart_, neesChart_}) {
    auto* ax = new QValueAxis;
    ax->setTitleText(tr("time s"));
    ax->setLabelFormat(QStringLiteral("%.0f"));
    auto* ay = new QValueAxis;
    c->addAxis(ax, Qt::AlignBottom);
    c->addAxis(ay, Qt::AlignLeft);
    for (QAbstractSeries* s : c->series()) {
      s->attachAxis(ax);
      s->attachAxis(ay);
    }
  }
  connect(quantity_, &QComboBox::currentIndexChanged, this, &ErrorPlots::refresh);
  connect(window_, &QComboBox::currentIndexChanged, this, &ErrorPlots::refresh);
}

QChartView* ErrorPlots::makeChart(const QString& title, QChart*& chart) {
  chart = new QChart;
  chart->setTitle(title);
  chart->legend()->setAlignment(Qt::AlignRight);
  chart->setMargins(QMargins(2, 2, 2, 2));
  auto* view = new QChartView(chart, this);
  view->setRenderHint(QPainter::Antialiasing);
  view->setMinimumHeight(120);
  return view;
}

void ErrorPlots::setDark(bool dark) {
  for (QChart* c : {valueChart_, errorChart_, neesChart_}) {
    c->setTheme(dark ? QChart::ChartThemeDark : QChart::ChartThemeLight);
    c->setMargins(QMargins(2, 2, 2, 2));
  }
  for (auto& [series, pen] : pens_) {
    QPen p = pen;
    if (dark) p.setColor(p.color().lighter(130));
    series->setPen(p);
  }
}

void ErrorPlots::setTrack(std::optional<int> trackId) {
  track_ = trackId;
  refresh();
}

std::vector<ErrorPlots::Row> ErrorPlots::rows(std::vector<double>* nees, bool decimate) const {
  if (!history_ || history_->empty()) return {};
  const double window = window_->currentData().toDouble();
  const int q = quantity_->currentIndex();
  if (subject_ == Subject::OwnShip && q >= kFirstRadarQuantity)
    return radarFixRows(q - kFirstRadarQuantity, window, nees, decimate);
  if (subject_ == Subject::OwnShip) return ownRows(q, window, nees, decimate);
  if (!track_) return {};
  return trackRows(q, window, nees, decimate);
}

std::vector<ErrorPlots::Row> ErrorPlots::radarFixRows(int q, double window, std::vector<double>* nees,
                                                      bool decimate) const {
  std::vector<Row> out;
  const auto& fixes = history_->radarFixes();
  const double t0 = window > 0.0 && !fixes.empty() ? fixes.back().tS - window : -1e300;
  const double nan = std::nan("");
  forWindow(fixes, t0, decimate, [&](const RadarFixSample& s) {
    switch (q) {
      case 0:
        out.push_back({s.tS, s.x, s.trueX, s.sdX});
        break;
      case 1:
        out.push_back({s.tS, s.y, s.trueY, s.sdY});
        break;
      case 2:
        out.push_back({s.tS, s.headingDeg, s.trueHeadingDeg, s.sdHeadingDeg});
        break;
      default:
        out.push_back({s.tS, s.rmsResidual, nan, nan});
        break;
    }
    if (nees) nees->push_back(s.nees);
  });
  return out;
}

std::vector<ErrorPlots::Row> ErrorPlots::ownRows(int q, double window, std::vector<double>* nees,
                                                 bool decimate) const {
  std::vector<Row> out;
  const auto& own = history_->own();
  const double t0 = window > 0.0 && !own.empty() ? own.back().tS - window : -1e300;
  forWindow(own, t0, decimate, [&](const OwnSample& s) {
    Row r{s.tS, 0, 0, 0};
    switch (q) {
      case 0:
        r = {s.tS, s.estPos[0], s.truePos[0], s.sdPos[0]};
        break;
      case 1:
        r = {s.tS, s.estPos[1], s.truePos[1], s.sdPos[1]};
        break;
      case 2:
        r = {s.tS, s.estVel[0], s.trueVel[0], s.sdVel[0]};
        break;
      case 3:
        r = {s.tS, s.estVel[1], s.trueVel[1], s.sdVel[1]};
        break;
      case 4:
        r = {s.tS, s.estCurrent[0], s.trueCurrent[0], s.sdCurrent[0]};
        break;
      case 5:
        r = {s.tS, s.estCurrent[1], s.trueCurrent[1], s.sdCurrent[1]};
        break;
      case 6:
        r = {s.tS, s.estLoran[0], s.trueLoran[0], s.sdLoran[0]};
        break;
      case 7:
        r = {s.tS, s.estLoran[1], s.trueLoran[1], s.sdLoran[1]};
        break;
      default:
        r = {s.tS, s.estLogBias, s.trueLogBias, s.sdLogBias};
        break;
    }
    out.push_back(r);
    if (nees) nees->push_back(s.nees);
  });
  return out;
}

std::vector<ErrorPlots::Row> ErrorPlots::trackRows(int q, double window, std::vector<double>* nees,
                                                   bool decimate) const {
  std::vector<Row> out;
  const auto& hist = history_->track(*track_);
  const double t0 = window > 0.0 && !hist.empty() ? hist.back().tS - window : -1e300;
  forWindow(hist, t0, decimate, [&](const TrackSample& s) {
    const double nan = std::nan("");
    Row r{s.tS, 0, 0, 0};
    switch (q) {
      case 0:
        r = {s.tS, s.estPos[0], s.hasTruth ? s.truePos[0] : nan, s.sdPos[0]};
        break;
      case 1:
        r = {s.tS, s.estPos[1], s.hasTruth ? s.truePos[1] : nan, s.sdPos[1]};
        break;
      case 2:
        r = {s.tS, s.estVel[0], s.hasTruth ? s.trueVel[0] : nan, s.sdVel[0]};
        break;
      default:
        r = {s.tS, s.estVel[1], s.hasTruth ? s.trueVel[1] : nan, s.sdVel[1]};
        break;
    }
    out.push_back(r);
    if (nees) nees->push_back(s.hasTruth ? s.nees : nan);
  });
  return out;
}

void ErrorPlots::refresh() {
  std::vector<double> nees;
  const std::vector<Row> samples = rows(&nees, true);
  QList<QPointF> est, truth, err, plus, minus, ne, lo, hi;
  est.reserve(static_cast<qsizetype>(samples.size()));
  const double dof = subject_ == Subject::Target                        ? 4.0
                     : quantity_->currentIndex() >= kFirstRadarQuantity ? 3.0
                                                                        : 11.0;
  const double qLo = est::chiSquareQuantile(0.025, dof), qHi = est::chiSquareQuantile(0.975, dof);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const Row& r = samples[i];
    est << QPointF(r.t, r.est);
    if (std::isfinite(r.truth)) {
      truth << QPointF(r.t, r.truth);
      err << QPointF(r.t, r.est - r.truth);
    }
    if (std::isfinite(r.sd)) {
      plus << QPointF(r.t, 2.0 * r.sd);
      minus << QPointF(r.t, -2.0 * r.sd);
    }
    if (std::isfinite(nees[i])) ne << QPointF(r.t, nees[i]);
  }
  if (!samples.empty()) {
    lo << QPointF(samples.front().t, qLo) << QPointF(samples.back().t, qLo);
    hi << QPointF(samples.front().t, qHi) << QPointF(samples.back().t, qHi);
  }
  est_->replace(est);
  truth_->replace(truth);
  error_->replace(err);
  plus2_->replace(plus);
  minus2_->replace(minus);
  nees_->replace(ne);
  neesLo_->replace(lo);
  neesHi_->replace(hi);
  const QString label =
      subject_ == Subject::OwnShip
          ? QString::fromUtf8(kOwnQuantities[std::max(0, quantity_->currentIndex())].unit)
          : QString::fromUtf8(kTargetQuantities[std::max(0, quantity_->currentIndex())].unit);
  valueChart_->setTitle(tr("%1: estimate and truth (%2)").arg(quantity_->currentText(), label));
  errorChart_->setTitle(tr("Error and ±2 sd (%1)").arg(label));
  neesChart_->setTitle(tr("NEES (%1 dof) and its 95% chi-square band").arg(dof, 0, 'f', 0));
  fitAxes(valueChart_, {est_, truth_});
  fitAxes(errorChart_, {error_, plus2_, minus2_});
  fitAxes(neesChart_, {nees_, neesLo_, neesHi_});
}

int ErrorPlots::pointCount() const {
  return static_cast<int>(est_->count() + error_->count() + nees_->count());
}

bool ErrorPlots::exportPng(const QString& path) const {
  QImage image(width(), height(), QImage::Format_ARGB32_Premultiplied);
  image.fill(Qt::white);
  QPainter p(&image);
  const_cast<ErrorPlots*>(this)->render(&p);
  p.end();
  return image.save(path, "PNG");
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
        << (std::isfinite(r.truth) ? QString::number(r.est - r.truth, 'g', 10) : QString()) << ','
        << QString::number(r.sd, 'g', 10) << ','
        << (std::isfinite(nees[i]) ? QString::number(nees[i], 'g', 8) : QString()) << '\n';
  }
  return out.status() == QTextStream::Ok && file.flush();
}

}  // namespace reckoner::ui
