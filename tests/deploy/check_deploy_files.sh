#!/usr/bin/env bash
# Checks of deploy/ that need no Docker engine: the committed compose file is what the generator
# writes (a discovery service, every role its client; --secure: certificates, no discovery
# service), every compose command installed accepts them, the container Fast DDS profiles keep the
# loopback profile's QoS and send no multicast (the discovery-server one), the image has the
# discovery server, the build packages are ones scripts/install-deps.sh installs, the entrypoint
# maps its environment to the right flags (and names what is wrong), and the apt source parser
# reads both formats.
#   check_deploy_files.sh SOURCE_DIR
set -uo pipefail
src=${1:?usage: check_deploy_files.sh SOURCE_DIR}
deploy=$src/deploy
failures=0
fail() {
  echo "FAIL: $*" >&2
  failures=$((failures + 1))
}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# 1. deploy/docker-compose.yml is the generator's 3 x 3 output.
"$deploy/compose-gen.sh" --check "$deploy/docker-compose.yml" ||
  fail "deploy/docker-compose.yml is stale: deploy/compose-gen.sh > deploy/docker-compose.yml"

# 2. Installed compose commands accept the committed file and a generated one.
"$deploy/compose-gen.sh" --groups 2 --robots 4 >"$work/2x4.yml"
grep -q '^  member-1-3:$' "$work/2x4.yml" || fail "compose-gen.sh --groups 2 --robots 4 has no member-1-3"
grep -q '^  member-1-4:$' "$work/2x4.yml" && fail "compose-gen.sh --groups 2 --robots 4 has a member-1-4"
grep -q '^  discovery:$' "$work/2x4.yml" || fail "compose-gen.sh writes no discovery service"
[[ $(grep -c '^  SWARM_DISCOVERY_SERVER: discovery:11811$' "$work/2x4.yml") == 1 ]] ||
  fail "compose-gen.sh does not make every role a client of the discovery service (x-env SWARM_DISCOVERY_SERVER)"
# --secure: every role mounts its own certificate and key (and nobody the CA's key); no discovery
# service, since Fast DDS 2.9's discovery server cannot authenticate.
"$deploy/compose-gen.sh" --groups 2 --robots 2 --secure /certs >"$work/secure.yml"
grep -q '^  discovery:$\|SWARM_DISCOVERY_SERVER' "$work/secure.yml" && fail "compose-gen.sh --secure keeps the discovery server"
grep -q 'ca\.key' "$work/secure.yml" && fail "compose-gen.sh --secure mounts the CA's private key"
for s in sim gcs leader-0 leader-1 member-0-1 member-1-1; do
  n=$(sed -n "/^  $s:\$/,/^\$/p" "$work/secure.yml" | grep -c "/security/\($s\.pem\|$s\.key\|ca\.pem\|governance\.p7s\|permissions\.p7s\):ro\$")
  [[ $n == 5 ]] || fail "compose-gen.sh --secure: service $s mounts $n of its 5 security files"
done
grep -q '^  SWARM_SECURITY_DIR: /security$' "$work/secure.yml" || fail "compose-gen.sh --secure sets no SWARM_SECURITY_DIR"
"$deploy/compose-gen.sh" --secure certs >/dev/null 2>&1 && fail "compose-gen.sh --secure accepted a relative folder"
checked=0
for c in "docker compose" "docker-compose"; do
  read -r -a cmd <<<"$c"
  "${cmd[@]}" version >/dev/null 2>&1 || continue
  checked=1
  for f in "$deploy/docker-compose.yml" "$work/2x4.yml" "$work/secure.yml"; do
    services=$(cd "$(dirname "$f")" && "${cmd[@]}" -f "$f" config --services 2>"$work/err") ||
      fail "'$c config' rejects $f: $(cat "$work/err")"
    [[ $f != "$deploy/docker-compose.yml" || $(wc -l <<<"$services") == 12 ]] ||
      fail "'$c config' sees $(wc -l <<<"$services") services in the 3 x 3 file, not 12 (discovery, sim, gcs, 3 leaders, 6 members)"
  done
done
((checked)) || echo "note: no compose command installed; compose files not validated by compose itself"

