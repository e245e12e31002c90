#!/usr/bin/env bash
# compose-test.sh and stack-test.sh --after-up hooks: waits until the mission is under way, i.e. the
# GCS has printed tick TICK or a later one (its progress lines, "tick    40  mapped ..."), so that a
# fault injected next lands mid-mission however long discovery took on a loaded machine.
# Gives up after 60 s (exit 1, saying so). Usage: wait_for_tick.sh TICK (needs
# COMPOSE_PROJECT_NAME from compose-test.sh, or SWARM_STACK from stack-test.sh).
set -euo pipefail
tick=${1:?usage: wait_for_tick.sh TICK}
if [[ -n ${SWARM_STACK:-} ]]; then
  gcs_log() { docker service logs --raw --no-task-ids "${SWARM_STACK}_gcs" 2>&1; }
else
  project=${COMPOSE_PROJECT_NAME:?wait_for_tick.sh runs under compose-test.sh or stack-test.sh --after-up}
  gcs=$(docker ps -aq --filter "label=com.docker.compose.project=$project" --filter "label=com.docker.compose.service=gcs" |
    head -n 1)
  [[ -n $gcs ]] || { echo "wait_for_tick: the project has no gcs container" >&2; exit 1; }
  gcs_log() { docker logs "$gcs" 2>&1; }
fi
for _ in $(seq 120); do
  if gcs_log | awk -v t="$tick" '$1 == "tick" && $2 + 0 >= t { found = 1 } END { exit !found }'; then
    exit 0
  fi
  sleep 0.5
done
echo "wait_for_tick: the GCS did not reach tick $tick within 60 s" >&2
exit 1
