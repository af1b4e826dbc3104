#!/usr/bin/env bash
# Whether two relt binaries render the same images, for a change meant to change none: every
# suite scene, every integrator, on 1 and 2 ranks, at 24x16 with seed 3 (2 spp or 2 mutations per
# pixel). Prints each pair that differs (RMSE from `relt compare`) and a count; exits 1 on any.
# Usage: scripts/checks/same_images.sh OLD_BIN NEW_BIN   (about 2 minutes on 2 cores)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
OLD="$1"
NEW="$2"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
MPIRUN=(mpirun --oversubscribe --mca pml ob1 --mca btl self,vader)
OUT="$(mktemp -d)"
trap 'rm -rf "$OUT"' EXIT
compared=0 differing=0
for scene in "$ROOT"/scenes/*.gltf; do
  for integrator in pt bdpt pssmlt mmlt erpt relt; do
    case $integrator in pt | bdpt | erpt) budget=(--spp 2) ;; *) budget=(--mutations-per-pixel 2) ;; esac
    for ranks in 1 2; do
      args=("$scene" --integrator "$integrator" --width 24 --height 16 "${budget[@]}" --seed 3)
      "${MPIRUN[@]}" -np "$ranks" "$OLD" render "${args[@]}" -o "$OUT/old.exr" > /dev/null 2>&1
      "${MPIRUN[@]}" -np "$ranks" "$NEW" render "${args[@]}" -o "$OUT/new.exr" > /dev/null 2>&1
      rmse=$("$NEW" compare "$OUT/new.exr" "$OUT/old.exr" | /usr/bin/python3 -c "import json, sys; print(json.load(sys.stdin)['rmse'])")
      compared=$((compared + 1))
      if [ "$rmse" != "0" ]; then
        differing=$((differing + 1))
        echo "differs: $(basename "$scene" .gltf) $integrator on $ranks ranks, RMSE $rmse"
      fi
    done
  done
done
echo "compared $compared renders, $differing differ"
[ "$differing" -eq 0 ]
