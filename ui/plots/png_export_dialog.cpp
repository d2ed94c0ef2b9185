#include "ui/plots/png_export_dialog.h"

#include <QDialog>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QSettings>
#include <QSpinBox>
#include <algorithm>

namespace reckoner::ui {
namespace {

const QString kWidthKey = QStringLiteral("plots/exportWidth");
const QString kHeightKey = QStringLiteral("plots/exportHeight");

int clampPx(int px) {
  return std::clamp(px, kMinPlotExportPx, kMaxPlotExportPx);
}

QSpinBox* pixelBox(int value, QWidget* parent) {
  auto* box = new QSpinBox(parent);
  box->setRange(kMinPlotExportPx, kMaxPlotExportPx);
  box->setSingleStep(100);
  box->setSuffix(QObject::tr(" px"));
  box->setValue(value);
  return box;
}

}  // namespace

QSize rememberedPlotExportSize() {
  const QSettings s;
  return {clampPx(s.value(kWidthKey, kDefaultPlotExportSize.width()).toInt()),
          clampPx(s.value(kHeightKey, kDefaultPlotExportSize.height()).toInt())};
}

void rememberPlotExportSize(QSize sizePx) {
  QSettings s;
  s.setValue(kWidthKey, clampPx(sizePx.width()));
  s.setValue(kHeightKey, clampPx(sizePx.height()));
}

std::optional<QSize> askPlotExportSize(QWidget* parent) {
  QDialog dialog(parent);
  dialog.setObjectName(QStringLiteral("plotExportSize"));
  dialog.setWindowTitle(QObject::tr("Export plots as PNG"));
  const QSize last = rememberedPlotExportSize();
  auto* width = pixelBox(last.width(), &dialog);
  width->setObjectName(QStringLiteral("width"));
  auto* height = pixelBox(last.height(), &dialog);
  height->setObjectName(QStringLiteral("height"));
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
  QObject::connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
  QObject::connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
  auto* form = new QFormLayout(&dialog);
  form->addRow(QObject::tr("Width"), width);
  form->addRow(QObject::tr("Height"), height);
  form->addRow(buttons);
  if (dialog.exec() != QDialog::Accepted) return std::nullopt;
  const QSize chosen(width->value(), height->value());
  rememberPlotExportSize(chosen);
  return chosen;
}

}  // namespace reckoner::ui
