#!/usr/bin/env bash
# Configures and builds swarm into build/ (executables in build/bin). Extra arguments go to the
# CMake configure step, e.g. scripts/build.sh -DSWARM_BUILD_TESTS=OFF.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "$@"
# Two jobs at most: one C++ unit including Fast DDS headers needs ~1 GB.
cmake --build build -j "${SWARM_BUILD_JOBS:-$(nproc)}"
