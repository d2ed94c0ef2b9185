#pragma once
// Seed 004's radar image and its echo points (docs/radar_matching.md).
// - simulateRadarImage: one sweep as a binary polar image (azimuth relative to the heading x range
//   bins), cast against the chart contours (the first contour a beam meets, then the land behind it
//   for landDepthM, and nothing behind: shadow) and against targets (discs), smeared by the beam width
//   and the pulse length, with receiver noise and sea clutter. The ship moves during the sweep: each
//   azimuth is taken at its own time and pose.
// - extractEchoes: the paper's preprocessing. Segment the binary image into radar objects (connected
//   echo areas), drop small ones, take each object's front contour (its nearest bin at each azimuth)
//   and aggregate neighbouring contour points into about `targetPoints` echo points.
#include <cstdint>
#include <vector>

#include "common/angles.h"
#include "common/rng.h"
#include "common/time.h"
#include "estimation/gaussian.h"
#include "radar/coastline.h"

namespace reckoner::radar {

/// Own ship during a sweep: position and heading at the sweep's start, moving with constant velocity
/// and turn rate (grid frame; heading clockwise from grid north).
struct SweepPose {
  TimeUs startUs = 0;
  double periodS = 2.5;
  est::Vec<2> position = est::Vec<2>::Zero();
  est::Vec<2> velocity = est::Vec<2>::Zero();
  double headingRad = 0.0;
  double turnRateRadPerS = 0.0;
  /// Time, position and heading when the beam points at relative azimuth az (in [0, 2 pi)).
  [[nodiscard]] double timeOffsetS(double azRad) const;
  [[nodiscard]] est::Vec<2> positionAt(double dtS) const { return position + velocity * dtS; }
  [[nodiscard]] double headingAt(double dtS) const { return headingRad + turnRateRadPerS * dtS; }
};

struct RadarImageParams {
  int azimuths = 4096;
  int rangeBins = 1024;
  double maxRangeM = 6000.0;
  double beamWidthRad = degToRad(1.0);     ///< 1 deg (horizontal, between half-power points)
  double pulseLengthM = 15.0;              ///< echo extent in range
  double rangeSdM = 10.0;                  ///< error of an echo's range
  double bearingSdRad = 0.00872664625997;  ///< 0.5 deg: error of an echo's bearing
  double landDepthM = 150.0;               ///< land echoes this far behind the contour
  double noiseProbability = 2e-4;          ///< receiver noise: any bin lit at random
  double clutterProbability = 0.05;        ///< sea clutter at zero range, falling off ...
  double clutterScaleM = 400.0;            ///< ... exponentially with this scale
  [[nodiscard]] double binM() const { return maxRangeM / rangeBins; }
  [[nodiscard]] double azStepRad() const;
};

/// What lit a bin. A radar's own picture has only None and Echo; the simulator also says which bins
/// its targets and its noise and clutter lit, for scoring the matching (never given to it).
enum class BinSource : std::uint8_t { None = 0, Echo = 1, Target = 2, Noise = 3 };

struct PolarImage {
  int azimuths = 0, rangeBins = 0;
  double binM = 0.0;
  /// azimuth-major: bins[az * rangeBins + r], a BinSource (non-zero: an echo)
  std::vector<std::uint8_t> bins;
  [[nodiscard]] bool at(int az, int r) const {
    return bins[static_cast<std::size_t>(az) * static_cast<std::size_t>(rangeBins) +
                static_cast<std::size_t>(r)] != 0;
  }
};

struct RadarTarget {
  est::Vec<2> position;  ///< grid, at the sweep (targets are slow against a sweep)
  double radiusM = 30.0;
};

PolarImage simulateRadarImage(const Coastline& coast, const std::vector<RadarTarget>& targets,
                              const SweepPose& pose, const RadarImageParams& params, Rng& rng);

struct EchoPoint {
  double rangeM = 0.0;
  double azimuthRad = 0.0;             ///< relative to the heading, [0, 2 pi)
  int object = 0;                      ///< index of its radar object
  int area = 0;                        ///< the object's area in bins
  BinSource source = BinSource::Echo;  ///< what lit most of its contour's bins (simulated pictures)
};

struct EchoExtractionParams {
  int minObjectArea = 12;  ///< smaller objects are noise
  /// A run shorter than this (in bins) is no front: an echo lasts at least a pulse, so a single lit
  /// bin is receiver noise or a clutter spike, also where it touches the land in front of it.
  int minFrontRunBins = 2;
  int targetPoints = 200;  ///< about this many echo points per image
};

std::vector<EchoPoint> extractEchoes(const PolarImage& image, double azStepRad,
                                     const EchoExtractionParams& params);

}  // namespace reckoner::radar
