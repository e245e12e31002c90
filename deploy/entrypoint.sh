#!/bin/sh
# The swarm image's entrypoint: starts one role of a run from environment variables, so that a
# compose service (or `docker run -e ...`) needs no command line.
#
#   SWARM_ROLE       sim | gcs | leader | member | discovery              (required)
#   SWARM_GROUP      group id, from 0                                 (leader, member)
#   SWARM_INDEX      robot index in the group, 1..R-1 (0 is the leader), or a list (1,2,3) of
#                    robots run in one process (member)
#   SWARM_SCENARIO   scenario file   (default: the image's scenarios/default.pbtxt)
#   SWARM_RUN_DIR    where the GCS writes metrics.json and run.pb     (default /results)
#   SWARM_DOMAIN     DDS domain id, 0..232                            (default 0)
#   SWARM_PARTITION  DDS partition                                    (default swarm)
#   SWARM_PROGRESS   bar | plain | none                               (gcs; default plain)
#   SWARM_RESUME     auto | never (gcs; default auto: a GCS container started again mid-run
#                    resumes from SWARM_RUN_DIR/gcs.journal, see below)
#   SWARM_DISCOVERY_SERVER  HOST:PORT of the run's Fast DDS discovery server (the compose files:
#                    discovery:11811): the role is its client (--discovery-server). Unset: simple
#                    discovery (SPDP multicast, TTL 1, on the container's network).
#   SWARM_SECURITY_DIR  DDS-Security: the folder holding this role's certificate, key, the CA and
#                    the signed governance and permissions (scripts/make-certs.sh; compose-gen.sh
#                    --secure mounts them at /security) (--security-dir). Needs simple discovery:
#                    Fast DDS 2.9's discovery server cannot authenticate.
#   SWARM_PEERS      simple discovery without multicast (a swarm overlay network carries none):
#                    the other roles' host names (the stack's service names); the role announces
#                    itself to their addresses, looked up once all resolve (at most
#                    SWARM_PEERS_WAIT seconds, default 60; the names not up by then announce
#                    themselves when they start). Not with SWARM_DISCOVERY_SERVER.
#   SWARM_DDS_PROFILE  Fast DDS profile (default: the image's deploy/fastdds_container.xml with a
#                    discovery server, deploy/fastdds_container_simple.xml without; UDP only)
#
# SWARM_ROLE=discovery runs the discovery server (fast-discovery-server, server id 0) on all of the
# container's interfaces, on SWARM_DISCOVERY_SERVER's port (default 11811). It ends by itself,
# SWARM_DISCOVERY_LINGER seconds (default 5) after the GCS wrote SWARM_RUN_DIR/metrics.json (mount
# the results volume, read-only is enough), so that `docker-compose up` ends with the mission.
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
  [ $# -gt 0 ] || fail "SWARM_ROLE is not set; set it to sim, gcs, leader, member or discovery (or give a command to run)"
  exec "$@"
fi
data=${SWARM_DATA_DIR:-/opt/swarm/share}
run_dir=${SWARM_RUN_DIR:-/results}
server=${SWARM_DISCOVERY_SERVER:-}
if [ -n "$server" ]; then
  case $server in
    ?*:*[!0-9]* | ?*:) fail "SWARM_DISCOVERY_SERVER='$server' is not HOST:PORT (e.g. discovery:11811)" ;;
    ?*:[0-9]*) ;;
    *) fail "SWARM_DISCOVERY_SERVER='$server' is not HOST:PORT (e.g. discovery:11811)" ;;
  esac
fi

