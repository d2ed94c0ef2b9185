#!/bin/sh
# Runs tst_connections' multicast delivery case in a network namespace of its own whose loopback takes
# multicast: lo on this kind of machine has no MULTICAST flag, and changing the host's interfaces is no
# business of a test. A machine without user and network namespaces skips it (ctest's skip code 77).
#   multicast_netns.sh PATH/tst_connections
set -eu
binary=$1
if ! unshare -rn true 2>/dev/null; then
  echo "multicast_netns: no user and network namespaces here (unshare -rn failed): skipped"
  exit 77
fi
if ! command -v ip >/dev/null; then
  echo "multicast_netns: ip (iproute2) is missing: skipped"
  exit 77
fi
exec unshare -rn sh -c 'ip link set lo up && ip link set lo multicast on &&
  ip route add 224.0.0.0/4 dev lo &&
  RECKONER_REQUIRE_MULTICAST=1 exec "$0" multicastJoinOnLoopbackOrItsError' "$binary"