# 3. The container profiles (discovery-server client, and simple discovery for secure
#    deployments) keep the loopback one's discovery timing and every writer/reader profile,
#    verbatim; neither has shared memory; the discovery-server one sends no multicast; the
#    simple one has one metatraffic socket.
same_part() {  # same_part FILE SED_SCRIPT WHAT (run with sed -n)
  if ! diff <(sed -n "$2" "$deploy/fastdds_loopback.xml") <(sed -n "$2" "$deploy/$1") >"$work/part.diff"; then
    fail "deploy/$1's $3 differs from deploy/fastdds_loopback.xml's (change them together):"
    cat "$work/part.diff" >&2
  fi
}
for xml in fastdds_container.xml fastdds_container_simple.xml; do
  # The first discovery_config: the robots' participant (the loopback file's second one is its
  # discovery server's).
  same_part "$xml" '/<discovery_config>/,/<\/discovery_config>/{p;/<\/discovery_config>/q;}' "discovery timing"
  same_part "$xml" '/<data_writer/,$p' "writer/reader QoS profiles"
  grep -q '<type>SHM</type>' "$deploy/$xml" && fail "$xml enables the SHM transport"
  grep -q '<useBuiltinTransports>false</useBuiltinTransports>' "$deploy/$xml" ||
    fail "$xml leaves the builtin transports (SHM) on"
done
# The participant's metatraffic locator is given, so Fast DDS makes no default multicast locator;
# the server profile is a SERVER; nothing names a multicast address.
participant=$(sed -n '/<participant profile_name="swarm_participant"/,/<\/participant>/p' "$deploy/fastdds_container.xml")
grep -q '<metatrafficUnicastLocatorList>' <<<"$participant" ||
  fail "fastdds_container.xml's swarm_participant has no metatrafficUnicastLocatorList (Fast DDS would add multicast)"
grep -q 'MulticastLocatorList\|<TTL>\|239\.255' <<<"$participant" && fail "fastdds_container.xml's swarm_participant uses multicast"
sed -n '/<participant profile_name="swarm_discovery_server"/,/<\/participant>/p' "$deploy/fastdds_container.xml" |
  grep -q '<discoveryProtocol>SERVER</discoveryProtocol>' ||
  fail "fastdds_container.xml has no swarm_discovery_server profile with discoveryProtocol SERVER"
# The secure (simple discovery) profile takes all metatraffic on one socket, the multicast port:
# with a second one, Fast DDS 2.9.1 races between its two receive threads and a pair of roles
# never authenticates (deploy/README.md, "Why a secure deployment sometimes never started").
port=$(sed -n '/<participant profile_name="swarm_participant"/,/<\/participant>/p' "$deploy/fastdds_container_simple.xml" |
  sed -n '/<port>/,/<\/port>/p' | tr -d ' \n')
[[ $port == *'<participantIDGain>0</participantIDGain>'* && $port == *'<offsetd0>0</offsetd0>'* &&
  $port == *'<offsetd1>0</offsetd1>'* ]] ||
  fail "fastdds_container_simple.xml's swarm_participant does not put unicast metatraffic on the multicast port (participantIDGain 0, offsetd0 = offsetd1 = 0): '$port'"
# The discovery service runs fast-discovery-server from the same image.
grep -qx 'fastdds-tools' "$deploy/packages-runtime.txt" ||
  fail "deploy/packages-runtime.txt lacks fastdds-tools (fast-discovery-server, the compose service 'discovery')"

# 4. The image's build packages are a subset of what the host build installs.
while read -r p; do
  grep -qwF "$p" "$src/scripts/install-deps.sh" ||
    fail "deploy/packages-build.txt lists $p, which scripts/install-deps.sh does not install"
done < <(sed -e 's/#.*//' -e '/^[[:space:]]*$/d' "$deploy/packages-build.txt")

# 5. The entrypoint: environment -> flags, and one line naming what is wrong.
mkdir -p "$work/bin" "$work/results"
for r in swarm-sim swarm-gcs swarm-leader swarm-member fast-discovery-server; do
  printf '#!/bin/sh\necho "%s $*"\n' "$r" >"$work/bin/$r"
  chmod +x "$work/bin/$r"
