#!/usr/bin/env bash
# Checks of deploy/ that need no Docker engine: the committed compose file is what the generator
# writes, every compose command installed accepts it, the container Fast DDS profile keeps the
# loopback profile's QoS, the build packages are ones scripts/install-deps.sh installs, the
# entrypoint maps its environment to the right flags (and names what is wrong), and the apt
# source parser reads both formats.
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
checked=0
for c in "docker compose" "docker-compose"; do
  read -r -a cmd <<<"$c"
  "${cmd[@]}" version >/dev/null 2>&1 || continue
  checked=1
  for f in "$deploy/docker-compose.yml" "$work/2x4.yml"; do
    services=$(cd "$(dirname "$f")" && "${cmd[@]}" -f "$f" config --services 2>"$work/err") ||
      fail "'$c config' rejects $f: $(cat "$work/err")"
    [[ $f != "$deploy/docker-compose.yml" || $(wc -l <<<"$services") == 11 ]] ||
      fail "'$c config' sees $(wc -l <<<"$services") services in the 3 x 3 file, not 11"
  done
done
((checked)) || echo "note: no compose command installed; compose files not validated by compose itself"

# 3. The container profile keeps the loopback one's discovery timing and every writer/reader
#    profile, verbatim.
same_part() {  # same_part SED_SCRIPT WHAT (run with sed -n)
  if ! diff <(sed -n "$1" "$deploy/fastdds_loopback.xml") \
    <(sed -n "$1" "$deploy/fastdds_container.xml") >"$work/part.diff"; then
    fail "deploy/fastdds_container.xml's $2 differs from deploy/fastdds_loopback.xml's (change both):"
    cat "$work/part.diff" >&2
  fi
}
# The first discovery_config: the robots' participant (the loopback file's second one is its
# discovery server's, which containers do not run).
same_part '/<discovery_config>/,/<\/discovery_config>/{p;/<\/discovery_config>/q;}' "discovery timing"
same_part '/<data_writer/,$p' "writer/reader QoS profiles"
grep -q '<type>SHM</type>' "$deploy/fastdds_container.xml" && fail "fastdds_container.xml enables the SHM transport"
grep -q '<useBuiltinTransports>false</useBuiltinTransports>' "$deploy/fastdds_container.xml" ||
  fail "fastdds_container.xml leaves the builtin transports (SHM) on"

# 4. The image's build packages are a subset of what the host build installs.
while read -r p; do
  grep -qwF "$p" "$src/scripts/install-deps.sh" ||
    fail "deploy/packages-build.txt lists $p, which scripts/install-deps.sh does not install"
done < <(sed -e 's/#.*//' -e '/^[[:space:]]*$/d' "$deploy/packages-build.txt")

# 5. The entrypoint: environment -> flags, and one line naming what is wrong.
mkdir -p "$work/bin"
for r in sim gcs leader member; do
  printf '#!/bin/sh\necho "swarm-%s $*"\n' "$r" >"$work/bin/swarm-$r"
  chmod +x "$work/bin/swarm-$r"
done
touch "$work/s.pbtxt"
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
common="--scenario $work/s.pbtxt --run-dir /results --domain 0 --partition swarm"
expect_run "swarm-sim $common" SWARM_ROLE=sim
expect_run "swarm-gcs --progress plain $common" SWARM_ROLE=gcs
expect_run "swarm-leader --group 2 $common" SWARM_ROLE=leader SWARM_GROUP=2
expect_run "swarm-member --group 1 --index 2 --scenario $work/s.pbtxt --run-dir /r --domain 7 --partition p" \
  SWARM_ROLE=member SWARM_GROUP=1 SWARM_INDEX=2 SWARM_RUN_DIR=/r SWARM_DOMAIN=7 SWARM_PARTITION=p
first=$(entry SWARM_ROLE=sim 2>&1 | head -n 1)
[[ $first == *"profile /opt/swarm/share/deploy/fastdds_container.xml)" ]] ||
  fail "a role's default Fast DDS profile is not the container one: '$first'"
profile=$(env -i PATH="$work/bin:/usr/bin:/bin" SWARM_ROLE=sim SWARM_SCENARIO="$work/s.pbtxt" SWARM_DDS_PROFILE=/p.xml \
  sh "$deploy/entrypoint.sh" 2>&1 | head -n 1)
[[ $profile == *"profile /p.xml)" ]] || fail "SWARM_DDS_PROFILE=/p.xml was not kept: '$profile'"
expect_error "SWARM_ROLE is not set" SWARM_ROLE=
expect_error "SWARM_ROLE='pilot' is not a role" SWARM_ROLE=pilot
expect_error "SWARM_GROUP is not set; a leader needs its group id" SWARM_ROLE=leader
expect_error "SWARM_GROUP is not set; a member needs its group id" SWARM_ROLE=member SWARM_INDEX=1
expect_error "SWARM_INDEX is not set; a member needs its robot index" SWARM_ROLE=member SWARM_GROUP=0
expect_error "SWARM_GROUP='-1' is not a number" SWARM_ROLE=leader SWARM_GROUP=-1
expect_error "SWARM_INDEX='a' is not a number" SWARM_ROLE=member SWARM_GROUP=0 SWARM_INDEX=a
expect_error "SWARM_PROGRESS='fancy' is not bar, plain or none" SWARM_ROLE=gcs SWARM_PROGRESS=fancy
expect_error "SWARM_DOMAIN=233 is above 232" SWARM_ROLE=sim SWARM_DOMAIN=233
expect_error "SWARM_SCENARIO=/nope.pbtxt does not exist" SWARM_ROLE=sim SWARM_SCENARIO=/nope.pbtxt

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

if ((failures)); then
  echo "$failures deploy check(s) failed" >&2
  exit 1
fi
echo "deploy files: all checks passed"
