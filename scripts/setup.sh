#!/usr/bin/env bash
# Installs the Debian packages relt needs (only those missing), then configures and builds.
# Sourced by run.sh and test.sh; BUILD_DIR defaults to build/.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$ROOT/build}"

PACKAGES=(build-essential cmake ninja-build pkg-config libopenmpi-dev openmpi-bin libembree-dev libopenexr-dev
          libglm-dev libtinygltf-dev nlohmann-json3-dev libcli11-dev libstb-dev libgtest-dev python3
          python3-matplotlib)
missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "relt setup: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

mkdir -p "$BUILD_DIR"
cmake -S "$ROOT" -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release > "$BUILD_DIR/configure.log" 2>&1 ||
  { cat "$BUILD_DIR/configure.log"; exit 1; }
cmake --build "$BUILD_DIR"
# The Khronos glTF validator, for the loader comparison test (skipped without it; never fails).
bash "$ROOT/scripts/validator/install.sh" "$BUILD_DIR/validator"

# Open MPI refuses to run as root unless told, and needs --oversubscribe beyond the core count.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
MPIRUN=(mpirun --oversubscribe --mca pml ob1 --mca btl self,vader)
