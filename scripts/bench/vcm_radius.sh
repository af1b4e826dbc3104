#!/usr/bin/env bash
# vcm's merging radius at equal time: each scene rendered by vcm for SECONDS on 2 ranks at each radius
# of RADII (in pixel footprints, --vcm-radius) and each seed of SEEDS, its RMSE and mean against
# scenes/references/SCENE.exr. A small radius has less bias (the blur of a merge) and more variance
# (fewer light vertices per merge); the default should be the radius of least error at the times
# users render for. Rows go to docs/img/vcm-radius.csv, the table (RMSE averaged over the seeds, by
# MSE) to standard output; a render made again replaces its row.
# Usage: scripts/bench/vcm_radius.sh [SCENE...]   env: RADII ("0.5 1 2 4"), SEEDS ("1 2"), SECONDS_BUDGET (30)
set -euo pipefail
source "$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/setup.sh"
source "$ROOT/scripts/bench/common.sh"
read -r -a RADII <<< "${RADII:-0.5 1 2 4}"
read -r -a SEED_LIST <<< "${SEEDS:-1 2}"
BUDGET="${SECONDS_BUDGET:-30}"
SCENES=("$@")
((${#SCENES[@]})) || SCENES=(cornell-box glass-cube water-box torus-in-glass glossy-caustics)
OUT="$ROOT/out/bench/vcm-radius"
CSV="$ROOT/docs/img/vcm-radius.csv"
mkdir -p "$OUT" "$ROOT/docs/img"
[ -f "$CSV" ] || echo "scene,radius,seed,seconds,rmse,rel_mse,mean,reference_mean,commit" > "$CSV"
COMMIT="$(git -C "$ROOT" rev-parse --short HEAD)"
for scene in "${SCENES[@]}"; do
  for radius in "${RADII[@]}"; do
    for seed in "${SEED_LIST[@]}"; do
      run="$OUT/$scene-r$radius-s$seed"
      "${MPIRUN[@]}" -np 2 "$BUILD_DIR/relt" render "$ROOT/scenes/$scene.gltf" -o "$run.exr" --time "$BUDGET" \
        --seed "$seed" --integrator vcm --vcm-radius "$radius" 2>/dev/null
      c="$(compare_row "$run.exr" "$ROOT/scenes/references/$scene.exr")"
      # A render again replaces its old row, so the table is over the latest reference and code.
      sed -i "/^$scene,$radius,$seed,$BUDGET,/d" "$CSV"
      echo "$scene,$radius,$seed,$BUDGET,$c,$COMMIT" | tee -a "$CSV"
    done
  done
done
/usr/bin/python3 - "$CSV" "$BUDGET" <<'PY'
import csv, sys, math
from collections import defaultdict
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["seconds"] == sys.argv[2]]
mse, bias = defaultdict(list), defaultdict(list)
for r in rows:
    key = (r["scene"], float(r["radius"]))
    mse[key].append(float(r["rmse"]) ** 2)
    bias[key].append(float(r["mean"]) / float(r["reference_mean"]) - 1)
radii = sorted({k[1] for k in mse})
print("| scene | " + " | ".join("r = %g" % r for r in radii) + " |")
print("|---" * (len(radii) + 1) + "|")
for scene in dict.fromkeys(k[0] for k in mse):
    cells = []
    for r in radii:
        v = mse.get((scene, r))
        cells.append("%.4g (%+.2f %%)" % (math.sqrt(sum(v) / len(v)), 100 * sum(bias[(scene, r)]) / len(v)) if v else "")
    print("| %s | %s |" % (scene, " | ".join(cells)))
PY
