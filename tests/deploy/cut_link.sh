#!/usr/bin/env bash
# compose-test.sh --after-up hook: once the mission is under way (the GCS has printed tick 40),
# takes SERVICE's container off the compose project's network for SECONDS, then reconnects it
# with the address it had (a different one would leave its peers sending to the old address).
# Usage: cut_link.sh SERVICE SECONDS   (needs COMPOSE_PROJECT_NAME, as compose-test.sh sets)
set -euo pipefail
service=$1 seconds=$2
project=${COMPOSE_PROJECT_NAME:?cut_link.sh runs as compose-test.sh --after-up}
of_service() {
  docker ps -q --filter "label=com.docker.compose.project=$project" --filter "label=com.docker.compose.service=$1" |
    head -n 1
}
gcs=$(of_service gcs)
cid=$(of_service "$service")
[[ -n $gcs && -n $cid ]] || { echo "cut_link: no running gcs or $service container" >&2; exit 1; }
net=$(docker network ls -q --filter "label=com.docker.compose.project=$project" | head -n 1)
[[ -n $net ]] || { echo "cut_link: the project has no network" >&2; exit 1; }
net_name=$(docker network inspect -f '{{.Name}}' "$net")
address() { docker inspect -f "{{with index .NetworkSettings.Networks \"$net_name\"}}{{.IPAddress}}{{end}}" "$cid"; }

bash "$(dirname "$0")/wait_for_tick.sh" 40
before=$(address)
start=$SECONDS
docker network disconnect "$net" "$cid"
echo "cut_link: $service ($before) disconnected from $net_name"
sleep "$seconds"
docker network connect --alias "$service" "$net" "$cid"
after=$(address)
echo "cut_link: $service reconnected after $((SECONDS - start)) s, address $after"
[[ $after == "$before" ]] || { echo "cut_link: $service came back as $after, not $before" >&2; exit 1; }
