#!/usr/bin/env bash
# Installs the Debian 12 packages swarm needs, only those that are missing. Idempotent.
# Runs apt-get as root (directly, or through sudo when run as a user).
set -euo pipefail

packages=(
  cmake ninja-build g++ pkg-config
  libfastrtps-dev libfastcdr-dev fastddsgen
  fastdds-tools  # fast-discovery-server: the discovery server every `swarm run` starts
  libeigen3-dev libopencv-core-dev libopencv-imgproc-dev libopencv-imgcodecs-dev
  libprotobuf-dev protobuf-compiler
  libyaml-cpp-dev nlohmann-json3-dev libcli11-dev libzstd-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  clang libclang-rt-14-dev  # scripts/sanitize.sh address and scripts/fuzz.sh: ASan + libFuzzer
  openssl  # scripts/make-certs.sh: swarm run --secure (DDS-Security certificates)
  debootstrap  # deploy/base-image.sh: the Debian base image where no registry is reachable
  libwebsocketpp-dev libasio-dev  # swarm view: its HTTP and WebSocket server (header-only)
  chromium  # the viewer's page tests: headless screenshots
  python3  # maps/generate.py and maps/office.py (standard library only), tests/repo's office plan
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo=""
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "install-deps: run as root (or install sudo) to install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -q
$sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
