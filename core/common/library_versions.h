#pragma once
// The versions of the libraries core/ is built with, from their headers (for the About box and
// `reckoner-cli --version`).
#include <GeographicLib/Config.h>
#include <Eigen/Core>
#include <string>

namespace reckoner {

inline std::string eigenVersion() {
  return std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) + "." +
         std::to_string(EIGEN_MINOR_VERSION);
}

inline std::string geographicLibVersion() {
  return GEOGRAPHICLIB_VERSION_STRING;
}

}  // namespace reckoner
