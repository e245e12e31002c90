#!/usr/bin/env bash
# compose-test.sh --after-up hook: once the mission is under way (the GCS has printed tick 20),
# cuts SERVICE's container's link for SECONDS, then heals it. The link is set down inside the
# container's network namespace (set_link.py, from a helper container that shares it), as a pulled
# cable would be: the container keeps its address, which Fast DDS announced at start-up and its
# peers keep sending to. (Taking it off the Docker network and putting it back does not keep it:
# Docker hands out the lowest free address at the reconnection.)
# Usage: cut_link.sh SERVICE SECONDS   (needs COMPOSE_PROJECT_NAME and SWARM_IMAGE, as compose-test.sh sets)
set -euo pipefail
service=$1 seconds=$2
project=${COMPOSE_PROJECT_NAME:?cut_link.sh runs as compose-test.sh --after-up}
image=${SWARM_IMAGE:?cut_link.sh runs as compose-test.sh --after-up}
here=$(cd "$(dirname "$0")" && pwd)
of_service() {
  docker ps -q --filter "label=com.docker.compose.project=$project" --filter "label=com.docker.compose.service=$1" |
    head -n 1
}
gcs=$(of_service gcs)
cid=$(of_service "$service")
[[ -n $gcs && -n $cid ]] || { echo "cut_link: no running gcs or $service container" >&2; exit 1; }
address=$(docker inspect -f '{{range .NetworkSettings.Networks}}{{.IPAddress}} {{end}}' "$cid" | awk '{print $1}')
[[ -n $address ]] || { echo "cut_link: $service has no address" >&2; exit 1; }

bash "$here/wait_for_tick.sh" 20
start=$SECONDS
# One helper for down and up: the cut lasts SECONDS however slow containers are to start, so it
# heals well before the mission (~450 ticks of 40 ms, 18 s) ends and the leader can come back.
docker run --rm -i --network "container:$cid" --cap-add NET_ADMIN --user 0 --entrypoint python3 \
  "$image" - "$address" down "$seconds" <"$here/set_link.py"
echo "cut_link: $service ($address) was cut off for $seconds s; healed $((SECONDS - start)) s after tick 20"
