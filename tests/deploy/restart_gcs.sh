#!/usr/bin/env bash
# The GCS's container dies mid-mission and is started again: `docker kill` of the gcs container
# once the real-time mission has reached tick 20, `docker start` of the same container 3 s later. Its entrypoint
# sees the run's journal on the results volume and starts swarm-gcs with --resume: it replays the
# journal, the simulator admits it back, the leaders send it what it missed, and the mission
# completes; metrics.json (written by the new process) records the restart.
# Usage: restart_gcs.sh SOURCE_DIR BIN_DIR OUT_DIR
set -euo pipefail
src=$1 bin=$2 out=$3
gcs='$(docker ps -aq --filter label=com.docker.compose.project=$COMPOSE_PROJECT_NAME --filter label=com.docker.compose.service=gcs)'
restart_cmd="bash '$src/tests/deploy/wait_for_tick.sh' 20; docker kill $gcs; sleep 3; docker start $gcs"
rc=0
bash "$src/deploy/compose-test.sh" --prebuilt "$bin" --image swarm:ctest \
  --scenario "$src/scenarios/deploy_faults.pbtxt" --out "$out" --after-up "$restart_cmd" || rc=$?
((rc == 0)) || exit "$rc"
test_name=restart_gcs metrics=$out/metrics.json
# shellcheck source=tests/deploy/metrics_checks.sh
source "$src/tests/deploy/metrics_checks.sh"
restarts=$(faults_list gcs_restarts)
[[ $restarts == *'"rejoined_at_tick":'[0-9]* && $restarts == *'"replayed_ticks":'[1-9]* ]] ||
  fail "metrics.json does not record the GCS's restart: $restarts"
echo "restart_gcs: $restarts"
echo "restart_gcs: PASSED"
