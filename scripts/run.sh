#!/usr/bin/env bash
# Set up (packages, build) and render the default scene with relt (replica exchange, its default
# kitaoka family) on 2 ranks into out/.
set -euo pipefail
source "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/setup.sh"
SCENE="${1:-$ROOT/scenes/cornell-box.gltf}"
NAME="$(basename "${SCENE%.*}")"
mkdir -p "$ROOT/out"
"${MPIRUN[@]}" -np 2 "$BUILD_DIR/relt" render "$SCENE" -o "$ROOT/out/$NAME.exr" --png "$ROOT/out/$NAME.png" \
  --stats "$ROOT/out/$NAME.json" --integrator relt --mutations-per-pixel 64
echo "relt: rendered $ROOT/out/$NAME.exr and $ROOT/out/$NAME.png (statistics in $ROOT/out/$NAME.json)"
