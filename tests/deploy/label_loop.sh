#!/usr/bin/env bash
# The deploy label's tests in series, N times, as ctest runs them (deploy_files, deploy_compose,
# deploy_kill_robots, deploy_cut_leader, deploy_restart_gcs, deploy_rogue), one line per test and
# round in OUT/summary.txt: how often each fails when run again and again (deploy/README.md).
# Usage: tests/deploy/label_loop.sh N SOURCE_DIR BIN_DIR OUT_DIR
#   e.g. tests/deploy/label_loop.sh 30 . build/bin /tmp/label-loop
set -u
n=${1:?rounds} src=${2:?source dir} bin=${3:?binary dir} out=${4:?output dir}
mkdir -p "$out"
log=$out/summary.txt
run() {  # NAME COMMAND...
  local name=$1 t0=$SECONDS rc=0
  shift
  "$@" >"$out/$i-$name.log" 2>&1 || rc=$?
  echo "$(date +%T) round $i $name rc=$rc $((SECONDS - t0))s" | tee -a "$log"
}
for i in $(seq "$n"); do
  run files bash "$src/tests/deploy/check_deploy_files.sh" "$src"
  run compose bash "$src/deploy/compose-test.sh" --prebuilt "$bin" --image swarm:ctest --compose all --out "$out/w/test-deploy"
  run kill bash "$src/tests/deploy/kill_robots.sh" "$src" "$bin" "$out/w/kill"
  run cut bash "$src/tests/deploy/cut_leader.sh" "$src" "$bin" "$out/w/cut"
  run restart bash "$src/tests/deploy/restart_gcs.sh" "$src" "$bin" "$out/w/restart"
  run rogue bash "$src/tests/deploy/rogue.sh" "$src" "$bin" "$out/w/rogue"
done
for t in files compose kill cut restart rogue; do
  echo "$t: $(grep -c " $t rc=0 " "$log") of $n passed"
done
