#!/usr/bin/env bash
# Cost of checkpoints: renders SCENE for SECONDS on 2 ranks at WIDTH x HEIGHT with each of relt
# (its defaults: 32 ladders x 4 levels) and pt, without checkpoints and with one every EVERY
# seconds; prints the checkpoint's size, the writes and their mean time (stats.json
# `checkpoints`), and the throughput of both runs. Runs stay in out/bench/checkpoint/.
# Usage: scripts/bench/checkpoint_cost.sh [SCENE] [SECONDS] [EVERY] [WIDTH] [HEIGHT]
set -euo pipefail
source "$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/setup.sh"
SCENE="${1:-cornell-box}"
SECONDS_="${2:-20}"
EVERY="${3:-1}"
W="${4:-512}"
H="${5:-512}"
OUT="$ROOT/out/bench/checkpoint"
rm -rf "$OUT"
mkdir -p "$OUT"
echo "| integrator | checkpoint size | writes | seconds per write | throughput without | with a checkpoint every ${EVERY} s |"
echo "|---|---|---|---|---|---|"
for integrator in relt pt; do
  for mode in plain ck; do
    extra=()
    [ "$mode" = ck ] && extra=(--checkpoint "$OUT/$integrator-ck" --checkpoint-every "$EVERY")
    "${MPIRUN[@]}" -np 2 "$BUILD_DIR/relt" render "$ROOT/scenes/$SCENE.gltf" -o "$OUT/$integrator-$mode.exr" \
      --integrator "$integrator" --width "$W" --height "$H" --time "$SECONDS_" --stats "$OUT/$integrator-$mode.json" \
      "${extra[@]}" > "$OUT/$integrator-$mode.log" 2>&1
  done
  /usr/bin/python3 - "$OUT" "$integrator" <<'PY'
import json, os, sys
out, integrator = sys.argv[1], sys.argv[2]
plain = json.load(open(f"{out}/{integrator}-plain.json"))
ck = json.load(open(f"{out}/{integrator}-ck.json"))
key = "mutations_per_second" if integrator == "relt" else "samples_per_second"
size = os.path.getsize(f"{out}/{integrator}-ck/checkpoint.relt") / 2**20
c = ck["checkpoints"]
print(f"| {integrator} | {size:.1f} MiB | {c['written']} | {c['seconds'] / c['written']:.3f} | "
      f"{plain[key] / 1e6:.3f} M/s | {ck[key] / 1e6:.3f} M/s |")
PY
done
