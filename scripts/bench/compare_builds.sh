#!/usr/bin/env bash
# Speed of two relt binaries against each other on one scene, for changes smaller than this
# machine's drift between runs (its speed wanders by 5-40 % within the hour).
#   interleaved: A then B, PAIRS times, both on core 0 (one thread: --threads defaults to the
#                cores a process may use); prints each pair's ratio B/A and their median.
#   concurrent:  A and B at the same time, each pinned to its own core, swapping cores every
#                run; a swap pair's ratio is the geometric mean of its two runs (cancels a
#                difference between the cores); prints those and their geometric mean.
# Usage: scripts/bench/compare_builds.sh BIN_A BIN_B [PAIRS] [SPP] [MODE] [INTEGRATOR] [SCENE]
#   defaults: 6 pairs, 128 spp, interleaved, pt, cornell-box (256x256, max depth 8, one rank)
#   SPP is samples per pixel for pt, bdpt and erpt, mutations per pixel for the Markov-chain
#   integrators (pssmlt, mmlt, relt), whose rate is mutations per second.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
A="$1"
B="$2"
PAIRS="${3:-6}"
SPP="${4:-128}"
MODE="${5:-interleaved}"
INTEGRATOR="${6:-pt}"
SCENE="${7:-cornell-box}"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT

case "$INTEGRATOR" in pt | bdpt | erpt) BUDGET=(--spp "$SPP") ;; *) BUDGET=(--mutations-per-pixel "$SPP") ;; esac

# Samples (or mutations) per second of one render (binary, core); relt prints "... X M samples/s ..."
# or "... X M mutations/s ...".
rate() {
  taskset -c "$2" "$1" render "$ROOT/scenes/$SCENE.gltf" --integrator "$INTEGRATOR" "${BUDGET[@]}" --width 256 --height 256 \
    --max-depth 8 -o "$TMP/out-$2.exr" 2>&1 | sed -n 's/.* \([0-9.]*\) M \(samples\|mutations\)\/s.*/\1/p' | tail -1
}

echo "A: $A"
echo "B: $B"
case "$MODE" in
  interleaved)
    for i in $(seq "$PAIRS"); do
      a=$(rate "$A" 0)
      b=$(rate "$B" 0)
      awk -v a="$a" -v b="$b" 'BEGIN {printf "A %.3f M  B %.3f M  B/A %.3f\n", a, b, b / a}'
    done | tee "$TMP/pairs"
    awk '{print $NF}' "$TMP/pairs" | sort -g |
      awk '{v[NR] = $1} END {printf "median B/A %.3f over %d pairs\n", (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2, NR}'
    ;;
  concurrent)
    for i in $(seq "$PAIRS"); do
      ratios=()
      for cores in "0 1" "1 0"; do
        read -r ca cb <<<"$cores"
        rate "$A" "$ca" >"$TMP/a" &
        rate "$B" "$cb" >"$TMP/b" &
        wait
        ratios+=("$(awk -v a="$(cat "$TMP/a")" -v b="$(cat "$TMP/b")" 'BEGIN {print b / a}')")
      done
      awk -v r1="${ratios[0]}" -v r2="${ratios[1]}" 'BEGIN {printf "swap pair: B/A %.3f (cores A0/B1 %.3f, A1/B0 %.3f)\n", sqrt(r1 * r2), r1, r2}'
    done | tee "$TMP/pairs"
    awk '{s += log($4); n++} END {printf "geometric mean B/A %.3f over %d swap pairs\n", exp(s / n), n}' "$TMP/pairs"
    ;;
  *)
    echo "compare_builds.sh: MODE must be interleaved or concurrent, not '$MODE'" >&2
    exit 2
    ;;
esac
