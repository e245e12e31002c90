#!/usr/bin/env bash
# The Docker Swarm deployment on a real cluster made on this machine (deploy/swarm-cluster.sh):
#   1. this engine alone, a one-node swarm, runs the default mission (docker stack deploy);
#   2. a second node joins: a Docker engine in a container, the image loaded by docker load.
#      With group 1 on it and groups 0 and 2 here, a mission with every kind of link emulation
#      (tests/deploy/links.pbtxt: delay, loss, a bandwidth cap) gives exactly the numbers of
#      `swarm run` of the same file on one host (lockstep, one seed): the same metrics.json keys,
#      steps, and per link class the bytes, messages, lost transmissions and queueing;
#   3. the default mission with DDS-Security across both nodes (certificates as swarm secrets);
#   4. the clear errors: the image missing on a node, a node without the memory its share
#      reserves, and (when this engine was not in swarm mode) no swarm at all;
#   5. faults: group 1's member containers on the worker are killed at tick 20, the worker is
#      drained at tick 60 (its leader goes with it) and the GCS's container is killed at tick 100;
#      group 1's three robots are counted lost, the swarm starts the GCS again (its restart
#      policy), it resumes from its journal, and the mission completes;
#   6. tear-down: no stack, service, network, volume, node or container is left
#      (swarm-cluster.sh down and stack-test.sh check it).
# Usage: stack_cluster.sh SOURCE_DIR BIN_DIR OUT_DIR (exit code 77: skipped, no Docker engine)
set -euo pipefail
src=$1 bin=$2 out=$3
image=swarm:ctest
# shellcheck source=deploy/lib.sh
source "$src/deploy/lib.sh"
if ! docker_engine_running; then
  echo "SKIPPED: no Docker engine answers here; the stack deployment was not tested"
  exit 77
fi
docker image inspect "$image" >/dev/null 2>&1 || die 1 "image $image is missing: ctest deploy_compose builds it"
cluster=(bash "$src/deploy/swarm-cluster.sh")
stack_test=(bash "$src/deploy/stack-test.sh" --image "$image" --timeout 300)
name=swarmcluster-$$
trap '"${cluster[@]}" down --name "$name" || exit 1' EXIT
rm -rf "$out"
mkdir -p "$out"
fail() { echo "stack_cluster: $*" >&2; exit 1; }
step() { echo "stack_cluster: $* ($SECONDS s)"; }

# expect_refusal CODE MESSAGE ARGS...: stack-test.sh ends with CODE, naming MESSAGE.
expect_refusal() {
  local code=$1 want=$2 got rc
  shift 2
  got=$("${stack_test[@]}" "$@" 2>&1) && rc=0 || rc=$?
  [[ $rc == "$code" && $got == *"$want"* ]] ||
    fail "stack-test.sh $*: exit code $rc (expected $code) and no '$want' in: $(tail -n 5 <<<"$got")"
  step "refused as expected: $(grep -m1 -F "$want" <<<"$got")"
}

if [[ $(docker info -f '{{.Swarm.LocalNodeState}}') == inactive ]]; then
  expect_refusal 2 "is not in swarm mode" --out "$out/no-swarm"
fi

step "1. one node: this engine"
"${cluster[@]}" up --name "$name" --workers 0
"${stack_test[@]}" --out "$out/one-node"

step "2. a second node joins"
"${cluster[@]}" up --name "$name" --workers 1 --image "$image"
worker=$("${cluster[@]}" node 1 --name "$name")
"${stack_test[@]}" --nodes 2 --scenario "$src/tests/deploy/links.pbtxt" --out "$out/two-nodes"
ran_on() { awk -v s="$1" '$1 == s { print $2; exit }' "$2/tasks.txt"; }
for s in leader-1 member-1-1 member-1-2; do
  [[ $(ran_on "$s" "$out/two-nodes") == "$worker" ]] || fail "$s ran on '$(ran_on "$s" "$out/two-nodes")', not on the worker $worker"
done
[[ $(ran_on leader-0 "$out/two-nodes") != "$worker" ]] || fail "leader-0 ran on the worker; slot 0 is this engine"
"$bin/swarm" run "$src/tests/deploy/links.pbtxt" --out "$out/one-host" --timeout 300 >"$out/one-host.log" 2>&1 ||
  fail "swarm run of links.pbtxt on one host failed: $(tail -n 3 "$out/one-host.log")"
