#include "charts/render/viewport.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/angles.h"

namespace reckoner::charts {
namespace {
constexpr double kEarthRadiusM = 6378137.0;  // WGS-84 equatorial radius: the sphere of web/ECDIS Mercator
constexpr double kMaxLatDeg = 85.0;

double mercatorY(double latDeg) {
  const double lat = degToRad(std::clamp(latDeg, -kMaxLatDeg, kMaxLatDeg));
  return std::log(std::tan(kPi / 4.0 + lat / 2.0));
}
}  // namespace

MercatorPoint toMercator(const LatLon& p) {
  return {degToRad(p.lonDeg), mercatorY(p.latDeg)};
}

LatLon fromMercator(const MercatorPoint& m) {
  return {radToDeg(2.0 * std::atan(std::exp(m.y)) - kPi / 2.0), radToDeg(m.x)};
}

Viewport::Viewport(LatLon centre, double scaleDenominator, int widthPx, int heightPx, double pixelSizeMm,
                   double rotationRad)
    : centre_(centre),
      scale_(scaleDenominator),
      width_(widthPx),
      height_(heightPx),
      pixelSizeM_(pixelSizeMm / 1000.0),
      rotation_(rotationRad) {
  if (!(scaleDenominator > 0.0) || widthPx <= 0 || heightPx <= 0 || !(pixelSizeMm > 0.0) ||
      std::abs(centre.latDeg) > kMaxLatDeg || !std::isfinite(centre.lonDeg) || !std::isfinite(rotationRad))
    throw std::invalid_argument("viewport: scale, size and pixel size must be positive, |latitude| <= 85");
  cx_ = degToRad(centre.lonDeg);
  cy_ = mercatorY(centre.latDeg);
  // A ground distance d at the centre latitude is d / (R cos(lat)) Mercator units and d / (N p) pixels.
  pxPerUnit_ = kEarthRadiusM * std::cos(degToRad(centre.latDeg)) / (scale_ * pixelSizeM_);
  cosR_ = std::cos(rotation_);
  sinR_ = std::sin(rotation_);
}

ScreenPoint Viewport::toScreen(const LatLon& p) const {
  // East and north offsets in pixels, then rotated so that the bearing `rotation` points up.
  const double e = (degToRad(p.lonDeg) - cx_) * pxPerUnit_;
  const double n = (mercatorY(p.latDeg) - cy_) * pxPerUnit_;
  const double right = e * cosR_ - n * sinR_;
  const double up = e * sinR_ + n * cosR_;
  return {0.5 * width_ + right, 0.5 * height_ - up};
}

MercatorToScreen Viewport::mercatorToScreen() const {
  // right = k (dx cos - dy sin), up = k (dx sin + dy cos); x = W/2 + right, y = H/2 - up.
  MercatorToScreen t;
  const double k = pxPerUnit_;
  t.a = k * cosR_;
  t.b = -k * sinR_;
  t.c = -k * sinR_;
  t.d = -k * cosR_;
  t.e = 0.5 * width_ - (t.a * cx_ + t.b * cy_);
  t.f = 0.5 * height_ - (t.c * cx_ + t.d * cy_);
  return t;
}

std::pair<MercatorPoint, MercatorPoint> Viewport::visibleMercator() const {
  MercatorPoint lo{1e9, 1e9}, hi{-1e9, -1e9};
  for (const ScreenPoint s : {ScreenPoint{0, 0}, ScreenPoint{static_cast<double>(width_), 0},
                              ScreenPoint{0, static_cast<double>(height_)},
                              ScreenPoint{static_cast<double>(width_), static_cast<double>(height_)}}) {
    const double right = s.x - 0.5 * width_, up = 0.5 * height_ - s.y;
    const double x = cx_ + (right * cosR_ + up * sinR_) / pxPerUnit_;
    const double y = cy_ + (-right * sinR_ + up * cosR_) / pxPerUnit_;
    lo = {std::min(lo.x, x), std::min(lo.y, y)};
    hi = {std::max(hi.x, x), std::max(hi.y, y)};
  }
  return {lo, hi};
}

LatLon Viewport::toLatLon(const ScreenPoint& s) const {
  const double right = s.x - 0.5 * width_, up = 0.5 * height_ - s.y;
  const double e = right * cosR_ + up * sinR_;
  const double n = -right * sinR_ + up * cosR_;
  const double lon = cx_ + e / pxPerUnit_;
  const double y = cy_ + n / pxPerUnit_;
  // Divided by the radians in a degree (not radToDeg's multiplication by 180 / pi): the same
  // arithmetic as ever, so picks and visible bounds keep their last bits.
  constexpr double kRadPerDeg = degToRad(1.0);
  return {(2.0 * std::atan(std::exp(y)) - kPi / 2.0) / kRadPerDeg, lon / kRadPerDeg};
}

double Viewport::metresPerPixel() const {
  return scale_ * pixelSizeM_;
}

Bounds Viewport::visibleBounds() const {
  Bounds b;
  for (const ScreenPoint s : {ScreenPoint{0, 0}, ScreenPoint{static_cast<double>(width_), 0},
                              ScreenPoint{0, static_cast<double>(height_)},
                              ScreenPoint{static_cast<double>(width_), static_cast<double>(height_)}})
    b.add(toLatLon(s));
  return b;
}

}  // namespace reckoner::charts
