#!/usr/bin/env bash
# A Docker Swarm cluster on this one machine, for the stack deployment's tests: this machine's
# engine is the manager (node slot 0) and each worker is a Docker engine in a container of the
# cluster-node image (deploy/Dockerfile.node), on a bridge network of the cluster's own. The images
# reach the workers by `docker save | docker load` (there is no registry).
#
#   deploy/swarm-cluster.sh up --workers 1 --image swarm:latest   # manager + 1 worker, labelled
#   deploy/swarm-cluster.sh node 1                                # the container of worker 1
#   deploy/swarm-cluster.sh down                                  # remove all of it
#
# `up` puts the engine in swarm mode when it is not (advertising on the cluster network's gateway,
# so that only the cluster's own network carries the swarm's traffic) and labels the nodes
# swarm-slot=0 (this engine), 1, 2, ... (the workers), the labels deploy/stack-gen.sh places by.
# An engine that is already a swarm manager is used as it is, and `down` leaves its swarm.
# `down` removes the workers (containers, nodes, volumes), the network and, when `up` made it,
# the swarm (docker swarm leave --force and the bridge docker_gwbridge it made); it fails,
# naming them, when any is left. The one exception is docker_gwbridge, on which Docker sometimes
# keeps a stale endpoint until the engine restarts: a warning says so, and the next swarm on the
# engine reuses the bridge.
#
# Flags: --name PREFIX (default swarmcluster; names the network PREFIX-nodes and the workers
# PREFIX-node-K), --workers N (default 1), --image IMAGE (repeatable: loaded into every worker),
# --node-image IMAGE (default swarm-node:latest; deploy/node-image.sh makes it when missing).
# Exit codes: 0 ok, 1 failed (named), 2 bad input, or no Docker engine.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=deploy/lib.sh
source "$here/lib.sh"

cmd=${1:-}
[[ $cmd =~ ^(up|down|node)$ ]] || die 2 "usage: swarm-cluster.sh up|down|node [flags] (see --help)"
[[ $cmd == -h || $cmd == --help ]] && { sed -n '2,24p' "$0" | sed 's/^# \{0,1\}//'; exit 0; }
shift
name=swarmcluster
workers=1
images=()
node_image=swarm-node:latest
node_index=""
[[ $cmd != node ]] || { node_index=${1:?node needs a worker number}; shift; }
while (($#)); do
  case $1 in
    --name) name=${2:?--name needs a prefix}; shift ;;
    --workers) workers=${2:-}; shift ;;
    --image) images+=("${2:?--image needs an image}"); shift ;;
    --node-image) node_image=${2:?--node-image needs an image}; shift ;;
    -h | --help) sed -n '2,24p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) die 2 "unknown flag $1 (see --help)" ;;
  esac
  shift
done
[[ $name =~ ^[a-z][a-z0-9-]*$ ]] || die 2 "--name '$name' must be lower-case letters, digits and dashes"
[[ $workers =~ ^[0-9]+$ ]] || die 2 "--workers '$workers' is not a number"
docker_engine_running || die 2 "no Docker engine answers (docker info failed); start it or run where one runs"

network=$name-nodes
label=swarm.cluster=$name
node_container() { echo "$name-node-$1"; }
[[ $cmd != node ]] || { echo "$(node_container "$node_index")"; exit 0; }

swarm_state() { docker info -f '{{.Swarm.LocalNodeState}}' 2>/dev/null; }

# wait_for SECONDS WHAT CMD...: runs CMD every half second until it succeeds; fails naming WHAT.
wait_for() {
  local seconds=$1 what=$2 i
  shift 2
  for ((i = 0; i < seconds * 2; i++)); do
    "$@" >/dev/null 2>&1 && return 0
    sleep 0.5
  done
  die 1 "$what did not happen within $seconds s"
}