# The numbers to compare, one line each: steps, and per link class bytes, messages, lost
# transmissions and the queue's 95th percentile (nlohmann's dump(2): keys sorted, 6 spaces in).
numbers() {
  sed -n 's/^  "steps": \([0-9]*\),$/steps \1/p' "$1"
  sed -n '/^    "by_link": {/,/^    }/p' "$1" | awk '
    /^      "[a-z_]*": \{/ { link = $1; gsub(/[":{]/, "", link) }
    /^        "(bytes|messages|lost_transmissions|queue_p95_ticks)":/ { v = $2; sub(/,$/, "", v); k = $1; gsub(/[":]/, "", k); print link, k, v }'
}
numbers "$out/two-nodes/metrics.json" >"$out/two-nodes.numbers"
numbers "$out/one-host/metrics.json" >"$out/one-host.numbers"
[[ $(wc -l <"$out/one-host.numbers") -gt 10 ]] || fail "metrics.json of swarm run gave too few numbers: $(cat "$out/one-host.numbers")"
diff "$out/one-host.numbers" "$out/two-nodes.numbers" >&2 ||
  fail "the two-node run's numbers (right) differ from swarm run's on one host (left)"
top_keys() { sed -n 's/^  "\([a-z_0-9]*\)":.*/\1/p' "$1" | paste -sd' '; }
[[ $(top_keys "$out/two-nodes/metrics.json") == "$(top_keys "$out/one-host/metrics.json")" ]] ||
  fail "metrics.json's keys differ: two nodes: $(top_keys "$out/two-nodes/metrics.json"); one host: $(top_keys "$out/one-host/metrics.json")"
grep -q '^leader_gcs lost_transmissions [1-9]' "$out/two-nodes.numbers" ||
  fail "no leader<->GCS transmission was lost, though links.pbtxt loses 5 %"
step "two nodes: the same numbers as swarm run on one host: $(paste -sd' ' "$out/two-nodes.numbers" | cut -c1-160) ..."

step "3. DDS-Security across the nodes"
"${stack_test[@]}" --nodes 2 --secure --out "$out/secure"
grep -q -- "--security-dir /run/secrets" "$out/secure/logs/member-1-1.log" || fail "member-1-1 did not run with its certificate"

step "4. clear errors"
docker tag "$image" swarm:ctest-manager-only
expect_refusal 1 "does not have the image swarm:ctest-manager-only" \
  --nodes 2 --image swarm:ctest-manager-only --out "$out/no-image"
docker rmi swarm:ctest-manager-only >/dev/null
expect_refusal 2 "reserve 1048576 MiB each" --nodes 2 --memory-mb 1048576 --out "$out/no-memory"

step "5. faults: group 1's members killed, the worker drained, the GCS killed"
kill_and_drain="bash '$src/tests/deploy/wait_for_tick.sh' 20 &&
  docker exec $worker docker kill \$(docker exec $worker docker ps -q --filter name=\${SWARM_STACK}_member-1-) >/dev/null &&
  bash '$src/tests/deploy/wait_for_tick.sh' 60 &&
  docker node update --availability drain $worker >/dev/null &&
  bash '$src/tests/deploy/wait_for_tick.sh' 100 &&
  docker kill \$(docker ps -q --filter name=\${SWARM_STACK}_gcs) >/dev/null"
"${stack_test[@]}" --nodes 2 --scenario "$src/scenarios/deploy_faults.pbtxt" --out "$out/faults" \
  --after-up "$kill_and_drain" --expect-lost member-1-2 --expect-lost leader-1 --expect-lost member-1-1
test_name=stack_cluster metrics=$out/faults/metrics.json
# shellcheck source=tests/deploy/metrics_checks.sh
source "$src/tests/deploy/metrics_checks.sh"
lost=$(faults_list agents_lost)
for a in member-1-2 leader-1 member-1-1; do
  [[ $lost == *"\"agent\":\"$a\""* ]] || fail "metrics.json does not record $a as lost: $lost"
done
step "lost on the worker: $lost"
restarts=$(faults_list gcs_restarts)
[[ $restarts == *'"replayed_ticks"'* ]] || fail "metrics.json records no GCS restart: $restarts"
step "the GCS started again by the swarm: $restarts"
step "PASSED"
