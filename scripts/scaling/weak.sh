#!/usr/bin/env bash
# Weak scaling of relt: MPP mutations per pixel per rank (256x256) and 32 ladders per rank, on 1, 2,
# 4 and 8 ranks of this machine; ranks beyond the core count are oversubscribed (marked).
# Writes out/scaling/weak.csv and docs/img/scaling-weak.{png,csv}.
# Usage: scripts/scaling/weak.sh [MPP] [RANKS...]   (defaults 16; 1 2 4 8)   env: SCENE, REPEATS (3; the plot takes medians)
set -euo pipefail
source "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/lib.sh"
MPP="${1:-16}"
shift $(($# > 0 ? 1 : 0))
RANKS=("$@")
((${#RANKS[@]})) || RANKS=(1 2 4 8)
CSV="$OUT/weak.csv"
csv_header "$CSV"
for _ in $(seq "${REPEATS:-3}"); do
  for p in "${RANKS[@]}"; do
    run_point "$CSV" weak "$p" --mutations-per-pixel $((MPP * p)) --ladders $((32 * p))
  done
done
publish weak
