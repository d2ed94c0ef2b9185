#include "ui/panels/own_ship_panel.h"

#include <QFormLayout>
#include <QGridLayout>
#include <QPushButton>
#include <QVBoxLayout>
#include <cmath>
#include <optional>

#include "common/angles.h"
#include "common/units.h"
#include "estimation/chi_square.h"
#include "estimation/gaussian.h"
#include "io/text_format.h"
#include "navigation/drkf.h"
#include "ui/panels/alert_panel.h"

namespace reckoner::ui {
namespace {
QString latLon(const geo::GeoPoint& g) {
  return QString::fromStdString(io::formatLatitude(g.latDeg) + ' ' + io::formatLongitude(g.lonDeg));
}

QString courseSpeed(double vx, double vy, double gamma, const DisplayUnits& u) {
  return formatBearing(bearingOf(vx, vy) + gamma) + QLatin1Char(' ') + formatSpeed(std::hypot(vx, vy), u, 2);
}

/// A number typed by the operator ("12.5" or "12,5"); nullopt when it is not one.
std::optional<double> typedNumber(const QString& text) {
  QString t = text.trimmed();
  t.replace(QLatin1Char(','), QLatin1Char('.'));
  bool ok = false;
  const double v = t.toDouble(&ok);
  return ok && std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

QString duration(double s) {
  if (s >= 4.0 * 3600.0 - 1.0) return QStringLiteral("> 4 h");
  const int m = static_cast<int>(s / 60.0);
  return QStringLiteral("%1 min %2 s").arg(m).arg(static_cast<int>(s) % 60, 2, 10, QChar('0'));
}
}  // namespace

void OwnShipPanel::setDisplayPalette(charts::Palette p) {
  dr_->setStyleSheet(alertLabelStyle(alerts::Priority::Alarm, p, 4));
}

OwnShipPanel::OwnShipPanel(QWidget* parent) : QWidget(parent) {
  auto* v = new QVBoxLayout(this);
  dr_ = new QLabel(this);
  dr_->setObjectName(QStringLiteral("drIndication"));
  dr_->setWordWrap(true);
  setDisplayPalette(charts::Palette::Day);
  dr_->hide();
  v->addWidget(dr_);
  v->addWidget(buildOrderRow());
  form_ = new QWidget(this);
  auto* f = new QFormLayout(form_);
  f->setContentsMargins(0, 0, 0, 0);
  v->addWidget(form_);
  v->addStretch(1);
  estPos_ = add(tr("Position (DRKF)"));
  truePos_ = add(tr("Position (truth)"));
  error_ = add(tr("Error / 95% radius"));
  seed002_[0] = add(tr("Geodetic KF (seed 002)"));
  seed002_[1] = add(tr("Least squares (seed 002)"));
  estCog_ = add(tr("COG/SOG (DRKF)"));
  trueCog_ = add(tr("COG/SOG (truth)"));
  heading_ = add(tr("Heading est / true"));
  current_ = add(tr("Current est / true"));
  log_ = add(tr("Log error est / true"));
  loran_ = add(tr("Loran-C error est / true"));
  sensors_ = add(tr("Sensors"));
  static const char* const kBlocks[] = {"NIS GPS position", "NIS GPS velocity", "NIS Loran-C", "NIS speedlog",
                                        "NIS gyro"};
  for (std::size_t i = 0; i < nis_.size(); ++i) nis_[i] = add(tr(kBlocks[i]));
  radarFix_ = add(tr("Radar fix (chart matching)"));
}

QWidget* OwnShipPanel::buildOrderRow() {
  auto* box = new QWidget(this);
  auto* grid = new QGridLayout(box);
  grid->setContentsMargins(0, 0, 0, 4);
  order_ = new QLabel(QStringLiteral("Order –"), box);
  order_->setObjectName(QStringLiteral("orderReadout"));
  QFont bold = order_->font();
  bold.setBold(true);
  order_->setFont(bold);
  grid->addWidget(order_, 0, 0, 1, 5);
  courseEdit_ = new QLineEdit(box);
  courseEdit_->setObjectName(QStringLiteral("orderCourse"));
  courseEdit_->setPlaceholderText(tr("course"));
  courseEdit_->setToolTip(tr("True course to order, 0 to 360 degrees (Enter orders it)"));
  courseEdit_->setMaximumWidth(70);
  speedEdit_ = new QLineEdit(box);
  speedEdit_->setObjectName(QStringLiteral("orderSpeed"));
  speedEdit_->setPlaceholderText(tr("speed"));
  speedEdit_->setMaximumWidth(70);
  speedUnit_ = new QLabel(box);
  auto* apply = new QPushButton(tr("Order"), box);
  apply->setObjectName(QStringLiteral("orderApply"));
  grid->addWidget(courseEdit_, 1, 0);
  grid->addWidget(new QLabel(QStringLiteral("°"), box), 1, 1);
  grid->addWidget(speedEdit_, 1, 2);
  grid->addWidget(speedUnit_, 1, 3);
  grid->addWidget(apply, 1, 4);
  grid->setColumnStretch(5, 1);
  orderError_ = new QLabel(box);
  orderError_->setObjectName(QStringLiteral("orderError"));
  orderError_->setWordWrap(true);
  orderError_->setStyleSheet(QStringLiteral("QLabel { color: #c62828; font-weight: bold; }"));
  orderError_->hide();
  grid->addWidget(orderError_, 2, 0, 1, 6);
  connect(courseEdit_, &QLineEdit::returnPressed, this, &OwnShipPanel::applyTypedOrder);
  connect(speedEdit_, &QLineEdit::returnPressed, this, &OwnShipPanel::applyTypedOrder);
  connect(apply, &QPushButton::clicked, this, &OwnShipPanel::applyTypedOrder);
  setUnits(units_);
  return box;
}

void OwnShipPanel::setUnits(const DisplayUnits& units) {
  units_ = units;
  speedUnit_->setText(unitName(units.speed));
  speedEdit_->setToolTip(tr("Speed through the water to order, 0 to %1 %2 (Enter orders it)")
                             .arg(formatSpeed(kMaxOrderSpeedMps, units, 1, false), unitName(units.speed)));
  showOrder(orderCourseRad_, orderSpeedMps_);
}

void OwnShipPanel::showOrder(double trueCourseRad, double speedMps) {
  orderCourseRad_ = trueCourseRad;
  orderSpeedMps_ = speedMps;
  order_->setText(tr("Order %1").arg(formatCourseSpeed(trueCourseRad, speedMps, units_)));
}

bool OwnShipPanel::applyTypedOrder() {
  double course = orderCourseRad_, speed = orderSpeedMps_;
  QString problem;
  if (!courseEdit_->text().trimmed().isEmpty()) {
    const auto c = typedNumber(courseEdit_->text());
    if (!c || *c < 0.0 || *c > 360.0)
      problem = tr("Course \"%1\": give degrees from 0 to 360").arg(courseEdit_->text().trimmed());
    else
      course = wrapTwoPi(degToRad(*c));
  }
  if (problem.isEmpty() && !speedEdit_->text().trimmed().isEmpty()) {
    const auto v = typedNumber(speedEdit_->text());
    const double limit = speedIn(kMaxOrderSpeedMps, units_.speed);
    if (!v || *v < 0.0 || *v > limit + 1e-9)
      problem = tr("Speed \"%1\": give %2 from 0 to %3")
                    .arg(speedEdit_->text().trimmed(), unitName(units_.speed))
                    .arg(limit, 0, 'f', 1);
    else
      speed = mpsFrom(*v, units_.speed);
  }
  orderError_->setText(problem);
  orderError_->setVisible(!problem.isEmpty());
  if (!problem.isEmpty()) return false;
  courseEdit_->clear();
  speedEdit_->clear();
  emit orderTyped(course, speed);
  return true;
}

QLabel* OwnShipPanel::add(const QString& name) {
  auto* l = new QLabel(QStringLiteral("–"), form_);
  l->setTextInteractionFlags(Qt::TextSelectableByMouse);
  static_cast<QFormLayout*>(form_->layout())->addRow(name, l);
  return l;
}

void OwnShipPanel::showTruthAndCalibration(const LiveFrame& live, const geo::LocalFrame& frame,
                                           double gamma) {
  namespace dk = est::drkf;
  const sim::SimFrame& f = live.frame;
  const auto& x = f.estimate.x;
  const auto& t = f.trueState;
  if (!f.hasTruth) {
    // A live run: there is no truth to show or to score against; the estimate and its sd only.
    const QString none = QStringLiteral("–");
    truePos_->setText(none);
    trueCog_->setText(none);
    error_->setText(QStringLiteral("– / %1 m").arg(live.error95M, 0, 'f', 1));
    heading_->setText(
        QStringLiteral("%1 / –").arg(formatBearing(bearingOf(x[dk::kVelX], x[dk::kVelY]) + gamma)));
    current_->setText(
        QStringLiteral("%1 @ %2").arg(formatSpeed(std::hypot(x[dk::kCurX], x[dk::kCurY]), units_, 2),
                                      formatBearing(bearingOf(x[dk::kCurX], x[dk::kCurY]) + gamma, 0)));
    log_->setText(formatSpeed(x[dk::kLogBias], units_, 3));
    loran_->setText(
        QStringLiteral("(%1, %2) m").arg(x[dk::kLoranX], 0, 'f', 1).arg(x[dk::kLoranY], 0, 'f', 1));
  } else {
    truePos_->setText(latLon(frame.toGeodetic(f.truth.position)));
    error_->setText(QStringLiteral("%1 m / %2 m")
                        .arg(std::hypot(x[dk::kPosX] - t[dk::kPosX], x[dk::kPosY] - t[dk::kPosY]), 0, 'f', 1)
                        .arg(live.error95M, 0, 'f', 1));
    trueCog_->setText(courseSpeed(f.truth.groundVxMps(), f.truth.groundVyMps(), gamma, units_));
    heading_->setText(
        QStringLiteral("%1 / %2").arg(formatBearing(bearingOf(x[dk::kVelX], x[dk::kVelY]) + gamma),
                                      formatBearing(f.truth.headingRad + gamma)));
    current_->setText(QStringLiteral("%1 / %2 @ %3 / %4")
                          .arg(formatSpeed(std::hypot(x[dk::kCurX], x[dk::kCurY]), units_, 2, false),
                               formatSpeed(std::hypot(t[dk::kCurX], t[dk::kCurY]), units_, 2),
                               formatBearing(bearingOf(x[dk::kCurX], x[dk::kCurY]) + gamma, 0),
                               formatBearing(bearingOf(t[dk::kCurX], t[dk::kCurY]) + gamma, 0)));
    log_->setText(QStringLiteral("%1 / %2").arg(formatSpeed(x[dk::kLogBias], units_, 3, false),
                                                formatSpeed(t[dk::kLogBias], units_, 3)));
    loran_->setText(QStringLiteral("(%1, %2) / (%3, %4) m")
                        .arg(x[dk::kLoranX], 0, 'f', 1)
                        .arg(x[dk::kLoranY], 0, 'f', 1)
                        .arg(t[dk::kLoranX], 0, 'f', 1)
                        .arg(t[dk::kLoranY], 0, 'f', 1));
  }
}

void OwnShipPanel::setFrame(const LiveFrame& live, const geo::LocalFrame& frame) {
  namespace dk = est::drkf;
  const sim::SimFrame& f = live.frame;
  const auto& x = f.estimate.x;
  const double gamma = frame.gridInfo({x[dk::kPosX], x[dk::kPosY]}).convergenceRad;
  estPos_->setText(latLon(frame.toGeodetic({x[dk::kPosX], x[dk::kPosY]})));
  estCog_->setText(courseSpeed(x[dk::kVelX] + x[dk::kCurX], x[dk::kVelY] + x[dk::kCurY], gamma, units_));
  showTruthAndCalibration(live, frame, gamma);
  for (std::size_t i = 0; i < seed002_.size(); ++i) {
    if (!live.seed002) {
      seed002_[i]->setText(QStringLiteral("–"));
      continue;
    }
    // Error against the truth and the 95% ellipse's semi-major axis (chi-square 2 dof: 2.45 sd).
    const est::Gaussian<4>& g = (*live.seed002)[i];
    const est::Mat<2> P = g.P.topLeftCorner<2, 2>();
    const double lmax = est::largestEigenvalue(P);
    if (!f.hasTruth) {
      seed002_[i]->setText(
          QStringLiteral("95% %1 m")
              .arg(std::sqrt(est::chiSquareQuantile(0.95, 2.0) * std::max(lmax, 0.0)), 0, 'f', 1));
      continue;
    }
    seed002_[i]->setText(
        QStringLiteral("error %1 m / 95% %2 m")
            .arg(std::hypot(g.x[0] - f.truth.position.xM, g.x[1] - f.truth.position.yM), 0, 'f', 1)
            .arg(std::sqrt(est::chiSquareQuantile(0.95, 2.0) * std::max(lmax, 0.0)), 0, 'f', 1));
  }
  sensors_->setText(QString::fromStdString(sim::sensorLabel(f.sensors)));
  const double now = toSeconds(f.timeUs);
  for (std::size_t i = 0; i < nis_.size(); ++i) {
    const BlockStatus& b = live.blocks[i];
    if (!b.seen || now - b.tS > 5.0) {
      nis_[i]->setText(QStringLiteral("–"));
      continue;
    }
    nis_[i]->setText(QStringLiteral("%1 (%2 dof)%3")
                         .arg(b.nis, 0, 'f', 2)
                         .arg(b.dim)
                         .arg(b.accepted ? QString() : tr(" rejected")));
  }
  if (const auto& r = live.lastRadarFix; r && now - r->tS <= 30.0) {
    radarFix_->setText(r->applied ? tr("%1 of %2 echoes, NIS %3 (%4 dof)")
                                        .arg(r->used)
                                        .arg(r->echoes)
                                        .arg(r->nis, 0, 'f', 2)
                                        .arg(r->dim)
                       : r->informative
                           ? tr("%1 of %2 echoes, rejected by the gate").arg(r->used).arg(r->echoes)
                           : tr("%1 of %2 echoes, too weak a fix").arg(r->used).arg(r->echoes));
  } else {
    radarFix_->setText(QStringLiteral("–"));
  }
  if (live.positionFixUsed) {
    dr_->hide();
  } else {
    QString text = tr("DR — no position fix. 95% error %1 m").arg(live.error95M, 0, 'f', 0);
    if (live.drHorizonS)
      text += *live.drHorizonS <= 0.0
                  ? tr(", past the %1 m limit").arg(live.drLimitM, 0, 'f', 0)
                  : tr(", %1 m limit in %2").arg(live.drLimitM, 0, 'f', 0).arg(duration(*live.drHorizonS));
    dr_->setText(text);
    dr_->show();
  }
}

}  // namespace reckoner::ui
