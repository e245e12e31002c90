#!/usr/bin/env bash
# Repeats one deployment start-up case N times and counts how often the mission never starts.
# It measures what tests/deploy/rogue.sh relies on: that a secure compose deployment starts
# every time. Each run is compose-test.sh on tests/deploy/rogue.pbtxt (6 containers, ~35-45 s).
#
#   tests/deploy/start_study.sh --case secure --runs 20 --out /tmp/study-secure
#
# Cases:
#   secure      a secure mission (compose-test.sh --secure), nothing else
#   rogue       tests/deploy/rogue.sh: the same secure mission with the rogue container, then the
#               open control mission
#   secure-log  a secure mission with SWARM_DDS_LOG=security: each role prints every DDS peer's
#               discovery and authentication as it happens, and Fast DDS's security log
#   open        the same mission without security (discovery server)
# Flags: --image IMAGE (default swarm:ctest, which the ctest deploy_compose builds; it is not
# rebuilt here), --out DIR (default: a temporary folder; every run's logs stay in DIR/run-I).
# Prints one line per run and, at the end, the pass count and every failure's first error line;
# DIR/summary.tsv has one row per run: run, case, result (pass/fail), seconds, first error line.
# Exit code: 0 when every run passed, 1 otherwise, 2 bad input.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/../.." && pwd)
# shellcheck source=deploy/lib.sh
source "$src/deploy/lib.sh"

case_name="" runs="" image=swarm:ctest out=""
while (($#)); do
  case $1 in
    --case) case_name=${2:-}; shift ;;
    --runs) runs=${2:-}; shift ;;
    --image) image=${2:?--image needs an image}; shift ;;
    --out) out=${2:?--out needs a folder}; shift ;;
    -h | --help) sed -n '2,24p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) die 2 "unknown flag $1 (see --help)" ;;
  esac
  shift
done
[[ $case_name =~ ^(secure|rogue|secure-log|open)$ ]] || die 2 "--case must be secure, rogue, secure-log or open (got '$case_name')"
[[ $runs =~ ^[1-9][0-9]*$ ]] || die 2 "--runs needs a positive number (got '$runs')"
docker image inspect "$image" >/dev/null 2>&1 ||
  die 2 "image $image does not exist: run ctest -R deploy_compose (or deploy/build-images.sh --prebuilt build/bin --tag $image)"
out=${out:-$(mktemp -d "${TMPDIR:-/tmp}/swarm-start-study.XXXXXX")}
mkdir -p "$out"
summary=$out/summary.tsv
printf 'run\tcase\tresult\tseconds\tfirst_error\n' >"$summary"

one_run() {
  local dir=$1
  local mission=(bash "$src/deploy/compose-test.sh" --no-build --image "$image" --scenario "$here/rogue.pbtxt" --out "$dir")
  case $case_name in
    secure) "${mission[@]}" --secure ;;
    secure-log) SWARM_DDS_LOG=security "${mission[@]}" --secure ;;
    open) "${mission[@]}" ;;
    rogue) bash "$here/rogue.sh" "$src" "" "$dir" ;;
  esac
}

passed=0
for ((i = 1; i <= runs; i++)); do
  dir=$out/run-$i
  start=$SECONDS
  if one_run "$dir" >"$out/run-$i.log" 2>&1; then
    result=pass
    passed=$((passed + 1))
    first=""
  else
    result=fail
    # The line that says why: a role that never became ready, a probe that saw something, ...
    first=$(grep -m1 -E 'never became ready|did not complete|rogue:.*(saw|expected|never)|exited with code|FAILED' \
      "$out/run-$i.log" || tail -n 1 "$out/run-$i.log")
  fi
  printf '%s\t%s\t%s\t%s\t%s\n' "$i" "$case_name" "$result" "$((SECONDS - start))" "$first" >>"$summary"
  say "run $i/$runs ($case_name): $result in $((SECONDS - start)) s${first:+: $first}"
done
say "$case_name: $passed of $runs runs passed; rows in $summary"
((passed == runs))
