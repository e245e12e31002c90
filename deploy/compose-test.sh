#!/usr/bin/env bash
# End-to-end test of the docker-compose deployment: build the image, bring a mission up (one
# container per role), wait for the GCS to declare completion, check metrics.json from the
# results volume, bring everything down. Leaves no container, network or volume behind, also
# when it fails or is interrupted.
#
#   deploy/compose-test.sh                          # deploy/docker-compose.yml (3 x 3), image built from source
#   deploy/compose-test.sh --prebuilt build/bin     # image from this host's binaries (fast)
#   deploy/compose-test.sh --scenario scenarios/small.pbtxt --compose all
#   deploy/compose-test.sh --prebuilt build/bin --groups 5 --robots 10   # 50 robots (~N min, see README)
#   deploy/compose-test.sh --prebuilt build/bin --secure                  # DDS-Security, certificates made here
#
# Flags:
#   --compose CMD|all     "docker compose", "docker-compose", or all installed (default: the first found)
#   --file FILE           compose file (default deploy/docker-compose.yml)
#   --scenario FILE       generate a compose file for FILE instead (deploy/compose-gen.sh)
#   --groups G --robots R generate a compose file for G x R robots: the scenario (--scenario, else
#                         scenarios/default.pbtxt) with its groups and robots_per_group set so
#   --secure              DDS-Security: certificates for every role (scripts/make-certs.sh, in the
#                         test's temporary folder) and a compose file that mounts them
#                         (compose-gen.sh --secure); with a generated compose file only
#   --image IMAGE         image to build and run (default swarm:latest)
#   --prebuilt DIR        build the image from binaries in DIR (deploy/build-images.sh --prebuilt)
#   --no-build            use the image as it is
#   --timeout S           seconds the mission may take once up (default 600)
#   --out DIR             keep metrics.json, run.pb and every service's log here (default: a temp dir)
#   --after-up CMD        run CMD (bash) once the mission is up, before waiting: the place for fault
#                         injection; it sees COMPOSE_PROJECT_NAME, SWARM_COMPOSE, SWARM_COMPOSE_FILE,
#                         SWARM_IMAGE and SWARM_NETWORK (the project's compose network)
#   --expect-exit S=CODE  service S is expected to end with CODE (default 0 for every service)
# Exit codes: 0 passed, 1 failed (the failing service, its exit code and last log lines are
# named), 2 bad input, 77 skipped: no Docker engine or no compose command here.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
# shellcheck source=deploy/lib.sh
source "$here/lib.sh"
# shellcheck source=deploy/results.sh
source "$here/results.sh"

compose_choice=""
file=$here/docker-compose.yml
scenario=""
file_given=0
size_groups=""
size_robots=""
secure=0
image=swarm:latest
prebuilt=""
build=1
timeout=600
out=""
after_up=""
declare -A expected_exit=()
while (($#)); do
  case $1 in
    --compose) compose_choice=${2:?--compose needs a command or all}; shift ;;
    --file) file=${2:?--file needs a compose file}; file_given=1; shift ;;
    --scenario) scenario=${2:?--scenario needs a scenario file}; shift ;;
    --groups) size_groups=${2:?--groups needs a number}; shift ;;
    --robots | --robots-per-group) size_robots=${2:?--robots needs a number}; shift ;;
    --secure) secure=1 ;;
    --image) image=${2:?--image needs an image name}; shift ;;
    --prebuilt) prebuilt=${2:?--prebuilt needs a folder}; shift ;;
    --no-build) build=0 ;;
    --timeout) timeout=${2:?--timeout needs seconds}; shift ;;
    --out) out=${2:?--out needs a folder}; shift ;;
    --after-up) after_up=${2:?--after-up needs a command}; shift ;;
    --expect-exit)
      [[ ${2:-} =~ ^([A-Za-z0-9_.-]+)=([0-9]+)$ ]] || die 2 "--expect-exit needs SERVICE=CODE (got '${2:-}')"
      expected_exit[${BASH_REMATCH[1]}]=${BASH_REMATCH[2]}
      shift
      ;;
    -h | --help) sed -n '2,32p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) die 2 "unknown flag $1 (see --help)" ;;
  esac
  shift
