# Shared by the scaling scripts: set-up and build, then run_point appends one CSV row per render.
# shellcheck shell=bash
source "$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/setup.sh"
SCENE="${SCENE:-cornell-box}"
OUT="$ROOT/out/scaling"
mkdir -p "$OUT"
CORES="$(nproc)"

# run_point CSV EXPERIMENT RANKS RELT_ARGS...: one relt render on RANKS ranks of this machine.
run_point() {
  local csv="$1" experiment="$2" ranks="$3"
  shift 3
  local stats="$OUT/$experiment-np$ranks-$(date +%s%N).json"
  "${MPIRUN[@]}" -np "$ranks" "$BUILD_DIR/relt" render "$ROOT/scenes/$SCENE.gltf" -o "$OUT/last.exr" \
    --stats "$stats" --integrator relt "$@" 2>/dev/null
  /usr/bin/python3 "$ROOT/scripts/scaling/row.py" "$stats" "$experiment" "$CORES" >> "$csv"
}

csv_header() {
  echo "experiment,ranks,oversubscribed,interval,placement,ladders,mutations,loop_seconds,collective_share_max,collective_share_mean,step_mean_seconds,step_cv,chain_moves" > "$1"
}

# publish KIND: plots out/scaling/KIND.csv into docs/img/scaling-KIND.png, copies the CSV beside it.
publish() {
  /usr/bin/python3 "$ROOT/scripts/scaling/plot.py" "$OUT/$1.csv" "$1" "$ROOT/docs/img/scaling-$1.png"
  cp "$OUT/$1.csv" "$ROOT/docs/img/scaling-$1.csv"
  cat "$OUT/$1.csv"
}
