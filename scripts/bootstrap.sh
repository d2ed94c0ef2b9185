#!/usr/bin/env bash
# Install what is missing (Debian 12 packages), build, and run the main job or the test suite.
#
#   scripts/bootstrap.sh run    # install, build, open the ECDIS window on the embedded chart and scenario
#   scripts/bootstrap.sh test   # install, build, run the whole test suite (ctest, Qt on offscreen)
#   scripts/bootstrap.sh deps   # only install the Debian packages
#   scripts/bootstrap.sh build  # install and build
#   scripts/bootstrap.sh fuzz   # install clang and libFuzzer, build the fuzz targets (docs/robustness.md)
#   scripts/bootstrap.sh release [STEP...]  # after test, the release checks (docs/robustness.md): soak (the
#                                 # 1-hour soak), tidy, sanitizers (ASan+UBSan, TSan: CI's subsets), fuzz (a
#                                 # minute a target: CI's), sanitizers-full and fuzz-full (by hand: longer)
#
# Environment: RECKONER_PRESET (default: ci = Release with warnings as errors), RECKONER_JOBS.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$here"
action=${1:-run}
preset=${RECKONER_PRESET:-ci}
jobs=${RECKONER_JOBS:-$(nproc 2>/dev/null || echo 2)}

packages=(
  build-essential cmake ninja-build ccache pkg-config git
  libeigen3-dev libgeographiclib-dev
  qt6-base-dev qt6-charts-dev qt6-multimedia-dev libqt6opengl6-dev libxkbcommon-dev qt6-qpa-plugins
  libgdal-dev gdal-bin zlib1g-dev libbenchmark-dev libcli11-dev python3
  libpugixml-dev  # XML of the route files, RTZ and GPX (core/io/rtz.cpp, gpx.cpp; docs/routes.md)
  libsqlite3-dev  # the voyage record of live --record, an SQLite database (core/files/voyage_record.h; docs/recorder.md)
  gmt-gshhg-low  # GSHHG shorelines (LGPL data), read at run time for the world background (docs/charts.md)
  qt6-serialport-dev libqt6serialport6  # serial sources of connections/ (QSerialPort; docs/connections.md)
  gpsd  # the real gpsd that tests/connections/tst_connection_devices.cpp connects a gpsd source to
  socat  # pseudo-terminal pairs for the serial source tests (tests/connections/)
  gpsd-clients  # gpsdecode, the independent AIS oracle of tests/app/tst_ais_cli.cpp (docs/ais.md)
  gpsd  # a real gpsd reads Reckoner's NMEA output in tests/connections/tst_nmea_destination.cpp
  socat  # pseudo-terminal pairs: serial lines to and from Reckoner in the connection tests (issue 19)
  iproute2  # ip: the multicast test's network namespace with a multicast loopback (tests/connections/multicast_netns.sh)
  help2man  # the man pages of reckoner and reckoner-cli, made from their --help at build time (cmake/ReckonerPackaging.cmake)
)
# Node.js and npm run the Signal K project's NMEA 0183 parser on Reckoner's output (tests/connections/
# tst_nmea_signalk.cpp, its package pinned in tests/support/signalk/); Debian's only where no node is.
command -v node >/dev/null || packages+=(nodejs npm)

# The fuzz targets only: clang's libFuzzer runtime is in libclang-rt-14-dev, which clang merely
# recommends, so it is named.
fuzz_packages=(clang libclang-rt-14-dev)
# The release checks: clang-tidy (scripts/tidy.sh) and the sanitizer builds (clang, scripts/ci_sanitizers.sh).
release_packages=(clang-tidy "${fuzz_packages[@]}")

install_deps() {
  local missing=() p
  for p in "${packages[@]}" "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "bootstrap: installing ${missing[*]}"
  local sudo=()
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "bootstrap: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
    sudo=(sudo)
  fi
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

build() {
  cmake --preset "$preset" >/dev/null
  cmake --build --preset "$preset" -j "$jobs"
}

case "$action" in
  deps) install_deps ;;
  build) install_deps; build ;;
  run)
    install_deps; build
    if [ -n "${DISPLAY:-}" ] || [ -n "${WAYLAND_DISPLAY:-}" ] || [ -n "${QT_QPA_PLATFORM:-}" ]; then
      exec "build/$preset/app/reckoner" --scenario builtin:default --enc builtin:default --run
    fi
    # No display to open a window on: the same scenario headless, with its summary and files.
    echo "bootstrap: no display (DISPLAY/WAYLAND_DISPLAY unset); running the default scenario headless"
    "build/$preset/app/reckoner-cli" run builtin:default --out "$here/out/default"
    ;;
  test)
    install_deps; build
    QT_QPA_PLATFORM=offscreen ctest --preset "$preset" -j "$jobs"
    ;;
  fuzz)
    install_deps "${fuzz_packages[@]}"
    cmake --preset fuzz >/dev/null
    cmake --build --preset fuzz -j "$jobs"
    ;;
  release)
    # The release checks after `test`, each or all: soak (the 1-hour soak), tidy (clang-tidy on the files
    # changed since RECKONER_TIDY_BASE), sanitizers (scripts/ci_sanitizers.sh ci: the light libraries'
    # tests), fuzz (a minute for each target of the light libraries); by hand, sanitizers-full (the engine
    # and the charts too) and fuzz-full (every target). CI runs soak, sanitizers, fuzz and tidy.
    steps=("${@:2}")
    [ ${#steps[@]} -gt 0 ] || steps=(soak tidy sanitizers fuzz)
    extra=()  # clang and clang-tidy only for the steps that use them
    for step in "${steps[@]}"; do [ "$step" = soak ] || extra=("${release_packages[@]}"); done
    install_deps "${extra[@]}"
    build
    for step in "${steps[@]}"; do
      t0=$SECONDS
      case "$step" in
        soak) "build/$preset/tests/reckoner-soak" --hours 1 --out "$here/out/soak" ;;
        tidy) RECKONER_BUILD_DIR="build/$preset" scripts/tidy.sh --base "${RECKONER_TIDY_BASE:-HEAD~1}" ;;
        sanitizers) RECKONER_JOBS=$jobs scripts/ci_sanitizers.sh ci ;;
        sanitizers-full) RECKONER_JOBS=$jobs scripts/ci_sanitizers.sh full ;;
        fuzz) scripts/fuzz_smoke.sh 60 ais line_framer route nmea ;;
        fuzz-full) scripts/fuzz_smoke.sh 60 ;;
        *) echo "bootstrap: unknown release step $step (soak, tidy, sanitizers, fuzz, sanitizers-full, fuzz-full)" >&2
           exit 2 ;;
      esac
      echo "bootstrap: release step $step took $((SECONDS - t0)) s"
    done
    ;;
  *) echo "usage: scripts/bootstrap.sh run|test|deps|build|fuzz|release" >&2; exit 2 ;;
esac