done
[[ $timeout =~ ^[1-9][0-9]*$ ]] || die 2 "--timeout '$timeout' is not a positive number of seconds"
[[ -z $size_groups$size_robots || ($size_groups =~ ^[1-9][0-9]*$ && $size_robots =~ ^[1-9][0-9]*$) ]] ||
  die 2 "--groups and --robots go together, as positive numbers (got '$size_groups' and '$size_robots')"
[[ $file_given == 0 || ($secure == 0 && -z $scenario$size_groups) ]] ||
  die 2 "--file names a finished compose file; --scenario, --groups/--robots and --secure generate one instead"

# Skip, loudly, where this cannot run.
if ! docker_engine_running; then
  echo "SKIPPED: no Docker engine answers here (docker info failed); the compose deployment was not tested"
  exit 77
fi
mapfile -t installed < <(compose_commands)
if ((${#installed[@]} == 0)); then
  echo "SKIPPED: neither 'docker compose' nor 'docker-compose' is installed; the compose deployment was not tested"
  exit 77
fi
case $compose_choice in
  "") composes=("${installed[0]}") ;;
  all) composes=("${installed[@]}") ;;
  *)
    printf '%s\n' "${installed[@]}" | grep -qxF "$compose_choice" ||
      die 2 "--compose '$compose_choice' is not installed here (installed: $(printf "'%s' " "${installed[@]}"))"
    composes=("$compose_choice")
    ;;
esac

work=$(mktemp -d "${TMPDIR:-/tmp}/swarm-compose-test.XXXXXX")
out=${out:-$work/out}
mkdir -p "$out"
out=$(cd "$out" && pwd)
project=""
compose=()

# Removes what carries compose's label for project $1, whatever made it.
remove_labelled() {
  local label=com.docker.compose.project=$1 ids
  ids=$(docker ps -aq --filter "label=$label")
  [[ -z $ids ]] || docker rm -f $ids >/dev/null 2>&1 || true
  ids=$(docker network ls -q --filter "label=$label")
  [[ -z $ids ]] || docker network rm $ids >/dev/null 2>&1 || true
  ids=$(docker volume ls -q --filter "label=$label")
  [[ -z $ids ]] || docker volume rm -f $ids >/dev/null 2>&1 || true
}

# A run killed outright (SIGKILL, e.g. a ctest timeout) cannot clean up: remove the projects of
# earlier runs (swarmtest-PID-N) whose PID is gone.
sweep_stale_projects() {
  local p
  for p in $({
    docker ps -a --filter label=com.docker.compose.project --format '{{.Label "com.docker.compose.project"}}'
    docker network ls --filter label=com.docker.compose.project --format '{{.Label "com.docker.compose.project"}}'
    docker volume ls --filter label=com.docker.compose.project --format '{{.Label "com.docker.compose.project"}}'
  } | sort -u); do
    [[ $p =~ ^swarmtest-([0-9]+)-[0-9]+$ ]] || continue
    kill -0 "${BASH_REMATCH[1]}" 2>/dev/null && continue
    say "removing project $p, left behind by a run that was killed"
    remove_labelled "$p"
  done
}

# Removes everything of the current project: compose's own `down`, then a sweep by compose's
# labels for anything it missed. Fails loudly if something is still there.
cleanup_project() {
  [[ -n $project ]] || return 0
  local p=$project id
  project=""
  # Every container's log, also when the run failed early (kept in --out).
  mkdir -p "$out/logs"
  for id in $(docker ps -aq --filter "label=com.docker.compose.project=$p"); do
    docker logs "$id" >"$out/logs/$(docker inspect -f '{{index .Config.Labels "com.docker.compose.service"}}' "$id").log" 2>&1 || true
  done
  "${compose[@]}" -p "$p" -f "$file" down --volumes --remove-orphans --timeout 5 >"$work/down.log" 2>&1 || true
  remove_labelled "$p"
  local label=com.docker.compose.project=$p
  local left
  left="$(docker ps -aq --filter "label=$label")$(docker network ls -q --filter "label=$label")$(docker volume ls -q --filter "label=$label")"
  if [[ -n $left ]]; then
    echo "compose-test: project $p left containers, networks or volumes behind: $left" >&2
    return 1
  fi
}
on_exit() {
  local rc=$?
  cleanup_project || rc=1
  rm -rf "$work/down.log" "$work/compose.yml" "$work/certs" "$work/scenario" "$work/make-certs.log"
  [[ $out == "$work/out" ]] || rm -rf "$work"
  exit "$rc"
}
trap on_exit EXIT
trap 'exit 130' INT TERM

