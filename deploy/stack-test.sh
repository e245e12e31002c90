#!/usr/bin/env bash
# End-to-end test of the Docker Swarm deployment on the swarm this engine manages: generate a
# stack file (deploy/stack-gen.sh), `docker stack deploy` it, wait for the GCS to declare
# completion, check metrics.json from the results volume, `docker stack rm`. Leaves no service,
# network, config or volume behind, also when it fails or is interrupted.
#
#   deploy/swarm-cluster.sh up --workers 1 --image swarm:latest
#   deploy/stack-test.sh --nodes 2                         # default mission, groups on both nodes
#   deploy/stack-test.sh --nodes 2 --groups 10 --robots 10 --agents-per-process 9
#   deploy/swarm-cluster.sh down
#
# Flags:
#   --scenario FILE       the scenario (default scenarios/default.pbtxt)
#   --groups G --robots R the scenario with its groups and robots_per_group set so
#   --nodes N, --agents-per-process K, --memory-mb M, --encrypted   passed to stack-gen.sh
#   --secure              DDS-Security: certificates for every role (scripts/make-certs.sh, in the
#                         test's temporary folder), handed to the roles as swarm secrets
#   --image IMAGE         the image every node runs (default swarm:latest); it must be on every node
#   --timeout S           seconds the mission may take once deployed (default 600)
#   --out DIR             keep metrics.json, run.pb, every service's log (logs/) and where each
#                         task ran and how it ended (tasks.txt) here (default: a temp dir)
#   --after-up CMD        run CMD (bash) once the stack is deployed: the place for fault injection;
#                         it sees SWARM_STACK (the stack's name) and SWARM_IMAGE
#   --expect-lost SVC     service SVC is ended on purpose (killed, or its node drained): its
#                         agents' reports are missing and its task may fail (repeatable)
# Checks before deploying, each failing with exit code 2 and the cause named: the engine is a
# swarm manager; a Ready, Active node carries each slot label swarm-slot=0..N-1; each node has
# the memory its services reserve. While it waits: a task rejected for a missing image names the
# node; a task left pending (no node fits) for 60 s names the scheduler's reason; a task whose
# container did not start (a Docker bug, see below) is started once more.
# Exit codes: 0 passed, 1 failed (the failing service, its state and last log lines are named),
# 2 bad input or the cluster cannot hold the stack, 77 skipped: no Docker engine here.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
# shellcheck source=deploy/lib.sh
source "$here/lib.sh"
# shellcheck source=deploy/results.sh
source "$here/results.sh"

scenario=$root/scenarios/default.pbtxt
size_groups=""
size_robots=""
gen=()
nodes=1
memory_mb=96
image=swarm:latest
timeout=600
out=""
after_up=""
lost=()
secure=0
while (($#)); do
  case $1 in
    --scenario) scenario=${2:?--scenario needs a scenario file}; shift ;;
    --groups) size_groups=${2:?--groups needs a number}; shift ;;
    --robots | --robots-per-group) size_robots=${2:?--robots needs a number}; shift ;;
    --nodes) nodes=${2:?--nodes needs a number}; gen+=(--nodes "$2"); shift ;;
    --agents-per-process) gen+=(--agents-per-process "${2:?--agents-per-process needs a number}"); shift ;;
    --memory-mb) memory_mb=${2:?--memory-mb needs a number}; gen+=(--memory-mb "$2"); shift ;;
    --encrypted) gen+=(--encrypted) ;;
    --secure) secure=1 ;;
    --image) image=${2:?--image needs an image name}; shift ;;
    --timeout) timeout=${2:?--timeout needs seconds}; shift ;;
    --out) out=${2:?--out needs a folder}; shift ;;
    --after-up) after_up=${2:?--after-up needs a command}; shift ;;
    --expect-lost) lost+=("${2:?--expect-lost needs a service}"); shift ;;
    -h | --help) sed -n '2,31p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) die 2 "unknown flag $1 (see --help)" ;;
  esac
  shift
done
[[ $timeout =~ ^[1-9][0-9]*$ ]] || die 2 "--timeout '$timeout' is not a positive number of seconds"
[[ $nodes =~ ^[1-9][0-9]*$ ]] || die 2 "--nodes '$nodes' is not a positive number"
[[ -z $size_groups$size_robots || ($size_groups =~ ^[1-9][0-9]*$ && $size_robots =~ ^[1-9][0-9]*$) ]] ||
  die 2 "--groups and --robots go together, as positive numbers (got '$size_groups' and '$size_robots')"
