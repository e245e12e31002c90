#!/usr/bin/env bash
# Writes a docker-compose file for G groups x R robots to stdout: services discovery (the run's
# Fast DDS discovery server), sim, gcs, leader-<g> (g = 0..G-1) and member-<g>-<i> (i = 1..R-1),
# each its own container with its ids in its environment. Compose's `scale`/`deploy.replicas`
# cannot give replicas distinct ids, so every robot is its own service, generated from one
# template here.
#
#   deploy/compose-gen.sh --groups 4 --robots 2 > my-compose.yml
#   deploy/compose-gen.sh --groups 5 --robots-per-group 10 > compose-50.yml
#   deploy/compose-gen.sh --from-scenario scenarios/open.pbtxt > my-compose.yml
#   deploy/compose-gen.sh --secure "$PWD/certs" > secure.yml   # DDS-Security (see below)
#   deploy/compose-gen.sh --check deploy/docker-compose.yml   # is the committed 3 x 3 file current?
#
# Flags:
#   --groups G, --robots R       the size (default 3 x 3, the scenario defaults); --robots-per-group
#                                is --robots
#   --from-scenario FILE         G, R and the scenario to mount from FILE (its groups: and
#                                robots_per_group: lines); the folder is written as an absolute path
#   --scenario-dir DIR           the host folder mounted read-only at /scenario (default ../scenarios,
#                                relative to the compose file); $SWARM_SCENARIO_DIR overrides it at `up`
#   --scenario-file NAME         the scenario file in it (default default.pbtxt; $SWARM_SCENARIO_FILE)
#   --secure DIR                 DDS-Security: every role mounts, read-only at /security, its own
#                                certificate and key, the CA certificate and the signed governance
#                                and permissions from DIR (an absolute folder; never the CA's key),
#                                made by
#                                  scripts/make-certs.sh DIR $(docker-compose -f FILE config --services)
#                                ($SWARM_CERTS_DIR overrides DIR at `up`). The roles then use simple
#                                discovery and there is no discovery service: Fast DDS 2.9's
#                                discovery server cannot authenticate.
#   --check FILE                 exit 1 (and show the difference) unless FILE equals what the other
#                                flags generate
# Exit codes: 0 ok, 1 --check found a difference, 2 bad input.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=deploy/lib.sh
source "$here/lib.sh"

groups=""
robots=""
scenario_dir=../scenarios
scenario_file=default.pbtxt
check=""
certs=""
while (($#)); do
  case $1 in
    --groups) groups=${2:-}; shift ;;
    --robots | --robots-per-group) robots=${2:-}; shift ;;
    --secure) certs=${2:?--secure needs the folder scripts/make-certs.sh wrote}; shift ;;
    --scenario-dir) scenario_dir=${2:?--scenario-dir needs a folder}; shift ;;
    --scenario-file) scenario_file=${2:?--scenario-file needs a file name}; shift ;;
    --from-scenario)
      f=${2:?--from-scenario needs a scenario file}
      shift
      [[ -f $f ]] || die 2 "--from-scenario $f: no such file"
      # Top-level fields only (no indentation); absent fields keep the proto defaults (3 x 3).
      g=$(sed -n 's/^groups:[[:space:]]*\([0-9][0-9]*\).*/\1/p' "$f" | tail -n 1)
      r=$(sed -n 's/^robots_per_group:[[:space:]]*\([0-9][0-9]*\).*/\1/p' "$f" | tail -n 1)
      [[ -n $groups ]] || groups=${g:-3}
      [[ -n $robots ]] || robots=${r:-3}
      scenario_dir=$(cd "$(dirname "$f")" && pwd)
      scenario_file=$(basename "$f")
      ;;
    --check) check=${2:?--check needs the compose file to compare}; shift ;;
    -h | --help) sed -n '2,32p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) die 2 "unknown flag $1 (see --help)" ;;
  esac
  shift
