#!/usr/bin/env bash
# Set up (packages, build) and run the whole test suite (labels: unit, stat, mpi, cluster).
set -euo pipefail
source "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/setup.sh"
cd "$BUILD_DIR"
ctest --output-on-failure -j 2 "$@"
