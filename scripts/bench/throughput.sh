#!/usr/bin/env bash
# Throughput figures for docs/BENCHMARKS.md: incoherent closest-hit rays/s per core on cornell-box
# and ring, pt / bdpt samples/s and pssmlt / mmlt mutations/s per core on cornell-box at 256x256, max
# depth 8, on 1 and 2 ranks. Every figure is the median of REPEATS runs. Run it on an otherwise
# idle machine.
# Usage: scripts/bench/throughput.sh [SPP_PT] [SPP_BDPT] [REPEATS] [MPP_PSSMLT]   (mmlt: 4 x MPP_PSSMLT)
# (writes out/bench/throughput.txt)
set -euo pipefail
source "$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/setup.sh"
source "$ROOT/scripts/bench/common.sh"
SPP_PT="${1:-256}"
SPP_BDPT="${2:-64}"
REPEATS="${3:-3}"
MPP="${4:-32}"
OUT="$ROOT/out/bench"
mkdir -p "$OUT"


{
  echo "machine: $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores; $(date -u +%Y-%m-%d); commit $(git -C "$ROOT" rev-parse --short HEAD)"
  for scene in cornell-box ring; do
    rate=$(for _ in $(seq "$REPEATS"); do
      "$BUILD_DIR/relt_bench_rays" "$ROOT/scenes/$scene.gltf" 4000000 | sed 's/.*"rays_per_second": \([0-9.]*\).*/\1/'
    done | median)
    awk -v s="$scene" -v r="$rate" 'BEGIN {printf "rays %-12s %6.2f M closest-hit rays/s per core\n", s, r / 1e6}'
  done
  for ranks in 1 2; do
    for integ in pt bdpt; do
      spp=$SPP_PT
      [ "$integ" = bdpt ] && spp=$SPP_BDPT
      stats="$OUT/$integ-np$ranks.json"
      rates=$(for _ in $(seq "$REPEATS"); do
        "${MPIRUN[@]}" -np "$ranks" "$BUILD_DIR/relt" render "$ROOT/scenes/cornell-box.gltf" -o "$OUT/$integ-np$ranks.exr" \
          --integrator "$integ" --spp "$spp" --width 256 --height 256 --max-depth 8 --stats "$stats" 2>/dev/null
        /usr/bin/python3 -c "import json,sys; s=json.load(open(sys.argv[1])); print(s['samples_per_second_per_rank'], s['rays_per_second'] / s['ranks'])" "$stats"
      done)
      samples=$(echo "$rates" | cut -d' ' -f1 | median)
      rays=$(echo "$rates" | cut -d' ' -f2 | median)
      awk -v i="$integ" -v n="$ranks" -v s="$samples" -v r="$rays" -v spp="$spp" -v k="$REPEATS" 'BEGIN {
        printf "%-4s np=%d: %5.3f M samples/s per core, %5.2f M rays/s per core (%d spp, median of %d)\n", i, n, s / 1e6, r / 1e6, spp, k}'
    done
    for integ in pssmlt mmlt; do
      mpp=$MPP
      [ "$integ" = mmlt ] && mpp=$((MPP * 4))
      stats="$OUT/$integ-np$ranks.json"
      rate=$(for _ in $(seq "$REPEATS"); do
        "${MPIRUN[@]}" -np "$ranks" "$BUILD_DIR/relt" render "$ROOT/scenes/cornell-box.gltf" -o "$OUT/$integ-np$ranks.exr" \
          --integrator "$integ" --mutations-per-pixel "$mpp" --width 256 --height 256 --max-depth 8 --stats "$stats" 2>/dev/null
        /usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['mutations_per_second_per_rank'])" "$stats"
      done | median)
      awk -v i="$integ" -v n="$ranks" -v r="$rate" -v m="$mpp" -v k="$REPEATS" 'BEGIN {
        printf "%-6s np=%d: %5.3f M mutations/s per core (%d mutations per pixel, 100k bootstrap included, median of %d)\n", i, n, r / 1e6, m, k}'
    done
  done
} | tee "$OUT/throughput.txt"
