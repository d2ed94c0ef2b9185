#include "ui/panels/mariner_settings_dialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>
#include <cmath>

namespace reckoner::ui {
namespace {

bool depthInRange(double m) {
  return std::isfinite(m) && m >= 0.0 && m <= kMaxSettingDepthM;
}

QString metres(double m) {
  return QStringLiteral("%1 m").arg(m, 0, 'g', 4);
}

QDoubleSpinBox* depthBox(QWidget* parent, const char* name, const QString& tip) {
  auto* box = new QDoubleSpinBox(parent);
  box->setObjectName(QString::fromLatin1(name));
  box->setRange(0.0, kMaxSettingDepthM);
  box->setDecimals(1);
  box->setSingleStep(1.0);
  box->setSuffix(QStringLiteral(" m"));
  box->setToolTip(tip);
  return box;
}

QCheckBox* checkBox(QWidget* parent, const char* name, const QString& text, const QString& tip) {
  auto* box = new QCheckBox(text, parent);
  box->setObjectName(QString::fromLatin1(name));
  box->setToolTip(tip);
  return box;
}

}  // namespace

QString marinerSettingsProblem(const charts::MarinerSettings& s) {
  const struct {
    const char* name;
    double value;
  } depths[] = {{"Shallow contour", s.shallowContourM},
                {"Safety contour", s.safetyContourM},
                {"Deep contour", s.deepContourM},
                {"Safety depth", s.safetyDepthM}};
  for (const auto& d : depths)
    if (!depthInRange(d.value))
      return QObject::tr("%1 %2 is not a depth from 0 to %3 m")
          .arg(QString::fromLatin1(d.name))
          .arg(d.value)
          .arg(kMaxSettingDepthM);
  if (s.shallowContourM > s.safetyContourM)
    return QObject::tr("Shallow contour %1 is deeper than the safety contour %2")
        .arg(metres(s.shallowContourM), metres(s.safetyContourM));
  if (s.safetyContourM > s.deepContourM)
    return QObject::tr("Safety contour %1 is deeper than the deep contour %2")
        .arg(metres(s.safetyContourM), metres(s.deepContourM));
  return {};
}

charts::MarinerSettings loadMarinerSettings(const QSettings& settings,
                                            const charts::MarinerSettings& defaults) {
  charts::MarinerSettings s = defaults;
  const auto depth = [&](const char* key, double fallback) {
    bool ok = false;
    const double v = settings.value(QStringLiteral("chart/") + QLatin1String(key)).toDouble(&ok);
    return ok && depthInRange(v) ? v : fallback;
  };
  const auto flag = [&](const char* key, bool fallback) {
    return settings.value(QStringLiteral("chart/") + QLatin1String(key), fallback).toBool();
  };
  s.shallowContourM = depth("shallowContourM", defaults.shallowContourM);
  s.safetyContourM = depth("safetyContourM", defaults.safetyContourM);
  s.deepContourM = depth("deepContourM", defaults.deepContourM);
  s.safetyDepthM = depth("safetyDepthM", defaults.safetyDepthM);
  const int category =
      settings.value(QStringLiteral("chart/category"), static_cast<int>(defaults.category)).toInt();
  if (category >= 0 && category <= static_cast<int>(charts::DisplayCategory::Other))
    s.category = static_cast<charts::DisplayCategory>(category);
  s.fourShades = flag("fourShades", defaults.fourShades);
  s.showText = flag("showText", defaults.showText);
  s.contourLabels = flag("contourLabels", defaults.contourLabels);
  s.honourScamin = flag("honourScamin", defaults.honourScamin);
  return marinerSettingsProblem(s).isEmpty() ? s : defaults;
}

void saveMarinerSettings(QSettings& settings, const charts::MarinerSettings& s) {
  settings.setValue(QStringLiteral("chart/shallowContourM"), s.shallowContourM);
  settings.setValue(QStringLiteral("chart/safetyContourM"), s.safetyContourM);
  settings.setValue(QStringLiteral("chart/deepContourM"), s.deepContourM);
  settings.setValue(QStringLiteral("chart/safetyDepthM"), s.safetyDepthM);
  settings.setValue(QStringLiteral("chart/category"), static_cast<int>(s.category));
  settings.setValue(QStringLiteral("chart/fourShades"), s.fourShades);
  settings.setValue(QStringLiteral("chart/showText"), s.showText);
  settings.setValue(QStringLiteral("chart/contourLabels"), s.contourLabels);
  settings.setValue(QStringLiteral("chart/honourScamin"), s.honourScamin);
}

MarinerSettingsDialog::MarinerSettingsDialog(const charts::MarinerSettings& current, QWidget* parent)
    : QDialog(parent), palette_(current.palette) {
  setWindowTitle(tr("Mariner settings"));
  auto* form = new QFormLayout;
  shallow_ = depthBox(this, "shallowContour",
                      tr("Water shallower than this contour is shaded darkest (four shades only)"));
  safety_ = depthBox(this, "safetyContour",
                     tr("Drawn bold: the chart's shallowest contour at or deeper than this value. Water "
                        "inside it is unsafe for own ship; isolated dangers are judged against it"));
  deep_ = depthBox(this, "deepContour", tr("Water deeper than this contour is shaded as deep water"));
  safetyDepth_ =
      depthBox(this, "safetyDepth", tr("Soundings at or shallower than this depth are drawn in bold black"));
  form->addRow(tr("Shallow contour"), shallow_);
  form->addRow(tr("Safety contour"), safety_);
  form->addRow(tr("Deep contour"), deep_);
  form->addRow(tr("Safety depth"), safetyDepth_);
  category_ = new QComboBox(this);
  category_->setObjectName(QStringLiteral("category"));
  category_->addItems({tr("Base"), tr("Standard"), tr("All")});
  category_->setToolTip(tr("S-52 display category: Base cannot be removed; All adds every other feature"));
  form->addRow(tr("Display category"), category_);
  fourShades_ = checkBox(this, "fourShades", tr("Four depth shades"),
                         tr("Four shades (shallow, safety, deep) instead of two (safety contour only)"));
  showText_ = checkBox(this, "showText", tr("Names and text"), tr("Feature names and other chart text"));
  contourLabels_ =
      checkBox(this, "contourLabels", tr("Contour labels"), tr("Depth values along the depth contours"));
  scamin_ = checkBox(this, "honourScamin", tr("Honour SCAMIN"),
                     tr("Hide features whose minimum display scale (SCAMIN) is larger than the view's"));
  for (QCheckBox* b : {fourShades_, showText_, contourLabels_, scamin_}) form->addRow(QString(), b);
  problem_ = new QLabel(this);
  problem_->setObjectName(QStringLiteral("problem"));
  problem_->setStyleSheet(QStringLiteral("QLabel { color: #c62828; }"));
  problem_->setWordWrap(true);
  buttons_ = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  connect(buttons_, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(problem_);
  layout->addWidget(buttons_);
  for (QDoubleSpinBox* b : {shallow_, safety_, deep_, safetyDepth_})
    connect(b, &QDoubleSpinBox::valueChanged, this, &MarinerSettingsDialog::check);
  setSettings(current);
}

charts::MarinerSettings MarinerSettingsDialog::settings() const {
  charts::MarinerSettings s;
  s.palette = palette_;
  s.shallowContourM = shallow_->value();
  s.safetyContourM = safety_->value();
  s.deepContourM = deep_->value();
  s.safetyDepthM = safetyDepth_->value();
  s.category = static_cast<charts::DisplayCategory>(category_->currentIndex());
  s.fourShades = fourShades_->isChecked();
  s.showText = showText_->isChecked();
  s.contourLabels = contourLabels_->isChecked();
  s.honourScamin = scamin_->isChecked();
  return s;
}

void MarinerSettingsDialog::setSettings(const charts::MarinerSettings& s) {
  palette_ = s.palette;
  shallow_->setValue(s.shallowContourM);
  safety_->setValue(s.safetyContourM);
  deep_->setValue(s.deepContourM);
  safetyDepth_->setValue(s.safetyDepthM);
  category_->setCurrentIndex(static_cast<int>(s.category));
  fourShades_->setChecked(s.fourShades);
  showText_->setChecked(s.showText);
  contourLabels_->setChecked(s.contourLabels);
  scamin_->setChecked(s.honourScamin);
  check();
}

void MarinerSettingsDialog::check() {
  const QString problem = marinerSettingsProblem(settings());
  problem_->setText(problem);
  problem_->setVisible(!problem.isEmpty());
  buttons_->button(QDialogButtonBox::Ok)->setEnabled(problem.isEmpty());
}

}  // namespace reckoner::ui
