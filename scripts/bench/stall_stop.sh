#!/usr/bin/env bash
# Two reliability figures of relt on 2 ranks (glass-cube 128x128, defaults), each after about 100,
# 1,000 and 10,000 rounds of the chains:
#  - stall: a --time budget with one rank paused (SIGSTOP, SIGCONT) for PAUSE seconds at that
#    point; the render's seconds against the budget (it must hold within 2 %, at most 0.5 s over);
#  - stop: SIGTERM to mpirun at that point, with --checkpoint; seconds until the image and the
#    checkpoint first exist, and until the final stats.json (mpirun kills the ranks 2 s after).
# The moments come from a calibration render (its setup time and rounds per second). The
# direct-emission pass takes a fixed 64 rays per pixel here, so that the moments fall in the
# chains' rounds (on auto, a 600 s budget gives it up to 36 s). Further rows: the stops again with
# packed placement, a default render stopped 2 s into its direct-emission pass, and bdpt at
# 1024x1024 stopped inside a pass.
# Usage: scripts/bench/stall_stop.sh [PAUSE] [ROUNDS...]   (defaults 0.3; 100 1000 10000)
# Writes out/bench/stall_stop.md.
set -euo pipefail
source "$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/setup.sh"
PAUSE="${1:-0.3}"
shift $(($# > 0 ? 1 : 0))
ROUNDS=("$@")
((${#ROUNDS[@]})) || ROUNDS=(100 1000 10000)
OUT="$ROOT/out/bench/stall-stop"
mkdir -p "$OUT"
TABLE="$ROOT/out/bench/stall_stop.md"
RENDER=("$BUILD_DIR/relt" render "$ROOT/scenes/glass-cube.gltf" --integrator relt --width 128 --height 128
        --direct-emission-spp 64)

# Calibration: seconds before the chains' first round, and rounds per second.
"${MPIRUN[@]}" -np 2 "${RENDER[@]}" -o "$OUT/calibrate.exr" --stats "$OUT/calibrate.json" --time 10 2>/dev/null
read -r SETUP RATE < <(/usr/bin/python3 -c "
import json; j = json.load(open('$OUT/calibrate.json')); r = j['relt']
print(j['wall_seconds'] - r['loop_seconds'], r['rounds'] / r['loop_seconds'])")

{
  echo "relt on 2 ranks, glass-cube 128x128, defaults; calibration: $(printf %.2f "$SETUP") s before the chains, $(printf %.0f "$RATE") rounds/s;"
  echo "$(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores, $(date -u +%Y-%m-%d), commit $(git -C "$ROOT" rev-parse --short HEAD)"
  echo
  echo "| rounds before | stall: budget s | stall: render s | stall: off by | stop: rounds | stop: image s | stop: checkpoint s | stop: final stats s |"
  echo "|---|---|---|---|---|---|---|---|"
} > "$TABLE"

# stop_after DIR SECONDS RENDER...: SIGTERM to mpirun SECONDS into a --time 600 render with a
# checkpoint; DIR/seen.txt gets the seconds until the image, the checkpoint and stats.json exist.
stop_after() {
  local dir="$1" at="$2"
  shift 2
  rm -rf "$dir"; mkdir -p "$dir"
  "${MPIRUN[@]}" -np 2 "$@" -o "$dir/out.exr" --stats "$dir/stats.json" --time 600 --checkpoint "$dir/ck" 2>/dev/null &
  local job=$!
  sleep "$at"
  /usr/bin/python3 - "$job" "$dir" > "$dir/seen.txt" <<'PY'
import os, signal, sys, time
pid, d = int(sys.argv[1]), sys.argv[2]
files = {"image": d + "/out.exr", "checkpoint": d + "/ck/checkpoint.relt", "stats": d + "/stats.json"}
t0 = time.time()
os.kill(pid, signal.SIGTERM)
seen = {}
while time.time() - t0 < 5 and len(seen) < len(files):
    for k, f in files.items():
        if k not in seen and os.path.exists(f):
            seen[k] = time.time() - t0
    time.sleep(0.002)
print(" ".join("%.3f" % seen.get(k, float("nan")) for k in files))
PY
  wait "$job" || true
}

for n in "${ROUNDS[@]}"; do
  at=$(/usr/bin/python3 -c "print(round($SETUP + $n / $RATE, 2))")
  budget=$(/usr/bin/python3 -c "print(round(2 * $at, 1))")
  # Stall: pause the second rank for PAUSE seconds once n rounds are behind.
  "${MPIRUN[@]}" -np 2 "${RENDER[@]}" -o "$OUT/stall-$n.exr" --stats "$OUT/stall-$n.json" --time "$budget" 2>/dev/null &
  job=$!
  sleep "$at"
  victim=$(pgrep -f -n "relt render $ROOT/scenes/glass-cube.gltf")
  kill -STOP "$victim"; sleep "$PAUSE"; kill -CONT "$victim"
  wait "$job"
  # Stop: SIGTERM to mpirun once n rounds are behind; when do the files appear?
  stop_after "$OUT/stop-$n" "$at" "${RENDER[@]}"
  /usr/bin/python3 - "$n" "$budget" "$OUT/stall-$n.json" "$OUT/stop-$n" >> "$TABLE" <<'PY'
import json, sys
n, budget, stall, stop = sys.argv[1], float(sys.argv[2]), json.load(open(sys.argv[3])), sys.argv[4]
seconds = stall["render_seconds"]
image, ck, final = open(stop + "/seen.txt").read().split()
rounds = json.load(open(stop + "/stats.json"))["relt"]["rounds"]
print("| %s | %.1f | %.2f | %+.1f %% | %d | %s | %s | %s |" % (n, budget, seconds, 100 * (seconds / budget - 1), rounds, image, ck, final))
PY
done
# stop_row DIR LABEL: a table row of a stop alone (rounds, or passes and rows of a pass stopped inside).
stop_row() {
  /usr/bin/python3 - "$1" "$2" >> "$TABLE" <<'PY'
import json, sys
image, ck, final = open(sys.argv[1] + "/seen.txt").read().split()
j = json.load(open(sys.argv[1] + "/stats.json"))
if "relt" in j:
    done = str(j["relt"]["rounds"])
elif "spp" in j:
    done = "%d passes + %d rows" % (j["spp"], j.get("rows_of_the_stopped_pass", 0))
else:  # stopped in the direct-emission pass, before the chains
    done = "direct pass, %d rays per pixel" % j["direct_emission_spp"]
print("| %s | | | | %s | %s | %s | %s |" % (sys.argv[2], done, image, ck, final))
PY
}
# Packed placement (local decisions), whose messages come back up to 256 rounds late.
for n in "${ROUNDS[@]}"; do
  at=$(/usr/bin/python3 -c "print(round($SETUP + $n / $RATE, 2))")
  stop_after "$OUT/stop-packed-$n" "$at" "${RENDER[@]}" --placement packed
  stop_row "$OUT/stop-packed-$n" "$n, packed"
done
# A default render (direct-emission pass on auto) stopped 2 s into that pass: no chain has run yet.
stop_after "$OUT/stop-direct" 2 "${RENDER[@]:0:${#RENDER[@]}-2}"
stop_row "$OUT/stop-direct" "in the direct pass (auto)"
# bdpt at 1024x1024 (about a second a pass on 2 ranks) stopped 5 s in: inside a pass.
stop_after "$OUT/stop-bdpt" 5 "$BUILD_DIR/relt" render "$ROOT/scenes/glass-cube.gltf" --integrator bdpt --width 1024 --height 1024
stop_row "$OUT/stop-bdpt" "bdpt 1024x1024, 5 s in"
cat "$TABLE"
