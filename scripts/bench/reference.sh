#!/usr/bin/env bash
# A long reference render of one scene of the suite at its test resolution, stored in
# scenes/references/SCENE.exr with SCENE.json next to it: the method, the commands that made it, the
# commit, the machine, the renders' stats and an estimate of the reference's own error.
#
# Every method splits the time into two independent halves of different seeds and takes their pixel
# mean (`relt average`). Their difference is only their errors, so RMSE(halves) / 2 is the RMSE of
# the mean (stored as reference_rmse_estimate); where one half is unbiased, a bias of the other
# shows in that difference too, at twice its size in the mean, so the estimate covers it.
# Methods (METHOD=bdpt|chains|mixed overrides the scene's default):
# - bdpt: bdpt (seeds 99 and 98): unbiased, and since every light of the suite is an area light it
#   reaches every path; the default for scenes whose light reaches the eye through diffuse surfaces.
# - chains, the default for glass-cube, water-box and torus-in-glass: caustics seen through glass or
#   water (specular-diffuse-specular paths) are sampled by bdpt only when its camera path happens to
#   hit the light, so they stay speckled after hours. The Markov-chain integrators find them, but one
#   integrator's long run would make a reference that its own estimator's error shares: pssmlt
#   (seed 99) and relt (seed 98), both estimating the directly seen emission apart with 4096 rays
#   per pixel.
# - mixed, the default for glossy-caustics and living-room: pssmlt (seed 99, as above) and vcm
#   (seed 98). vcm's merging is the most efficient estimator of their glossy and glass caustics but
#   is biased at a finite radius; pairing it with an unbiased half keeps that bias visible in the
#   halves' difference and halves it in the reference.
# Usage: scripts/bench/reference.sh SCENE [SECONDS] [RANKS]   (defaults 1200 s in all, 2 ranks)
set -euo pipefail
source "$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/setup.sh"
SCENE="${1:?usage: reference.sh SCENE [SECONDS] [RANKS]}"
SECONDS_BUDGET="${2:-1200}"
RANKS="${3:-2}"
[ -f "$ROOT/scenes/$SCENE.gltf" ] || { echo "reference.sh: no scene $ROOT/scenes/$SCENE.gltf" >&2; exit 2; }
case "$SCENE" in
  glass-cube | water-box | torus-in-glass) DEFAULT_METHOD=chains ;;
  glossy-caustics | living-room) DEFAULT_METHOD=mixed ;;
  *) DEFAULT_METHOD=bdpt ;;
esac
METHOD="${METHOD:-$DEFAULT_METHOD}"
HALF="$(/usr/bin/python3 -c "print($SECONDS_BUDGET / 2)")"
PSSMLT=(--integrator pssmlt --time "$HALF" --seed 99 --direct-emission-spp 4096)
case "$METHOD" in
  bdpt) A=(--integrator bdpt --time "$HALF" --seed 99) B=(--integrator bdpt --time "$HALF" --seed 98) ;;
  chains) A=("${PSSMLT[@]}") B=(--integrator relt --time "$HALF" --seed 98 --direct-emission-spp 4096) ;;
  mixed) A=("${PSSMLT[@]}") B=(--integrator vcm --time "$HALF" --seed 98) ;;
  *) echo "reference.sh: METHOD must be bdpt, chains or mixed, not $METHOD" >&2; exit 2 ;;
esac
DIR="$ROOT/scenes/references"
mkdir -p "$DIR"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
COMMIT="$(git -C "$ROOT" rev-parse --short HEAD)"
MACHINE="$(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores"

# render NAME ARGS...: one render of the scene into $TMP/NAME.exr, its stats into $TMP/NAME.json.
render() {
  local name="$1"
  shift
  (cd "$ROOT" && "${MPIRUN[@]}" -np "$RANKS" "$BUILD_DIR/relt" render "scenes/$SCENE.gltf" -o "$TMP/$name.exr" \
    --stats "$TMP/$name.json" "$@")
}

render a "${A[@]}"
render b "${B[@]}"
"$BUILD_DIR/relt" average "$TMP/a.exr" "$TMP/b.exr" -o "$TMP/$SCENE.exr" --png "$TMP/$SCENE.png"
"$BUILD_DIR/relt" compare "$TMP/a.exr" "$TMP/b.exr" > "$TMP/halves.json"
/usr/bin/python3 - "$TMP" "$DIR/$SCENE.json" "$RANKS" "$SCENE" "$COMMIT" "$MACHINE" "$METHOD" "${A[*]}" "${B[*]}" <<'PY'
import json, sys
tmp, out, ranks, scene, commit, machine, method, a, b = sys.argv[1:]
halves = json.load(open(tmp + "/halves.json"))
stats = {"a": json.load(open(tmp + "/a.json")), "b": json.load(open(tmp + "/b.json"))}
cmd = "mpirun -np %s relt render scenes/%s.gltf -o %%s.exr %%s" % (ranks, scene)
json.dump({"method": method + ": the mean of two independent renders of half the time each",
           "commands": [cmd % ("a", a), cmd % ("b", b),
                        "relt average a.exr b.exr -o scenes/references/%s.exr" % scene],
           "halves": {"rmse": halves["rmse"], "rel_mse": halves["rel_mse"], "mean_a": halves["mean"],
                      "mean_b": halves["reference_mean"]},
           "reference_rmse_estimate": halves["rmse"] / 2,
           "commit": commit, "machine": machine, "stats": stats},
          open(out, "w"), indent=1)
print("halves: RMSE %.5f (reference's own RMSE about %.5f), means %.5f / %.5f"
      % (halves["rmse"], halves["rmse"] / 2, halves["mean"], halves["reference_mean"]))
PY
mv "$TMP/$SCENE.exr" "$DIR/$SCENE.exr"
mv "$TMP/$SCENE.png" "$DIR/$SCENE.png"
echo "reference: $DIR/$SCENE.exr ($DIR/$SCENE.json)"
