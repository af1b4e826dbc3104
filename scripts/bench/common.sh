# Sourced by benchmark scripts (after setup.sh): helpers several of them share.
# shellcheck shell=bash

# median: the median of the numbers on standard input, one a line.
median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

# The suite's scenes in the order of scenes/README.md (the furnace, an analytic test, left out).
SUITE_SCENES=(cornell-box glass-cube water-box ring torus-in-glass door-ajar mirror-balls glossy-caustics living-room)
