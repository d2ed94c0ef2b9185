#!/usr/bin/env bash
# The sanitizer jobs of CI (docs/robustness.md, "Sanitizers"): configure, build only the tests of the
# subset, run them; any sanitizer report fails the test and so the job.
#
#   scripts/ci_sanitizers.sh [ci|full|asan|tsan|asan-full|tsan-full]   # default: ci
#
#   ci         asan and tsan: what CI runs (the light libraries; a cold build inside CI's budget)
#   full       asan-full and tsan-full: the release run by hand (the engine too; longer than CI allows)
#   asan       preset asan-ci, label "asan": the light libraries' tests under ASan+UBSan (and LeakSanitizer)
#   tsan       preset tsan, label "tsan": the Monte Carlo pool with the light libraries on four threads
#   asan-full  preset asan-ci, label "asan-full": every core test and the chart tests
#   tsan-full  preset tsan, label "tsan-full": the pool and tst_simulation_engine (not the Qt threads: docs)
#
# The sanitizer options (fatal reports, the suppression files of tests/sanitizers/) are the test presets'
# environment in CMakePresets.json, so `ctest --preset asan-ci -L asan` by hand runs the same way.
# Environment: RECKONER_JOBS (default: nproc).
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$here"
what=${1:-ci}
jobs=${RECKONER_JOBS:-$(nproc 2>/dev/null || echo 2)}

# The same options as the test presets' environment, for the programs the build runs (reckoner-chartgen
# writes the embedded chart through GDAL) and for any test started outside ctest.
supp=$here/tests/sanitizers
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:halt_on_error=1:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1
export LSAN_OPTIONS=suppressions=$supp/lsan.supp:print_suppressions=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1:suppressions=$supp/tsan.supp:print_suppressions=0

# One job: configure the preset, build the test executables carrying the label (their names are their
# targets), run them.
job() {
  local preset=$1 label=$2 start=$SECONDS
  echo "ci_sanitizers: $preset (label $label)"
  cmake --preset "$preset" >/dev/null
  local tests=()
  mapfile -t tests < <(ctest --preset "$preset" -N -L "^$label\$" | sed -n 's/^ *Test *#[0-9]*: *//p')
  [ ${#tests[@]} -gt 0 ] || { echo "ci_sanitizers: no test labelled $label" >&2; exit 1; }
  nice cmake --build --preset "$preset" -j "$jobs" --target "${tests[@]}"
  local built=$SECONDS
  ctest --preset "$preset" -L "^$label\$" -j "$jobs"
  echo "ci_sanitizers: $preset: ${#tests[@]} tests, build $((built - start)) s, run $((SECONDS - built)) s"
}

case "$what" in
  asan) job asan-ci asan ;;
  tsan) job tsan tsan ;;
  asan-full) job asan-ci asan-full ;;
  tsan-full) job tsan tsan-full ;;
  ci) job asan-ci asan; job tsan tsan ;;
  full) job asan-ci asan-full; job tsan tsan-full ;;
  *) echo "usage: scripts/ci_sanitizers.sh [ci|full|asan|tsan|asan-full|tsan-full]" >&2; exit 2 ;;
esac
