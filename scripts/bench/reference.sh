#!/usr/bin/env bash
# A long reference render of one scene of the suite at its test resolution, stored in
# scenes/references/SCENE.exr with SCENE.json next to it: the command that made it, the commit, the
# machine, and the render's stats (settings, samples, time).
# The integrator is bdpt for every scene: it is unbiased and, because every light of the suite is an
# area light (scenes/README.md), it reaches every path, including the caustics seen through glass
# (specular-diffuse-specular paths) that only its camera-side strategy (s = 0, the camera path hitting
# the light) can sample; such paths converge slowly, hence the long time. pt reaches them too but
# with more noise; the Markov-chain integrators are consistent but their error is harder to state.
# Usage: scripts/bench/reference.sh SCENE [SECONDS] [RANKS]   (defaults 600 s, 2 ranks; seed 99)
set -euo pipefail
source "$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/setup.sh"
SCENE="${1:?usage: reference.sh SCENE [SECONDS] [RANKS]}"
SECONDS_BUDGET="${2:-600}"
RANKS="${3:-2}"
[ -f "$ROOT/scenes/$SCENE.gltf" ] || { echo "reference.sh: no scene $ROOT/scenes/$SCENE.gltf" >&2; exit 2; }
DIR="$ROOT/scenes/references"
mkdir -p "$DIR"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
CMD=(render "scenes/$SCENE.gltf" -o "scenes/references/$SCENE.exr" --integrator bdpt --time "$SECONDS_BUDGET" --seed 99)
(cd "$ROOT" && "${MPIRUN[@]}" -np "$RANKS" "$BUILD_DIR/relt" "${CMD[@]:0:2}" -o "$TMP/$SCENE.exr" "${CMD[@]:4}" \
  --stats "$TMP/stats.json" --png "$TMP/$SCENE.png")
/usr/bin/python3 - "$TMP/stats.json" "$DIR/$SCENE.json" "mpirun -np $RANKS relt ${CMD[*]}" \
  "$(git -C "$ROOT" rev-parse --short HEAD)" "$(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores" <<'PY'
import json, sys
stats = json.load(open(sys.argv[1]))
json.dump({"command": sys.argv[3], "commit": sys.argv[4], "machine": sys.argv[5], "stats": stats},
          open(sys.argv[2], "w"), indent=1)
PY
mv "$TMP/$SCENE.exr" "$DIR/$SCENE.exr"
mv "$TMP/$SCENE.png" "$DIR/$SCENE.png"
echo "reference: $DIR/$SCENE.exr ($DIR/$SCENE.json)"
