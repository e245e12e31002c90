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

# rogue_cmd EXPECTED_EXIT PROBE_FLAGS: the --after-up command. The probe listens for 15 s from
# `up` on (tests/deploy/rogue.pbtxt: the roles find each other in ~7 s, then ~70 ticks of 100 ms)
# and must end with EXPECTED_EXIT (0: it read clock samples, 1: none).
rogue_cmd() {
  local want=$1 flags=$2 report=$out/rogue-$1.txt
  echo "rc=0; docker run --rm --network \"\$SWARM_NETWORK\" \"\$SWARM_IMAGE\" swarm probe --domain 0 --partition swarm" \
    "--seconds 15 $flags >'$report' 2>&1 || rc=\$?; cat '$report';" \
    "[[ \$rc == $want ]] || { echo \"rogue: swarm probe ended with \$rc, expected $want\" >&2; exit 1; }"
}

rc=0
echo "rogue: 1. a secure deployment; the rogue has no certificate (simple discovery, as the roles)"
bash "$src/deploy/compose-test.sh" --prebuilt "$bin" --image swarm:ctest --secure \
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
