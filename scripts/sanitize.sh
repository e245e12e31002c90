#!/usr/bin/env bash
# scripts/sanitize.sh address|thread [ctest args...]
#
# Builds swarm with a sanitizer into its own folder (build-address: AddressSanitizer +
# UndefinedBehaviorSanitizer; build-thread: ThreadSanitizer), then runs every unit test, one multi-process mission over real
# DDS, one multi-process run with a killed member and one whose GCS is killed and restarted (its
# journal replayed), and exits non-zero if any test fails or any
# process (tests, and every role process they start) reported anything. Reports go to files under
# build-<kind>/sanitizer-reports/ (one per process), shown at the end. Suppressions
# (scripts/sanitize/*.supp) may only name code wholly inside Fast DDS and its libraries, each with
# the reason. The address run ends with `scripts/fuzz.sh --smoke` (clang's libFuzzer, with ASan
# and UBSan too; SWARM_SKIP_FUZZ=1 skips it).
#
# Roles end with _Exit after their work (comm::exit_after_work: no Fast DDS teardown), so leak
# checking happens in the test processes only, never in role processes.
set -euo pipefail
cd "$(dirname "$0")/.."
kind=${1:-}
case "$kind" in
  address | thread) shift ;;
  *)
    echo "usage: scripts/sanitize.sh address|thread [ctest args...]" >&2
    exit 2
    ;;
esac

src=$(pwd)
build="$src/build-$kind"
reports="$build/sanitizer-reports"
supp="$src/scripts/sanitize"

args=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DSWARM_SANITIZE="$kind"
  -DSWARM_BUILD_BENCH=OFF)
command -v ccache >/dev/null && args+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# -O1: the sanitizers' usual setting (fast enough, frames still readable); -g1: line tables for
# the stacks; no benchmarks (their speed means nothing here).
cmake -S . -B "$build" -G Ninja "${args[@]}" >/dev/null
cmake --build "$build" -j "${SWARM_BUILD_JOBS:-$(nproc)}"

rm -rf "$reports"
mkdir -p "$reports"
# Every process of a test (and every role process it starts) inherits these: a report goes to
# its own file, and makes the process fail.
common="log_path=$reports/report:print_stacktrace=1"
export UBSAN_OPTIONS="$common:halt_on_error=1:suppressions=$supp/ubsan.supp"
if [[ $kind == address ]]; then
  # new_delete_type_mismatch=0: Fast DDS 2.9.1 (Debian 12) deletes its statistics readers and
  # writers (allocated as StatisticsReaderImpl / StatisticsWriterImpl, 64 bytes) through
  # ~RTPSReader / ~RTPSWriter with the base's size (56 bytes): every frame of the report is inside
  # libfastrtps, from DataReader/DataWriter deletion. ASan cannot suppress this check by location,
  # so it is off; every other check stays on.
  export ASAN_OPTIONS="$common:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1:new_delete_type_mismatch=0"
  export LSAN_OPTIONS="suppressions=$supp/lsan.supp:print_suppressions=0"
else
  export TSAN_OPTIONS="$common:halt_on_error=0:second_deadlock_stack=1:suppressions=$supp/tsan.supp"
fi

status=0
cd "$build"
# The unit tests, then one mission and one killed member over real DDS (multi-process).
ctest --output-on-failure --timeout 900 -j "${SWARM_TEST_JOBS:-2}" -L unit "$@" || status=1
ctest --output-on-failure --timeout 900 \
  -R '^(IntegrationRun\.SmallMissionCompletesWithEveryOutput|Faults\.KilledMemberIsNoticedAndTheMissionCompletes|Faults\.KilledGcsIsRestartedAndTheMissionCompletesWithTheSameMap)$' \
  "$@" || status=1
cd "$src"

shopt -s nullglob
found=("$reports"/report*)
if ((${#found[@]} > 0)); then
  echo "sanitize.sh $kind: ${#found[@]} process(es) reported:" >&2
  for f in "${found[@]}"; do
    echo "==== $f" >&2
    head -60 "$f" >&2
  done
  status=1
fi
if [[ $kind == address && ${SWARM_SKIP_FUZZ:-0} != 1 ]]; then
  unset ASAN_OPTIONS UBSAN_OPTIONS LSAN_OPTIONS
  scripts/fuzz.sh --smoke || status=1
fi
if ((status == 0)); then
  echo "sanitize.sh $kind: no report, every test passed"
else
  echo "sanitize.sh $kind: FAILED (reports in $reports)" >&2
fi
exit "$status"
