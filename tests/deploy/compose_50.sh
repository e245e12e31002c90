#!/usr/bin/env bash
# 50 robots on docker-compose (5 groups x 10, the default exploration mission; 53 containers and
# the discovery server): they come up and complete. ~2 min on the 2-core machine, most of it
# `docker-compose up` creating the containers, so it runs only when asked:
#   SWARM_TEST_DEPLOY_50=1 ctest -R deploy_compose_50
# (or directly: deploy/compose-test.sh --prebuilt build/bin --groups 5 --robots 10).
# Usage: compose_50.sh SOURCE_DIR BIN_DIR OUT_DIR
set -euo pipefail
src=$1 bin=$2 out=$3
if [[ ${SWARM_TEST_DEPLOY_50:-0} != 1 ]]; then
  echo "SKIPPED: the 50-robot compose mission (~2 min) runs only with SWARM_TEST_DEPLOY_50=1"
  exit 77
fi
exec bash "$src/deploy/compose-test.sh" --prebuilt "$bin" --image swarm:ctest --groups 5 --robots 10 \
  --out "$out"
