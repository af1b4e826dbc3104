#!/usr/bin/env bash
# relt on RANKS ranks (default 2) at exchange intervals 1, 4, 16, 64 with spread and packed
# placement, same work (MPP mutations per pixel, 256x256). Writes out/scaling/sweep.csv and
# docs/img/scaling-sweep.{png,csv}.
# Usage: scripts/scaling/sweep.sh [MPP] [RANKS]   (defaults 32, 2)   env: SCENE, INTERVALS
set -euo pipefail
source "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/lib.sh"
MPP="${1:-32}"
P="${2:-2}"
read -r -a INTERVALS <<< "${INTERVALS:-1 4 16 64}"
CSV="$OUT/sweep.csv"
csv_header "$CSV"
for placement in spread packed; do
  for k in "${INTERVALS[@]}"; do
    run_point "$CSV" sweep "$P" --mutations-per-pixel "$MPP" --exchange-interval "$k" --placement "$placement"
  done
done
publish sweep
