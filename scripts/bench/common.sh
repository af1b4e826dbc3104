# Sourced by benchmark scripts (after setup.sh): helpers several of them share.
# shellcheck shell=bash

# median: the median of the numbers on standard input, one a line.
median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

# compare_row IMAGE REFERENCE: "rmse,rel_mse,mean,reference_mean" of IMAGE against REFERENCE.
compare_row() {
  "$BUILD_DIR/relt" compare "$1" "$2" | /usr/bin/python3 -c \
    "import json,sys; c=json.load(sys.stdin); print('%.6g,%.6g,%.6g,%.6g' % (c['rmse'], c['rel_mse'], c['mean'], c['reference_mean']))"
}

# The suite's scenes in the order of scenes/README.md (the furnace, an analytic test, left out).
SUITE_SCENES=(cornell-box glass-cube water-box ring torus-in-glass door-ajar mirror-balls glossy-caustics living-room)
