#!/usr/bin/env bash
# A small "cluster" on one machine: N network namespaces (hosts relt-h1..relt-hN, addresses
# 127.200.0.1..N/24 on a private bridge, never any other range), and one mpirun across them over
# TCP, one rank per host. Open MPI starts its daemons on the other hosts through
# scripts/cluster/netns_agent.sh (its plm_rsh_agent), which enters the host's namespace instead of
# using ssh. Everything is torn down on exit. Needs root and `ip netns`.
# Usage: scripts/cluster/netns.sh N relt render SCENE -o OUT.exr [relt options...]
#        (the command after N runs as the MPI program; `relt` means the built executable)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$ROOT/build}"
N="${1:?usage: netns.sh N relt ARGS...}"
shift
(($# > 0)) || { echo "netns.sh: no command given" >&2; exit 2; }
((N >= 1 && N <= 200)) || { echo "netns.sh: N must be 1..200" >&2; exit 2; }
[ "$(id -u)" -eq 0 ] || { echo "netns.sh: needs root (network namespaces)" >&2; exit 3; }
command -v ip >/dev/null || { echo "netns.sh: the ip command (iproute2) is missing" >&2; exit 3; }

TAG="relt$$"            # unique per run: bridge and namespace names do not collide
BRIDGE="${TAG}br"
WORK="$(mktemp -d)"
cleanup() {
  for i in $(seq 1 "$N"); do
    ip netns del "$TAG-h$i" 2>/dev/null || true
    rm -rf "/etc/netns/$TAG-h$i"
  done
  ip link del "$BRIDGE" 2>/dev/null || true
  rm -rf "$WORK"
}
trap cleanup EXIT INT TERM

ip link add "$BRIDGE" type bridge
ip link set "$BRIDGE" up
for i in $(seq 1 "$N"); do
  ns="$TAG-h$i"
  ip netns add "$ns"
  ip link add "${TAG}v$i" type veth peer name eth0 netns "$ns"
  ip link set "${TAG}v$i" master "$BRIDGE" up
  # Loopback keeps only 127.0.0.1/32, so 127.200.0.0/24 is not "local" and goes out on eth0;
  # route_localnet lets 127.x addresses travel on a real interface.
  ip netns exec "$ns" ip link set lo up
  ip netns exec "$ns" ip addr del 127.0.0.1/8 dev lo
  ip netns exec "$ns" ip addr add 127.0.0.1/32 dev lo
  ip netns exec "$ns" sysctl -qw net.ipv4.conf.all.route_localnet=1 net.ipv4.conf.eth0.route_localnet=1
  ip netns exec "$ns" ip addr add "127.200.0.$i/24" dev eth0
  ip netns exec "$ns" ip link set eth0 up
  echo "127.200.0.$i slots=1" >> "$WORK/hostfile"
done

# The command: `relt` is the built executable.
cmd=("$@")
[ "${cmd[0]}" = relt ] && cmd[0]="$BUILD_DIR/relt"

export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export RELT_NETNS_TAG="$TAG"
# mpirun runs on host 1; every host gets its own hostname (UTS namespace) so Open MPI sees N nodes.
ip netns exec "$TAG-h1" unshare --uts sh -c 'hostname "$0"; exec "$@"' "$TAG-h1" \
  mpirun --hostfile "$WORK/hostfile" -np "$N" --map-by node \
  --mca plm_rsh_agent "$ROOT/scripts/cluster/netns_agent.sh" \
  --mca pml ob1 --mca btl tcp,self \
  --mca btl_tcp_if_include 127.200.0.0/24 --mca oob_tcp_if_include 127.200.0.0/24 \
  -x OMPI_ALLOW_RUN_AS_ROOT -x OMPI_ALLOW_RUN_AS_ROOT_CONFIRM \
  "${cmd[@]}"
