#include "ui/panels/widget_palette.h"

#include <QApplication>

namespace reckoner::ui {

QPalette widgetPalette(charts::Palette palette) {
  QPalette pal = QApplication::palette();
  if (palette == charts::Palette::Day) return pal;
  const bool night = palette == charts::Palette::Night;
  const QColor window = night ? QColor(12, 12, 14) : QColor(40, 40, 48);
  const QColor text = night ? QColor(150, 140, 110) : QColor(215, 215, 215);
  const QColor highlight = night ? QColor(48, 44, 36) : QColor(60, 72, 100);
  const struct {
    QPalette::ColorRole role;
    QColor colour;
  } roles[] = {{QPalette::Window, window},
               {QPalette::Base, window.darker(120)},
               {QPalette::AlternateBase, window},
               {QPalette::Button, window.lighter(130)},
               {QPalette::Light, window.lighter(170)},
               {QPalette::Midlight, window.lighter(150)},
               {QPalette::Mid, window.lighter(120)},
               {QPalette::Dark, window.darker(150)},
               {QPalette::Shadow, Qt::black},
               {QPalette::WindowText, text},
               {QPalette::Text, text},
               {QPalette::ButtonText, text},
               {QPalette::BrightText, text.lighter(120)},
               {QPalette::PlaceholderText, text.darker(150)},
               {QPalette::Highlight, highlight},
               {QPalette::HighlightedText, text.lighter(115)},
               {QPalette::ToolTipBase, window.lighter(150)},
               {QPalette::ToolTipText, text},
               {QPalette::Link, night ? QColor(110, 110, 140) : QColor(140, 170, 230)},
               {QPalette::LinkVisited, night ? QColor(120, 100, 130) : QColor(170, 140, 210)}};
  for (const auto& r : roles) pal.setColor(r.role, r.colour);
  for (const QPalette::ColorRole r : {QPalette::WindowText, QPalette::Text, QPalette::ButtonText})
    pal.setColor(QPalette::Disabled, r, text.darker(180));
  return pal;
}

}  // namespace reckoner::ui
