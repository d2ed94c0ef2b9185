#!/usr/bin/env bash
# clang-tidy with the repository's .clang-tidy (bugprone-*, performance-*, concurrency-* and no function
# over 80 lines, every finding an error; the checks left out, and why, are listed there) on the C++ of
# app/, core/, charts/, connections/, ui/, resources/ and tests/.
#
#   scripts/tidy.sh [--base REV] [-j N]   the .cpp and .h files changed against REV (default: where the
#                                         branch left origin/main or main; on main, HEAD~1); what CI runs
#   scripts/tidy.sh --all [-j N]          every source of those directories in the build's database
#   scripts/tidy.sh [-j N] FILE...        the files given
#
# A .cpp is checked with its own compile command, and the project headers it includes with it
# (HeaderFilterRegex). A changed .h is also checked on its own, with the flags clang-tidy takes from the
# nearest source in the database (same name or same directory), so a header no changed .cpp includes is
# still covered. Sources not in the database are skipped with a note: tests/fuzz (built only by the fuzz
# preset) and tests/core/estimation/model_concepts/probe.cpp (compiled by ctest to fail on purpose).
#
# Needs a configured build with compile_commands.json (build/ci, or RECKONER_BUILD_DIR) whose Qt autogen
# headers exist (build it once). N parallel clang-tidy processes (default 2). Exit 1 on any finding, 2 on a
# setup error.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$here"
build=${RECKONER_BUILD_DIR:-build/ci}
db="$build/compile_commands.json"
base=""
all=0
jobs=2
while [ $# -gt 0 ]; do
  case "$1" in
    --base) base=$2; shift 2 ;;
    --all) all=1; shift ;;
    -j) jobs=$2; shift 2 ;;
    -j*) jobs=${1#-j}; shift ;;
    *) break ;;
  esac
done
[ -f "$db" ] || { echo "tidy: no $db (configure first: cmake --preset ci)" >&2; exit 2; }
dirs=(app core charts connections ui resources tests)
files=("$@")
if [ "$all" = 1 ]; then
  mapfile -t files < <(sed -n 's/^ *"file": "\(.*\)",\{0,1\}$/\1/p' "$db" | sed "s|^$here/||" |
                         grep -E "^($(IFS='|'; echo "${dirs[*]}"))/" | sort -u)
elif [ ${#files[@]} -eq 0 ]; then
  if [ -z "$base" ]; then  # where this branch left main; on main itself, the last commit
    head=$(git rev-parse HEAD)
    for ref in origin/main main; do
      mb=$(git merge-base "$ref" HEAD 2>/dev/null || true)
      if [ -n "$mb" ] && [ "$mb" != "$head" ]; then base=$mb; break; fi
    done
    [ -n "$base" ] || base=$(git rev-parse HEAD~1)
  fi
  pathspecs=()
  for d in "${dirs[@]}"; do pathspecs+=("$d/*.cpp" "$d/*.h"); done
  mapfile -t files < <(git diff --name-only --diff-filter=AMR "$base" -- "${pathspecs[@]}")
fi
checked=()
for f in "${files[@]}"; do
  if [[ "$f" == *.h ]] || grep -qF "\"file\": \"$here/${f#"$here/"}\"" "$db"; then
    checked+=("$f")
  else
    echo "tidy: skipped $f (not in $db)"
  fi
done
[ ${#checked[@]} -eq 0 ] && { echo "tidy: no C++ files to check"; exit 0; }
echo "tidy: ${#checked[@]} file(s), $jobs at a time"
start=$SECONDS
set +e
printf '%s\n' "${checked[@]}" | xargs -P "$jobs" -n 1 clang-tidy -p "$build" --quiet 2>&1 |
  grep -v -E '^[0-9]+ warnings? generated\.$'
status=${PIPESTATUS[1]}
set -e
echo "tidy: $((SECONDS - start)) s"
if [ $status -ne 0 ]; then
  echo "tidy: findings (or clang-tidy failed) above" >&2
  exit 1
fi
