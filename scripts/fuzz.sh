#!/usr/bin/env bash
# scripts/fuzz.sh [--smoke] [--runs N] [--build-only] [TARGET...]
#
# Builds the libFuzzer targets of fuzz/ with clang (ASan + UBSan) into build-fuzz/ and runs each
# (scripts/sanitize.sh address ends with --smoke):
# by default 1,000,000 inputs per target (--runs N for another count); --smoke runs each for a few
# seconds (CI); --build-only builds them and stops (scripts/test.sh builds them during ctest).
# The corpus of every target lives in fuzz/corpus/<target>/ (seeds, and what the fuzzer found
# that adds coverage, minimised); a crash stops the script with the input saved in
# build-fuzz/crashes/<target>/ and a non-zero exit.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=1000000
smoke=0
build_only=0
targets=()
while (($#)); do
  case "$1" in
    --smoke) smoke=1 ;;
    --runs) runs=$2; shift ;;
    --build-only) build_only=1 ;;
    -*) echo "usage: scripts/fuzz.sh [--smoke] [--runs N] [--build-only] [TARGET...]" >&2; exit 2 ;;
    *) targets+=("$1") ;;
  esac
  shift
done
command -v clang++ >/dev/null || { echo "fuzz.sh: clang++ is missing (scripts/install-deps.sh installs it)" >&2; exit 2; }

build=build-fuzz
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DSWARM_SANITIZE=fuzz -DSWARM_BUILD_TESTS=OFF \
  -DSWARM_BUILD_BENCH=OFF "${launcher[@]}" >/dev/null
cmake --build "$build" -j "${SWARM_BUILD_JOBS:-$(nproc)}" --target swarm_fuzz_all
((build_only == 0)) || exit 0

if ((${#targets[@]} == 0)); then
  for f in fuzz/fuzz_*.cpp; do targets+=("$(basename "$f" .cpp)"); done
fi
status=0
for t in "${targets[@]}"; do
  corpus="fuzz/corpus/$t"
  crashes="$build/crashes/$t"
  mkdir -p "$corpus" "$crashes"
  if ((smoke)); then
    limit=(-max_total_time="${SWARM_FUZZ_SECONDS:-5}")
  else
    limit=(-runs="$runs")
  fi
  echo "== $t"
  # New inputs go to a scratch folder first; merged (minimised) into the corpus at the end, so
  # the tree keeps only inputs that add coverage.
  scratch="$build/new/$t"
  rm -rf "$scratch"
  mkdir -p "$scratch"
  if ! "$build/fuzz/$t" "${limit[@]}" -max_len=4096 -rss_limit_mb=2048 -timeout=10 \
    -artifact_prefix="$crashes/" -print_final_stats=1 "$scratch" "$corpus" 2>"$build/$t.log"; then
    echo "fuzz.sh: $t FAILED; the input is in $crashes/, the log in $build/$t.log" >&2
    tail -30 "$build/$t.log" >&2
    status=1
    continue
  fi
  grep -E "stat::number_of_executed_units|stat::average_exec_per_sec" "$build/$t.log" | tr '\n' ' '
  echo
  if ((!smoke)); then
    "$build/fuzz/$t" -merge=1 "$corpus" "$scratch" 2>>"$build/$t.log" >/dev/null
  fi
done
exit "$status"