[[ -f $scenario ]] || die 2 "--scenario $scenario: no such file"
# An encrypted overlay is IPsec ESP between the nodes; a kernel built without it (this project's
# CI VM: CONFIG_INET_ESP is not set) leaves the groups on other nodes unreachable, silently.
if [[ " ${gen[*]} " == *" --encrypted "* ]] && zgrep -q '^# CONFIG_INET_ESP is not set' /proc/config.gz 2>/dev/null; then
  die 2 "--encrypted: this kernel has no IPsec ESP (CONFIG_INET_ESP), so an encrypted overlay carries nothing between nodes; use --secure (DDS-Security encrypts the swarm's own traffic) instead"
fi

if ! docker_engine_running; then
  echo "SKIPPED: no Docker engine answers here (docker info failed); the stack deployment was not tested"
  exit 77
fi
# The cluster: this engine manages a swarm.
state=$(docker info -f '{{.Swarm.LocalNodeState}}')
[[ $state == active ]] ||
  die 2 "this Docker engine is not in swarm mode (swarm: $state): make a swarm first (docker swarm init, or deploy/swarm-cluster.sh up for one on this machine)"
[[ $(docker info -f '{{.Swarm.ControlAvailable}}') == true ]] ||
  die 2 "this Docker engine is a swarm worker: run the stack from a manager"
docker image inspect "$image" >/dev/null 2>&1 ||
  die 2 "image $image does not exist on this manager; build it (deploy/build-images.sh) and load it on every node"

work=$(mktemp -d "${TMPDIR:-/tmp}/swarm-stack-test.XXXXXX")
out=${out:-$work/out}
mkdir -p "$out"
out=$(cd "$out" && pwd)
stack=""

# The scenario at the size asked for, and the stack file.
if [[ -n $size_groups ]]; then
  sed -e '/^groups:/d' -e '/^robots_per_group:/d' "$scenario" >"$work/$(basename "$scenario")"
  printf 'groups: %s\nrobots_per_group: %s\n' "$size_groups" "$size_robots" >>"$work/$(basename "$scenario")"
  scenario=$work/$(basename "$scenario")
fi
"$here/stack-gen.sh" --from-scenario "$scenario" "${gen[@]}" >"$work/stack.yml"
mapfile -t services < <(sed -n '/^services:/,/^networks:/s/^  \([a-z][a-z0-9-]*\):$/\1/p' "$work/stack.yml")
if ((secure)); then
  # One identity per role, named as its service; a secure stack has no discovery service.
  mapfile -t services < <(printf '%s\n' "${services[@]}" | grep -vx discovery)
  "$root/scripts/make-certs.sh" "$work/certs" "${services[@]}" >"$work/make-certs.log" 2>&1 ||
    { cat "$work/make-certs.log" >&2; die 1 "scripts/make-certs.sh failed (above)"; }
  "$here/stack-gen.sh" --from-scenario "$scenario" "${gen[@]}" --secure "$work/certs" >"$work/stack.yml"
fi
for s in "${lost[@]}"; do
  printf '%s\n' "${services[@]}" | grep -qxF "$s" || die 2 "--expect-lost $s: the stack has no such service"
done

# slot_of SERVICE: the swarm-slot its placement names.
slot_of() { sed -n "/^  $1:\$/,/^\$/s/.*node.labels.swarm-slot == \([0-9]*\).*/\1/p" "$work/stack.yml"; }

