#include "ui/bridge/radar_raster.h"

#include <algorithm>
#include <cmath>

#include "common/angles.h"

namespace reckoner::ui {

RadarRaster rasteriseRadarPicture(const radar::PolarImage& image, const radar::SweepPose& pose, double tS) {
  RadarRaster out;
  const int A = image.azimuths, R = image.rangeBins;
  if (A <= 0 || R <= 0 || !(image.binM > 0.0) ||
      image.bins.size() != static_cast<std::size_t>(A) * static_cast<std::size_t>(R))
    return out;
  const double m = image.binM;
  const int n = 2 * R + 8;  // the picture's diameter plus a margin for the ship's motion in the sweep
  out.tS = tS;
  out.metresPerPixel = m;
  const est::Vec<2> centre = pose.positionAt(pose.periodS);
  if (!centre.allFinite()) return out;
  out.centreX = centre[0];
  out.centreY = centre[1];
  out.mask = QImage(n, n, QImage::Format_Alpha8);
  out.mask.fill(0);
  const double half = 0.5 * n * m;
  const double azStep = kTwoPi / A;
  for (int a = 0; a < A; ++a) {
    const std::uint8_t* row = &image.bins[static_cast<std::size_t>(a) * static_cast<std::size_t>(R)];
    const double az = (a + 0.5) * azStep;
    const double dt = pose.timeOffsetS(az);
    const est::Vec<2> o = pose.positionAt(dt) - centre;
    const double th = pose.headingAt(dt) + az;
    for (int r = 0; r < R; ++r) {
      if (!row[r]) continue;
      const double range = (r + 0.5) * m;
      // Cover the bin: its arc (range times the azimuth step) and its depth (one bin), sampled at
      // under a pixel.
      const int along = std::max(1, static_cast<int>(std::ceil(range * azStep / m)) + 1);
      for (int k = 0; k < along; ++k) {
        const double t = th + azStep * ((k + 0.5) / along - 0.5);
        const double s = std::sin(t), c = std::cos(t);
        for (const double dr : {-0.25 * m, 0.25 * m}) {
          const double x = o[0] + (range + dr) * s, y = o[1] + (range + dr) * c;
          const int px = static_cast<int>(std::floor((x + half) / m));
          const int py = static_cast<int>(std::floor((half - y) / m));
          if (px < 0 || py < 0 || px >= n || py >= n) continue;
          out.mask.scanLine(py)[px] = 255;
        }
      }
    }
  }
  return out;
}

}  // namespace reckoner::ui
