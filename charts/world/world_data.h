#pragma once
// Where the world background's shorelines come from and which of them a view uses: GSHHG's binned
// files of Debian's gmt-gshhg-low, read at run time from the installed package (never copied into
// the repository), each loaded once per process at its first use and kept.
#include <memory>
#include <string>

#include "charts/world/gshhg.h"

namespace reckoner::charts::world {

/// The folder of the GSHHG files: $RECKONER_GSHHG_DIR when set and not empty, else /usr/share/gmt-gshhg.
std::string gshhgDirectory();
/// The file of one resolution in gshhgDirectory(): ".../binned_GSHHS_c.nc".
std::string gshhgPath(ShoreResolution r);

/// The resolution for a view of `metresPerPixel` ground metres per pixel: the coarsest whose
/// simplification tolerance (25 km crude, 5 km low, 1 km intermediate) stays within about 12 pixels:
/// crude above 2 000 m/px (1:7 100 000 at 0.28 mm pixels), low above 400 m/px (1:1 430 000),
/// intermediate closer.
ShoreResolution resolutionFor(double metresPerPixel);

struct WorldData {
  /// The shoreline drawn: the wanted resolution, or the nearest one that could be read; null when none.
  std::shared_ptr<const Shoreline> shoreline;
  /// Why the wanted resolution is not drawn, naming the file ("/usr/share/gmt-gshhg/binned_GSHHS_c.nc:
  /// no such file (install Debian's gmt-gshhg-low)"); empty when it is.
  std::string problem;
};

/// The shoreline for a view wanting `wanted`. Each file is read once per process, at its first use
/// (the caller's thread, a render worker's; thread-safe) and kept; a file that cannot be read is
/// logged once (qWarning) with its problem and not tried again. Falls back to the other resolutions,
/// coarser first.
WorldData worldShoreline(ShoreResolution wanted);

}  // namespace reckoner::charts::world
