#!/usr/bin/env bash
# The installed programs run from their installed files alone (docs/packaging.md, "Tests").
#
#   tests/package/install_run.sh BUILD_DIR SOURCE_DIR MAN_PAGES(ON|OFF)
#
# GIVEN the build installed with `cmake --install` into a temporary DESTDIR (prefix /usr),
# WHEN the installed reckoner-cli runs the default scenario and both programs print --version, from an
#   empty working directory, with an environment holding nothing of the build (env -i) and, where a
#   mount namespace can be made, the source tree, the build tree and ../shared hidden under empty
#   tmpfs mounts,
#   and the window runs the default scenario for 10 s on the offscreen platform,
# THEN the run writes its files and a sane summary.json, the installed files are the ones the package
#   promises, and the programs carry no RPATH into the build tree.
set -euo pipefail
build=$(cd "$1" && pwd)
source=$(cd "$2" && pwd)
man_pages=${3:-OFF}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/reckoner-install.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

root=$tmp/root
DESTDIR=$root cmake --install "$build" --prefix /usr >"$tmp/install.log" || { cat "$tmp/install.log"; fail "cmake --install"; }
echo "installed into $root:"
(cd "$root" && find . -type f | sort | sed 's|^\./|  /|')

for f in usr/bin/reckoner usr/bin/reckoner-cli usr/share/applications/reckoner.desktop \
         usr/share/icons/hicolor/scalable/apps/reckoner.svg usr/share/doc/reckoner/README.md \
         usr/share/doc/reckoner/packaging.md usr/share/doc/reckoner/cli.md; do
  [ -f "$root/$f" ] || fail "missing /$f"
done
if [ "$man_pages" = ON ]; then
  for f in usr/share/man/man1/reckoner-cli.1.gz usr/share/man/man1/reckoner.1.gz; do
    [ -f "$root/$f" ] || fail "missing /$f"
  done
fi
# Nothing of the build's own: no static library, header or test program is installed.
extra=$(cd "$root" && find . -type f \( -name '*.a' -o -name '*.h' -o -name 'tst_*' -o -name 'reckoner-bench' \
        -o -name 'reckoner-chartgen' \))
[ -z "$extra" ] || fail "installed what the package must not carry: $extra"

for p in reckoner reckoner-cli; do
  if readelf -d "$root/usr/bin/$p" | grep -Eq 'RPATH|RUNPATH'; then
    fail "/usr/bin/$p keeps an RPATH: $(readelf -d "$root/usr/bin/$p" | grep -E 'RPATH|RUNPATH')"
  fi
  if ldd "$root/usr/bin/$p" | grep -Eq "not found|$build|$source"; then
    fail "/usr/bin/$p: $(ldd "$root/usr/bin/$p" | grep -E "not found|$build|$source")"
  fi
done

# The run: an empty working directory and home, nothing in the environment but PATH.
mkdir -p "$tmp/work" "$tmp/home" "$tmp/out"
hidden=("$source" "$build")
[ -d "$source/../shared" ] && hidden+=("$(cd "$source/../shared" && pwd)")
# Deepest first (the build tree is usually inside the source tree): then each is empty or gone.
mapfile -t hidden < <(printf '%s\n' "${hidden[@]}" | awk '{ print length, $0 }' | sort -rn | cut -d' ' -f2-)
cat >"$tmp/run.sh" <<EOF
set -eu
for d in "\$@"; do mount -t tmpfs -o size=1m,mode=0755 reckoner-hidden "\$d"; done
for d in "\$@"; do [ ! -e "\$d" ] || [ -z "\$(ls -A "\$d")" ] || { echo "could not hide \$d" >&2; exit 3; }; done
cd "$tmp/work"
"$root/usr/bin/reckoner-cli" --version
"$root/usr/bin/reckoner" --version
"$root/usr/bin/reckoner-cli" run builtin:default --out "$tmp/out"
# The window on the offscreen platform, running the default scenario until stopped after 10 s.
set +e
QT_QPA_PLATFORM=offscreen timeout 10 "$root/usr/bin/reckoner" --fresh --run
code=\$?
set -e
[ \$code -eq 124 ] || { echo "reckoner ended by itself (exit \$code) within 10 s" >&2; exit 4; }
echo "reckoner: the window ran the default scenario for 10 s (offscreen)"
EOF
clean_env=(env -i PATH=/usr/bin:/bin HOME="$tmp/home" LANG=C.UTF-8)
if "${clean_env[@]}" unshare --mount --propagation private true 2>/dev/null; then
  how="a mount namespace with ${hidden[*]} hidden"
  runner=("${clean_env[@]}" unshare --mount --propagation private bash "$tmp/run.sh" "${hidden[@]}")
elif "${clean_env[@]}" unshare --mount --map-root-user --propagation private true 2>/dev/null; then
  how="a user and mount namespace with ${hidden[*]} hidden"
  runner=("${clean_env[@]}" unshare --mount --map-root-user --propagation private bash "$tmp/run.sh" "${hidden[@]}")
else
  how="env -i only (no mount namespace here: the trees stay visible)"
  runner=("${clean_env[@]}" bash "$tmp/run.sh")
fi
echo "running the installed programs in $how"
"${runner[@]}" >"$tmp/run.log" 2>"$tmp/run.err" || { cat "$tmp/run.log" "$tmp/run.err"; fail "the installed run failed"; }
cat "$tmp/run.log"
[ -s "$tmp/run.err" ] && { echo "stderr:"; cat "$tmp/run.err"; }

version=$(sed -n 's/^#define RECKONER_VERSION "\(.*\)"$/\1/p' "$build/generated/reckoner_version.h")
grep -qx "reckoner $version" "$tmp/run.log" || fail "reckoner --version does not print 'reckoner $version'"
grep -qx "reckoner-cli $version" "$tmp/run.log" || fail "reckoner-cli --version does not print 'reckoner-cli $version'"
for f in ownship.csv summary.json; do
  [ -s "$tmp/out/$f" ] || fail "the run wrote no $f (files: $(ls "$tmp/out"))"
done
python3 - "$tmp/out/summary.json" <<'EOF' || fail "summary.json is not sane"
import json, math, sys
s = json.load(open(sys.argv[1]))
def numbers(x):
    if isinstance(x, dict):
        for v in x.values(): yield from numbers(v)
    elif isinstance(x, list):
        for v in x: yield from numbers(v)
    elif isinstance(x, (int, float)) and not isinstance(x, bool):
        yield x
values = list(numbers(s))
assert s["scenario"].startswith("Reckoner Sound"), f"scenario {s['scenario']!r}"  # builtin:default's title
assert s["steps"] > 0 and len(s["phases"]) == 6, f"{s['steps']} steps, {len(s['phases'])} phases"
assert all(math.isfinite(v) for v in values), "a figure is not finite"
print(f"summary.json: {s['scenario']!r}, {s['steps']} steps, {len(s['phases'])} phases, {len(values)} figures, all finite")
EOF
echo "PASS: installed programs ran from $root"
