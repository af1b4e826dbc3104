#!/usr/bin/env bash
# Ranks against threads on this machine's cores (docs/BENCHMARKS.md, "Threads inside a rank"):
#   speed:  pt, bdpt (samples/s), erpt, pssmlt, mmlt and relt (mutations/s) on cornell-box 256x256,
#           max depth 8, with
#           2 ranks x 1 thread and 1 rank x 2 threads (unbound), in pairs; prints each pair's ratio
#           threads/ranks and the median.
#   memory: ring and water-box at 1024x1024, 1 spp of bdpt, both set-ups: the node's resident
#           memory is the sum of the ranks' peaks (stats.json peak_resident_mib_per_rank).
# Usage: scripts/bench/threads.sh [PAIRS] [INTEGRATOR...]   (default 5 pairs of every integrator and
#   the memory; with integrators named, only their speed; writes out/bench/threads.txt)
set -euo pipefail
source "$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/setup.sh"
source "$ROOT/scripts/bench/common.sh"
PAIRS="${1:-5}"
shift || true
INTEGRATORS=("$@")
MEMORY=$((${#INTEGRATORS[@]} == 0))
((MEMORY)) && INTEGRATORS=(pt bdpt erpt pssmlt mmlt relt)
OUT="$ROOT/out/bench"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
mkdir -p "$OUT"


# A render on SETUP (ranks or threads) with the given options; its stats go to $TMP/stats.json.
run() {
  local setup="$1"
  shift
  if [ "$setup" = ranks ]; then
    "${MPIRUN[@]}" -np 2 "$BUILD_DIR/relt" render "$@" --threads 1 --stats "$TMP/stats.json" -o "$TMP/out.exr" 2>/dev/null
  else
    "${MPIRUN[@]}" -np 1 --bind-to none "$BUILD_DIR/relt" render "$@" --threads 2 --stats "$TMP/stats.json" \
      -o "$TMP/out.exr" 2>/dev/null
  fi
}
field() { /usr/bin/python3 -c "import json,sys; j=json.load(open('$TMP/stats.json')); print($1)"; }

{
  echo "machine: $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores; $(date -u +%Y-%m-%d); commit $(git -C "$ROOT" rev-parse --short HEAD)"
  for integ in "${INTEGRATORS[@]}"; do
    case "$integ" in
      pt) amount=(--spp 256); key=samples_per_second ;;
      bdpt) amount=(--spp 64); key=samples_per_second ;;
      erpt) amount=(--spp 2); key=mutations_per_second ;;
      *) amount=(--mutations-per-pixel 32); key=mutations_per_second ;;
    esac
    for _ in $(seq "$PAIRS"); do
      run ranks "$ROOT/scenes/cornell-box.gltf" --integrator "$integ" "${amount[@]}" --width 256 --height 256 --max-depth 8
      r=$(field "j['$key']")
      run threads "$ROOT/scenes/cornell-box.gltf" --integrator "$integ" "${amount[@]}" --width 256 --height 256 --max-depth 8
      t=$(field "j['$key']")
      awk -v i="$integ" -v r="$r" -v t="$t" 'BEGIN {printf "%-5s 2 ranks %8.3f M/s  2 threads %8.3f M/s  threads/ranks %.3f\n", i, r / 1e6, t / 1e6, t / r}'
    done | tee "$TMP/pairs"
    awk '{print $NF}' "$TMP/pairs" | median | awk -v i="$integ" '{printf "%-5s median threads/ranks %.3f\n", i, $1}'
  done
  ((MEMORY)) && for scene in ring water-box; do
    for setup in ranks threads; do
      run "$setup" "$ROOT/scenes/$scene.gltf" --integrator bdpt --spp 1 --width 1024 --height 1024
      awk -v s="$scene" -v u="$setup" -v m="$(field "sum(j['peak_resident_mib_per_rank'])")" \
        -v p="$(field "j['peak_resident_mib_per_rank']")" 'BEGIN {printf "memory %-10s %-7s %7.1f MiB per node (ranks: %s)\n", s, u, m, p}'
    done
  done
} | tee "$OUT/threads.txt"
