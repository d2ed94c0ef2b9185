#!/usr/bin/env bash
# scripts/fuzz_smoke.sh [SECONDS [TARGET...]]: the short fuzz run (docs/robustness.md, "Fuzzing"). Builds
# the preset fuzz (clang and libclang-rt-14-dev must be installed: scripts/bootstrap.sh's fuzz packages;
# this script installs nothing), then runs every fuzz target (or the TARGETs named, without fuzz_; CI
# names those of the light libraries) for SECONDS (default 60) each, two at a
# time, under nice, from the committed seeds (tests/fuzz/corpus/<name>/, and the project's own files of
# the format) with the target's dictionary (tests/fuzz/dict/), each in a scratch folder under
# $FUZZ_WORK (default /tmp/fz/smoke). Fails when any target reports a crash, a leak, a timeout, a
# sanitizer report or a failed check; its log and the input that did it are left in the scratch folder.
set -uo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
chosen=("${@:2}")
work=${FUZZ_WORK:-/tmp/fz/smoke}
build=$root/build/fuzz
bin=$build/tests/fuzz
start=$(date +%s)

cd "$root"
cmake --preset fuzz >/dev/null || exit 1

# name  max_len  dictionary  extra seed folders (the project's own files of the format)
targets=(
  "ais 4096 ais"
  "line_framer 4096 ais"
  "route 16384 route tests/core/io/routes"
  "operator_action 512 -"
  "nmea 1024 nmea"
  "nmea_epochs 8192 nmea"
  "radar_csv 4096 radar_csv"
  "scenario 16384 scenario resources/scenarios"
  "voyage_record 65536 -"
  "s57 65536 s57"
)

if [ ${#chosen[@]} -gt 0 ]; then
  picked=()
  build_targets=()
  for c in "${chosen[@]}"; do
    found=
    for t in "${targets[@]}"; do
      [ "${t%% *}" = "$c" ] && { picked+=("$t"); found=1; }
    done
    [ -n "$found" ] || { echo "fuzz_smoke: no fuzz target $c" >&2; exit 2; }
    build_targets+=("fuzz_$c")
    [ "$c" = ais ] && build_targets+=(ais_seeds)
    [ "$c" = s57 ] && build_targets+=(s57_seeds)
    [ "$c" = voyage_record ] && build_targets+=(voyage_seeds)
  done
  targets=("${picked[@]}")
  nice -n 10 cmake --build --preset fuzz -j2 --target "${build_targets[@]}" || exit 1
else
  nice -n 10 cmake --build --preset fuzz -j2 || exit 1
fi

rm -rf "$work"
mkdir -p "$work"

run() {
  local name=$1 maxlen=$2 dict=$3
  shift 3
  local dir=$work/$name
  mkdir -p "$dir/corpus"
  local args=(-max_total_time="$seconds" -max_len="$maxlen" -timeout=30 -rss_limit_mb=2048
              -print_final_stats=1 -artifact_prefix="$dir/")
  [ "$dict" != "-" ] && args+=(-dict="$root/tests/fuzz/dict/$dict.dict")
  local seeds=()
  [ -d "$root/tests/fuzz/corpus/$name" ] && seeds+=("$root/tests/fuzz/corpus/$name")
  for extra in "$@"; do seeds+=("$root/$extra"); done
  # The binary seeds' writers (voyage_seeds, s57_seeds) write them afresh as well: cheap, and always
  # of this build's schema.
  if [ -x "$bin/${name%_record}_seeds" ] || [ -x "$bin/${name}_seeds" ]; then
    local writer=$bin/${name}_seeds
    [ -x "$writer" ] || writer=$bin/${name%_record}_seeds
    mkdir -p "$dir/written" && "$writer" "$dir/written" >/dev/null && seeds+=("$dir/written")
  fi
  nice -n 10 "$bin/fuzz_$name" "${args[@]}" "$dir/corpus" "${seeds[@]}" >"$dir/log" 2>&1
  echo $? >"$dir/status"
}

running=0
for t in "${targets[@]}"; do
  # shellcheck disable=SC2086
  run $t &
  running=$((running + 1))
  if [ "$running" -ge 2 ]; then
    wait -n
    running=$((running - 1))
  fi
done
wait

failed=0
for t in "${targets[@]}"; do
  name=${t%% *}
  dir=$work/$name
  status=$(cat "$dir/status" 2>/dev/null || echo 1)
  runs=$(grep -o 'stat::number_of_executed_units: [0-9]*' "$dir/log" | grep -o '[0-9]*$' || true)
  if [ "$status" != 0 ] || grep -qE 'ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error:|SUMMARY: ' "$dir/log"; then
    echo "FAIL fuzz_$name (exit $status): see $dir/log"
    grep -E 'ERROR:|runtime error:|SUMMARY:|Test unit written' "$dir/log" | head -5
    failed=1
  else
    echo "ok   fuzz_$name: ${runs:-?} executions in ${seconds} s, corpus $(find "$dir/corpus" -type f | wc -l) new inputs"
  fi
done
echo "fuzz_smoke: $(($(date +%s) - start)) s wall time"
exit $failed
