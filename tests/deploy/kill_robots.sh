#!/usr/bin/env bash
# A member and a leader die in the docker-compose deployment: `docker kill` of member-1-2's and
# leader-2's containers while the real-time mission runs. The simulator notices both through DDS
# (the 1 s liveliness lease); group 1's leader plans without its member; group 2's standby
# member-2-1 takes its group over (comm/leadership.hpp); the mission completes, and metrics.json
# records both losses and the hand-over.
# Usage: kill_robots.sh SOURCE_DIR BIN_DIR OUT_DIR
set -euo pipefail
src=$1 bin=$2 out=$3
kill_cmd="bash '$src/tests/deploy/wait_for_tick.sh' 20; "'docker kill $(docker ps -q --filter label=com.docker.compose.project=$COMPOSE_PROJECT_NAME --filter label=com.docker.compose.service=member-1-2) $(docker ps -q --filter label=com.docker.compose.project=$COMPOSE_PROJECT_NAME --filter label=com.docker.compose.service=leader-2)'
rc=0
bash "$src/deploy/compose-test.sh" --prebuilt "$bin" --image swarm:ctest \
  --scenario "$src/scenarios/deploy_faults.pbtxt" --out "$out" \
  --after-up "$kill_cmd" --expect-exit member-1-2=137 --expect-exit leader-2=137 || rc=$?
((rc == 0)) || exit "$rc"
test_name=kill_robots metrics=$out/metrics.json
# shellcheck source=tests/deploy/metrics_checks.sh
source "$src/tests/deploy/metrics_checks.sh"
lost=$(faults_list agents_lost)
[[ $lost == *'"agent":"member-1-2"'* ]] || fail "metrics.json does not record member-1-2 as lost"
[[ $lost == *'"agent":"leader-2"'* ]] || fail "metrics.json does not record leader-2 as lost"
handovers=$(faults_list leader_handovers)
[[ $handovers == *'"from":"leader-2"'* && $handovers == *'"group":2'* && $handovers == *'"to":"member-2-1"'* ]] ||
  fail "member-2-1 did not take group 2 over: $handovers"
echo "kill_robots: lost: $lost"
echo "kill_robots: hand-over: $handovers"
echo "kill_robots: PASSED"
