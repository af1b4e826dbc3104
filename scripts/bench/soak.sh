#!/usr/bin/env bash
# Soak test of checkpoints (run by hand, not in CI): a relt render of about SECONDS on RANKS ranks
# with a checkpoint every EVERY seconds, killed with -9 (one rank, at random) at KILLS random
# moments and resumed each time, against the same render uninterrupted. The final images must be
# equal; the table gives the wall time each kill cost (work since the last checkpoint, the restart).
# Usage: scripts/bench/soak.sh [SECONDS] [KILLS] [RANKS] [EVERY] [SCENE]
#        (defaults 1800 10 4 20 glass-cube; SEED=N picks the kill moments)
# Writes out/bench/soak.md and the two images under out/bench/soak/.
set -euo pipefail
source "$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/setup.sh"
SECONDS_WANTED="${1:-1800}" KILLS="${2:-10}" RANKS="${3:-4}" EVERY="${4:-20}" SCENE="${5:-glass-cube}"
OUT="$ROOT/out/bench/soak"
rm -rf "$OUT"; mkdir -p "$OUT"
TABLE="$ROOT/out/bench/soak.md"
RENDER=("$BUILD_DIR/relt" render "$ROOT/scenes/$SCENE.gltf" --integrator relt --width 128 --height 128)
now() { date +%s.%N; }

# A fixed mutation budget that takes about SECONDS: the image then depends only on it and the seed.
"${MPIRUN[@]}" -np "$RANKS" "${RENDER[@]}" -o "$OUT/calibrate.exr" --stats "$OUT/calibrate.json" --time 20 2>/dev/null
MPP=$(/usr/bin/python3 -c "
import json; j = json.load(open('$OUT/calibrate.json'))
print('%.3f' % (j['mutations_per_second'] * $SECONDS_WANTED / (128 * 128)))")

t0=$(now)
"${MPIRUN[@]}" -np "$RANKS" "${RENDER[@]}" -o "$OUT/uninterrupted.exr" --mutations-per-pixel "$MPP" \
  --checkpoint "$OUT/ck-uninterrupted" --checkpoint-every "$EVERY" 2>/dev/null
plain=$(/usr/bin/python3 -c "print($(now) - $t0)")

# Kill moments: KILLS uniform draws over the render, sorted, as offsets into each attempt.
mapfile -t MOMENTS < <(/usr/bin/python3 -c "
import random; r = random.Random(${SEED:-1}); t = sorted(r.uniform(0.05, 0.95) * $plain for _ in range($KILLS))
print('\n'.join('%.2f' % (b - a) for a, b in zip([0.0] + t, t)))")
t0=$(now)
kills=0
resume=()
for wait_s in "${MOMENTS[@]}" ""; do
  "${MPIRUN[@]}" -np "$RANKS" "${RENDER[@]}" -o "$OUT/interrupted.exr" --mutations-per-pixel "$MPP" \
    --checkpoint "$OUT/ck" --checkpoint-every "$EVERY" "${resume[@]}" 2>>"$OUT/interrupted.log" &
  job=$!
  if [ -n "$wait_s" ]; then
    sleep "$wait_s"
    ranks=($(pgrep -f "^$BUILD_DIR/relt render" || true))
    if ((${#ranks[@]})); then kill -9 "${ranks[RANDOM % ${#ranks[@]}]}" && kills=$((kills + 1)); fi
  fi
  wait "$job" || true
  [ -f "$OUT/ck/checkpoint.relt" ] && resume=(--resume "$OUT/ck")
done
soaked=$(/usr/bin/python3 -c "print($(now) - $t0)")
diff=$("$BUILD_DIR/relt" compare "$OUT/interrupted.exr" "$OUT/uninterrupted.exr")
identical=$(/usr/bin/python3 -c "
import json; c = json.loads('$diff'); print('yes' if c['rmse'] == 0 and c['mean'] == c['reference_mean'] else 'no')")
{
  echo "relt soak on $RANKS ranks, $SCENE 128x128, $MPP mutations per pixel, checkpoint every $EVERY s, seed ${SEED:-1};"
  echo "$(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores, $(date -u +%Y-%m-%d), commit $(git -C "$ROOT" rev-parse --short HEAD)"
  echo
  echo "| uninterrupted s | with kills s | kills | lost per kill s | images identical | compare |"
  echo "|---|---|---|---|---|---|"
  /usr/bin/python3 -c "print('| %.1f | %.1f | %d | %.1f | $identical | %s |' % ($plain, $soaked, $kills, ($soaked - $plain) / max($kills, 1), '$diff'))"
} > "$TABLE"
cat "$TABLE"