sweep_stale_projects
phase_start=$SECONDS
elapsed() { echo "$((SECONDS - phase_start)) s"; }

# 1. The image.
if ((build)); then
  args=(--tag "$image")
  [[ -z $prebuilt ]] || args+=(--prebuilt "$prebuilt")
  "$here/build-images.sh" "${args[@]}" || die 1 "building the image failed (above)"
  say "image $image ready ($(elapsed))"
else
  docker image inspect "$image" >/dev/null 2>&1 || die 2 "--no-build: image $image does not exist; build it (deploy/build-images.sh)"
fi

# 2. The compose file: the one given, or one generated for the scenario, the size, security.
if [[ -n $scenario$size_groups ]] || ((secure)); then
  scenario=${scenario:-$root/scenarios/default.pbtxt}
  [[ -f $scenario ]] || die 2 "--scenario $scenario: no such file"
  if [[ -n $size_groups ]]; then
    # The same scenario with its top-level size fields set (added when absent).
    mkdir -p "$work/scenario"
    sed -e '/^groups:/d' -e '/^robots_per_group:/d' "$scenario" >"$work/scenario/$(basename "$scenario")"
    printf 'groups: %s\nrobots_per_group: %s\n' "$size_groups" "$size_robots" >>"$work/scenario/$(basename "$scenario")"
    scenario=$work/scenario/$(basename "$scenario")
  fi
  gen=(--from-scenario "$scenario")
  ((secure == 0)) || gen+=(--secure "$work/certs")
  "$here/compose-gen.sh" "${gen[@]}" >"$work/compose.yml"
  file=$work/compose.yml