done
touch "$work/s.pbtxt"
mkdir -p "$work/security"
entry() { env -i PATH="$work/bin:/usr/bin:/bin" SWARM_SCENARIO="$work/s.pbtxt" "$@" sh "$deploy/entrypoint.sh"; }
expect_run() {  # expect_run "EXPECTED COMMAND LINE" VAR=VALUE...
  local want=$1 got
  shift
  got=$(entry "$@" 2>&1 | tail -n 1)
  [[ $got == "$want" ]] || fail "entrypoint with $*: ran '$got', expected '$want'"
}
expect_error() {  # expect_error "TEXT IN THE MESSAGE" VAR=VALUE...
  local want=$1 got rc
  shift
  got=$(entry "$@" 2>&1)
  rc=$?
  [[ $rc == 2 ]] || fail "entrypoint with $*: exit code $rc, expected 2"
  [[ $(wc -l <<<"$got") == 1 && $got == *"$want"* ]] || fail "entrypoint with $*: said '$got', expected one line with '$want'"
}
expect_profile() {  # expect_profile PROFILE VAR=VALUE...: the profile the entrypoint announces
  local want=$1 first
  shift
  first=$(entry "$@" 2>&1 | head -n 1)
  [[ $first == *"profile $want)" ]] || fail "entrypoint with $*: profile is not $want: '$first'"
}
common="--scenario $work/s.pbtxt --run-dir /results --domain 0 --partition swarm"
ds="--discovery-server localhost:11811"
expect_run "swarm-sim $common" SWARM_ROLE=sim
expect_run "swarm-sim $ds $common" SWARM_ROLE=sim SWARM_DISCOVERY_SERVER=localhost:11811
expect_run "swarm-gcs --progress plain $ds $common" SWARM_ROLE=gcs SWARM_DISCOVERY_SERVER=localhost:11811
expect_run "swarm-leader --group 2 $common" SWARM_ROLE=leader SWARM_GROUP=2
expect_run "swarm-member --group 1 --index 2 --scenario $work/s.pbtxt --run-dir /r --domain 7 --partition p" \
  SWARM_ROLE=member SWARM_GROUP=1 SWARM_INDEX=2 SWARM_RUN_DIR=/r SWARM_DOMAIN=7 SWARM_PARTITION=p
expect_run "swarm-member --group 1 --index 1,2,3 $common" SWARM_ROLE=member SWARM_GROUP=1 SWARM_INDEX=1,2,3
expect_run "swarm-leader --group 0 --security-dir $work/security $common" \
  SWARM_ROLE=leader SWARM_GROUP=0 SWARM_SECURITY_DIR="$work/security"
expect_profile /opt/swarm/share/deploy/fastdds_container.xml SWARM_ROLE=sim SWARM_DISCOVERY_SERVER=localhost:11811
expect_profile /opt/swarm/share/deploy/fastdds_container_simple.xml SWARM_ROLE=sim
expect_profile /p.xml SWARM_ROLE=sim SWARM_DDS_PROFILE=/p.xml
expect_run "fast-discovery-server -i 0 -l 0.0.0.0 -p 11811 -x swarm_discovery_server@/opt/swarm/share/deploy/fastdds_container.xml" \
  SWARM_ROLE=discovery SWARM_DISCOVERY_SERVER=discovery:11811
expect_run "fast-discovery-server -i 0 -l 0.0.0.0 -p 7777 -x swarm_discovery_server@/p.xml" \
  SWARM_ROLE=discovery SWARM_DISCOVERY_SERVER=d:7777 SWARM_DDS_PROFILE=/p.xml
# The discovery server ends by itself once the mission has written metrics.json (a stale one,
# older than the container, does not count).
printf '#!/bin/sh\nexec sleep 30\n' >"$work/bin/fast-discovery-server"
touch -d '1 hour ago' "$work/results/metrics.json"
start=$SECONDS
(sleep 2; touch "$work/results/metrics.json") &
got=$(entry SWARM_ROLE=discovery SWARM_RUN_DIR="$work/results" SWARM_DISCOVERY_LINGER=0 2>&1)
rc=$?
wait
((SECONDS - start >= 2 && SECONDS - start < 10 && rc == 0)) ||
  fail "the discovery role did not end (code 0) soon after metrics.json was written: code $rc after $((SECONDS - start)) s: $got"
# SWARM_PEERS: the profile the role gets names every resolved peer at the SPDP port of its domain.
got=$(entry SWARM_ROLE=sim SWARM_DOMAIN=2 SWARM_PEERS="localhost nobody.invalid" SWARM_PEERS_WAIT=0 \
  SWARM_DDS_PROFILE="$deploy/fastdds_container_simple.xml" 2>&1)
peers_profile=$(sed -n 's/.*(scenario .*profile \(.*\))$/\1/p' <<<"$got" | tail -n 1)
[[ $got == *"not resolved after 0 s: nobody.invalid"* && $got == *"announcing to 127.0.0.1 (port 7900)"* ]] ||
  fail "entrypoint with SWARM_PEERS said: $got"
