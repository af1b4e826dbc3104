#!/usr/bin/env bash
# Equal-time error: each integrator renders for SECONDS on 2 ranks and is compared (relt compare)
# with a long bdpt reference of REF_SECONDS. Writes out/bench/equal_time.md (a table) and the
# signed-difference images out/bench/equal-time/<scene>-<integrator>-diff.{exr,png}.
# Usage: scripts/bench/equal_time.sh [SECONDS] [REF_SECONDS] [SCENES...]   (defaults 60, 600,
# cornell-box glass-cube water-box)
set -euo pipefail
source "$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/setup.sh"
SECONDS_BUDGET="${1:-60}"
REF_SECONDS="${2:-600}"
shift $(($# > 2 ? 2 : $#))
SCENES=("$@")
((${#SCENES[@]})) || SCENES=(cornell-box glass-cube water-box)
OUT="$ROOT/out/bench/equal-time"
mkdir -p "$OUT"
TABLE="$ROOT/out/bench/equal_time.md"
{
  echo "Equal time ${SECONDS_BUDGET} s on 2 ranks against a ${REF_SECONDS} s bdpt reference (seed 1 vs 99);"
  echo "$(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores, $(date -u +%Y-%m-%d), commit $(git -C "$ROOT" rev-parse --short HEAD)"
  echo
  echo "| scene | integrator | RMSE | relative MSE | mean | reference mean |"
  echo "|---|---|---|---|---|---|"
} > "$TABLE"
for scene in "${SCENES[@]}"; do
  ref="$OUT/$scene-reference.exr"
  "${MPIRUN[@]}" -np 2 "$BUILD_DIR/relt" render "$ROOT/scenes/$scene.gltf" -o "$ref" --integrator bdpt \
    --time "$REF_SECONDS" --seed 99 2>/dev/null
  for integ in bdpt pssmlt mmlt erpt; do
    img="$OUT/$scene-$integ.exr"
    "${MPIRUN[@]}" -np 2 "$BUILD_DIR/relt" render "$ROOT/scenes/$scene.gltf" -o "$img" --png "$OUT/$scene-$integ.png" \
      --integrator "$integ" --time "$SECONDS_BUDGET" --seed 1 2>/dev/null
    "$BUILD_DIR/relt" compare "$img" "$ref" --diff "$OUT/$scene-$integ-diff.exr" --png "$OUT/$scene-$integ-diff.png" |
      /usr/bin/python3 -c "import json,sys; c=json.loads(sys.stdin.read()); print('| $scene | $integ | %.5f | %.5f | %.5f | %.5f |' % (c['rmse'], c['rel_mse'], c['mean'], c['reference_mean']))" >> "$TABLE"
  done
done
cat "$TABLE"
