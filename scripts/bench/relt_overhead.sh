#!/usr/bin/env bash
# Cost of the exchanges: share of the round loop's time each rank spends inside its collectives
# (the round's MPI_Allgatherv, including waiting for the slower rank) at several exchange intervals, relt on
# 2 ranks, cornell-box 256x256, same mutation budget, each with load balancing (the default
# 0.25 s window) and without (--balance-window 0). Writes out/bench/relt_overhead.md.
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
  echo "| exchange interval | balance window s | rounds | round loop s | in collectives s (rank 0, rank 1) | share (worst rank) | chains moved | chains per rank at the end |"
  echo "|---|---|---|---|---|---|---|---|"
} > "$TABLE"
for k in "${INTERVALS[@]}"; do
  for w in 0.25 0; do
    "${MPIRUN[@]}" -np 2 "$BUILD_DIR/relt" render "$ROOT/scenes/cornell-box.gltf" -o "$OUT/k$k-w$w.exr" \
      --stats "$OUT/k$k-w$w.json" --integrator relt --family relaxed --mutations-per-pixel "$MPP" \
      --exchange-interval "$k" --balance-window "$w" 2>/dev/null
    /usr/bin/python3 - "$OUT/k$k-w$w.json" "$k" "$w" >> "$TABLE" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))["relt"]
c = r["round_collective_seconds_per_rank"]
t = r["loop_seconds"]
print("| %s | %s | %d | %.2f | %.3f, %.3f | %.2f %% | %d | %s |" % (sys.argv[2], sys.argv[3], r["rounds"], t, c[0], c[1],
      100 * max(c) / t, r["chain_moves"], ", ".join(map(str, r["chains_per_rank"]))))
PY
  done
done
cat "$TABLE"
