# Sourced by the equal-time and convergence scripts (after setup.sh): renders followed by their
# snapshots, error curves against a reference, and their plot.
# shellcheck shell=bash

# compare IMAGE REFERENCE -> "rmse rel_mse"
compare() {
  "$BUILD_DIR/relt" compare "$1" "$2" | /usr/bin/python3 -c "import json,sys; c=json.load(sys.stdin); print(c['rmse'], c['rel_mse'])"
}

# render_followed RUN SCENE SECONDS SNAP ARGS...: renders scenes/SCENE.gltf for SECONDS on 2 ranks
# (seed 1) with a snapshot every SNAP seconds (0: none, erpt has none), copying each one as it appears to
# RUN.snaps/<seconds since start>.exr; the final image is RUN.exr and RUN.png, the stats RUN.json.
render_followed() {
  local run="$1" scene="$2" budget="$3" snap="$4"
  shift 4
  rm -rf "$run.snaps" "$run.exr" && mkdir -p "$run.snaps"
  local every=()
  [ "$snap" = 0 ] || every=(--snapshot-every "$snap")
  "${MPIRUN[@]}" -np 2 "$BUILD_DIR/relt" render "$ROOT/scenes/$scene.gltf" -o "$run.exr" --png "$run.png" \
    --stats "$run.json" --time "$budget" "${every[@]}" --seed "${SEED:-1}" "$@" 2>/dev/null &
  local pid=$! start last="" stamp
  start=$(date +%s.%N)
  while kill -0 "$pid" 2>/dev/null; do
    if [ -f "$run.exr" ]; then
      stamp=$(stat -c %y "$run.exr")
      if [ "$stamp" != "$last" ]; then
        last=$stamp
        cp "$run.exr" "$run.snaps/$(awk -v s="$start" -v n="$(date +%s.%N)" 'BEGIN {printf "%08.2f", n - s}').exr"
      fi
    fi
    sleep 0.2
  done
  wait "$pid"
  # No snapshot seen (erpt, or a render shorter than the polling): the final image is the one point.
  if [ -z "$(ls -A "$run.snaps")" ] && [ -f "$run.exr" ]; then
    cp "$run.exr" "$run.snaps/$(awk -v s="$start" -v n="$(date +%s.%N)" 'BEGIN {printf "%08.2f", n - s}').exr"
  fi
}

# curve RUN REFERENCE NAME: RUN.csv, one line "NAME,seconds,rmse,rel_mse" per snapshot.
curve() {
  local run="$1" ref="$2" name="$3" snap t rmse rel
  : > "$run.csv"
  for snap in "$run.snaps"/*.exr; do
    t=$(basename "$snap" .exr)
    read -r rmse rel < <(compare "$snap" "$ref")
    echo "$name,$t,$rmse,$rel" >> "$run.csv"
  done
}

# plot_curves CSV PNG TITLE: RMSE against time, log-log, one line per configuration.
plot_curves() {
  /usr/bin/python3 - "$1" "$2" "$3" <<'PY'
import csv, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
rows = list(csv.DictReader(open(sys.argv[1])))
fig, ax = plt.subplots(figsize=(6, 4))
for name in dict.fromkeys(r["configuration"] for r in rows):
    pts = sorted((float(r["seconds"]), float(r["rmse"])) for r in rows if r["configuration"] == name)
    ax.plot([p[0] for p in pts], [p[1] for p in pts], marker=".", label=name)
ax.set_xscale("log"); ax.set_yscale("log")
ax.set_xlabel("seconds (2 ranks)"); ax.set_ylabel("RMSE vs reference"); ax.set_title(sys.argv[3])
ax.legend(fontsize=8); fig.tight_layout(); fig.savefig(sys.argv[2], dpi=110)
PY
}
