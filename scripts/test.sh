#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to every test: installs what is missing, builds,
# runs ctest (unit, integration and, where a Docker engine runs, deploy tests), then a short
# libFuzzer run of every parser and decoder with ASan + UBSan (scripts/fuzz.sh --smoke;
# SWARM_SKIP_FUZZ=1 skips it). Extra arguments go to ctest, e.g. scripts/test.sh -L unit (then
# the fuzz run is skipped too).
#
# The full sanitizer runs are not part of it (each is a second build of the whole tree, which
# would take CI past its 30 minutes on 2 cores): SWARM_SANITIZE=address (or thread) adds
# scripts/sanitize.sh to the end; run it by hand on every change to comm/ or a role.
#
# Where a Docker engine runs, the deploy tests' base image and packages (debootstrap and
# downloads: waiting on the network, not the CPU) are prepared in the background while the
# project compiles.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh

prepare_pid=""
prepare_log=build/deploy-prepare.log
if (($# == 0)) && command -v docker >/dev/null 2>&1 && docker info >/dev/null 2>&1; then
  mkdir -p build
  (deploy/base-image.sh && deploy/fetch-debs.sh runtime) >"$prepare_log" 2>&1 &
  prepare_pid=$!
fi
scripts/build.sh
if [[ -n $prepare_pid ]] && ! wait "$prepare_pid"; then
  # Not fatal here: the deploy tests make what is missing themselves and report the failure.
  echo "test.sh: preparing the deploy base image failed (see $prepare_log); the deploy tests retry" >&2
fi
# Three at a time on 2 cores: most tests wait on DDS round trips, real time or Docker more than
# they compute (at -j 2 the cores were about a third busy), and every lockstep run counts ticks,
# not seconds; the deploy chain, the longest, starts first (tests/deploy/CMakeLists.txt).
# The fuzz targets (a second, clang build) compile during ctest, one job at low priority: the
# tests leave the cores partly idle while they wait on DDS and Docker.
fuzz_build_pid=""
if (($# == 0)) && [[ ${SWARM_SKIP_FUZZ:-0} != 1 ]]; then
  SWARM_BUILD_JOBS=1 nice -n 15 scripts/fuzz.sh --build-only >build/fuzz-build.log 2>&1 &
  fuzz_build_pid=$!
fi
status=0
(cd build && ctest --output-on-failure --timeout 600 -j "${SWARM_TEST_JOBS:-3}" "$@") || status=$?
if [[ -n $fuzz_build_pid ]]; then
  wait "$fuzz_build_pid" || { tail -n 30 build/fuzz-build.log >&2; echo "test.sh: building the fuzz targets failed (build/fuzz-build.log)" >&2; exit 1; }
fi
((status == 0)) || exit "$status"
if [[ -n $fuzz_build_pid ]]; then
  scripts/fuzz.sh --smoke
fi
if (($# == 0)) && [[ -n ${SWARM_SANITIZE:-} ]]; then
  SWARM_SKIP_FUZZ=1 scripts/sanitize.sh "$SWARM_SANITIZE"
fi
