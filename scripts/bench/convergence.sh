#!/usr/bin/env bash
# Convergence of integrator configurations on one scene: each renders for SECONDS on 2 ranks with
# snapshots every SNAP seconds, every snapshot is compared with scenes/references/SCENE.exr
# (scripts/bench/reference.sh), and RMSE against time is plotted log-log. Also an equal-time table
# (final RMSE, relative MSE, speedup of each configuration over pssmlt = (RMSE_pssmlt / RMSE)^2)
# and a strip of crops of the final images next to the reference's.
# Writes docs/img/convergence-SCENE.{csv,png,md} and docs/img/crops-SCENE.png; runs stay in
# out/bench/convergence/.
# Usage: scripts/bench/convergence.sh SCENE [SECONDS] [CONFIG...]
#   CONFIG: pt, bdpt, pssmlt, mmlt, erpt, relt (relt's recommended defaults), or NAME=ARGS with the
#   relt options separated by '+', e.g. relt-relaxed=--integrator+relt+--family+relaxed
#   env: SNAP (default SECONDS / 10, at least 2), CROP "X Y W H" in pixels (default: the centre third)
set -euo pipefail
source "$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/setup.sh"
source "$ROOT/scripts/bench/snapshots.sh"
SCENE="${1:?usage: convergence.sh SCENE [SECONDS] [CONFIG...]}"
BUDGET="${2:-60}"
shift $(($# > 1 ? 2 : 1))
CONFIGS=("$@")
((${#CONFIGS[@]})) || CONFIGS=(pt bdpt pssmlt mmlt erpt relt)
SNAP="${SNAP:-$(( BUDGET / 10 > 2 ? BUDGET / 10 : 2 ))}"
REF="$ROOT/scenes/references/$SCENE.exr"
[ -f "$REF" ] || { echo "convergence.sh: no reference $REF; run scripts/bench/reference.sh $SCENE" >&2; exit 2; }
OUT="$ROOT/out/bench/convergence"
IMG="$ROOT/docs/img"
mkdir -p "$OUT" "$IMG"

csv="$IMG/convergence-$SCENE.csv"
echo "configuration,seconds,rmse,rel_mse" > "$csv"
finals="$OUT/$SCENE-finals.csv"
echo "configuration,rmse,rel_mse,png" > "$finals"
for config in "${CONFIGS[@]}"; do
  name="${config%%=*}"
  if [[ "$config" == *=* ]]; then args="${config#*=}"; args="${args//+/ }"; else args="--integrator $config"; fi
  run="$OUT/$SCENE-$name"
  snap="$SNAP"
  [[ " $args " == *" --integrator erpt "* ]] && snap=0  # erpt writes no snapshots: its final point only
  # shellcheck disable=SC2086
  render_followed "$run" "$SCENE" "$BUDGET" "$snap" $args
  curve "$run" "$REF" "$name"
  cat "$run.csv" >> "$csv"
  read -r rmse rel < <(compare "$run.exr" "$REF")
  echo "$name,$rmse,$rel,$run.png" >> "$finals"
done
plot_curves "$csv" "$IMG/convergence-$SCENE.png" "$SCENE, ${BUDGET} s on 2 ranks"
/usr/bin/python3 "$ROOT/scripts/bench/crops.py" "$finals" "${REF%.exr}.png" "$IMG/crops-$SCENE.png" \
  "$SCENE: %s, $BUDGET s on 2 ranks" "${CROP:-}"
/usr/bin/python3 - "$finals" "$IMG/convergence-$SCENE.md" "$SCENE" "$BUDGET" "$(git -C "$ROOT" rev-parse --short HEAD)" <<'PY'
import csv, sys, datetime
finals, table, scene, budget, commit = sys.argv[1:6]
rows = list(csv.DictReader(open(finals)))
base = next((float(r["rmse"]) for r in rows if r["configuration"] == "pssmlt"), None)
with open(table, "w") as f:
    f.write("%s, %s s on 2 ranks (seed 1) against scenes/references/%s.exr; %s, commit %s\n\n"
            % (scene, budget, scene, datetime.date.today(), commit))
    f.write("| configuration | RMSE | relative MSE | speedup over pssmlt |\n|---|---|---|---|\n")
    for r in rows:
        speed = "%.2f" % ((base / float(r["rmse"])) ** 2) if base else "-"
        f.write("| %s | %.5f | %.5f | %s |\n" % (r["configuration"], float(r["rmse"]), float(r["rel_mse"]), speed))
print(open(table).read())
PY
