#!/usr/bin/env bash
# A member dies in the docker-compose deployment: `docker kill` of member-1-2's container while
# the real-time mission runs. The simulator notices through DDS (the 1 s liveliness lease), its
# leader plans without it, the mission completes, and metrics.json records the loss.
# Usage: kill_member.sh SOURCE_DIR BIN_DIR OUT_DIR
set -euo pipefail
src=$1 bin=$2 out=$3
kill_cmd='sleep 8; docker kill $(docker ps -q --filter label=com.docker.compose.project=$COMPOSE_PROJECT_NAME --filter label=com.docker.compose.service=member-1-2)'
rc=0
bash "$src/deploy/compose-test.sh" --prebuilt "$bin" --image swarm:ctest \
  --scenario "$src/scenarios/deploy_faults.pbtxt" --out "$out" \
  --after-up "$kill_cmd" --expect-exit member-1-2=137 || rc=$?
((rc == 0)) || exit "$rc"
# The loss is in the run's metrics, with when it was noticed.
if ! sed -n '/"agents_lost"/,/\]/p' "$out/metrics.json" | grep -q '"agent": "member-1-2"'; then
  echo "kill_member: metrics.json does not record member-1-2 as lost:" >&2
  sed -n '/"faults"/,/^  }/p' "$out/metrics.json" >&2
  exit 1
fi
sed -n '/"agents_lost"/,/\]/p' "$out/metrics.json"
echo "kill_member: PASSED"