if [ "$ROLE" = discovery ]; then
  port=${server##*:}
  port=${port:-11811}
  profile=${SWARM_DDS_PROFILE:-$data/deploy/fastdds_container.xml}
  linger=${SWARM_DISCOVERY_LINGER:-5}
  case $linger in
    '' | *[!0-9]*) fail "SWARM_DISCOVERY_LINGER='$linger' is not a number of seconds" ;;
  esac
  echo "swarm-entrypoint: fast-discovery-server -i 0 -l 0.0.0.0 -p $port (profile $profile; ends ${linger} s after $run_dir/metrics.json is written)"
  started=$(mktemp)
  fast-discovery-server -i 0 -l 0.0.0.0 -p "$port" -x "swarm_discovery_server@$profile" "$@" &
  pid=$!
  trap 'kill -TERM "$pid" 2>/dev/null' INT TERM
  while kill -0 "$pid" 2>/dev/null; do
    # Written by this run's GCS: newer than this container's start (the volume may hold an old one).
    if [ -n "$(find "$run_dir" -maxdepth 1 -name metrics.json -newer "$started" 2>/dev/null)" ]; then
      echo "swarm-entrypoint: the mission wrote $run_dir/metrics.json; stopping the discovery server in $linger s"
      sleep "$linger"
      kill -TERM "$pid" 2>/dev/null
      wait "$pid" || true
      exit 0
    fi
    sleep 1
  done
  wait "$pid"
  exit $?
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
    # A GCS container started again mid-run (docker start / restart after a crash) resumes from
    # its journal (gcs/gcs_node.hpp "Restart"): the results volume holds a journal written in the
    # last 2 minutes (a running mission's: it grows every tick; an older one is a past run's left
    # in a reused volume) and no metrics.json written after it. SWARM_RESUME=never starts afresh.
    resume=${SWARM_RESUME:-auto}
    case $resume in
      auto | never) ;;
      *) fail "SWARM_RESUME='$resume' is not auto or never" ;;
    esac
    if [ "$resume" = auto ] && [ -s "$run_dir/gcs.journal" ] &&
      [ -n "$(find "$run_dir" -maxdepth 1 -name gcs.journal -mmin -2 2>/dev/null)" ] &&
      [ -z "$(find "$run_dir" -maxdepth 1 -name metrics.json -newer "$run_dir/gcs.journal" 2>/dev/null)" ]; then
      echo "swarm-entrypoint: $run_dir/gcs.journal is a running mission's: the GCS resumes it"
      role_flags="$role_flags --resume"
    fi
    ;;
  leader)
    need_id SWARM_GROUP "${SWARM_GROUP:-}" "group id (0..groups-1)"
    role_flags="--group $SWARM_GROUP"
    ;;
  member)
    need_id SWARM_GROUP "${SWARM_GROUP:-}" "group id (0..groups-1)"
    # One robot, or several in this process (1,2,3: --agents-per-process, deploy/stack-gen.sh).
    [ -n "${SWARM_INDEX:-}" ] || fail "SWARM_INDEX is not set; a member needs its robot index in the group (1..robots_per_group-1; 0 is the leader)"
    case $SWARM_INDEX in
      *[!0-9,]* | ,* | *, | *,,*) fail "SWARM_INDEX='$SWARM_INDEX' is not a robot index (1..robots_per_group-1) or a list of them (1,2,3)" ;;
    esac
    role_flags="--group $SWARM_GROUP --index $SWARM_INDEX"
    ;;
  *) fail "SWARM_ROLE='$ROLE' is not a role; set it to sim, gcs, leader, member or discovery" ;;
esac

scenario=${SWARM_SCENARIO:-$data/scenarios/default.pbtxt}
[ -f "$scenario" ] ||
  fail "SWARM_SCENARIO=$scenario does not exist in the container; mount the scenario's folder (read-only) and name the file in it"
domain=${SWARM_DOMAIN:-0}
case $domain in
  '' | *[!0-9]*) fail "SWARM_DOMAIN='$domain' is not a DDS domain id (0..232)" ;;
esac
[ "$domain" -le 232 ] || fail "SWARM_DOMAIN=$domain is above 232, the largest DDS domain id Fast DDS's ports allow"
partition=${SWARM_PARTITION:-swarm}
[ -n "$partition" ] || fail "SWARM_PARTITION is empty; leave it unset for the default 'swarm'"

