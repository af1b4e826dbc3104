#!/usr/bin/env bash
# Cost of the exchanges: share of the round loop's time each rank spends inside its collectives
# (the round's MPI_Allgatherv, including waiting for the slower rank) at several exchange intervals, relt on
# 2 ranks, cornell-box 256x256, same mutation budget. Writes out/bench/relt_overhead.md.
# Usage: scripts/bench/relt_overhead.sh [MUTATIONS_PER_PIXEL] [INTERVALS...]   (defaults 16; 1 4 16 64)
set -euo pipefail
source "$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/setup.sh"
MPP="${1:-16}"
shift $(($# > 0 ? 1 : 0))
INTERVALS=("$@")
((${#INTERVALS[@]})) || INTERVALS=(1 4 16 64)
OUT="$ROOT/out/bench/relt-overhead"
mkdir -p "$OUT"
TABLE="$ROOT/out/bench/relt_overhead.md"
{
  echo "relt (relaxed, 8 levels, 32 ladders, deo) on 2 ranks, cornell-box 256x256, $MPP mutations per pixel;"
  echo "$(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores, $(date -u +%Y-%m-%d), commit $(git -C "$ROOT" rev-parse --short HEAD)"
  echo
  echo "| exchange interval | rounds | round loop s | in collectives s (rank 0, rank 1) | share (worst rank) |"
  echo "|---|---|---|---|---|"
} > "$TABLE"
for k in "${INTERVALS[@]}"; do
  "${MPIRUN[@]}" -np 2 "$BUILD_DIR/relt" render "$ROOT/scenes/cornell-box.gltf" -o "$OUT/k$k.exr" \
    --stats "$OUT/k$k.json" --integrator relt --family relaxed --mutations-per-pixel "$MPP" --exchange-interval "$k" 2>/dev/null
  /usr/bin/python3 - "$OUT/k$k.json" "$k" >> "$TABLE" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
c = j["relt"]["round_collective_seconds_per_rank"]
t = j["relt"]["loop_seconds"]
print("| %s | %d | %.2f | %.3f, %.3f | %.2f %% |" % (sys.argv[2], j["relt"]["rounds"], t, c[0], c[1], 100 * max(c) / t))
PY
done
cat "$TABLE"