# Each slot's node: exactly one Ready, Active node, with the memory its services reserve.
for ((k = 0; k < nodes; k++)); do
  mapfile -t ids < <(docker node ls -q --filter "node.label=swarm-slot=$k")
  ((${#ids[@]} == 1)) || die 2 "slot $k: ${#ids[@]} nodes carry the label swarm-slot=$k (need exactly 1: docker node update --label-add swarm-slot=$k NODE)"
  read -r host node_state availability mem < <(docker node inspect -f \
    '{{.Description.Hostname}} {{.Status.State}} {{.Spec.Availability}} {{.Description.Resources.MemoryBytes}}' "${ids[0]}")
  [[ $node_state == ready && $availability == active ]] ||
    die 2 "slot $k's node $host is $node_state and $availability (need ready and active)"
  count=0
  for s in "${services[@]}"; do [[ $(slot_of "$s") != "$k" ]] || count=$((count + 1)); done
  need=$((count * memory_mb))
  ((mem / 1048576 >= need)) ||
    die 2 "node $host (slot $k) has $((mem / 1048576)) MiB of memory; its $count services reserve $memory_mb MiB each, $need MiB: spread over more nodes (--nodes) or reserve less (--memory-mb)"
done

# Removes the stack and waits until its services, containers, network and configs are gone;
# the results volume (on this node) last. Fails loudly if something is still there.
remove_stack() {
  local s=$1 i left
  docker stack rm "$s" >/dev/null 2>&1 || true
  for ((i = 0; i < 120; i++)); do
    left="$(docker service ls -q --filter "label=com.docker.stack.namespace=$s")$(docker ps -aq --filter "label=com.docker.stack.namespace=$s")$(docker network ls -q --filter "label=com.docker.stack.namespace=$s")"
    [[ -n $left ]] || break
    sleep 0.5
  done
  for ((i = 0; i < 20; i++)); do
    docker volume rm "${s}_results" >/dev/null 2>&1 || true
    docker volume inspect "${s}_results" >/dev/null 2>&1 || break
    sleep 0.5
  done
  left="$(docker service ls -q --filter "label=com.docker.stack.namespace=$s")$(docker network ls -q --filter "label=com.docker.stack.namespace=$s")$(docker config ls -q --filter "label=com.docker.stack.namespace=$s")$(docker volume ls -q --filter "name=^${s}_results\$")"
  if [[ -n $left ]]; then
    echo "stack-test: stack $s left services, networks, configs or volumes behind: $left" >&2
    return 1
  fi
}

# A run killed outright cannot clean up: remove the stacks of earlier runs (swarmtest-PID-N)
# whose PID is gone.
for s in $(docker stack ls --format '{{.Name}}' 2>/dev/null); do
  [[ $s =~ ^swarmtest-([0-9]+)-[0-9]+$ ]] || continue
  kill -0 "${BASH_REMATCH[1]}" 2>/dev/null && continue
  say "removing stack $s, left behind by a run that was killed"
  remove_stack "$s" || true
done

on_exit() {
  local rc=$? s
  if [[ -n $stack ]]; then
    # Where each service ran and how its task ended (SERVICE NODE STATE), for the record.
    docker stack ps "$stack" --no-trunc --format '{{.Name}} {{.Node}} {{.CurrentState}}' 2>/dev/null |
      sed "s/^${stack}_\([^ ]*\)\.[0-9]* /\1 /" >"$out/tasks.txt" || true
    mkdir -p "$out/logs"
    for s in "${services[@]}"; do
      docker service logs --raw --no-task-ids "${stack}_$s" >"$out/logs/$s.log" 2>&1 || true
    done
    remove_stack "$stack" || rc=1
  fi
  [[ $out == "$work/out" ]] || rm -rf "$work"
  exit "$rc"
}
trap on_exit EXIT
trap 'exit 130' INT TERM

# task[SERVICE]="STATE|NODE|ERROR" of each service's newest task, in one docker call.
declare -A task=()
poll_tasks() {
  local name node st err
  task=()
  while IFS='|' read -r name node st err; do
    name=${name#"${stack}_"}
    name=${name%.*}
    [[ -n ${task[$name]:-} ]] || task[$name]="$st|$node|$err"
  done < <(docker stack ps "$stack" --no-trunc --format '{{.Name}}|{{.Node}}|{{.CurrentState}}|{{.Error}}' 2>/dev/null)
}

report_service() {
  echo "stack-test: service $1 $2; its last log lines:" >&2
  docker service logs --raw --no-task-ids --tail 15 "${stack}_$1" 2>&1 | sed 's/^/  | /' >&2
  return 1
}

is_lost() { printf '%s\n' "${lost[@]}" | grep -qxF "$1"; }

start=$SECONDS
stack=swarmtest-$$-$RANDOM
export SWARM_STACK=$stack SWARM_IMAGE=$image
say "deploying stack $stack: ${#services[@]} services over $nodes node(s), image $image"
if ! docker stack deploy --resolve-image never -c "$work/stack.yml" "$stack" >"$work/deploy.log" 2>&1; then
  sed 's/^/  | /' "$work/deploy.log" >&2
  die 1 "docker stack deploy failed (above)"
fi
t_up=$SECONDS
if [[ -n $after_up ]]; then
  bash -c "$after_up" || die 1 "the --after-up command failed"
fi

# Wait for the GCS's task to complete, failing fast on a task that ends or cannot start.
deadline=$((SECONDS + timeout))
gcs_done=0
declare -A pending_since=() retried=()
while ((SECONDS < deadline)); do
  poll_tasks
  for s in "${services[@]}"; do
    IFS='|' read -r st node err <<<"${task[$s]:-}"
    case $st in
      "")
        ;;
      Rejected* | Failed*)
        if [[ $err == *"No such image"* || $err == *"pull access denied"* || $err == *"does not exist"* ]]; then
          die 1 "node ${node:-?} does not have the image $image ($s: $err): load it there (docker save $image | docker -H NODE load)"
        fi
        # Docker 20.10 sometimes fails to start a task whose secrets or configs it mounts
        # ("unable to remount dir as readonly ... device or resource busy", moby/moby#48783).
        # The role never ran, so starting its task once more changes nothing of the mission.
        if [[ $err == *"starting container failed"* && -z ${retried[$s]:-} ]]; then
          retried[$s]=1
          say "$s did not start on node ${node:-?} ($err); starting it again (docker service update --force)"
          timeout 90 docker service update --force --quiet "${stack}_$s" >/dev/null 2>&1 || die 1 "could not start $s again"
          continue
        fi
        is_lost "$s" || { report_service "$s" "is $st on node ${node:-?}: $err"; exit 1; }
        ;;
      Pending* | Assigned* | Preparing*)
        pending_since[$s]=${pending_since[$s]:-$SECONDS}
        if ((SECONDS - pending_since[$s] > 60)); then
          err=$(docker service ps "${stack}_$s" --no-trunc --format '{{.Error}}' | head -n 1)
          die 1 "service $s has not started in 60 s: ${err:-no node fits it (docker service ps ${stack}_$s)}"
        fi
        ;;
      Complete*)
        [[ $s != gcs ]] || gcs_done=1
        ;;
    esac
  done
  ((gcs_done == 0)) || break
  sleep 1
