#!/usr/bin/env bash
# A long reference render of one scene of the suite at its test resolution, stored in
# scenes/references/SCENE.exr with SCENE.json next to it: the method, the commands that made it, the
# commit, the machine, the renders' stats and, for the chains method, an estimate of its own error.
#
# Two methods (METHOD=bdpt|chains overrides the scene's default):
# - bdpt (seed 99): unbiased, and since every light of the suite is an area light it reaches every
#   path; the default for scenes whose light reaches the eye through diffuse surfaces.
# - chains, the default for glass-cube, water-box and torus-in-glass: caustics seen through glass or
#   water (specular-diffuse-specular paths) are sampled by bdpt only when its camera path happens to
#   hit the light, so they stay speckled after hours (water-box's under-water floor above all). The
#   Markov-chain integrators find them, but one integrator's long run would make a reference that
#   its own estimator's error shares. So the time is split into two independent halves, pssmlt
#   (seed 99) and relt (seed 98), both estimating the directly seen emission apart with 4096
#   rays per pixel, and the reference is their pixel mean (`relt average`). Both are
#   consistent, so their difference is only their error: RMSE(halves) / 2 estimates the reference's
#   own RMSE (stored as reference_rmse_estimate), and a difference in the means would show a bias.
# Usage: scripts/bench/reference.sh SCENE [SECONDS] [RANKS]   (defaults 1200 s, 2 ranks)
set -euo pipefail
source "$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/setup.sh"
SCENE="${1:?usage: reference.sh SCENE [SECONDS] [RANKS]}"
SECONDS_BUDGET="${2:-1200}"
RANKS="${3:-2}"
[ -f "$ROOT/scenes/$SCENE.gltf" ] || { echo "reference.sh: no scene $ROOT/scenes/$SCENE.gltf" >&2; exit 2; }
case "$SCENE" in
  glass-cube | water-box | torus-in-glass) DEFAULT_METHOD=chains ;;
  *) DEFAULT_METHOD=bdpt ;;
esac
METHOD="${METHOD:-$DEFAULT_METHOD}"
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

case "$METHOD" in
  bdpt)
    ARGS=(--integrator bdpt --time "$SECONDS_BUDGET" --seed 99)
    render bdpt "${ARGS[@]}" --png "$TMP/$SCENE.png"
    mv "$TMP/bdpt.exr" "$TMP/$SCENE.exr"
    /usr/bin/python3 - "$TMP" "$DIR/$SCENE.json" "$RANKS" "$SCENE" "$COMMIT" "$MACHINE" "${ARGS[*]}" <<'PY'
import json, sys
tmp, out, ranks, scene, commit, machine, args = sys.argv[1:]
stats = json.load(open(tmp + "/bdpt.json"))
json.dump({"method": "bdpt", "command": "mpirun -np %s relt render scenes/%s.gltf -o scenes/references/%s.exr %s"
           % (ranks, scene, scene, args), "commit": commit, "machine": machine, "stats": stats},
          open(out, "w"), indent=1)
PY
    ;;
  chains)
    HALF="$(/usr/bin/python3 -c "print($SECONDS_BUDGET / 2)")"
    PSSMLT=(--integrator pssmlt --time "$HALF" --seed 99 --direct-emission-spp 4096)
    RELT=(--integrator relt --time "$HALF" --seed 98 --direct-emission-spp 4096)
    render pssmlt "${PSSMLT[@]}"
    render relt "${RELT[@]}"
    "$BUILD_DIR/relt" average "$TMP/pssmlt.exr" "$TMP/relt.exr" -o "$TMP/$SCENE.exr" --png "$TMP/$SCENE.png"
    "$BUILD_DIR/relt" compare "$TMP/pssmlt.exr" "$TMP/relt.exr" > "$TMP/halves.json"
    /usr/bin/python3 - "$TMP" "$DIR/$SCENE.json" "$RANKS" "$SCENE" "$COMMIT" "$MACHINE" "${PSSMLT[*]}" "${RELT[*]}" <<'PY'
import json, sys
tmp, out, ranks, scene, commit, machine, pssmlt, relt = sys.argv[1:]
halves = json.load(open(tmp + "/halves.json"))
cmd = "mpirun -np %s relt render scenes/%s.gltf -o %%s.exr %%s" % (ranks, scene)
json.dump({"method": "chains: mean of a pssmlt and a relt render of half the time each",
           "commands": [cmd % ("pssmlt", pssmlt), cmd % ("relt", relt),
                        "relt average pssmlt.exr relt.exr -o scenes/references/%s.exr" % scene],
           "halves": {"rmse": halves["rmse"], "rel_mse": halves["rel_mse"], "mean_pssmlt": halves["mean"],
                      "mean_relt": halves["reference_mean"]},
           "reference_rmse_estimate": halves["rmse"] / 2,
           "commit": commit, "machine": machine,
           "stats": {"pssmlt": json.load(open(tmp + "/pssmlt.json")), "relt": json.load(open(tmp + "/relt.json"))}},
          open(out, "w"), indent=1)
print("halves: RMSE %.5f (reference's own RMSE about %.5f), means %.5f / %.5f"
      % (halves["rmse"], halves["rmse"] / 2, halves["mean"], halves["reference_mean"]))
PY
    ;;
  *) echo "reference.sh: METHOD must be bdpt or chains, not $METHOD" >&2; exit 2 ;;
esac
mv "$TMP/$SCENE.exr" "$DIR/$SCENE.exr"
mv "$TMP/$SCENE.png" "$DIR/$SCENE.png"
echo "reference: $DIR/$SCENE.exr ($DIR/$SCENE.json)"