security=${SWARM_SECURITY_DIR:-}
if [ -n "$security" ]; then
  [ -d "$security" ] ||
    fail "SWARM_SECURITY_DIR=$security does not exist in the container; mount the certificates there (deploy/compose-gen.sh --secure DIR does)"
  [ -z "$server" ] ||
    fail "SWARM_SECURITY_DIR and SWARM_DISCOVERY_SERVER are both set; Fast DDS 2.9's discovery server cannot authenticate, so a secure role needs simple discovery: unset SWARM_DISCOVERY_SERVER"
  role_flags="$role_flags --security-dir $security"
fi
if [ -n "$server" ]; then
  # A swarm starts the services in no order, and the server's name resolves only once its task
  # runs: wait for it (compose's depends_on orders them, so there it resolves at once).
  host=${server%:*}
  wait_s=${SWARM_STALL_TIMEOUT:-60}
  case $wait_s in '' | *[!0-9]*) wait_s=60 ;; esac
  end=$(($(date +%s) + wait_s))
  until getent ahostsv4 "$host" >/dev/null 2>&1; do
    [ "$(date +%s)" -lt "$end" ] || fail "the discovery server's name '$host' did not resolve within $wait_s s; is its service running?"
    sleep 1
  done
  role_flags="$role_flags --discovery-server $server"
  default_profile=$data/deploy/fastdds_container.xml
else
  default_profile=$data/deploy/fastdds_container_simple.xml
fi
SWARM_DDS_PROFILE=${SWARM_DDS_PROFILE:-$default_profile}
peers=${SWARM_PEERS:-}
if [ -n "$peers" ]; then
  [ -z "$server" ] || fail "SWARM_PEERS and SWARM_DISCOVERY_SERVER are both set; peers are for simple discovery without a server"
  wait_s=${SWARM_PEERS_WAIT:-60}
  case $wait_s in '' | *[!0-9]*) fail "SWARM_PEERS_WAIT='$wait_s' is not a number of seconds" ;; esac
  # Every peer's address, waiting for the names of roles that are still starting.
  end=$(($(date +%s) + wait_s))
  while :; do
    addresses="" unresolved=""
    for name in $peers; do
      a=$(getent ahostsv4 "$name" | awk '{ print $1; exit }')
      if [ -n "$a" ]; then addresses="$addresses $a"; else unresolved="$unresolved $name"; fi
    done
    [ -n "$unresolved" ] && [ "$(date +%s)" -lt "$end" ] || break
    sleep 1
  done
  [ -z "$unresolved" ] || echo "swarm-entrypoint: not resolved after ${wait_s} s:$unresolved (they announce themselves when they start)"
  # The SPDP port: one socket per participant, 7400 + 250 x domain (the simple profile's ports).
  port=$((7400 + 250 * domain))
  locators=""
  for a in $addresses; do
    locators="$locators<locator><udpv4><address>$a</address><port>$port</port></udpv4></locator>"
  done
  profile=$(mktemp "${TMPDIR:-/tmp}/swarm-peers.XXXXXX.xml")
  sed "0,/<builtin>/s|<builtin>|<builtin><initialPeersList>$locators</initialPeersList>|" "$SWARM_DDS_PROFILE" >"$profile"
  echo "swarm-entrypoint: announcing to$addresses (port $port)"
  SWARM_DDS_PROFILE=$profile
fi
export SWARM_DDS_PROFILE

echo "swarm-entrypoint: swarm-$ROLE $role_flags (scenario $scenario, domain $domain, partition $partition, profile $SWARM_DDS_PROFILE)"
# shellcheck disable=SC2086 # role_flags holds separate words on purpose
exec "swarm-$ROLE" $role_flags --scenario "$scenario" --run-dir "$run_dir" --domain "$domain" \
  --partition "$partition" "$@"
