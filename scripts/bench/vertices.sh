#!/usr/bin/env bash
# Subpath vertices per second per core, vcm against bdpt (issue target: within 1.5x): every scene
# of the suite at its test size, one rank with one thread, SECONDS each, the two integrators
# alternating REPEATS times; each figure is the median of its repeats. The vertices are the surface
# points the camera and light subpaths reached (stats.json subpath_vertices_per_second_per_core),
# which both integrators trace alike, so the ratio is the cost of what vcm does at each vertex
# (merging, more connections) beyond bdpt's.
# Usage: scripts/bench/vertices.sh [SECONDS] [REPEATS] [SCENES...]   (defaults 5, 3, the suite;
#   writes out/bench/vertices.txt)
set -euo pipefail
source "$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/setup.sh"
source "$ROOT/scripts/bench/common.sh"
SECS="${1:-5}"
REPEATS="${2:-3}"
shift 2 || shift $#
SCENES=("$@")
((${#SCENES[@]})) || SCENES=("${SUITE_SCENES[@]}")
OUT="$ROOT/out/bench"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
mkdir -p "$OUT"

# rate SCENE INTEGRATOR: one render's subpath vertices per second per core, in millions.
rate() {
  "${MPIRUN[@]}" -np 1 "$BUILD_DIR/relt" render "$ROOT/scenes/$1.gltf" --integrator "$2" --time "$SECS" --threads 1 \
    --seed 1 -o "$TMP/out.exr" --stats "$TMP/stats.json" 2>/dev/null
  /usr/bin/python3 -c "import json; print(json.load(open('$TMP/stats.json'))['subpath_vertices_per_second_per_core'] * 1e-6)"
}

{
  echo "machine: $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores; $(date -u +%Y-%m-%d); commit $(git -C "$ROOT" rev-parse --short HEAD)"
  echo "subpath vertices per second per core (millions), median of $REPEATS x $SECS s, 1 rank x 1 thread"
  printf '%-16s %8s %8s %10s\n' scene bdpt vcm bdpt/vcm
  for scene in "${SCENES[@]}"; do
    : > "$TMP/bdpt" && : > "$TMP/vcm"
    for _ in $(seq "$REPEATS"); do
      rate "$scene" bdpt >> "$TMP/bdpt"
      rate "$scene" vcm >> "$TMP/vcm"
    done
    b="$(median < "$TMP/bdpt")" v="$(median < "$TMP/vcm")"
    printf '%-16s %8.3f %8.3f %10.2f\n' "$scene" "$b" "$v" "$(/usr/bin/python3 -c "print($b / $v)")"
  done
} | tee "$OUT/vertices.txt"
