#!/usr/bin/env bash
# Measures the cost model's inputs on 2 ranks (a relt render with spread placement and the
# collectives benchmark) and writes the predicted efficiencies to docs/img/scaling-model.{md,png}.
# Usage: scripts/scaling/model.sh [MPP]   (default 64)   env: SCENE, ALPHA (s), BANDWIDTH (bytes/s)
set -euo pipefail
source "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/lib.sh"
MPP="${1:-64}"
"${MPIRUN[@]}" -np 2 "$BUILD_DIR/relt" render "$ROOT/scenes/$SCENE.gltf" -o "$OUT/model.exr" --stats "$OUT/model.json" \
  --integrator relt --mutations-per-pixel "$MPP" --placement spread 2>/dev/null
"${MPIRUN[@]}" -np 2 "$BUILD_DIR/relt_bench_collectives" > "$OUT/collectives.jsonl"
/usr/bin/python3 "$ROOT/scripts/scaling/model.py" "$OUT/model.json" "$OUT/collectives.jsonl" \
  "$ROOT/docs/img/scaling-model.md" "$ROOT/docs/img/scaling-model.png" \
  --alpha "${ALPHA:-2e-6}" --bandwidth "${BANDWIDTH:-12e9}"
