#!/usr/bin/env bash
# `swarm probe` on this machine, no Docker: bad flags and a bad discovery server address are
# refused (exit 2, the reason named); with no swarm in its domain and partition it reads nothing
# (exit 1, saying what to check); beside a `swarm run` (real time, its own discovery server on
# loopback) it reads the clock (exit 0) through that server.
# Usage: probe_cli.sh BIN_DIR OUT_DIR
set -uo pipefail
bin=$1 out=$2
rm -rf "$out"
mkdir -p "$out"
failures=0
fail() {
  echo "FAIL: $*" >&2
  failures=$((failures + 1))
}
# expect CODE TEXT ARGS...: `swarm probe ARGS` ends with CODE and says TEXT.
expect() {
  local want=$1 text=$2 got rc
  shift 2
  got=$("$bin/swarm" probe "$@" 2>&1)
  rc=$?
  [[ $rc == "$want" && $got == *"$text"* ]] ||
    fail "swarm probe $*: exit code $rc (expected $want), said: $got (expected: $text)"
  echo "swarm probe $*: $rc: $got" | head -n 2
}
expect 2 "--seconds" --seconds 0
expect 2 "bad discovery server address" --discovery-server 'no such server!' --seconds 0.2
expect 2 "cannot resolve the host name 'no-such-host.invalid'" --discovery-server no-such-host.invalid:11811 --seconds 0.2
expect 1 ": 0 clock samples from 0 clock writers" --domain 41 --partition nobody-here --seconds 1

# A run in domain 41: its discovery server listens on 127.0.0.1, port 7400 + 500 x 41 + 495.
"$bin/swarm" run --map small --groups 1 --robots-per-group 2 --realtime --tick-ms 20 --max-ticks 400 \
  --domain 41 --partition probe-test --out "$out/run" >"$out/run.log" 2>&1 &
run=$!
sleep 1
expect 0 "clock samples from 1 clock writers; 1 done readers matched" --domain 41 --partition probe-test \
  --discovery-server 127.0.0.1:28395 --seconds 4
wait "$run" || fail "the swarm run beside the probe failed ($out/run.log): $(tail -n 3 "$out/run.log")"

if ((failures)); then
  echo "$failures swarm probe check(s) failed" >&2
  exit 1
fi
echo "swarm probe: all checks passed"
