#pragma once
// The local metric frame: the UTM grid of the zone that holds the origin (transverse Mercator, WGS-84,
// k0 = 0.9996, GeographicLib's Krueger series), shifted so that the origin is (0, 0); x east, y north.
// The grid differs from true directions by the meridian convergence and from true lengths by the
// point scale; gridInfo() gives both so sensors that report true quantities can be converted.

namespace reckoner::geo {

struct GeoPoint {
  double latDeg = 0.0;  ///< WGS-84 latitude, degrees, [-90, 90]
  double lonDeg = 0.0;  ///< WGS-84 longitude, degrees, [-180, 180)
};

struct GridPoint {
  double xM = 0.0;  ///< grid easting relative to the origin, metres
  double yM = 0.0;  ///< grid northing relative to the origin, metres
};

struct GridInfo {
  /// Bearing of grid north clockwise from true north, radians. true bearing = grid bearing + this.
  double convergenceRad = 0.0;
  /// Point scale: grid length / true length (about 0.9996 to 1.0010 within a UTM zone).
  double scale = 1.0;
};

class LocalFrame {
 public:
  /// Origin latitude must lie in [-80, 84] (the UTM band); throws std::invalid_argument otherwise,
  /// or for a non-finite or out-of-range longitude.
  LocalFrame(double originLatDeg, double originLonDeg);

  /// Grid coordinates of a geodetic point. Returns NaN coordinates for non-finite input or for a
  /// point so far from the zone's central meridian that the projection is invalid (> 35 deg).
  [[nodiscard]] GridPoint toLocal(const GeoPoint& p) const;
  /// Geodetic coordinates of a grid point; NaN for non-finite input.
  [[nodiscard]] GeoPoint toGeodetic(const GridPoint& p) const;
  /// Convergence and scale at a grid point; {NaN, NaN} for non-finite input.
  [[nodiscard]] GridInfo gridInfo(const GridPoint& p) const;

  [[nodiscard]] GeoPoint origin() const { return origin_; }
  [[nodiscard]] int utmZone() const { return zone_; }
  [[nodiscard]] double centralMeridianDeg() const { return lon0Deg_; }

 private:
  GeoPoint origin_;
  int zone_ = 0;
  double lon0Deg_ = 0.0;
  double x0M_ = 0.0;  // transverse Mercator coordinates of the origin (no false easting/northing)
  double y0M_ = 0.0;
};

}  // namespace reckoner::geo
