#!/usr/bin/env bash
# Throughput figures for docs/BENCHMARKS.md: incoherent closest-hit rays/s per core on cornell-box
# and ring, and pt / bdpt samples/s per core on cornell-box at 256x256, max depth 8.
# Usage: scripts/bench/throughput.sh [SPP_PT] [SPP_BDPT]   (writes out/bench/throughput.json)
set -euo pipefail
source "$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/setup.sh"
SPP_PT="${1:-64}"
SPP_BDPT="${2:-16}"
OUT="$ROOT/out/bench"
mkdir -p "$OUT"
{
  echo "machine: $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores"
  for scene in cornell-box ring; do
    "$BUILD_DIR/relt_bench_rays" "$ROOT/scenes/$scene.gltf" 4000000
  done
  for ranks in 1 2; do
    for integ in pt bdpt; do
      spp=$SPP_PT; [ "$integ" = bdpt ] && spp=$SPP_BDPT
      "${MPIRUN[@]}" -np "$ranks" "$BUILD_DIR/relt" render "$ROOT/scenes/cornell-box.gltf" -o "$OUT/$integ-np$ranks.exr" \
        --integrator "$integ" --spp "$spp" --width 256 --height 256 --max-depth 8 --stats "$OUT/$integ-np$ranks.json" 2>/dev/null
      /usr/bin/python3 - "$OUT/$integ-np$ranks.json" "$integ" "$ranks" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
print(f"{sys.argv[2]} np={sys.argv[3]}: {s['samples_per_second_per_rank']/1e6:.3f} M samples/s per rank, "
      f"{s['rays_per_second']/1e6:.2f} M rays/s total, {s['spp']} spp in {s['render_seconds']:.2f} s")
PY
    done
  done
} | tee "$OUT/throughput.txt"
