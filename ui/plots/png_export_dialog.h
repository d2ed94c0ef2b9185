#pragma once
// The size of a PNG export of the plots, asked of the user: width and height in pixels, the last answer
// remembered in QSettings ("plots/exportWidth", "plots/exportHeight"; 1600 x 1000 at first).
#include <QSize>
#include <optional>

QT_BEGIN_NAMESPACE
class QWidget;
QT_END_NAMESPACE

namespace reckoner::ui {

inline constexpr QSize kDefaultPlotExportSize{1600, 1000};
inline constexpr int kMinPlotExportPx = 200, kMaxPlotExportPx = 8000;

/// The size remembered (the default before any export).
[[nodiscard]] QSize rememberedPlotExportSize();
void rememberPlotExportSize(QSize sizePx);
/// A modal dialog with the remembered size; the size chosen (and remembered), or nothing on cancel.
[[nodiscard]] std::optional<QSize> askPlotExportSize(QWidget* parent);

}  // namespace reckoner::ui
