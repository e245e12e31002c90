#!/usr/bin/env bash
# A link is cut and healed in the docker-compose deployment: leader-1's container's link is set
# down for 10 s while the real-time mission runs, then up again (cut_link.sh). The simulator
# declares it lost (1 s liveliness lease), its standby member-1-1 takes the group over and keeps
# it; leader-1 is re-admitted when it speaks again and serves as a member; what was sent to or by
# it during the cut arrives after the reconnection (DDS keeps the session for the 30 s participant
# lease and resends), so every message reaches every receiver it was meant for, and the mission
# completes.
# Usage: cut_leader.sh SOURCE_DIR BIN_DIR OUT_DIR
set -euo pipefail
src=$1 bin=$2 out=$3
rc=0
bash "$src/deploy/compose-test.sh" --prebuilt "$bin" --image swarm:ctest \
  --scenario "$src/scenarios/deploy_faults.pbtxt" --out "$out" \
  --after-up "bash '$src/tests/deploy/cut_link.sh' leader-1 10" || rc=$?
((rc == 0)) || exit "$rc"

test_name=cut_leader metrics=$out/metrics.json
# shellcheck source=tests/deploy/metrics_checks.sh
source "$src/tests/deploy/metrics_checks.sh"
lost=$(faults_list agents_lost)
unreachable=$(faults_list unreachable)
[[ $lost == *'"agent":"leader-1"'* ]] || fail "metrics.json does not record leader-1 as lost while cut"
[[ $lost =~ \"rejoined_at_tick\":([0-9]+) ]] || fail "leader-1 was never re-admitted after the link healed"
# Its standby took the group over when the simulator declared it lost, and kept it after the
# reconnection: leader-1 came back as a member (comm/leadership.hpp).
handovers=$(faults_list leader_handovers)
[[ $handovers == *'"from":"leader-1"'* && $handovers == *'"to":"member-1-1"'* ]] ||
  fail "member-1-1 did not take group 1 over from leader-1: $handovers"
[[ $handovers =~ \"at_tick\":([0-9]+) ]] || fail "the hand-over has no tick"
took_over=${BASH_REMATCH[1]}
old_terms=$(sed -n '/^    "leader-1": {/,/^    }/p' "$metrics" | tr -d ' \n')
# One term, from tick 0 to the first clock it read after the reconnection (it stepped no tick
# while cut off, and in real time it then skips to the newest).
[[ $old_terms =~ \"led\":\[\{\"from_tick\":0,\"to_tick\":([0-9]+)\}\] ]] ||
  fail "leader-1 led more than once, or never stood down (its terms: $old_terms)"
((BASH_REMATCH[1] >= took_over)) || fail "leader-1 stood down at ${BASH_REMATCH[1]}, before the hand-over at $took_over"
# The GCS heard group 1 again once the standby led: silent for about the 1 s lease, not the 10 s cut.
away=0
while read -r interval; do
  [[ $interval =~ \"agent\":\"leader-1\",\"from_tick\":([0-9]+),\"to_tick\":([0-9]+) ]] || continue
  ((BASH_REMATCH[2] - BASH_REMATCH[1] > away)) && away=$((BASH_REMATCH[2] - BASH_REMATCH[1]))
done < <(sed 's/},{/}\n{/g' <<<"$unreachable")
((away < 200)) || fail "group 1 was unreachable for $away ticks although its standby took over"

# Every message reached every receiver it was meant for (the standbys hear the members too). The
# leaders' task reports carry each exploration round's waypoints to the GCS, which drives them.
for topic in patch_up patch_gcs task_report; do
  b=$(block_of "\"$topic\": {")
  [[ $b =~ \"addressed_messages\":([0-9]+) ]] || fail "no traffic on $topic"
  sent=${BASH_REMATCH[1]}
  [[ $b =~ \"received_messages\":([0-9]+) ]] || fail "no received count on $topic"
  ((sent == BASH_REMATCH[1])) || fail "$topic: $sent addressed but ${BASH_REMATCH[1]} received; something was lost"
  echo "cut_leader: $topic: $sent addressed, all received"
done
echo "cut_leader: member-1-1 led group 1 from tick $took_over; group 1 unreachable for $away ticks; leader-1 lost and re-admitted as a member: $lost"
echo "cut_leader: PASSED"
