#!/usr/bin/env bash
# clang-tidy with the repository's .clang-tidy (no function over 80 lines) on C++ sources of app/, core/,
# charts/, connections/ and ui/: the files given, or those changed against BASE (default: origin/main, else HEAD~1).
#
#   scripts/tidy.sh [--base REV] [FILE.cpp...]
#
# Needs a configured build with compile_commands.json (build/ci, or RECKONER_BUILD_DIR). Exit 1 when a
# check fails.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$here"
build=${RECKONER_BUILD_DIR:-build/ci}
base=""
if [ "${1:-}" = --base ]; then base=$2; shift 2; fi
files=("$@")
if [ ${#files[@]} -eq 0 ]; then
  if [ -z "$base" ]; then base=$(git rev-parse --verify -q origin/main || git rev-parse HEAD~1); fi
  mapfile -t files < <(git diff --name-only --diff-filter=AMR "$base" -- 'app/*.cpp' 'core/*.cpp' 'charts/*.cpp' 'connections/*.cpp' 'ui/*.cpp')
fi
[ ${#files[@]} -eq 0 ] && { echo "tidy: no changed C++ sources"; exit 0; }
[ -f "$build/compile_commands.json" ] || { echo "tidy: no $build/compile_commands.json (configure first)" >&2; exit 2; }
echo "tidy: ${#files[@]} file(s)"
printf '%s\n' "${files[@]}" | xargs -P "$(nproc 2>/dev/null || echo 2)" -n 4 clang-tidy -p "$build" --quiet
