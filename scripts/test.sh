#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to every test: installs what is missing, builds,
# runs ctest (unit, integration and, where a Docker engine runs, deploy tests), then the
# AddressSanitizer run with a short fuzz run per target (scripts/sanitize.sh address;
# SWARM_SKIP_SANITIZE=1 skips it). Extra arguments go to ctest, e.g. scripts/test.sh -L unit
# (then the sanitizer run is skipped too).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
(cd build && ctest --output-on-failure --timeout 600 -j "${SWARM_TEST_JOBS:-2}" "$@")
if (($# == 0)) && [[ ${SWARM_SKIP_SANITIZE:-0} != 1 ]]; then
  scripts/sanitize.sh address
fi
