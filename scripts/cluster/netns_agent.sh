#!/usr/bin/env bash
# Open MPI's remote-start agent for scripts/cluster/netns.sh: called as `AGENT HOST COMMAND...`
# like ssh, it runs COMMAND inside the namespace of HOST (127.200.0.K -> $RELT_NETNS_TAG-hK) with
# that host's own hostname.
set -euo pipefail
host="$1"
shift
case "$host" in
  127.200.0.*) k="${host##*.}" ;;
  *) echo "netns_agent.sh: $host is not a 127.200.0.0/24 host" >&2; exit 2 ;;
esac
ns="${RELT_NETNS_TAG:?RELT_NETNS_TAG not set}-h$k"
exec ip netns exec "$ns" unshare --uts sh -c 'hostname "$0"; exec sh -c "$*"' "$ns" "$@"
