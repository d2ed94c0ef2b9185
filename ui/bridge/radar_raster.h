#pragma once
// One sweep's radar picture (seed 004's polar image) as a north-up raster for the chart overlay. Each
// lit bin is drawn where the radar puts it: from own ship's estimated pose at the moment the beam
// pointed at it (position and heading moving through the sweep), at its range and relative azimuth.
// One pixel per range bin; a bin is drawn over as many pixels as its arc and depth cover, so distant
// echoes are not dotted. An alpha mask: the display colours it.
#include <QImage>

#include "radar/radar_image.h"

namespace reckoner::ui {

struct RadarRaster {
  double tS = 0.0;
  QImage mask;                          ///< Format_Alpha8, 255 where an echo is drawn
  double centreX = 0.0, centreY = 0.0;  ///< grid m of the image's centre (own ship at the sweep's end)
  double metresPerPixel = 0.0;
  [[nodiscard]] bool isNull() const { return mask.isNull(); }
};

/// Throws nothing; an empty or inconsistent picture gives a null raster.
RadarRaster rasteriseRadarPicture(const radar::PolarImage& image, const radar::SweepPose& estimatedPose,
                                  double tS);

}  // namespace reckoner::ui
