#!/usr/bin/env bash
# relt's default ladder (kitaoka, deo) on the suite's scenes at equal time, for comparing builds of
# the ladder: each scene for every length of LENGTHS on 2 ranks with every seed of SEEDS, compared
# with scenes/references/SCENE.exr. One row a render in docs/img/relt-ladder.csv (with the commit
# and the levels the bootstrap left out); the rows of pssmlt and of relt before a change are in
# docs/img/suite.csv (the same seeds and lengths).
# Usage: scripts/bench/relt_ladder.sh [SCENE...]   env: SEEDS ("1 2"), LENGTHS ("30"), ARGS (extra)
set -euo pipefail
source "$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/setup.sh"
source "$ROOT/scripts/bench/common.sh"
read -r -a SEED_LIST <<< "${SEEDS:-1 2}"
read -r -a LENGTH_LIST <<< "${LENGTHS:-30}"
read -r -a EXTRA <<< "${ARGS:-}"
SCENES=("$@")
((${#SCENES[@]})) || SCENES=(cornell-box door-ajar glass-cube water-box)
CSV="$ROOT/docs/img/relt-ladder.csv"
OUT="$ROOT/out/bench/relt-ladder"
mkdir -p "$OUT"
[ -f "$CSV" ] || echo "scene,seed,seconds,rmse,rel_mse,mean,reference_mean,levels_left_out,commit,date" > "$CSV"
COMMIT="$(git -C "$ROOT" rev-parse --short HEAD)"
for scene in "${SCENES[@]}"; do
  for secs in "${LENGTH_LIST[@]}"; do
    for seed in "${SEED_LIST[@]}"; do
      run="$OUT/$scene-s$seed-$secs"
      "${MPIRUN[@]}" -np 2 "$BUILD_DIR/relt" render "$ROOT/scenes/$scene.gltf" -o "$run.exr" --stats "$run.json" \
        --time "$secs" --seed "$seed" --integrator relt "${EXTRA[@]}" 2> "$run.log"
      c="$(compare_row "$run.exr" "$ROOT/scenes/references/$scene.exr")"
      out="$(/usr/bin/python3 -c "import json,sys; print(' '.join(json.load(open(sys.argv[1]))['relt'].get('levels_left_out', [])) or '-')" "$run.json")"
      echo "$scene,$seed,$secs,$c,$out,$COMMIT,$(date -u +%Y-%m-%d)" >> "$CSV"
      echo "relt_ladder: $scene seed $seed $secs s: rmse ${c%%,*} (left out: $out)"
    done
  done
done
