#!/usr/bin/env bash
# A link is cut and healed in the docker-compose deployment: leader-1's container is taken off the
# project's network (`docker network disconnect`) for 10 s while the real-time mission runs, then
# put back. The simulator declares it lost (1 s liveliness lease) and re-admits it when it speaks
# again; the GCS shows it unreachable meanwhile; what its group mapped during the cut reaches the
# GCS after the reconnection (DDS keeps the session for the 30 s participant lease and resends),
# so every map patch sent is received, and the mission completes.
# Usage: cut_leader.sh SOURCE_DIR BIN_DIR OUT_DIR
set -euo pipefail
src=$1 bin=$2 out=$3
rc=0
bash "$src/deploy/compose-test.sh" --prebuilt "$bin" --image swarm:ctest \
  --scenario "$src/scenarios/deploy_faults.pbtxt" --out "$out" \
  --after-up "bash '$src/tests/deploy/cut_link.sh' leader-1 10" || rc=$?
((rc == 0)) || exit "$rc"

m=$out/metrics.json
fail() {
  echo "cut_leader: $*" >&2
  sed -n '/"faults"/,/^  }/p' "$m" >&2
  exit 1
}
# The object (pretty-printed by nlohmann::json, 2 spaces per level) that holds LINE, as one line.
block_of() { sed -n "/$1/,/}/p" "$m" | tr -d ' \n'; }
# metrics.json's faults section (top-level keys sit at two spaces), as one line.
faults=$(sed -n '/^  "faults": {/,/^  }/p' "$m" | tr -d ' \n')
[[ $faults =~ \"agents_lost\":\[(.*)\],\"unreachable\":\[(.*)\] ]] || fail "metrics.json has no faults section"
lost=${BASH_REMATCH[1]} unreachable=${BASH_REMATCH[2]}
[[ $lost == *'"agent":"leader-1"'* ]] || fail "metrics.json does not record leader-1 as lost while cut"
[[ $lost =~ \"rejoined_at_tick\":([0-9]+) ]] || fail "leader-1 was never re-admitted after the link healed"
# The longest interval in which the GCS showed leader-1 unreachable.
away=0
while read -r interval; do
  [[ $interval =~ \"agent\":\"leader-1\",\"from_tick\":([0-9]+),\"to_tick\":([0-9]+) ]] || continue
  ((BASH_REMATCH[2] - BASH_REMATCH[1] > away)) && away=$((BASH_REMATCH[2] - BASH_REMATCH[1]))
done < <(sed 's/},{/}\n{/g' <<<"$unreachable")
((away > 0)) || fail "the GCS never showed leader-1 unreachable"

# 10 s at 40 ms a tick is 250 ticks; the GCS notices within a few ticks of the silence.
((away >= 200 && away <= 400)) || fail "leader-1 was unreachable for $away ticks; a 10 s cut is ~250"
for topic in patch_up patch_gcs group_status; do
  b=$(block_of "\"$topic\": {")
  [[ $b =~ \"messages\":([0-9]+) ]] || fail "no traffic on $topic"
  sent=${BASH_REMATCH[1]}
  [[ $b =~ \"received_messages\":([0-9]+) ]] || fail "no received count on $topic"
  ((sent == BASH_REMATCH[1])) || fail "$topic: $sent sent but ${BASH_REMATCH[1]} received; something was lost"
  echo "cut_leader: $topic: $sent sent, all received"
done
echo "cut_leader: leader-1 unreachable for $away ticks; lost and re-admitted: $lost"
echo "cut_leader: PASSED"
