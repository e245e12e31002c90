#!/bin/sh
# The swarm image's entrypoint: starts one role of a run from environment variables, so that a
# compose service (or `docker run -e ...`) needs no command line.
#
#   SWARM_ROLE       sim | gcs | leader | member                      (required)
#   SWARM_GROUP      group id, from 0                                 (leader, member)
#   SWARM_INDEX      robot index in the group, 1..R-1 (0 is the leader) (member)
#   SWARM_SCENARIO   scenario file   (default: the image's scenarios/default.pbtxt)
#   SWARM_RUN_DIR    where the GCS writes metrics.json and run.pb     (default /results)
#   SWARM_DOMAIN     DDS domain id, 0..232                            (default 0)
#   SWARM_PARTITION  DDS partition                                    (default swarm)
#   SWARM_PROGRESS   bar | plain | none                               (gcs; default plain)
#   SWARM_DDS_PROFILE  Fast DDS profile (default: the image's deploy/fastdds_container.xml:
#                    UDP only, multicast discovery; one role per container)
#
# It runs swarm-ROLE with the matching flags, plus any arguments given to the container. With no
# SWARM_ROLE but a command (`docker run IMAGE swarm run ...`), it runs that command instead.
# A missing or malformed variable ends it with exit code 2 and one line naming the variable, as
# the role binaries do for bad flags.
set -eu

fail() {
  echo "swarm-entrypoint: $*" >&2
  exit 2
}

# need_id NAME VALUE WHAT: VALUE must be a non-negative integer.
need_id() {
  [ -n "$2" ] || fail "$1 is not set; a $ROLE needs its $3"
  case $2 in
    *[!0-9]*) fail "$1='$2' is not a number; it is the $3" ;;
  esac
}

ROLE=${SWARM_ROLE:-}
if [ -z "$ROLE" ]; then
  [ $# -gt 0 ] || fail "SWARM_ROLE is not set; set it to sim, gcs, leader or member (or give a command to run)"
  exec "$@"
fi

role_flags=""
case $ROLE in
  sim) ;;
  gcs)
    progress=${SWARM_PROGRESS:-plain}
    case $progress in
      bar | plain | none) ;;
      *) fail "SWARM_PROGRESS='$progress' is not bar, plain or none" ;;
    esac
    role_flags="--progress $progress"
    ;;
  leader)
    need_id SWARM_GROUP "${SWARM_GROUP:-}" "group id (0..groups-1)"
    role_flags="--group $SWARM_GROUP"
    ;;
  member)
    need_id SWARM_GROUP "${SWARM_GROUP:-}" "group id (0..groups-1)"
    need_id SWARM_INDEX "${SWARM_INDEX:-}" "robot index in the group (1..robots_per_group-1; 0 is the leader)"
    role_flags="--group $SWARM_GROUP --index $SWARM_INDEX"
    ;;
  *) fail "SWARM_ROLE='$ROLE' is not a role; set it to sim, gcs, leader or member" ;;
esac

scenario=${SWARM_SCENARIO:-${SWARM_DATA_DIR:-/opt/swarm/share}/scenarios/default.pbtxt}
[ -f "$scenario" ] ||
  fail "SWARM_SCENARIO=$scenario does not exist in the container; mount the scenario's folder (read-only) and name the file in it"
run_dir=${SWARM_RUN_DIR:-/results}
domain=${SWARM_DOMAIN:-0}
case $domain in
  '' | *[!0-9]*) fail "SWARM_DOMAIN='$domain' is not a DDS domain id (0..232)" ;;
esac
[ "$domain" -le 232 ] || fail "SWARM_DOMAIN=$domain is above 232, the largest DDS domain id Fast DDS's ports allow"
partition=${SWARM_PARTITION:-swarm}
[ -n "$partition" ] || fail "SWARM_PARTITION is empty; leave it unset for the default 'swarm'"

SWARM_DDS_PROFILE=${SWARM_DDS_PROFILE:-${SWARM_DATA_DIR:-/opt/swarm/share}/deploy/fastdds_container.xml}
export SWARM_DDS_PROFILE

echo "swarm-entrypoint: swarm-$ROLE $role_flags (scenario $scenario, domain $domain, partition $partition, profile $SWARM_DDS_PROFILE)"
# shellcheck disable=SC2086 # role_flags holds separate words on purpose
exec "swarm-$ROLE" $role_flags --scenario "$scenario" --run-dir "$run_dir" --domain "$domain" \
  --partition "$partition" "$@"