grep -q '<builtin><initialPeersList><locator><udpv4><address>127.0.0.1</address><port>7900</port></udpv4></locator></initialPeersList>' \
  "$peers_profile" 2>/dev/null || fail "entrypoint with SWARM_PEERS: $peers_profile has no initial peer 127.0.0.1:7900"
rm -f "$peers_profile"
expect_error "SWARM_PEERS and SWARM_DISCOVERY_SERVER are both set" SWARM_ROLE=sim SWARM_PEERS=gcs \
  SWARM_DISCOVERY_SERVER=localhost:11811
expect_error "the discovery server's name 'nobody.invalid' did not resolve within 0 s" SWARM_ROLE=sim \
  SWARM_DISCOVERY_SERVER=nobody.invalid:11811 SWARM_STALL_TIMEOUT=0
expect_error "SWARM_ROLE is not set" SWARM_ROLE=
expect_error "SWARM_ROLE='pilot' is not a role" SWARM_ROLE=pilot
expect_error "SWARM_GROUP is not set; a leader needs its group id" SWARM_ROLE=leader
expect_error "SWARM_GROUP is not set; a member needs its group id" SWARM_ROLE=member SWARM_INDEX=1
expect_error "SWARM_INDEX is not set; a member needs its robot index" SWARM_ROLE=member SWARM_GROUP=0
expect_error "SWARM_GROUP='-1' is not a number" SWARM_ROLE=leader SWARM_GROUP=-1
expect_error "SWARM_INDEX='a' is not a robot index" SWARM_ROLE=member SWARM_GROUP=0 SWARM_INDEX=a
expect_error "SWARM_INDEX='1,,2' is not a robot index" SWARM_ROLE=member SWARM_GROUP=0 SWARM_INDEX=1,,2
expect_error "SWARM_PROGRESS='fancy' is not bar, plain or none" SWARM_ROLE=gcs SWARM_PROGRESS=fancy
expect_error "SWARM_DOMAIN=233 is above 232" SWARM_ROLE=sim SWARM_DOMAIN=233
expect_error "SWARM_SCENARIO=/nope.pbtxt does not exist" SWARM_ROLE=sim SWARM_SCENARIO=/nope.pbtxt
expect_error "SWARM_DISCOVERY_SERVER='discovery' is not HOST:PORT" SWARM_ROLE=sim SWARM_DISCOVERY_SERVER=discovery
expect_error "SWARM_DISCOVERY_SERVER='d:x1' is not HOST:PORT" SWARM_ROLE=discovery SWARM_DISCOVERY_SERVER=d:x1
expect_error "SWARM_SECURITY_DIR=/nope does not exist in the container" SWARM_ROLE=sim SWARM_SECURITY_DIR=/nope
expect_error "SWARM_SECURITY_DIR and SWARM_DISCOVERY_SERVER are both set" \
  SWARM_ROLE=sim SWARM_SECURITY_DIR="$work/security" SWARM_DISCOVERY_SERVER=localhost:11811

# 6. The Debian mirror comes from apt's configuration, in both formats.
mkdir -p "$work/apt/sources.list.d"
printf '# deb http://commented.example/debian bookworm main\ndeb [arch=amd64 signed-by=/k.gpg] http://one.example/debian bookworm main contrib\ndeb-src http://src.example/debian bookworm main\n' \
  >"$work/apt/sources.list"
printf 'Types: deb\nURIs: http://two.example/debian\nSuites: bookworm-updates bookworm\nComponents: main\n\nTypes: deb\nEnabled: no\nURIs: http://off.example/debian\nSuites: bookworm\n' \
  >"$work/apt/sources.list.d/debian.sources"
