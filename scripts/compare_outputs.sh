#!/usr/bin/env bash
# Runs every built-in scenario through two builds of reckoner-cli and compares what they write, byte for
# byte: `run` (ownship.csv, targets.csv) and `montecarlo --runs 3` (montecarlo.csv), and summary.json with
# its wall-clock fields removed. Use it to show that a change leaves every output as it was, or which
# outputs it changes.
#
#   scripts/compare_outputs.sh OLD_CLI NEW_CLI [WORK_DIR]
#
# Exit code 0 when everything is identical, 1 when something differs (listed), 2 on bad usage.
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: scripts/compare_outputs.sh OLD_CLI NEW_CLI [WORK_DIR]" >&2; exit 2; }
old=$1 new=$2
work=${3:-$(mktemp -d)}
mkdir -p "$work"
scenarios=$("$new" scenarios | awk '{print $1}')
strip() { sed -E '/"wall_time_s"|"wall_s"|"threads"/d' "$1"; }
same=0 differ=0
for s in $scenarios; do
  name=${s#builtin:}
  for kind in run montecarlo; do
    args=("$kind" "$s" --quiet)
    [ "$kind" = montecarlo ] && args+=(--runs 3 --threads 1)
    for side in old new; do
      cli=$old; [ "$side" = new ] && cli=$new
      rm -rf "$work/$side/$kind/$name"
      mkdir -p "$work/$side/$kind"
      "$cli" "${args[@]}" --out "$work/$side/$kind/$name" >/dev/null 2>"$work/$side/$kind.$name.err" ||
        echo "$side $kind $name: exit $? ($(head -c 200 "$work/$side/$kind.$name.err"))" >&2
    done
    for f in "$work/new/$kind/$name"/*; do
      [ -e "$f" ] || continue
      b=$(basename "$f")
      o="$work/old/$kind/$name/$b"
      if [ "$b" = summary.json ]; then
        if cmp -s <(strip "$o") <(strip "$f"); then same=$((same + 1)); else differ=$((differ + 1)); echo "differs: $kind $name $b"; fi
      elif cmp -s "$o" "$f"; then
        same=$((same + 1))
      else
        differ=$((differ + 1)); echo "differs: $kind $name $b"
      fi
    done
  done
done
echo "compare_outputs: $same files identical, $differ differ (in $work)"
[ "$differ" -eq 0 ]