# The capabilities (Docker's names) missing from the engine's bounding set, which no container
# can be given: read from dockerd's /proc status when it runs here, else from this shell's.
missing_capabilities() {
  local names=(CHOWN DAC_OVERRIDE DAC_READ_SEARCH FOWNER FSETID KILL SETGID SETUID SETPCAP
    LINUX_IMMUTABLE NET_BIND_SERVICE NET_BROADCAST NET_ADMIN NET_RAW IPC_LOCK IPC_OWNER SYS_MODULE
    SYS_RAWIO SYS_CHROOT SYS_PTRACE SYS_PACCT SYS_ADMIN SYS_BOOT SYS_NICE SYS_RESOURCE SYS_TIME
    SYS_TTY_CONFIG MKNOD LEASE AUDIT_WRITE AUDIT_CONTROL SETFCAP MAC_OVERRIDE MAC_ADMIN SYSLOG
    WAKE_ALARM BLOCK_SUSPEND AUDIT_READ PERFMON BPF CHECKPOINT_RESTORE)
  local status=/proc/self/status pid bits i
  pid=$(pgrep -xo dockerd 2>/dev/null || true)
  [[ -z $pid || ! -r /proc/$pid/status ]] || status=/proc/$pid/status
  bits=$((16#$(awk '/^CapBnd:/ { print $2 }' "$status")))
  for ((i = 0; i < ${#names[@]}; i++)); do
    (((bits >> i) & 1)) || echo "${names[$i]}"
  done
}

down() {
  local ids left="" i c node_id
  # Workers: their containers, their nodes in the swarm, their engines' volumes.
  for c in $(docker ps -a --filter "label=$label" --format '{{.Names}}'); do
    node_id=$(docker node ls -q --filter "name=$c" 2>/dev/null | head -n 1)
    docker rm -f "$c" >/dev/null 2>&1 || true
    [[ -z $node_id ]] || docker node rm --force "$node_id" >/dev/null 2>&1 || true
  done
  ids=$(docker volume ls -q --filter "label=$label")
  [[ -z $ids ]] || docker volume rm -f $ids >/dev/null 2>&1 || true
  # The swarm, when `up` made it (the network's label says so).
  if [[ $(docker network inspect -f '{{index .Labels "swarm.cluster.initialized"}}' "$network" 2>/dev/null) == 1 &&
    $(swarm_state) == active ]]; then
    docker swarm leave --force >/dev/null 2>&1 || die 1 "docker swarm leave --force failed"
    # Swarm mode makes this bridge for its containers' way out, and leaving keeps it; its last
    # endpoint (the ingress sandbox's) goes a moment after the leave.
    for ((i = 0; i < 20; i++)); do
      docker network inspect docker_gwbridge >/dev/null 2>&1 || break
      docker network rm docker_gwbridge >/dev/null 2>&1 && break
      sleep 0.5
    done
    # Docker sometimes keeps a stale endpoint on it until the engine restarts ("has active
    # endpoints" with none listed); the next swarm on this engine takes it over as it is.
    if docker network inspect docker_gwbridge >/dev/null 2>&1; then
      echo "$(basename "$0"): warning: Docker's own bridge docker_gwbridge could not be removed (the engine holds a stale endpoint on it until it restarts); the next swarm reuses it" >&2
    fi
  fi
  docker network rm "$network" >/dev/null 2>&1 || true
  left+="$(docker ps -aq --filter "label=$label")$(docker volume ls -q --filter "label=$label")$(docker network ls -q --filter "name=^$network\$")"
  for ((i = 1; i <= 64; i++)); do
    [[ $(swarm_state) != active ]] && break
    left+=$(docker node ls -q --filter "name=$(node_container "$i")" 2>/dev/null)
  done
  [[ -z $left ]] || die 1 "the cluster $name left containers, volumes, networks or nodes behind: $left"
  say "cluster $name removed"
}

up() {
  local state gateway token manager_id i c ip node_id mem img
  for img in "${images[@]}"; do
    docker image inspect "$img" >/dev/null 2>&1 || die 2 "--image $img does not exist here; build it first"
  done
  state=$(swarm_state)
  local initialized=0
  case $state in
    inactive) initialized=1 ;;
    active)
      [[ $(docker info -f '{{.Swarm.ControlAvailable}}') == true ]] ||
        die 2 "this engine is in a swarm but not a manager; run on a manager, or leave that swarm first"
      ;;
    *) die 2 "this engine's swarm state is '$state'; it must be inactive (up makes the swarm) or an active manager" ;;
  esac
  if ! docker network inspect "$network" >/dev/null 2>&1; then
    # MTU 1500 on the nodes' own network: the overlay's default 1450 plus VXLAN's 50 bytes fit.
    docker network create --driver bridge -o com.docker.network.driver.mtu=1500 --label "$label" \
      --label "swarm.cluster.initialized=$initialized" "$network" >/dev/null
  fi
  gateway=$(docker network inspect -f '{{(index .IPAM.Config 0).Gateway}}' "$network")
  if ((initialized)); then
    docker swarm init --advertise-addr "$gateway" --listen-addr "$gateway:2377" >/dev/null ||
      die 1 "docker swarm init --advertise-addr $gateway failed"
    say "swarm made on this engine, manager at $gateway:2377"
  fi
  manager_id=$(docker info -f '{{.Swarm.NodeID}}')
  docker node update --label-add swarm-slot=0 "$manager_id" >/dev/null
  token=$(docker swarm join-token -q worker)
  local manager_addr
  manager_addr=$(docker info -f '{{.Swarm.NodeAddr}}'):2377
  ((workers == 0)) || {
    docker image inspect "$node_image" >/dev/null 2>&1 || "$here/node-image.sh" --tag "$node_image"
  }
  for ((i = 1; i <= workers; i++)); do
    c=$(node_container "$i")
    if ! docker inspect "$c" >/dev/null 2>&1; then
      # Every capability this engine can grant and no seccomp or AppArmor filter, instead of
      # --privileged: where the engine itself lacks a capability (CAP_SYS_RESOURCE on some VMs),
      # --privileged fails with "unable to apply caps". The device rule lets the inner engine
      # give its containers /dev/null and the rest.
      local drop=() cap
      for cap in $(missing_capabilities); do drop+=(--cap-drop "$cap"); done
      docker run -d --name "$c" --hostname "$c" --label "$label" --network "$network" \
        --cap-add ALL "${drop[@]}" --security-opt seccomp=unconfined --security-opt apparmor=unconfined \
        --security-opt systempaths=unconfined --device-cgroup-rule 'a *:* rwm' \
        --mount "type=volume,source=$c-data,target=/var/lib/docker,volume-label=$label" \
        "$node_image" >/dev/null || die 1 "starting the worker container $c failed"
    fi
    wait_for 60 "the engine in $c answering" docker exec "$c" docker info
    for img in "${images[@]}"; do
      docker save "$img" | docker exec -i "$c" docker load >/dev/null || die 1 "loading $img into $c failed"
    done
    if [[ $(docker exec "$c" docker info -f '{{.Swarm.LocalNodeState}}') != active ]]; then
      ip=$(docker inspect -f "{{(index .NetworkSettings.Networks \"$network\").IPAddress}}" "$c")
      docker exec "$c" docker swarm join --token "$token" --advertise-addr "$ip" "$manager_addr" >/dev/null ||
        die 1 "$c could not join the swarm at $manager_addr"
    fi
    node_id=$(docker exec "$c" docker info -f '{{.Swarm.NodeID}}')
    wait_for 60 "node $c becoming Ready" bash -c "[[ \$(docker node inspect -f '{{.Status.State}}' $node_id) == ready ]]"
    docker node update --label-add "swarm-slot=$i" "$node_id" >/dev/null
    mem=$(docker node inspect -f '{{.Description.Resources.MemoryBytes}}' "$node_id")
    say "worker $c joined as slot $i ($ip, $((mem / 1048576)) MiB)${images[*]:+, images loaded: ${images[*]}}"
  done
}

"$cmd"
