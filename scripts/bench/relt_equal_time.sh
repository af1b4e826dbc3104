#!/usr/bin/env bash
# Equal-time error of pssmlt and relt configurations on 2 ranks, with convergence curves: each run
# writes snapshots every SNAP seconds, copied as they appear, and every copy is compared with the
# reference (relt compare). References: scenes/references/<scene>.exr (scripts/bench/reference.sh),
# else the long bdpt renders of equal_time.sh (out/bench/equal-time/<scene>-reference.exr); missing
# ones are rendered for REF_SECONDS.
# Writes out/bench/relt_equal_time.md (final RMSE table), out/bench/relt-curves/<scene>.csv and
# <scene>.png (RMSE against time), and each run's final PNG. Each run keeps its own curve and table
# row, so a rerun of some configurations (CONFIGS) updates them and keeps the others' results.
# Usage: scripts/bench/relt_equal_time.sh [SECONDS] [SCENES...]   (defaults 60; glass-cube water-box ring)
#        env: SNAP (default 5), REF_SECONDS (default 600), CONFIGS (names, default all), SEED (1),
#             EXTRA (options added to every configuration, e.g. "--direct-emission-spp 256"),
#             TAG (results go to out/bench/relt-curves-TAG and relt_equal_time-TAG.md)
set -euo pipefail
source "$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/setup.sh"
source "$ROOT/scripts/bench/snapshots.sh"
BUDGET="${1:-60}"
shift $(($# > 0 ? 1 : 0))
SCENES=("$@")
((${#SCENES[@]})) || SCENES=(glass-cube water-box ring)
SNAP="${SNAP:-5}"
REF_SECONDS="${REF_SECONDS:-600}"
REF_DIR="$ROOT/out/bench/equal-time"
OUT="$ROOT/out/bench/relt-curves${TAG:+-$TAG}"
read -r -a EXTRA_ARGS <<< "${EXTRA:-}"
mkdir -p "$OUT" "$REF_DIR"

declare -A ARGS=(
  [pssmlt]="--integrator pssmlt"
  [relaxed-deo]="--integrator relt --family relaxed --exchange deo"
  [relaxed-permutation]="--integrator relt --family relaxed --exchange permutation"
  [kitaoka-deo]="--integrator relt --family kitaoka --exchange deo"
  [kitaoka-permutation]="--integrator relt --family kitaoka --exchange permutation"
  [tempered-deo]="--integrator relt --family tempered --exchange deo"
  [tempered-permutation]="--integrator relt --family tempered --exchange permutation"
)
ALL="pssmlt relaxed-deo relaxed-permutation kitaoka-deo kitaoka-permutation tempered-deo tempered-permutation"
read -r -a NAMES <<< "${CONFIGS:-$ALL}"

TABLE="$ROOT/out/bench/relt_equal_time${TAG:+-$TAG}.md"
{
  echo "Equal time ${BUDGET} s on 2 ranks (seed ${SEED:-1}${EXTRA:+, every configuration with $EXTRA}) against scenes/references (scripts/bench/reference.sh);"
  echo "$(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores, $(date -u +%Y-%m-%d), commit $(git -C "$ROOT" rev-parse --short HEAD)"
  echo
  echo "| scene | configuration | RMSE | relative MSE | mutations | swap acceptance (adjacent pairs) | round trips |"
  echo "|---|---|---|---|---|---|---|"
} > "$TABLE"

for scene in "${SCENES[@]}"; do
  ref="$ROOT/scenes/references/$scene.exr"  # scripts/bench/reference.sh; else a reference of its own
  [ -f "$ref" ] || ref="$REF_DIR/$scene-reference.exr"
  [ -f "$ref" ] || "${MPIRUN[@]}" -np 2 "$BUILD_DIR/relt" render "$ROOT/scenes/$scene.gltf" -o "$ref" \
    --integrator bdpt --time "$REF_SECONDS" --seed 99 2>/dev/null
  csv="$OUT/$scene.csv"
  for name in "${NAMES[@]}"; do
    run="$OUT/$scene-$name"
    # shellcheck disable=SC2086
    render_followed "$run" "$scene" "$BUDGET" "$SNAP" ${ARGS[$name]} "${EXTRA_ARGS[@]}"
    curve "$run" "$ref" "$name"
    read -r rmse rel < <(compare "$run.exr" "$ref")
    /usr/bin/python3 - "$run.json" "$scene" "$name" "$rmse" "$rel" > "$run.row" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
swaps, trips = "-", "-"
if "relt" in j:
    levels = j["relt"]["levels"]
    swaps = " ".join("%.2f" % l["swap_acceptance_with_next"] for l in levels[:-1] if l.get("swap_acceptance_with_next") is not None)
    trips = str(j["relt"]["round_trips"])
print("| %s | %s | %.5f | %.5f | %d | %s | %s |" % (sys.argv[2], sys.argv[3], float(sys.argv[4]), float(sys.argv[5]), j["mutations"], swaps, trips))
PY
  done
  echo "configuration,seconds,rmse,rel_mse" > "$csv"
  for name in $ALL; do
    [ -f "$OUT/$scene-$name.csv" ] && cat "$OUT/$scene-$name.csv" >> "$csv"
    [ -f "$OUT/$scene-$name.row" ] && cat "$OUT/$scene-$name.row" >> "$TABLE"
  done
  plot_curves "$csv" "$OUT/$scene.png" "$scene"
done
cat "$TABLE"
