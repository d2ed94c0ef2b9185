// The GSHHG files found, chosen per view and loaded once per process (world_data.h).
#include "charts/world/world_data.h"

#include <QtGlobal>

#include <cstdlib>
#include <map>
#include <mutex>
#include <stdexcept>

namespace reckoner::charts::world {
namespace {

struct Entry {
  std::shared_ptr<const Shoreline> shoreline;
  std::string problem;
};

/// The file at `path`, loaded at its first request; later requests share it (or its problem).
Entry entryFor(ShoreResolution r) {
  static std::mutex mutex;
  static std::map<std::string, Entry> loaded;
  const std::string path = gshhgPath(r);
  const std::lock_guard lock(mutex);
  if (const auto it = loaded.find(path); it != loaded.end()) return it->second;
  Entry e;
  try {
    e.shoreline = std::make_shared<const Shoreline>(loadGshhg(path, r));
  } catch (const std::exception& err) {
    e.problem = err.what();
    if (e.problem.find("no such file") != std::string::npos) e.problem += " (install Debian's gmt-gshhg-low)";
    qWarning("world background: %s", e.problem.c_str());
  }
  return loaded.emplace(path, std::move(e)).first->second;
}

}  // namespace

std::string gshhgDirectory() {
  // getenv races only setenv, and nothing sets the environment once threads run (the CLI's qputenv
  // comes before the application starts).
  const char* dir = std::getenv("RECKONER_GSHHG_DIR");  // NOLINT(concurrency-mt-unsafe)
  return dir && *dir ? std::string(dir) : std::string("/usr/share/gmt-gshhg");
}

std::string gshhgPath(ShoreResolution r) {
  std::string path = gshhgDirectory();
  path.append("/binned_GSHHS_").push_back(resolutionLetter(r));
  path.append(".nc");
  return path;
}

ShoreResolution resolutionFor(double metresPerPixel) {
  if (metresPerPixel > 2000.0) return ShoreResolution::Crude;
  if (metresPerPixel > 400.0) return ShoreResolution::Low;
  return ShoreResolution::Intermediate;
}

WorldData worldShoreline(ShoreResolution wanted) {
  WorldData d;
  const Entry first = entryFor(wanted);
  d.shoreline = first.shoreline;
  d.problem = first.problem;
  // The nearest coarser ones first (smaller and quicker to draw), then the finer ones.
  const int w = static_cast<int>(wanted);
  for (int step = 1; step <= 2 && !d.shoreline; ++step)
    for (const int r : {w - step, w + step})
      if (r >= 0 && r <= static_cast<int>(ShoreResolution::Intermediate) && !d.shoreline)
        d.shoreline = entryFor(static_cast<ShoreResolution>(r)).shoreline;
  return d;
}

}  // namespace reckoner::charts::world
