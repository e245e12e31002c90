#!/usr/bin/env bash
# Writes a Docker Swarm stack file (`docker stack deploy -c FILE NAME`) for G groups x R robots to
# stdout: the same roles as compose-gen.sh's compose file (discovery, sim, gcs, leader-<g>,
# member-<g>-<i>), as swarm services spread over the cluster's nodes.
#
#   deploy/stack-gen.sh --groups 3 --robots 3 --nodes 2 > stack.yml
#   deploy/stack-gen.sh --from-scenario scenarios/open.pbtxt --nodes 2 > stack.yml
#   deploy/stack-gen.sh --groups 10 --robots 10 --agents-per-process 9 --nodes 2 > stack-100.yml
#   docker stack deploy --resolve-image never -c stack.yml swarm
#
# Placement (the rule): the cluster's nodes carry the label swarm-slot=0..N-1 (N = --nodes; set it
# with `docker node update --label-add swarm-slot=K NODE`). Group g runs on the node of slot
# g mod N, its leader and members together, since most of a group's traffic stays inside it. The
# discovery server, the simulator and the GCS run on slot 0, which also keeps the results volume.
#
# Flags:
#   --groups G, --robots R       the size (default 3 x 3); --robots-per-group is --robots
#   --from-scenario FILE         the scenario (default scenarios/default.pbtxt); it becomes the
#                                stack's config "scenario", which the swarm hands to every node.
#                                G and R default to its groups: and robots_per_group: and must
#                                equal them
#   --nodes N                    slots to spread the groups over (default 1)
#   --agents-per-process K       a group's members in services of K robots each
#                                (members-<g>-<first>-<last>, as `swarm run --agents-per-process`)
#   --memory-mb M                memory each role's container reserves (default 96; the scheduler
#                                places a service only on a node that has it free)
#   --encrypted                  encrypt the overlay network's traffic between nodes (IPsec)
#   --mtu BYTES                  the overlay network's MTU (default: Docker's, 1450); 50 below the
#                                nodes' own network MTU
#   --secure DIR                 DDS-Security: each role gets, as swarm secrets at /run/secrets, its
#                                own certificate and key, the CA certificate and the signed
#                                governance and permissions from DIR (absolute; never the CA's key),
#                                made by scripts/make-certs.sh DIR SERVICE... There is no discovery
#                                service (Fast DDS 2.9's cannot authenticate) and an overlay carries
#                                no multicast: each role announces itself to the others' addresses,
#                                which the entrypoint looks up by service name (SWARM_PEERS).
# Results: the GCS writes metrics.json, run.pb and gcs.journal to the volume <stack>_results on the
# node of slot 0: `docker run --rm -v <stack>_results:/results IMAGE ls /results` there.
# Exit codes: 0 ok, 2 bad input.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=deploy/lib.sh
source "$here/lib.sh"

groups=""
robots=""
scenario=""
nodes=1
per_process=1
memory_mb=96
encrypted=0
mtu=""
certs=""
while (($#)); do
  case $1 in
    --groups) groups=${2:-}; shift ;;
    --robots | --robots-per-group) robots=${2:-}; shift ;;
    --from-scenario)
      scenario=${2:?--from-scenario needs a scenario file}
      shift
      ;;
    --nodes) nodes=${2:-}; shift ;;
    --agents-per-process) per_process=${2:-}; shift ;;
    --memory-mb) memory_mb=${2:-}; shift ;;
    --encrypted) encrypted=1 ;;
    --mtu) mtu=${2:-}; shift ;;
    --secure) certs=${2:?--secure needs the folder scripts/make-certs.sh wrote}; shift ;;
    -h | --help) sed -n '2,31p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) die 2 "unknown flag $1 (see --help)" ;;
  esac
  shift
done
scenario=${scenario:-$here/../scenarios/default.pbtxt}
[[ -f $scenario ]] || die 2 "--from-scenario $scenario: no such file"
scenario=$(cd "$(dirname "$scenario")" && pwd)/$(basename "$scenario")
read -r g r < <(scenario_size "$scenario")
groups=${groups:-$g}
robots=${robots:-$r}
[[ $groups == "$g" && $robots == "$r" ]] ||
  die 2 "$scenario is $g x $r robots, not $groups x $robots: give --from-scenario a scenario of that size"
positive() { [[ $2 =~ ^[1-9][0-9]*$ ]] || die 2 "$1 '$2' is not a positive number"; }
positive --groups "$groups"
positive --robots "$robots"
positive --nodes "$nodes"
positive --agents-per-process "$per_process"
positive --memory-mb "$memory_mb"
[[ -z $mtu || ($mtu =~ ^[0-9]+$ && $mtu -ge 576 && $mtu -le 9000) ]] ||
  die 2 "--mtu '$mtu' is not an MTU (576..9000 bytes)"