# shellcheck source=deploy/lib.sh
source "$deploy/lib.sh"
got=$(APT_SOURCES_ROOT=$work/apt apt_source_entries | tr '\t' ' ')
want=$'http://one.example/debian bookworm main contrib\nhttp://two.example/debian bookworm-updates main\nhttp://two.example/debian bookworm main'
[[ $got == "$want" ]] || fail "apt_source_entries read:"$'\n'"$got"$'\n'"expected:"$'\n'"$want"
rm "$work/apt/sources.list"
got=$(APT_SOURCES_ROOT=$work/apt debian_mirror_for bookworm)
[[ $got == http://two.example/debian ]] || fail "debian_mirror_for bookworm from deb822 gave '$got'"

# 7. The stack file: one service per role (or per K members), placed by slot, and its refusals.
stack=$("$deploy/stack-gen.sh" --nodes 2)
services=$(sed -n '/^services:/,/^networks:/s/^  \([a-z][a-z0-9-]*\):$/\1/p' <<<"$stack" | paste -sd' ')
[[ $services == "discovery sim gcs leader-0 leader-1 leader-2 member-0-1 member-0-2 member-1-1 member-1-2 member-2-1 member-2-2" ]] ||
  fail "stack-gen.sh --nodes 2 wrote the services: $services"
slot_of() { sed -n "/^  $1:\$/,/^\$/s/.*node.labels.swarm-slot == \([0-9]*\).*/\1/p" <<<"$stack"; }
for pair in discovery=0 sim=0 gcs=0 leader-0=0 member-0-2=0 leader-1=1 member-1-1=1 leader-2=0 member-2-2=0; do
  [[ $(slot_of "${pair%=*}") == "${pair#*=}" ]] || fail "stack-gen.sh --nodes 2 put ${pair%=*} on slot $(slot_of "${pair%=*}"), not ${pair#*=}"
done
restart_of() { sed -n "/^  $1:\$/,/^\$/s/.*condition: \(.*\)/\1/p" <<<"$stack"; }
[[ $(restart_of gcs) == on-failure && $(restart_of member-1-2) == none && $(restart_of leader-0) == none ]] ||
  fail "stack-gen.sh restart policies: gcs $(restart_of gcs), member-1-2 $(restart_of member-1-2), leader-0 $(restart_of leader-0)"
printf 'groups: 10\nrobots_per_group: 10\n' >"$work/big.pbtxt"
stack=$("$deploy/stack-gen.sh" --from-scenario "$work/big.pbtxt" --agents-per-process 9 --nodes 2)
[[ $(grep -c '^  members-[0-9]*-1-9:$' <<<"$stack") == 10 && $stack == *'SWARM_INDEX: "1,2,3,4,5,6,7,8,9"'* ]] ||
  fail "stack-gen.sh --agents-per-process 9 did not give each group one members service of robots 1..9"
# --secure: no discovery service, every role's own certificate and key as secrets, and the peers
# every role announces itself to instead of multicast.
mkdir -p "$work/certs"
touch "$work/certs/ca.pem"
stack=$("$deploy/stack-gen.sh" --secure "$work/certs")
services=$(sed -n '/^services:/,/^networks:/s/^  \([a-z][a-z0-9-]*\):$/\1/p' <<<"$stack" | paste -sd' ')
[[ $services == "sim gcs leader-0 leader-1 leader-2 member-0-1 member-0-2 member-1-1 member-1-2 member-2-1 member-2-2" ]] ||
  fail "stack-gen.sh --secure wrote the services: $services"
[[ $stack == *"SWARM_PEERS: sim gcs leader-0 leader-1 leader-2 member-0-1 member-0-2 member-1-1 member-1-2 member-2-1 member-2-2"* &&
  $stack == *"SWARM_SECURITY_DIR: /run/secrets"* && $stack != *"SWARM_DISCOVERY_SERVER"* ]] ||
  fail "stack-gen.sh --secure: the roles' environment is not peers + /run/secrets without a discovery server"
secrets_of() { sed -n "/^  $1:\$/,/^\$/s/.*- source: \(.*\)/\1/p" <<<"$stack" | paste -sd' '; }
[[ $(secrets_of member-1-2) == "ca.pem governance.p7s permissions.p7s member-1-2.pem member-1-2.key" ]] ||
  fail "stack-gen.sh --secure: member-1-2's secrets are $(secrets_of member-1-2)"
[[ $stack == *"  member-1-2.key:"$'\n'"    file: $work/certs/member-1-2.key"* ]] ||
  fail "stack-gen.sh --secure: no secret member-1-2.key from $work/certs"
stack_error() {  # stack_error MESSAGE FLAG...
  local want=$1 got rc
  shift
  got=$("$deploy/stack-gen.sh" "$@" 2>&1 >/dev/null) && rc=0 || rc=$?
  [[ $rc == 2 && $got == *"$want"* ]] || fail "stack-gen.sh $*: code $rc, said '$got' (expected 2 and '$want')"
}
stack_error "not 4 x 3" --groups 4
stack_error "--nodes 4 is more than the 3 groups" --nodes 4
stack_error "--mtu '70000' is not an MTU" --mtu 70000
stack_error "no such file" --from-scenario /nope.pbtxt
stack_error "give an absolute folder" --secure certs
stack_error "a secure identity is one robot's" --secure "$work/certs" --agents-per-process 2

if ((failures)); then
  echo "$failures deploy check(s) failed" >&2
  exit 1
fi
echo "deploy files: all checks passed"
