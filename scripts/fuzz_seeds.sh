#!/usr/bin/env bash
# scripts/fuzz_seeds.sh OUT [BUILD]: the seed corpora of the fuzz targets (docs/robustness.md,
# "Fuzzing"), gathered at run time into OUT/<name>/ (a scratch folder; nothing here is committed):
#   - the committed seeds, tests/fuzz/corpus/<name>/, and the project's own files of each format
#     (resources/scenarios/*.json, tests/core/io/routes/*, the default chart RK5SOUND.000 from BUILD);
#   - when ../shared is beside the repository, a sample of the real third-party data there: pieces of
#     the NMEA recordings and of the AIS sample, and the small files of the NOAA ENC exchange sets
#     (updates and catalogues; the base cells are larger than a fuzzer's -max_len). They are read from
#     ../shared at run time only, never copied into the repository (../shared/data/*/NOTICE.md).
# BUILD is the fuzz build (default build/fuzz). A run reads OUT/<name> as its second corpus folder.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:?usage: scripts/fuzz_seeds.sh OUT [BUILD]}
build=${2:-$root/build/fuzz}
shared=$root/../shared/data

names="ais line_framer route operator_action nmea nmea_epochs radar_csv scenario voyage_record s57"
for n in $names; do
  mkdir -p "$out/$n"
  [ -d "$root/tests/fuzz/corpus/$n" ] && cp "$root/tests/fuzz/corpus/$n"/* "$out/$n/"
done

# The project's own files of each format.
cp "$root"/resources/scenarios/*.json "$out/scenario/"
cp "$root"/tests/core/io/routes/* "$out/route/"
chart=$build/resources/charts/RK5SOUND/RK5SOUND.000
[ -f "$chart" ] && cp "$chart" "$out/s57/RK5SOUND.000"

# pieces LINES PREFIX FILE DIR: the file cut into pieces of LINES lines, at most 12 of them, spread over it.
pieces() {
  local lines=$1 prefix=$2 file=$3 dir=$4
  local total step k=0
  total=$(wc -l <"$file")
  step=$(( total / 12 > lines ? total / 12 : lines ))
  for ((start = 1; start <= total && k < 12; start += step, k++)); do
    sed -n "${start},$((start + lines - 1))p" "$file" >"$dir/${prefix}_$k"
  done
}

if [ -d "$shared" ]; then
  for f in "$shared"/nmea/*.log "$shared"/nmea/*.nmea; do
    [ -f "$f" ] || continue
    base=$(basename "$f" | tr -c 'A-Za-z0-9_\n' '_')
    pieces 12 "shared_$base" "$f" "$out/nmea"
    pieces 200 "shared_$base" "$f" "$out/nmea_epochs"
    pieces 40 "shared_$base" "$f" "$out/line_framer"
  done
  for f in "$shared"/ais/*.aivdm; do
    [ -f "$f" ] || continue
    pieces 30 "shared_$(basename "$f" .aivdm)" "$f" "$out/ais"
  done
  for f in "$shared"/enc/*/*.00[1-9] "$shared"/enc/*/CATALOG.031; do
    [ -f "$f" ] || continue
    cp "$f" "$out/s57/shared_$(basename "$(dirname "$f")")_$(basename "$f")"
  done
else
  echo "fuzz_seeds: no ../shared/data beside the repository: the project's own seeds only" >&2
fi
for n in $names; do
  printf '%-16s %4d files %8d bytes\n' "$n" "$(find "$out/$n" -type f | wc -l)" "$(cat "$out/$n"/* 2>/dev/null | wc -c)"
done
