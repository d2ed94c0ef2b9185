#!/usr/bin/env bash
# The Debian package as cpack builds it (docs/packaging.md, "Tests").
#
#   tests/package/deb_package.sh BUILD_DIR MAN_PAGES(ON|OFF)
#
# GIVEN the build, WHEN cpack -G DEB packages it into a temporary directory, THEN the .deb is named
# reckoner_<version>_<arch>.deb, its control fields name the package, the build's version, the section,
# the maintainer and the Debian dependencies (from dpkg-shlibdeps, and the ones named by hand), it
# carries exactly the files it should, owned by root, with stripped programs, its desktop entry is
# valid, and the programs extracted from it print the version with nothing of the build around.
set -euo pipefail
build=$(cd "$1" && pwd)
man_pages=${2:-OFF}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/reckoner-deb.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

version=$(sed -n 's/^#define RECKONER_VERSION "\(.*\)"$/\1/p' "$build/generated/reckoner_version.h")
[ -n "$version" ] || fail "no version in $build/generated/reckoner_version.h"
arch=$(dpkg --print-architecture)

cpack --config "$build/CPackConfig.cmake" -G DEB -B "$tmp/pkg" >"$tmp/cpack.log" 2>&1 || { cat "$tmp/cpack.log"; fail "cpack"; }
deb=$tmp/pkg/reckoner_${version}_${arch}.deb
[ -f "$deb" ] || fail "no $(basename "$deb"); cpack wrote: $(ls "$tmp/pkg")"
echo "$(basename "$deb"): $(stat -c %s "$deb") bytes"

dpkg-deb -I "$deb" | tee "$tmp/info"
field() { dpkg-deb -f "$deb" "$1"; }
[ "$(field Package)" = reckoner ] || fail "Package: $(field Package)"
[ "$(field Version)" = "$version" ] || fail "Version: $(field Version), the build says $version"
[ "$(field Architecture)" = "$arch" ] || fail "Architecture: $(field Architecture)"
[ "$(field Section)" = science ] || fail "Section: $(field Section)"
[[ "$(field Maintainer)" == *"<"*"@"*">" ]] || fail "Maintainer: $(field Maintainer)"
[ -n "$(field Description)" ] || fail "no Description"
depends=$(field Depends)
for d in libc6 libstdc++6 libqt6core6 libqt6widgets6 libqt6gui6 libgdal libgeographiclib qt6-qpa-plugins; do
  [[ ", $depends" == *", $d"* ]] || fail "Depends lacks $d: $depends"
done
[[ "$(field Recommends)" == *gmt-gshhg-low* ]] || fail "Recommends: $(field Recommends)"
dpkg --compare-versions "$version" gt 0 || fail "$version is no Debian version"

dpkg-deb -c "$deb" | tee "$tmp/contents"
files=$(awk '$1 !~ /^d/ { print $6 }' "$tmp/contents" | sort)
expected=(./usr/bin/reckoner ./usr/bin/reckoner-cli ./usr/share/applications/reckoner.desktop
          ./usr/share/icons/hicolor/scalable/apps/reckoner.svg ./usr/share/doc/reckoner/README.md
          ./usr/share/doc/reckoner/packaging.md)
[ "$man_pages" = ON ] && expected+=(./usr/share/man/man1/reckoner-cli.1.gz ./usr/share/man/man1/reckoner.1.gz)
for f in "${expected[@]}"; do grep -qx -- "$f" <<<"$files" || fail "the package lacks $f"; done
unexpected=$(grep -v -e '^\./usr/bin/reckoner\(-cli\)\?$' -e '^\./usr/share/applications/reckoner\.desktop$' \
  -e '^\./usr/share/icons/hicolor/scalable/apps/reckoner\.svg$' -e '^\./usr/share/doc/reckoner/[a-z0-9_]*\.md$' \
  -e '^\./usr/share/doc/reckoner/README\.md$' -e '^\./usr/share/man/man1/reckoner\(-cli\)\?\.1\.gz$' <<<"$files" || true)
[ -z "$unexpected" ] || fail "the package carries what it should not: $unexpected"
owners=$(awk '{ print $2 }' "$tmp/contents" | sort -u)
[ "$owners" = root/root ] || fail "files not owned by root/root: $owners"

dpkg-deb -x "$deb" "$tmp/root"
for p in reckoner reckoner-cli; do
  ! readelf -S "$tmp/root/usr/bin/$p" | grep -q '\.symtab' || fail "/usr/bin/$p is not stripped"
done
if command -v desktop-file-validate >/dev/null; then
  desktop-file-validate "$tmp/root/usr/share/applications/reckoner.desktop" || fail "desktop-file-validate"
fi
if [ "$man_pages" = ON ] && command -v man >/dev/null; then
  # The man page renders without a warning (groff's -ww would print them).
  warnings=$(MANWIDTH=100 man --warnings -l "$tmp/root/usr/share/man/man1/reckoner-cli.1.gz" 2>&1 >/dev/null || true)
  [ -z "$warnings" ] || fail "man reckoner-cli: $warnings"
fi
(cd "$tmp" && env -i PATH=/usr/bin:/bin HOME="$tmp" "$tmp/root/usr/bin/reckoner" --version) | tee "$tmp/gui"
(cd "$tmp" && env -i PATH=/usr/bin:/bin HOME="$tmp" "$tmp/root/usr/bin/reckoner-cli" --version) | tee "$tmp/cli"
grep -qx "reckoner $version" "$tmp/gui" || fail "reckoner --version"
grep -qx "reckoner-cli $version" "$tmp/cli" || fail "reckoner-cli --version"
echo "PASS: $(basename "$deb")"
