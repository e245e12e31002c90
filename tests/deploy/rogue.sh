#!/usr/bin/env bash
# Only our own participants join a secure deployment: a rogue container on the same compose network,
# with no certificate (`swarm probe`: a plain DDS participant in the swarm's domain and partition
# that subscribes to the clock and offers a writer on `done`), reads no clock sample and matches
# none of the swarm's endpoints while a secure mission (compose-gen.sh --secure, certificates from
# scripts/make-certs.sh) runs and completes. The control: the same rogue against the same mission
# without security reads the clock (so the probe would have seen the traffic).
# Usage: rogue.sh SOURCE_DIR BIN_DIR OUT_DIR
set -euo pipefail
src=$1 bin=$2 out=$3
mkdir -p "$out"
share=/opt/swarm/share/deploy

# rogue_cmd EXPECTED_EXIT PROBE_FLAGS: the --after-up command. Once the mission is under way (the
# GCS has printed its first tick: tests/deploy/rogue.pbtxt runs ~70 ticks of 100 ms), the probe
# joins and listens for 15 s, and must end with EXPECTED_EXIT (0: it read clock samples, 1: none).
# It joins a running swarm, as an intruder would. A mission that never starts (the GCS or the
# simulator exits, or 90 s pass without a tick) fails the test here, saying so: the probe does not
# run, since "0 clock samples" beside a swarm that never ran would prove nothing.
rogue_cmd() {
  local want=$1 flags=$2 report=$out/rogue-$1.txt
  local of='$(docker ps -aq --filter label=com.docker.compose.project=$COMPOSE_PROJECT_NAME --filter label=com.docker.compose.service='
  cat <<EOF
started=0
for _ in \$(seq 360); do
  if docker logs ${of}gcs) 2>&1 | grep -Eq '^tick +[0-9]+ '; then started=1; break; fi
  for s in gcs sim; do
    [[ \$(docker inspect -f '{{.State.Status}}' ${of}\$s) 2>/dev/null) != exited ]] && continue
    echo "rogue: the mission never started: \$s exited before the first tick; the probe did not run" >&2
    exit 1
  done
  sleep 0.25
done
((started)) || { echo "rogue: the mission never started: no tick from the GCS in 90 s; the probe did not run" >&2; exit 1; }
rc=0
docker run --rm --network "\$SWARM_NETWORK" "\$SWARM_IMAGE" swarm probe --domain 0 --partition swarm --seconds 15 $flags >'$report' 2>&1 || rc=\$?
cat '$report'
[[ \$rc == $want ]] || { echo "rogue: swarm probe ended with \$rc, expected $want" >&2; exit 1; }
EOF
}

# BIN_DIR empty: the image swarm:ctest as it is (tests/deploy/start_study.sh repeats this test).
build=(--prebuilt "$bin")
[[ -n $bin ]] || build=(--no-build)

rc=0
echo "rogue: 1. a secure deployment; the rogue has no certificate (simple discovery, as the roles)"
bash "$src/deploy/compose-test.sh" "${build[@]}" --image swarm:ctest --secure \
  --scenario "$src/tests/deploy/rogue.pbtxt" --out "$out/secure" \
  --after-up "$(rogue_cmd 1 "--profile $share/fastdds_container_simple.xml")" || rc=$?
((rc == 0)) || exit "$rc"
grep -q ': 0 clock samples from 0 clock writers; 0 done readers matched' "$out/rogue-1.txt" || {
  echo "rogue: the rogue saw something of the secure deployment:" >&2
  cat "$out/rogue-1.txt" >&2
  exit 1
}

echo "rogue: 2. the control: the same mission without security; the rogue is a client of its discovery server"
bash "$src/deploy/compose-test.sh" --no-build --image swarm:ctest \
  --scenario "$src/tests/deploy/rogue.pbtxt" --out "$out/open" \
  --after-up "$(rogue_cmd 0 "--profile $share/fastdds_container.xml --discovery-server discovery:11811")" || rc=$?
((rc == 0)) || exit "$rc"
[[ $(cat "$out/rogue-0.txt") =~ :\ ([1-9][0-9]*)\ clock\ samples\ from\ ([1-9][0-9]*)\ clock\ writers ]] || {
  echo "rogue: the control rogue read no clock from the open deployment, so the secure result shows nothing:" >&2
  cat "$out/rogue-0.txt" >&2
  exit 1
}
echo "rogue: PASSED (secure: nothing seen; open: ${BASH_REMATCH[1]} clock samples)"
