#pragma once
// The chart view's projection: Mercator on the sphere (as ECDIS displays are), a centre, a scale 1:N
// referred to the centre latitude, a rotation (north-up = 0) and a pixel size. Converts both ways
// between latitude/longitude and screen pixels (x right, y down). Plain C++, a value type.
#include <utility>

#include "charts/model/chart_model.h"

namespace reckoner::charts {

struct ScreenPoint {
  double x = 0.0, y = 0.0;
};

/// A point in spherical Mercator units (radians: x = longitude, y = ln tan(pi/4 + lat/2)).
struct MercatorPoint {
  double x = 0.0, y = 0.0;
};

/// The affine map from Mercator units to screen pixels of one view: x = a mx + b my + e,
/// y = c mx + d my + f. Geometry projected once to Mercator is drawn in any view with it.
struct MercatorToScreen {
  double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;
  [[nodiscard]] ScreenPoint operator()(double mx, double my) const {
    return {a * mx + b * my + e, c * mx + d * my + f};
  }
};

/// Latitude clamped to +-85 degrees, as the view does.
MercatorPoint toMercator(const LatLon& p);
/// The inverse of toMercator().
LatLon fromMercator(const MercatorPoint& m);

class Viewport {
 public:
  /// scaleDenominator N of 1:N; pixelSizeMm: the screen's pixel pitch (0.28 mm is S-52's reference);
  /// rotationRad: the up direction's true bearing (0 north-up; course-up sets it to the course).
  Viewport(LatLon centre, double scaleDenominator, int widthPx, int heightPx, double pixelSizeMm = 0.28,
           double rotationRad = 0.0);

  [[nodiscard]] ScreenPoint toScreen(const LatLon& p) const;
  [[nodiscard]] MercatorToScreen mercatorToScreen() const;
  /// The Mercator box containing the whole (possibly rotated) screen.
  [[nodiscard]] std::pair<MercatorPoint, MercatorPoint> visibleMercator() const;
  [[nodiscard]] LatLon toLatLon(const ScreenPoint& s) const;
  /// Ground metres per pixel at the centre latitude.
  [[nodiscard]] double metresPerPixel() const;
  /// Latitude/longitude box containing the whole screen.
  [[nodiscard]] Bounds visibleBounds() const;

  [[nodiscard]] const LatLon& centre() const { return centre_; }
  [[nodiscard]] double scaleDenominator() const { return scale_; }
  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }
  [[nodiscard]] double rotationRad() const { return rotation_; }

 private:
  LatLon centre_;
  double scale_;
  int width_, height_;
  double pixelSizeM_;
  double rotation_;
  double cx_, cy_;      // Mercator coordinates of the centre (radians)
  double pxPerUnit_;    // pixels per Mercator radian
  double cosR_, sinR_;  // rotation
};

}  // namespace reckoner::charts