done
groups=${groups:-3}
robots=${robots:-3}
[[ $groups =~ ^[1-9][0-9]*$ ]] || die 2 "--groups '$groups' is not a positive number"
[[ $robots =~ ^[1-9][0-9]*$ ]] || die 2 "--robots '$robots' is not a positive number"
[[ -z $certs || $certs == /* ]] ||
  die 2 "--secure $certs: give an absolute folder (compose would resolve a relative one against the compose file's folder)"

# service NAME ENV_LINE...: one role's service (YAML); with --secure, its volumes include its own
# certificate files.
service() {
  local name=$1 line f
  shift
  printf '\n  %s:\n    <<: *role\n' "$name"
  if [[ -n $certs ]]; then
    printf '    volumes:\n      - ${SWARM_SCENARIO_DIR:-%s}:/scenario:ro\n' "$scenario_dir"
    [[ $name != gcs ]] || printf '      - results:/results\n'
    for f in ca.pem governance.p7s permissions.p7s "$name.pem" "$name.key"; do
      printf '      - ${SWARM_CERTS_DIR:-%s}/%s:/security/%s:ro\n' "$certs" "$f" "$f"
    done
  elif [[ $name == gcs ]]; then
    printf '    volumes:\n      - ${SWARM_SCENARIO_DIR:-%s}:/scenario:ro\n      - results:/results\n' "$scenario_dir"
  fi
  printf '    environment:\n      <<: *env\n'
  for line in "$@"; do printf '      %s\n' "$line"; done
}

generate() {
  # A role gives up when discovery stalls this long. `up` starts the containers one after another
  # (~1.4 s each measured here, 53 containers: 76 s), and the first ones must outwait the last:
  # 3 s per container, at least 60 s.
  local containers=$((groups * robots + 2 + (${#certs} ? 0 : 1)))
  local stall=$((containers * 3 > 60 ? containers * 3 : 60))
  cat <<EOF
# swarm on docker-compose: $groups groups x $robots robots, one container per role.
# Generated by deploy/compose-gen.sh --groups $groups --robots $robots${certs:+ --secure $certs}; edit the generator, not this.
#
#   docker-compose -f deploy/docker-compose.yml up        # or: docker compose ...
#   docker-compose -f deploy/docker-compose.yml down -v   # remove containers, network, results
#
# Environment (all optional):
#   SWARM_IMAGE          the image (default swarm:latest; deploy/build-images.sh makes it)
#   SWARM_SCENARIO_DIR   host folder mounted read-only at /scenario (default $scenario_dir)
#   SWARM_SCENARIO_FILE  the scenario in it (default $scenario_file); its groups and
#                        robots_per_group must be $groups and $robots
#   SWARM_DOMAIN         DDS domain id (default 0); the network is the run's own, so 0 is safe
#   SWARM_STALL_TIMEOUT  seconds a role waits for discovery or a peer before failing (default $stall:
#                        3 s per container, at least 60, since \`up\` starts them one by one)
#   SWARM_DDS_LOG        "security": every role logs each DDS peer's discovery and authentication
#                        as it happens, Fast DDS's warnings and its security log
# Results: the GCS writes metrics.json and run.pb to the named volume "results" (/results).
EOF
  if [[ -n $certs ]]; then
    cat <<EOF
# DDS-Security: each role reads its own certificate and key, the CA certificate and the signed
# governance and permissions at /security, mounted from SWARM_CERTS_DIR (default $certs),
# made by: scripts/make-certs.sh DIR \$(docker-compose -f THIS_FILE config --services)
# The containers' user (uid 10001) must be able to read the keys. A participant without a
# certificate of that CA can neither read nor write the swarm's topics.
# DDS: UDP only; simple discovery (SPDP multicast, TTL 1) on the network "swarm" below, the
# project's own bridge (deploy/fastdds_container_simple.xml): Fast DDS 2.9's discovery server
# cannot authenticate, so a secure deployment has none.
EOF
  else
    cat <<EOF
# DDS: UDP only, no multicast (deploy/fastdds_container.xml). The service "discovery" is the run's
# Fast DDS discovery server (fast-discovery-server, in the same image); every role is its client
# (SWARM_DISCOVERY_SERVER) and talks unicast to the peers it shares topics with, on the network
# "swarm" below, the project's own bridge. The server stops a few seconds after the GCS has
# written metrics.json, so \`up\` ends with the mission.
EOF
  fi
  cat <<EOF
version: "3.8"

x-role: &role
  image: \${SWARM_IMAGE:-swarm:latest}
  init: true
  networks: [swarm]
EOF
  [[ -n $certs ]] || echo "  depends_on: [discovery]"
  cat <<EOF
  volumes:
    - \${SWARM_SCENARIO_DIR:-$scenario_dir}:/scenario:ro

x-env: &env
  SWARM_SCENARIO: /scenario/\${SWARM_SCENARIO_FILE:-$scenario_file}
  SWARM_DOMAIN: \${SWARM_DOMAIN:-0}
  SWARM_PARTITION: swarm
  SWARM_STALL_TIMEOUT: \${SWARM_STALL_TIMEOUT:-$stall}
  SWARM_DDS_LOG: \${SWARM_DDS_LOG:-}
EOF
  if [[ -n $certs ]]; then
    echo "  SWARM_SECURITY_DIR: /security"
  else
    echo "  SWARM_DISCOVERY_SERVER: discovery:11811"
  fi
  printf '\nservices:\n'
  if [[ -z $certs ]]; then
    cat <<EOF
  discovery:
    image: \${SWARM_IMAGE:-swarm:latest}
    init: true
    networks: [swarm]
    volumes:
      - results:/results:ro
    environment:
      <<: *env
      SWARM_ROLE: discovery
EOF
  fi
  service sim "SWARM_ROLE: sim"
  service gcs "SWARM_ROLE: gcs" "SWARM_PROGRESS: plain"
  local g i
  for ((g = 0; g < groups; g++)); do
    service "leader-$g" "SWARM_ROLE: leader" "SWARM_GROUP: \"$g\""
  done
  for ((g = 0; g < groups; g++)); do
    for ((i = 1; i < robots; i++)); do
      service "member-$g-$i" "SWARM_ROLE: member" "SWARM_GROUP: \"$g\"" "SWARM_INDEX: \"$i\""
    done
  done
  cat <<EOF

networks:
  swarm:
    driver: bridge

volumes:
  results:
EOF
}

if [[ -n $check ]]; then
  [[ -f $check ]] || die 2 "--check $check: no such file"
  if ! diff -u "$check" <(generate) >&2; then
    die 1 "$check differs from what deploy/compose-gen.sh generates (diff above); regenerate it"
  fi
  exit 0
fi
generate