done
((gcs_done)) || { report_service gcs "did not complete within --timeout $timeout s"; exit 1; }
t_gcs=$SECONDS
# Every other role reports to the GCS before it exits, so they end right after it.
grace=$((SECONDS + 30))
while ((SECONDS < grace)); do
  poll_tasks
  running=0
  for s in "${services[@]}"; do
    is_lost "$s" || [[ ${task[$s]:-} == Complete* ]] || running=1
  done
  ((running)) || break
  sleep 1
done
failed=0
for s in "${services[@]}"; do
  is_lost "$s" && continue
  IFS='|' read -r st node err <<<"${task[$s]:-missing||}"
  [[ $st == Complete* ]] || report_service "$s" "is '$st' on node $node 30 s after the GCS finished${err:+ ($err)}" || failed=1
done
((failed == 0)) || die 1 "FAILED (logs and whatever results there were: $out)"

# The results, out of the volume on slot 0's node (this one in a cluster swarm-cluster.sh made).
rm -f "$out/metrics.json" "$out/run.pb"
docker run --rm --network none -v "${stack}_results:/results:ro" --entrypoint tar "$image" -C /results -cf - . |
  tar -C "$out" -xf - || die 1 "could not read the volume ${stack}_results on this node"
# The lost services' agents: member-G-I, members-G-A-B (robots A..B), leader-G.
want=()
for s in "${lost[@]}"; do
  if [[ $s =~ ^members-([0-9]+)-([0-9]+)-([0-9]+)$ ]]; then
    for ((i = BASH_REMATCH[2]; i <= BASH_REMATCH[3]; i++)); do want+=("\"member-${BASH_REMATCH[1]}-$i\""); done
  else
    want+=("\"$s\"")
  fi
done
check_results "$out" "[$(IFS=,; echo "${want[*]}")]" || die 1 "FAILED (results and logs: $out)"
wall=$(top_value wall_seconds "$out/metrics.json")
startup=$(awk -v t="$((t_gcs - t_up))" -v w="$wall" 'BEGIN { printf "%.0f", t - w }')
say "passed: $(summary "$out/metrics.json"); ${#services[@]} services on $nodes node(s): deployed in" \
  "$((t_up - start)) s, first tick ~${startup} s after, GCS done $((t_gcs - t_up)) s after deploying;" \
  "results and logs in $out"
