#!/usr/bin/env bash
# Installs the .deb into a bare Debian 12 root and runs it there (docs/packaging.md, "The bare-root
# check"): the proof that the package names every dependency it needs. Not run by CI: it downloads a
# Debian root (debootstrap --variant=minbase, about 100 MB) and needs root.
#
#   sudo scripts/check_deb_in_chroot.sh [build/ci/reckoner_*.deb]
#
# Environment:
#   RECKONER_CHROOT        the root to install into (default /tmp/reckoner-bare); made afresh each run
#   RECKONER_CHROOT_BASE   a cached bare root (default /tmp/reckoner-bare-base): debootstrapped once,
#                          then copied for every run, so each run starts from a root nothing was installed in
#   RECKONER_MIRROR        the Debian mirror (default: this machine's deb.debian.org, else the official one)
#
# Steps: debootstrap the base once; copy it to the root; bind /proc, /sys, /dev and /dev/pts; copy the .deb in;
# `apt-get update`; `apt-get install -y ./reckoner_*.deb` (Recommends included, as a user's apt does);
# then in the root, with no display: reckoner-cli --version, reckoner --version, reckoner-cli run
# builtin:default --out /tmp/out, and the window on the offscreen platform for 10 s.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
deb=${1:-$(ls -t "$here"/build/ci/reckoner_*.deb 2>/dev/null | head -1)}
[ -f "$deb" ] || { echo "check_deb_in_chroot: no .deb (build it: cmake --build --preset ci --target package)" >&2; exit 2; }
[ "$(id -u)" -eq 0 ] || { echo "check_deb_in_chroot: needs root (debootstrap, chroot, mount)" >&2; exit 2; }
root=${RECKONER_CHROOT:-/tmp/reckoner-bare}
base=${RECKONER_CHROOT_BASE:-/tmp/reckoner-bare-base}
mirror=${RECKONER_MIRROR:-$( (grep -rhoE 'https?://[^ ]*deb\.debian\.org/debian/?( |$)' /etc/apt/sources.list \
  /etc/apt/sources.list.d/ 2>/dev/null || true) | head -1 | tr -d ' ')}
mirror=${mirror:-http://deb.debian.org/debian}

command -v debootstrap >/dev/null || { apt-get update -qq; apt-get install -y -qq debootstrap; }
if [ ! -f "$base/etc/debian_version" ]; then
  echo "== debootstrap --variant=minbase bookworm $base $mirror"
  debootstrap --variant=minbase bookworm "$base" "$mirror"
fi

mounted=()
cleanup() {
  local m
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do umount -l "${mounted[i]}" 2>/dev/null || true; done
}
trap cleanup EXIT
echo "== fresh root $root from $base"
# A run stopped before its cleanup may have left /proc, /sys or /dev mounted in the old root.
for m in $(findmnt -rn -o TARGET | grep "^$root/" | sort -r); do umount -l "$m"; done
rm -rf --one-file-system "$root"
cp -a "$base" "$root"
for fs in proc sys dev dev/pts; do
  mount --bind "/$fs" "$root/$fs" && mounted+=("$root/$fs")
done
cp /etc/resolv.conf "$root/etc/resolv.conf"
cp "$deb" "$root/tmp/"
name=$(basename "$deb")
echo "== $name: $(stat -c %s "$deb") bytes"

in_root() { chroot "$root" env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 "$@"; }
echo "== chroot $root apt-get update"
in_root apt-get update -qq
echo "== chroot $root apt-get install -y ./$name"
in_root sh -c "cd /tmp && DEBIAN_FRONTEND=noninteractive apt-get install -y -q ./$name" | tail -5
echo "== installed: $(in_root dpkg-query -W -f='${Package} ${Version}, ${Installed-Size} KiB installed' reckoner)"
echo "== Depends: $(in_root dpkg-query -W -f='${Depends}' reckoner)"
echo "== Recommends: $(in_root dpkg-query -W -f='${Recommends}' reckoner)"
echo "== packages in the root: $(in_root dpkg-query -W -f='.\n' | wc -l)"

echo "== chroot $root reckoner-cli --version"
in_root reckoner-cli --version
echo "== chroot $root reckoner --version   (no display, no QT_QPA_PLATFORM)"
in_root reckoner --version
echo "== chroot $root reckoner-cli run builtin:default --out /tmp/out"
in_root sh -c 'cd /tmp && reckoner-cli run builtin:default --out /tmp/out'
echo "== files: $(in_root ls /tmp/out | tr '\n' ' ')"
echo "== chroot $root reckoner --fresh --run   (QT_QPA_PLATFORM=offscreen, stopped after 10 s)"
set +e
in_root QT_QPA_PLATFORM=offscreen timeout 10 reckoner --fresh --run
code=$?
set -e
[ $code -eq 124 ] || { echo "check_deb_in_chroot: the window ended by itself (exit $code)" >&2; exit 1; }
echo "== the window ran 10 s"
echo "== man -w reckoner-cli: $(in_root man -w reckoner-cli 2>/dev/null || echo '(man-db is not in a minbase root; the page is /usr/share/man/man1/reckoner-cli.1.gz)')"
echo "check_deb_in_chroot: OK"
