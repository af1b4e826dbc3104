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
# The halves are kept (scenes/references/halves/SCENE.a.exr, .b.exr), so a reference can be made
# longer over several sittings: EXTEND=1 renders a new pair of halves of SECONDS in all (the next
# seeds: 97 and 96, then 95 and 94, ...) and merges each into the stored half of its method, weighted
# by rays traced (the work of one integrator, whatever else shared the machine); the JSON lists
# every pair ("passes").
# Usage: scripts/bench/reference.sh SCENE [SECONDS] [RANKS]   (defaults 1200 s in all, 2 ranks)
#        EXTEND=1 scripts/bench/reference.sh SCENE SECONDS [RANKS]
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
DIR="$ROOT/scenes/references"
HALVES="$DIR/halves"
PASSES=0
if [ "${EXTEND:-0}" = 1 ]; then
  [ -f "$HALVES/$SCENE.a.exr" ] && [ -f "$HALVES/$SCENE.b.exr" ] && [ -f "$DIR/$SCENE.json" ] ||
    { echo "reference.sh: EXTEND=1 needs the halves of a previous reference in $HALVES" >&2; exit 2; }
  read -r PASSES STORED_METHOD < <(/usr/bin/python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(len(d['passes']), d['method'].split(':')[0])" "$DIR/$SCENE.json")
  DEFAULT_METHOD="$STORED_METHOD"
fi
METHOD="${METHOD:-$DEFAULT_METHOD}"
[ "${EXTEND:-0}" != 1 ] || [ "$METHOD" = "$STORED_METHOD" ] ||
  { echo "reference.sh: the stored reference of $SCENE is $STORED_METHOD, not $METHOD" >&2; exit 2; }
HALF="$(/usr/bin/python3 -c "print($SECONDS_BUDGET / 2)")"
SEED_A=$((99 - 2 * PASSES)) SEED_B=$((98 - 2 * PASSES))
PSSMLT=(--integrator pssmlt --time "$HALF" --seed "$SEED_A" --direct-emission-spp 4096)
case "$METHOD" in
  bdpt) A=(--integrator bdpt --time "$HALF" --seed "$SEED_A") B=(--integrator bdpt --time "$HALF" --seed "$SEED_B") ;;
  chains) A=("${PSSMLT[@]}") B=(--integrator relt --time "$HALF" --seed "$SEED_B" --direct-emission-spp 4096) ;;
  mixed) A=("${PSSMLT[@]}") B=(--integrator vcm --time "$HALF" --seed "$SEED_B") ;;
  *) echo "reference.sh: METHOD must be bdpt, chains or mixed, not $METHOD" >&2; exit 2 ;;
esac
mkdir -p "$DIR" "$HALVES"
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
# merge HALF: the new render of that half, merged into the stored one by rays traced.
merge() {
  local half="$1" old_rays new_rays
  if ((PASSES == 0)); then cp "$TMP/$half.exr" "$TMP/$half.merged.exr"; return; fi
  read -r old_rays new_rays < <(/usr/bin/python3 -c "
import json, sys
old = sum(p['stats'][sys.argv[3]]['rays'] for p in json.load(open(sys.argv[1]))['passes'])
print(old, json.load(open(sys.argv[2]))['rays'])" "$DIR/$SCENE.json" "$TMP/$half.json" "$half")
  "$BUILD_DIR/relt" average "$HALVES/$SCENE.$half.exr" "$TMP/$half.exr" --weights "$old_rays,$new_rays" \
    -o "$TMP/$half.merged.exr"
}
merge a
merge b
"$BUILD_DIR/relt" average "$TMP/a.merged.exr" "$TMP/b.merged.exr" -o "$TMP/$SCENE.exr" --png "$TMP/$SCENE.png"
"$BUILD_DIR/relt" compare "$TMP/a.merged.exr" "$TMP/b.merged.exr" > "$TMP/halves.json"
PREVIOUS="$DIR/$SCENE.json"
((PASSES)) || PREVIOUS=""
/usr/bin/python3 - "$TMP" "$TMP/$SCENE.json" "$RANKS" "$SCENE" "$COMMIT" "$MACHINE" "$METHOD" "${A[*]}" "${B[*]}" "$PREVIOUS" <<'PY'
import datetime, json, sys
tmp, out, ranks, scene, commit, machine, method, a, b, previous = sys.argv[1:]
halves = json.load(open(tmp + "/halves.json"))
cmd = "mpirun -np %s relt render scenes/%s.gltf -o %%s.exr %%s" % (ranks, scene)
passes = json.load(open(previous))["passes"] if previous else []
passes.append({"commands": [cmd % ("a", a), cmd % ("b", b)], "commit": commit, "machine": machine,
               "date": datetime.date.today().isoformat(),
               "stats": {"a": json.load(open(tmp + "/a.json")), "b": json.load(open(tmp + "/b.json"))}})
for p in passes:  # per-chain details would make the file megabytes; the totals stay
    for s in p["stats"].values():
        for key in [k for k, v in s.items() if isinstance(v, list) and len(v) > 64]:
            del s[key]
seconds = sum(p["stats"][h]["render_seconds"] for p in passes for h in "ab")
json.dump({"method": method + ": the mean of two independent halves, each the rays-weighted mean of its passes",
           "merge": "each half: relt average of its passes --weights RAYS; reference: relt average a.exr b.exr",
           "seconds": seconds,
           "halves": {"rmse": halves["rmse"], "rel_mse": halves["rel_mse"], "mean_a": halves["mean"],
                      "mean_b": halves["reference_mean"]},
           "reference_rmse_estimate": halves["rmse"] / 2, "passes": passes},
          open(out, "w"), indent=1)
print("%s: %d passes, %.0f s; halves: RMSE %.5f (reference's own RMSE about %.5f), means %.5f / %.5f"
      % (scene, len(passes), seconds, halves["rmse"], halves["rmse"] / 2, halves["mean"], halves["reference_mean"]))
PY
# The stored files change only now, together, once every render and merge has succeeded.
mv "$TMP/a.merged.exr" "$HALVES/$SCENE.a.exr"
mv "$TMP/b.merged.exr" "$HALVES/$SCENE.b.exr"
mv "$TMP/$SCENE.exr" "$DIR/$SCENE.exr"
mv "$TMP/$SCENE.png" "$DIR/$SCENE.png"
mv "$TMP/$SCENE.json" "$DIR/$SCENE.json"
echo "reference: $DIR/$SCENE.exr ($DIR/$SCENE.json, halves in $HALVES)"
