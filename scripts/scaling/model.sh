#!/usr/bin/env bash
# Measures the cost model's inputs on 2 ranks (RUNS relt renders with spread placement, each
# tracing every group round's stepping time, and the collectives benchmark) and writes the
# predicted efficiencies of each run to docs/img/scaling-model-K.{md,png}, with one summary table
# at 1,024 ranks in docs/img/scaling-model.md (this VM's noise differs from run to run).
# Usage: scripts/scaling/model.sh [MPP]   (default 64)   env: SCENE, RUNS (3), ALPHA (s), BANDWIDTH (bytes/s)
set -euo pipefail
source "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/lib.sh"
MPP="${1:-64}"
RUNS="${RUNS:-3}"
FIRST="${FIRST:-1}"  # number of the first run; above 1 the summary keeps its earlier rows
"${MPIRUN[@]}" -np 2 "$BUILD_DIR/relt_bench_collectives" > "$OUT/collectives.jsonl"
summary="$ROOT/docs/img/scaling-model.md"
[ "$FIRST" -gt 1 ] || {
  echo "Predicted efficiency at 1,024 ranks, $MPP mutations per pixel on $SCENE, $(date -u +%Y-%m-%d), commit $(git -C "$ROOT" rev-parse --short HEAD)."
  echo "Per run: t_g, its spread and longest group round; the 2 ranks' measured time in collectives; the replay's predicted waiting; then per noise case each protocol (details in scaling-model-K.md)."
  echo
  echo "| run | group round | measured in collectives | replay waiting | noise | blocking-spread | staggered-spread | sub-communicators | staggered-packed | lagged-packed D=8 | lagged-packed D=32 | unlimited lag |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
} > "$summary"
lengths="$ROOT/docs/img/scaling-model-length.md"
[ "$FIRST" -gt 1 ] && [ -f "$lengths" ] || {
  echo "Predicted efficiency at 1,024 ranks against render length (multiples 1 / 4 / 16 of the measured render, as measured, independent blocks of 64 group rounds), $(date -u +%Y-%m-%d), commit $(git -C "$ROOT" rev-parse --short HEAD). Growing lag: max(32, min(256, R / 8)) at round R, relt's default since 2026-12-01 (--normaliser-lag-growth 8)."
  echo
  echo "| run | group round | measured stepping | lagged-packed D=32 | growing lag (default) | unlimited lag |"
  echo "|---|---|---|---|---|---|"
} > "$lengths"
for k in $(seq "$FIRST" $((FIRST + RUNS - 1))); do
  "${MPIRUN[@]}" -np 2 "$BUILD_DIR/relt" render "$ROOT/scenes/$SCENE.gltf" -o "$OUT/model.exr" --stats "$OUT/model-$k.json" --trace "$OUT/trace-$k.json" \
    --integrator relt --mutations-per-pixel "$MPP" --placement spread 2>/dev/null
  /usr/bin/python3 "$ROOT/scripts/scaling/model.py" "$OUT/model-$k.json" "$OUT/collectives.jsonl" --trace "$OUT/trace-$k.json" \
    "$ROOT/docs/img/scaling-model-$k.md" "$ROOT/docs/img/scaling-model-$k.png" \
    --alpha "${ALPHA:-2e-6}" --bandwidth "${BANDWIDTH:-12e9}" --summary "$summary" --length-summary "$lengths" --label "$k" > /dev/null
done
cat "$summary" "$lengths"
