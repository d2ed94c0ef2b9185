# The programs' version from `git describe`, refreshed at every build (docs/packaging.md, "Version").
#
# The target reckoner_version (an interface library) gives its users the generated header
# reckoner_version.h (RECKONER_VERSION, RECKONER_GIT_DESCRIBE). The header is written by
# cmake/WriteVersion.cmake from a custom target that runs at every build, so a new commit changes the
# version without reconfiguring; the header's text only changes when the version does, so only the few
# files that include it recompile, and only then.
set(RECKONER_GENERATED_DIR ${PROJECT_BINARY_DIR}/generated)
find_program(RECKONER_GIT git)
add_custom_target(reckoner_version_header ALL
  COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DOUTPUT_DIR=${RECKONER_GENERATED_DIR}
          -DPROJECT_VERSION=${PROJECT_VERSION} -DGIT=${RECKONER_GIT}
          -P ${PROJECT_SOURCE_DIR}/cmake/WriteVersion.cmake
  BYPRODUCTS ${RECKONER_GENERATED_DIR}/reckoner_version.h ${RECKONER_GENERATED_DIR}/reckoner_version.cmake
  COMMENT "Version from git describe"
  VERBATIM)
add_library(reckoner_version INTERFACE)
target_include_directories(reckoner_version INTERFACE ${RECKONER_GENERATED_DIR})
add_dependencies(reckoner_version reckoner_version_header)
