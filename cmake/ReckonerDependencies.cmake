# Every dependency is a Debian 12 package (scripts/bootstrap.sh installs them).
find_package(Eigen3 3.4 REQUIRED NO_MODULE)

# Debian ships GeographicLib's Find module only, outside CMake's default module path.
list(APPEND CMAKE_MODULE_PATH /usr/share/cmake/geographiclib)
find_package(GeographicLib REQUIRED)
if(NOT TARGET reckoner::GeographicLib)
  add_library(reckoner::GeographicLib INTERFACE IMPORTED)
  set_target_properties(reckoner::GeographicLib PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${GeographicLib_INCLUDE_DIRS}"
    INTERFACE_SYSTEM_INCLUDE_DIRECTORIES "${GeographicLib_INCLUDE_DIRS}"
    INTERFACE_LINK_LIBRARIES "${GeographicLib_LIBRARIES}")
endif()

if(RECKONER_FUZZ)  # core/ and the S-57 loader: GDAL, no Qt
  find_package(GDAL 3.6 REQUIRED)
  return()
endif()

# Widgets, Charts and GDAL are for ui/ and charts/; finding them already makes every configure prove
# that the bootstrap installs them (Debian's Qt6 Charts also needs libqt6opengl6-dev and
# libxkbcommon-dev, a known trap).
find_package(Qt6 6.4 REQUIRED COMPONENTS Core Gui Widgets Charts Test)
# The live connections (connections/): sockets and serial ports (Debian qt6-base-dev, qt6-serialport-dev).
find_package(Qt6 6.4 REQUIRED COMPONENTS Network SerialPort)
# The alerts' audible signal (ui/panels/alert_sound.cpp): Qt Multimedia where it is installed (the
# bootstrap installs Debian's qt6-multimedia-dev); without it the window is silent.
find_package(Qt6 6.4 QUIET COMPONENTS Multimedia)
find_package(GDAL 3.6 REQUIRED)
# reckoner-cli's command line (header-only; Debian's libcli11-dev).
find_package(CLI11 CONFIG REQUIRED)

if(RECKONER_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()
