#!/usr/bin/env bash
# Installs the Khronos glTF validator (npm package gltf-validator, pinned) into DIR/node_modules
# for scripts/validator/compare.py. Does nothing when it is there already; without npm or a
# network it says so and returns 0, and the comparison test is skipped.
# Usage: scripts/validator/install.sh [DIR]   (default build/validator)
set -uo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
DIR="${1:-$ROOT/build/validator}"
VERSION=2.0.0-dev.3.10
[ -f "$DIR/node_modules/gltf-validator/package.json" ] &&
  grep -q "\"version\": \"$VERSION\"" "$DIR/node_modules/gltf-validator/package.json" && exit 0
if ! command -v npm > /dev/null 2>&1; then
  echo "relt setup: npm not found; gltf-validator not installed (the validator comparison test will be skipped)"
  exit 0
fi
mkdir -p "$DIR"
if npm install --prefix "$DIR" --no-audit --no-fund --fetch-retries=1 --fetch-timeout=30000 \
  "gltf-validator@$VERSION" > "$DIR/install.log" 2>&1; then
  echo "relt setup: gltf-validator $VERSION installed in $DIR"
else
  echo "relt setup: gltf-validator could not be installed (offline?), see $DIR/install.log;" \
    "the validator comparison test will be skipped"
fi
exit 0
