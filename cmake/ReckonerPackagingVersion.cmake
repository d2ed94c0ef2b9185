# Read by cpack when it runs (CPACK_PROJECT_CONFIG_FILE of cmake/ReckonerPackaging.cmake): the package
# takes the version the build wrote (cmake/WriteVersion.cmake), the same the programs' --version print.
if(NOT EXISTS "${CPACK_RECKONER_VERSION_FILE}")
  message(FATAL_ERROR "${CPACK_RECKONER_VERSION_FILE} is missing: build before packaging")
endif()
include("${CPACK_RECKONER_VERSION_FILE}")
set(CPACK_PACKAGE_VERSION "${RECKONER_BUILD_VERSION}")
set(CPACK_DEBIAN_PACKAGE_VERSION "${RECKONER_BUILD_VERSION}")