[[ -z $certs || $certs == /* ]] || die 2 "--secure $certs: give an absolute folder"
[[ -z $certs || -f $certs/ca.pem ]] || die 2 "--secure $certs: no ca.pem there; make the certificates with scripts/make-certs.sh"
[[ -z $certs || $per_process == 1 ]] ||
  die 2 "--secure with --agents-per-process $per_process: a secure identity is one robot's, so run one robot per process"
((nodes <= groups)) || die 2 "--nodes $nodes is more than the $groups groups: a node would hold no group"

# deploy_block SLOT RESTART: the service's placement, restart policy and reservation.
deploy_block() {
  cat <<EOF
    deploy:
      endpoint_mode: dnsrr
      placement:
        constraints: [node.labels.swarm-slot == $1]
      restart_policy:
        condition: $2
        delay: 3s
      resources:
        reservations:
          memory: ${memory_mb}M
EOF
}

# service NAME SLOT RESTART ENV_LINE...
service() {
  local name=$1 slot=$2 restart=$3 line
  shift 3
  printf '\n  %s:\n    <<: *role\n' "$name"
  [[ $name != gcs && $name != discovery ]] || printf '    volumes:\n      - results:/results%s\n' "$([[ $name == discovery ]] && echo :ro)"
  if [[ -n $certs ]]; then
    printf '    secrets:\n'
    local f
    for f in $(role_security_files "$name"); do
      printf '      - source: %s\n        uid: "10001"\n        mode: 0400\n' "$f"
    done
  fi
  printf '    environment:\n      <<: *env\n'
  for line in "$@"; do printf '      %s\n' "$line"; done
  deploy_block "$slot" "$restart"
}

# The robots' services: leader-<g>, then member-<g>-<i> or members-<g>-<first>-<last>, each with
# its slot and environment ("SLOT|LINE|LINE...").
robot_services=()
robot_lines=()
for ((g = 0; g < groups; g++)); do
  robot_services+=("leader-$g")
  robot_lines+=("$((g % nodes))|SWARM_ROLE: leader|SWARM_GROUP: \"$g\"")
done
for ((g = 0; g < groups; g++)); do
  for ((first = 1; first < robots; first += per_process)); do
    last=$((first + per_process - 1 < robots - 1 ? first + per_process - 1 : robots - 1))
    if ((first == last)); then
      robot_services+=("member-$g-$first")
      indices=$first
    else
      robot_services+=("members-$g-$first-$last")
      indices=$(seq -s, "$first" "$last")
    fi
    robot_lines+=("$((g % nodes))|SWARM_ROLE: member|SWARM_GROUP: \"$g\"|SWARM_INDEX: \"$indices\"")
  done
done
containers=$((${#robot_services[@]} + 3))
stall=$(stall_timeout "$containers")
cat <<EOF
# swarm on Docker Swarm: $groups groups x $robots robots over $nodes node slot(s), one service per role.
# Generated by deploy/stack-gen.sh --groups $groups --robots $robots --nodes $nodes$( ((per_process > 1)) && echo " --agents-per-process $per_process") --from-scenario $scenario${certs:+ --secure $certs}; edit the generator, not this.
#
#   docker stack deploy --resolve-image never -c THIS_FILE NAME
#   docker stack rm NAME                 # then, on slot 0's node: docker volume rm NAME_results
#
# Placement: nodes labelled swarm-slot=0..$((nodes - 1)) (docker node update --label-add swarm-slot=K NODE);
# group g on slot g mod $nodes; discovery, sim and gcs on slot 0, with the results volume.
# Restart policies, as the faults are meant: a robot that dies stays dead (condition none; its
# group's standby takes over, the simulator counts it lost); the GCS is started again on failure
# and resumes from its journal in the results volume; the discovery server is started again.
# Environment at deploy time (all optional): SWARM_IMAGE (default swarm:latest; every node needs
# it: docker save | docker load without a registry), SWARM_DOMAIN (default 0), SWARM_STALL_TIMEOUT
# (default $stall s), SWARM_DDS_LOG.
# DDS: UDP unicast over the overlay network "swarm" (no multicast crosses an overlay): every role a
# client of the discovery server, which the service name "discovery" reaches (dnsrr: the name is
# the task's own address); with --secure, every role announces itself to the others' addresses.
version: "3.8"

x-role: &role
  image: \${SWARM_IMAGE:-swarm:latest}
  init: true
  networks: [swarm]
  configs:
    - source: scenario
      target: /scenario/scenario.pbtxt
      mode: 0444

x-env: &env
  SWARM_SCENARIO: /scenario/scenario.pbtxt
  SWARM_DOMAIN: \${SWARM_DOMAIN:-0}
  SWARM_PARTITION: swarm
  SWARM_STALL_TIMEOUT: \${SWARM_STALL_TIMEOUT:-$stall}
  SWARM_DDS_LOG: \${SWARM_DDS_LOG:-}
EOF
if [[ -n $certs ]]; then
  printf '  SWARM_SECURITY_DIR: /run/secrets\n  SWARM_PEERS: sim gcs %s\n' "${robot_services[*]}"
else
  echo "  SWARM_DISCOVERY_SERVER: discovery:11811"
fi
printf '\nservices:\n'
[[ -n $certs ]] || service discovery 0 on-failure "SWARM_ROLE: discovery"
service sim 0 none "SWARM_ROLE: sim"
service gcs 0 on-failure "SWARM_ROLE: gcs" "SWARM_PROGRESS: plain"
for ((k = 0; k < ${#robot_services[@]}; k++)); do
  IFS='|' read -r -a fields <<<"${robot_lines[$k]}"
  service "${robot_services[$k]}" "${fields[0]}" none "${fields[@]:1}"
done
cat <<EOF

networks:
  swarm:
    driver: overlay
    attachable: true
EOF
if ((encrypted)) || [[ -n $mtu ]]; then
  echo "    driver_opts:"
  ((encrypted == 0)) || echo '      encrypted: ""'
  [[ -z $mtu ]] || echo "      com.docker.network.driver.mtu: \"$mtu\""
fi
cat <<EOF

volumes:
  results:

configs:
  scenario:
EOF
echo "    file: $scenario"
if [[ -n $certs ]]; then
  printf '\nsecrets:\n'
  # Each file once: the shared three come with every role's list.
  for f in $(for name in sim gcs "${robot_services[@]}"; do role_security_files "$name"; done | awk '!seen[$0]++'); do
    printf '  %s:\n    file: %s/%s\n' "$f" "$certs" "$f"
  done
fi