fi
[[ -f $file ]] || die 2 "compose file $file does not exist"
file=$(cd "$(dirname "$file")" && pwd)/$(basename "$file")
if ((secure)); then
  # One identity per service (the services are named as the roles' certificates), readable by
  # the containers' user (uid 10001): this folder is the test's own and removed with it.
  read -r -a c <<<"${composes[0]}"
  mapfile -t names < <("${c[@]}" -f "$file" config --services)
  ((${#names[@]})) || die 2 "$file defines no services"
  "$root/scripts/make-certs.sh" "$work/certs" "${names[@]}" >"$work/make-certs.log" 2>&1 ||
    { cat "$work/make-certs.log" >&2; die 1 "scripts/make-certs.sh failed (above)"; }
  chmod -R a+rX "$work/certs"
  say "certificates for ${#names[@]} roles in $work/certs"
fi

container_of() { docker ps -aq --filter "label=com.docker.compose.project=$project" --filter "label=com.docker.compose.service=$1" | head -n 1; }

# state[SERVICE]="STATUS EXITCODE" for every container of the project, in two docker calls (the
# mission shares the machine's cores with this loop).
declare -A state=()
poll_states() {
  local ids service st code
  state=()
  ids=$(docker ps -aq --filter "label=com.docker.compose.project=$project")
  [[ -n $ids ]] || return 0
  while read -r service st code; do
    [[ -n $service ]] && state[$service]="$st $code"
  done < <(docker inspect -f '{{index .Config.Labels "com.docker.compose.service"}} {{.State.Status}} {{.State.ExitCode}}' $ids 2>/dev/null)
}

# Names a service that ended (or is) not as expected, with its last log lines; returns 1.
report_service() {
  local service=$1 what=$2 cid
  cid=$(container_of "$service")
  echo "compose-test: service $service $what; its last log lines:" >&2
  if [[ -n $cid ]]; then docker logs --tail 15 "$cid" 2>&1 | sed 's/^/  | /' >&2; fi
  return 1
}

run_mission() {
  local run_start=$SECONDS services s cid st code want
  project=swarmtest-$$-$RANDOM
  export COMPOSE_PROJECT_NAME=$project SWARM_COMPOSE="${compose[*]}" SWARM_COMPOSE_FILE=$file SWARM_IMAGE=$image \
    SWARM_NETWORK=${project}_swarm
  mapfile -t services < <("${compose[@]}" -f "$file" config --services)
  ((${#services[@]})) || die 2 "$file defines no services"
  say "[${compose[*]}] up: project $project, ${#services[@]} services, image $image"

  # 3. Up.
  if ! "${compose[@]}" -p "$project" -f "$file" up -d >"$work/up.log" 2>&1; then
    sed 's/^/  | /' "$work/up.log" >&2
    echo "compose-test: '${compose[*]} up' failed (above)" >&2
    return 1
  fi

  local t_up=$SECONDS
  # 4. Faults (later: killing a member, cutting a leader off) go here, between up and wait.
  if [[ -n $after_up ]]; then
    bash -c "$after_up" || { echo "compose-test: the --after-up command failed" >&2; return 1; }
  fi

  # 5. Wait for the GCS to finish, failing fast when any service ends unexpectedly.
  local deadline=$((SECONDS + timeout)) gcs_done=0
  while ((SECONDS < deadline)); do
    poll_states
    gcs_done=1
    for s in "${services[@]}"; do
      [[ -n ${state[$s]:-} ]] || { report_service "$s" "has no container"; return 1; }
      read -r st code <<<"${state[$s]}"
      want=${expected_exit[$s]:-0}
      if [[ $st == exited && $code != "$want" ]]; then
        report_service "$s" "exited with code $code (expected $want)"
        return 1
      fi
      [[ $s != gcs || $st == exited ]] || gcs_done=0
    done
    ((gcs_done == 0)) || break
    sleep 1
  done
  ((gcs_done)) || { report_service gcs "did not finish within --timeout $timeout s"; return 1; }
  local t_gcs=$SECONDS
  # Every other role reports to the GCS before it exits, so they end right after it.
  local grace=$((SECONDS + 30)) running
  while ((SECONDS < grace)); do
    poll_states
    running=0
    for s in "${services[@]}"; do
      [[ ${state[$s]:-} == exited* ]] || running=1
    done
    ((running)) || break
    sleep 1
  done
  local t_all=$SECONDS failed=0
  for s in "${services[@]}"; do
    read -r st code <<<"${state[$s]:-missing -1}"
    want=${expected_exit[$s]:-0}
    if [[ $st != exited ]]; then
      report_service "$s" "is still $st 30 s after the GCS finished" || failed=1
    elif [[ $code != "$want" ]]; then
      report_service "$s" "exited with code $code (expected $want)" || failed=1
    fi
  done
  ((failed == 0)) || return 1

  # 6. The results, out of the volume.
  local volume
  volume=$(docker volume ls -q --filter "label=com.docker.compose.project=$project" \
    --filter "label=com.docker.compose.volume=results")
  [[ -n $volume ]] || { echo "compose-test: the project has no 'results' volume" >&2; return 1; }
  rm -f "$out/metrics.json" "$out/run.pb"
  docker run --rm --network none -v "$volume:/results:ro" --entrypoint tar "$image" -C /results -cf - . |
    tar -C "$out" -xf -
  # Every agent reports, except the services killed on purpose (--expect-exit S=137).
  local killed=()
  for s in "${!expected_exit[@]}"; do [[ ${expected_exit[$s]} == 137 ]] && killed+=("\"$s\""); done
  check_results "$out" "[$(IFS=,; echo "${killed[*]}")]" || return 1
  # Start-up: from `up` returning to the first tick, i.e. the GCS's whole time less the ticks'.
  local wall startup
  wall=$(top_value wall_seconds "$out/metrics.json")
  startup=$(awk -v t="$((t_gcs - t_up))" -v w="$wall" 'BEGIN { printf "%.0f", t - w }')
  say "[${compose[*]}] passed: $(summary "$out/metrics.json"); ${#services[@]} containers: up $((t_up - run_start)) s," \
    "first tick ~${startup} s after up, GCS done $((t_gcs - t_up)) s after up, all exited $((t_all - t_gcs)) s" \
    "after it, checked and copied in $((SECONDS - t_all)) s; results and logs in $out"
}

result=0
for c in "${composes[@]}"; do
  read -r -a compose <<<"$c"
  run_mission || result=1
  cleanup_project || result=1
  ((result == 0)) || break
done
((result == 0)) || die 1 "FAILED (logs and whatever results there were: $out)"
say "PASSED in $(elapsed) with ${composes[*]}"
