#pragma once
// Places text labels beside chart symbols so that no label overlaps another label, a symbol or a
// reserved area (the own-ship symbol, the readout boxes): for each label in turn, the first free one of
// a fixed list of positions around its symbol (right and up first, then the other seven compass
// points, then the same again farther out); when none is free, the position that overlaps least.
#include <QRectF>
#include <vector>

namespace reckoner::ui {

struct LabelRequest {
  QPointF anchor;        ///< the symbol's centre, widget pixels
  double clearancePx{};  ///< the symbol's radius: labels start this far from the anchor (plus a gap)
  QSizeF size;           ///< the text's bounding box
};

/// One rectangle per request, in the requests' order. `obstacles`: what no label may cover (every
/// symbol's box, reserved areas); `bounds`: where labels should stay (the widget), preferred over
/// positions that leave it.
[[nodiscard]] std::vector<QRectF> placeLabels(const std::vector<LabelRequest>& requests,
                                              std::vector<QRectF> obstacles, const QRectF& bounds);

}  // namespace reckoner::ui
