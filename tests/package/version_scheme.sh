#!/usr/bin/env bash
# The version scheme of cmake/WriteVersion.cmake (docs/packaging.md, "Version") on a scratch git
# repository: every version is a valid Debian version, later commits sort later, and the header is
# rewritten only when the version changes (so an unchanged HEAD recompiles nothing).
#
#   tests/package/version_scheme.sh SOURCE_DIR PROJECT_VERSION
set -euo pipefail
script=$(cd "$1" && pwd)/cmake/WriteVersion.cmake
project_version=$2
tmp=$(mktemp -d "${TMPDIR:-/tmp}/reckoner-version.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
export GIT_AUTHOR_NAME=test GIT_AUTHOR_EMAIL=test@example.org GIT_COMMITTER_NAME=test GIT_COMMITTER_EMAIL=test@example.org
export GIT_CONFIG_NOSYSTEM=1 HOME=$tmp

# The version WriteVersion.cmake gives the sources in $1.
version_of() {
  cmake -DSOURCE_DIR="$1" -DOUTPUT_DIR="$tmp/out" -DPROJECT_VERSION="$project_version" -P "$script" >/dev/null
  sed -n 's/^#define RECKONER_VERSION "\(.*\)"$/\1/p' "$tmp/out/reckoner_version.h"
}
expect() {  # expect NAME ACTUAL EXPECTED
  [ "$2" = "$3" ] || fail "$1: '$2', expected '$3'"
  dpkg --compare-versions "$2" gt 0 || fail "$1: '$2' is no Debian version"
  echo "$1: $2"
}
later() { dpkg --compare-versions "$2" gt "$1" || fail "'$2' does not sort after '$1'"; }

repo=$tmp/repo
git init -q "$repo"
cd "$repo"
echo a >file && git add file && git commit -qm one
v1=$(version_of "$repo")
expect "no tag, 1 commit" "$v1" "$project_version+git1.g$(git rev-parse --short HEAD)"

touch -d '2000-01-01' "$tmp/out/reckoner_version.h"
[ "$(version_of "$repo")" = "$v1" ] || fail "a second run changed the version"
[ "$(stat -c %Y "$tmp/out/reckoner_version.h")" = "$(date -d 2000-01-01 +%s)" ] || fail "an unchanged version rewrote the header"

echo b >file && git commit -qam two
v2=$(version_of "$repo")
expect "no tag, 2 commits" "$v2" "$project_version+git2.g$(git rev-parse --short HEAD)"
later "$v1" "$v2"

echo c >file
v2d=$(version_of "$repo")
expect "uncommitted changes" "$v2d" "$v2.dirty"
later "$v2" "$v2d"
git checkout -q file

git tag -a v9.1.0 -m release
v3=$(version_of "$repo")
expect "tag v9.1.0" "$v3" "9.1.0"
later "$v2d" "$v3"

echo d >file && git commit -qam three
v4=$(version_of "$repo")
expect "1 commit after v9.1.0" "$v4" "9.1.0+git1.g$(git rev-parse --short HEAD)"
later "$v3" "$v4"

# No tag and an abbreviated hash of decimal digits only (about one commit in 27): still a snapshot of
# PROJECT_VERSION, not a "version" made of the hash (this test failed on such a hash, 2026-12-05). The
# commit is remade with fixed dates and a counter in its message until its hash is all digits, so the
# same commit is found on every run.
digits=$tmp/digits
git init -q "$digits"
(
  cd "$digits"
  export GIT_AUTHOR_DATE='2026-12-05T00:00:00Z' GIT_COMMITTER_DATE='2026-12-05T00:00:00Z'
  echo a >file && git add file && git commit -qm "digits 0"
  n=0
  until [[ $(git rev-parse --short HEAD) =~ ^[0-9]+$ ]]; do
    n=$((n + 1))
    [ "$n" -le 5000 ] || fail "no all-digit hash in 5000 commits"
    git commit -q --amend -m "digits $n"
  done
)
hd=$(git -C "$digits" rev-parse --short HEAD)
expect "no tag, all-digit hash $hd" "$(version_of "$digits")" "$project_version+git1.g$hd"

mkdir -p "$tmp/tarball" "$repo/sub"
expect "no git (a tarball)" "$(version_of "$tmp/tarball")" "$project_version"
expect "inside another project's work tree" "$(version_of "$repo/sub")" "$project_version"
echo "PASS"
