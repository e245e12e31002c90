#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to a finished default mission: installs what is
# missing, builds, and runs `swarm run` (3 groups x 3 robots exploring maze1). Extra arguments go
# to `swarm run`, e.g. scripts/mission.sh --map maze2 --mode baseline.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
exec build/bin/swarm run "$@"
