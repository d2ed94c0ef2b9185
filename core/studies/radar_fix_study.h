#pragma once
// Seed 004's GPS-outage study (docs/radar_matching.md): Monte Carlo runs of a scenario by dead
// reckoning alone, or with the radar picture matched to the chart and fed to the DRKF, scored without
// GPS. The fixes are scored too, against the truth less what the error of the motion they were placed
// with explains (RadarFixReport::motionSensitivity): that part is the DRKF's, which the fix's model
// carries, so the fix's own covariance is checked on what it claims.
#include <cstdint>
#include <memory>

#include "radar/coastline.h"
#include "radar/land_mask.h"
#include "sim/scenario.h"
#include "sim/simulation_engine.h"

namespace reckoner::studies {

struct RadarFixStudy {
  int runs = 0;
  long rows = 0;  ///< cycles without GPS (after the first minute), all runs
  double positionP95M = 0.0, positionRmsM = 0.0;
  double headingP95Deg = 0.0;  ///< the DRKF's heading (the direction of its velocity through the water)
  double meanNees = 0.0;       ///< the DRKF's, 11 dof
  long pictures = 0, applied = 0;
  double echoesPerPicture = 0.0, matchedPerPicture = 0.0;
  /// Echo points from vessels and from clutter or noise (scored from the truth), and how many of them
  /// the matching used.
  long vesselEchoes = 0, clutterEchoes = 0, spuriousUsed = 0;
  [[nodiscard]] double spuriousRejectedFraction() const {
    const long n = vesselEchoes + clutterEchoes;
    return n > 0 ? 1.0 - static_cast<double>(spuriousUsed) / static_cast<double>(n) : 1.0;
  }
  /// The fixes the DRKF was given (informative ones), against the truth at their time.
  long fixes = 0;
  double fixPositionP95M = 0.0, fixHeadingP95Deg = 0.0;
  double fixNees = 0.0, fixPositionNees = 0.0, fixHeadingNees = 0.0;  ///< 3, 2 and 1 dof
};

/// `runs` runs (seeds seed, seed + 1, ...) on `threads` threads, with radar matching on or off.
RadarFixStudy runRadarFixStudy(const sim::Scenario& scenario, std::shared_ptr<const radar::Coastline> coast,
                               std::shared_ptr<const radar::LandMask> land, bool matching, int runs,
                               int threads, std::uint64_t seed);

}  // namespace reckoner::studies
