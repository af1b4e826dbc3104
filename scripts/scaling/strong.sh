#!/usr/bin/env bash
# Strong scaling of relt: the same total work (MPP mutations per pixel, 256x256) on 1, 2, 4 and 8
# ranks of this machine; ranks beyond the core count are oversubscribed (marked in the CSV and plot).
# Writes out/scaling/strong.csv and docs/img/scaling-strong.{png,csv}.
# Usage: scripts/scaling/strong.sh [MPP] [RANKS...]   (defaults 32; 1 2 4 8)   env: SCENE, REPEATS (3; the plot takes medians), LADDERS (64)
set -euo pipefail
source "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/lib.sh"
MPP="${1:-32}"
shift $(($# > 0 ? 1 : 0))
RANKS=("$@")
((${#RANKS[@]})) || RANKS=(1 2 4 8)
CSV="$OUT/strong.csv"
csv_header "$CSV"
for _ in $(seq "${REPEATS:-3}"); do
  for p in "${RANKS[@]}"; do
    run_point "$CSV" strong "$p" --mutations-per-pixel "$MPP" --ladders "${LADDERS:-64}"
  done
done
publish strong
