#!/usr/bin/env bash
# Instructions two relt binaries execute for the same renders (valgrind's callgrind, one thread,
# whole runs including loading and the BVH build): a measure of a change's cost that this
# machine's wall-clock drift (15-30 % within minutes) cannot hide. Prints a Markdown table.
# Usage: scripts/bench/instructions.sh OLD_BIN NEW_BIN   (about 10 minutes on this machine)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
OLD="$1"
NEW="$2"
command -v valgrind > /dev/null || { echo "instructions.sh: needs valgrind (apt-get install valgrind)" >&2; exit 2; }
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT

# Instructions of one render: binary, then relt render's arguments.
instructions() {
  local bin="$1"
  shift
  valgrind --tool=callgrind --callgrind-out-file="$TMP/callgrind.out" "$bin" render "$@" --width 64 --height 64 \
    --threads 1 -o "$TMP/out.exr" 2>&1 | sed -n 's/.*Collected : \([0-9]*\).*/\1/p'
}

echo "| render | old | new | change |"
echo "|---|---|---|---|"
while IFS='|' read -r label args; do
  read -r -a argv <<<"$args"
  old=$(instructions "$OLD" "$ROOT/scenes/${argv[0]}.gltf" "${argv[@]:1}")
  new=$(instructions "$NEW" "$ROOT/scenes/${argv[0]}.gltf" "${argv[@]:1}")
  awk -v l="$label" -v o="$old" -v n="$new" \
    'BEGIN {printf "| %s | %s | %s | %+.2f %% |\n", l, o, n, (n - o) / o * 100}'
done <<'RENDERS'
cornell-box, pt, 8 spp|cornell-box --integrator pt --spp 8
cornell-box, bdpt, 4 spp|cornell-box --integrator bdpt --spp 4
glass-cube, pssmlt, 4 mutations per pixel|glass-cube --integrator pssmlt --mutations-per-pixel 4
glass-cube, relt (kitaoka), 4 mutations per pixel|glass-cube --integrator relt --mutations-per-pixel 4
ring, relt (tempered), 2 mutations per pixel|ring --integrator relt --family tempered --mutations-per-pixel 2
RENDERS
