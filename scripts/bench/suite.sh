#!/usr/bin/env bash
# The equal-time table over the whole suite: each configuration renders each scene for SHORT and
# LONG seconds on 2 ranks with every seed of SEEDS, compared with scenes/references/SCENE.exr.
# Results are appended to docs/img/suite.csv as they come (one row a render, with its commit), so
# the table is built over several sittings: a group (scene, seed, length: every configuration) found
# complete there is skipped, an incomplete one is rendered again whole. The first seed's LONG group
# also writes RMSE-over-time curves (docs/img/suite-curves-SCENE.{csv,png}, snapshots every LONG/20 s)
# and crops of its final images next to the reference (docs/img/suite-crops-SCENE.png). Then
# docs/img/suite.md is made from the CSV (scripts/bench/suite_table.py).
# With ADD=1 the CONFIGS are added to groups recorded already: only the configurations without a row
# are rendered, the others' rows are kept (they came from another sitting), the curves get the
# added configurations' lines and the crops are left as they were.
# Usage: scripts/bench/suite.sh [SCENE...]   (default every scene with a reference)
#   env: CONFIGS (default "bdpt pssmlt relt vcm"), SEEDS ("1 2"), SHORT (30), LONG (120), ADD (0)
set -euo pipefail
source "$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/setup.sh"
source "$ROOT/scripts/bench/snapshots.sh"
source "$ROOT/scripts/bench/common.sh"
read -r -a CONFIGS <<< "${CONFIGS:-bdpt pssmlt relt vcm}"
read -r -a SEED_LIST <<< "${SEEDS:-1 2}"
SHORT="${SHORT:-30}" LONG="${LONG:-120}" ADD="${ADD:-0}"
SCENES=("$@")
((${#SCENES[@]})) || SCENES=("${SUITE_SCENES[@]}")
IMG="$ROOT/docs/img"
OUT="$ROOT/out/bench/suite"
CSV="$IMG/suite.csv"
mkdir -p "$IMG" "$OUT"
[ -f "$CSV" ] || echo "scene,configuration,seed,seconds,rmse,rel_mse,mean,reference_mean,commit,date" > "$CSV"
COMMIT="$(git -C "$ROOT" rev-parse --short HEAD)"

# done_in_csv SCENE CONFIG SEED SECONDS: that render has a row.
done_in_csv() { grep -q "^$1,$2,$3,$4," "$CSV"; }

# group SCENE SEED SECONDS: every configuration's render, unless all are in the CSV already (with
# ADD=1: the configurations not in it).
group() {
  local scene="$1" seed="$2" secs="$3" ref="$ROOT/scenes/references/$1.exr" config todo=() curves=0
  for config in "${CONFIGS[@]}"; do done_in_csv "$scene" "$config" "$seed" "$secs" || todo+=("$config"); done
  ((${#todo[@]})) || { echo "suite: $scene seed $seed ${secs} s: in $CSV already"; return; }
  ((ADD)) || todo=("${CONFIGS[@]}")  # an incomplete group is rendered again whole
  [ "$seed" = "${SEED_LIST[0]}" ] && [ "$secs" = "$LONG" ] && curves=1
  local rows=() curve_csv="$OUT/$scene-curves.csv" finals="$OUT/$scene-finals.csv" kept="$IMG/suite-curves-$scene.csv"
  echo "configuration,seconds,rmse,rel_mse" > "$curve_csv"
  if ((ADD)) && [ -f "$kept" ]; then
    tail -n +2 "$kept" | grep -v -E "^($(IFS='|'; echo "${todo[*]}"))," >> "$curve_csv" || true
  fi
  echo "configuration,rmse,rel_mse,png" > "$finals"
  for config in "${todo[@]}"; do
    local run="$OUT/$scene-$config-s$seed-$secs" snap=0
    ((curves)) && [ "$config" != erpt ] && snap=$((LONG / 20 > 1 ? LONG / 20 : 1))
    SEED="$seed" render_followed "$run" "$scene" "$secs" "$snap" --integrator "$config"
    if ((curves)); then curve "$run" "$ref" "$config" && cat "$run.csv" >> "$curve_csv"; fi
    local c
    c="$(compare_row "$run.exr" "$ref")"
    rows+=("$scene,$config,$seed,$secs,$c,$COMMIT,$(date -u +%Y-%m-%d)")
    echo "$config,${c%%,*},$(echo "$c" | cut -d, -f2),$run.png" >> "$finals"
    echo "suite: $scene $config seed $seed ${secs} s: rmse ${c%%,*}"
  done
  # Only a whole group is recorded (its renders shared the machine's state of one sitting), or with
  # ADD=1 the configurations added.
  if ((ADD)); then
    for config in "${todo[@]}"; do sed -i "/^$scene,$config,$seed,$secs,/d" "$CSV"; done
  else
    sed -i "/^$scene,[^,]*,$seed,$secs,/d" "$CSV"
  fi
  printf '%s\n' "${rows[@]}" >> "$CSV"
  if ((curves)); then
    cp "$curve_csv" "$kept"
    plot_curves "$curve_csv" "$IMG/suite-curves-$scene.png" "$scene, ${secs} s on 2 ranks (seed $seed)"
    ((ADD)) || /usr/bin/python3 "$ROOT/scripts/bench/crops.py" "$finals" "$ROOT/scenes/references/$scene.png" \
      "$IMG/suite-crops-$scene.png" "$scene: %s, ${secs} s on 2 ranks (seed $seed)" "${CROP:-}"
  fi
}

for scene in "${SCENES[@]}"; do
  [ -f "$ROOT/scenes/references/$scene.exr" ] || { echo "suite: no reference for $scene, skipped" >&2; continue; }
  for seed in "${SEED_LIST[@]}"; do
    group "$scene" "$seed" "$LONG"
    group "$scene" "$seed" "$SHORT"
  done
done
/usr/bin/python3 "$ROOT/scripts/bench/suite_table.py" "$CSV" "$IMG/suite.md"
