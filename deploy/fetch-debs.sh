#!/usr/bin/env bash
# Downloads, on the host, the Debian packages an image stage installs, so that `docker build`
# needs no network: deploy/debs/SET/ gets every .deb that SET's list (deploy/packages-SET.txt)
# needs on top of the base image, and a Packages index that makes the folder a flat apt
# repository. deploy/apt-install.sh, run inside the image build, installs from it when present.
#
#   deploy/fetch-debs.sh runtime          # what the runtime stage needs (~100 MB of .debs)
#   deploy/fetch-debs.sh build runtime    # and the build stage's compilers, -dev packages (~280 MB)
#   deploy/fetch-debs.sh node             # the cluster-node image (Docker engine, ~60 MB)
#
# How: the base image's dpkg status file stands in for "what is installed", and the host's apt
# (its sources and its keys, so the downloads are verified against the signed Release files)
# resolves and downloads the rest into deploy/.cache/apt. Nothing on the host is installed or
# changed. A set is fetched again only when its list or the base image changed.
# Flags: --base IMAGE (default debian:bookworm-slim). Exit codes: 0 ok, 1 failure, 2 bad input.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=deploy/lib.sh
source "$here/lib.sh"

base=debian:bookworm-slim
sets=()
while (($#)); do
  case $1 in
    --base) base=${2:?--base needs an image}; shift ;;
    build | runtime | node) sets+=("$1") ;;
    -h | --help) sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) die 2 "unknown argument $1 (sets: build, runtime, node; flag: --base IMAGE)" ;;
  esac
  shift
done
((${#sets[@]})) || die 2 "name the package sets to fetch: build, runtime, node"
command -v apt-get >/dev/null || die 2 "apt-get is missing; fetching .deb files needs a Debian host"
docker_engine_running || die 2 "no Docker engine answers (docker info failed)"
base_id=$(docker image inspect -f '{{.Id}}' "$base" 2>/dev/null) ||
  die 2 "base image $base is missing; make it first: deploy/base-image.sh"

cache=$here/.cache/apt
mkdir -p "$cache/lists/partial" "$cache/archives/partial"
arch=$(dpkg --print-architecture)
status=$cache/status-${base_id#sha256:}
if [[ ! -s $status ]]; then
  docker run --rm --network none --entrypoint cat "$base" /var/lib/dpkg/status >"$status.tmp"
  mv "$status.tmp" "$status"
fi
# The host's sources and trust, everything else private to the cache.
apt_opts=(
  -o "Dir::State::status=$status"
  -o "Dir::State::Lists=$cache/lists"
  -o "Dir::State::extended_states=$cache/extended_states"
  -o "Dir::Cache=$cache"
  -o "Dir::Cache::archives=$cache/archives"
  -o "Dir::Cache::pkgcache=" -o "Dir::Cache::srcpkgcache="
  -o "APT::Architecture=$arch" -o "APT::Architectures::=$arch"
  -o "APT::Install-Recommends=false" -o "APT::Install-Suggests=false"
  -o "Debug::NoLocking=true" -o "APT::Sandbox::User=root"
  -o "Acquire::Languages=none"
)
updated=0

for set in "${sets[@]}"; do
  list=$here/packages-$set.txt
  dest=$here/debs/$set
  mkdir -p "$dest"
  mapfile -t pkgs < <(sed -e 's/#.*//' -e '/^[[:space:]]*$/d' "$list" | tr -d ' \t')
  stamp=$(cat "$list" <(echo "$base_id") | sha256sum | cut -d' ' -f1)
  if [[ -f $dest/Packages && $(cat "$dest/.stamp" 2>/dev/null) == "$stamp" ]]; then
    say "$set: up to date ($(find "$dest" -name '*.deb' | wc -l) packages in deploy/debs/$set)"
    continue
  fi
  if ((updated == 0)); then
    t0=$SECONDS
    say "apt-get update (private lists in deploy/.cache/apt, the machine's sources)"
    apt-get "${apt_opts[@]}" -q update >"$cache/update.log" 2>&1 || {
      tail -n 15 "$cache/update.log" >&2
      die 1 "apt-get update failed (last lines above)"
    }
    updated=1
    say "apt-get update took $((SECONDS - t0)) s"
  fi
  t1=$SECONDS
  # The exact files this set needs on top of the base image, then download what is not cached.
  # (--print-uris leaves out what the archives folder already holds: resolve against an empty one.)
  mkdir -p "$cache/empty/partial"
  uris=$(apt-get "${apt_opts[@]}" -o "Dir::Cache::archives=$cache/empty" -qq --print-uris install "${pkgs[@]}" \
    2>"$cache/resolve.log") || {
    cat "$cache/resolve.log" >&2
    die 1 "$set: apt cannot resolve deploy/packages-$set.txt against $base (above)"
  }
  say "$set: needs $(grep -c . <<<"$uris") packages; downloading those not yet in deploy/.cache/apt"
  apt-get "${apt_opts[@]}" -q -y --download-only install "${pkgs[@]}" >"$cache/download.log" 2>&1 || {
    tail -n 15 "$cache/download.log" >&2
    die 1 "$set: downloading failed (last lines above)"
  }
  find "$dest" -mindepth 1 -not -name .keep -delete
  while read -r _ file _; do
    ln "$cache/archives/$file" "$dest/$file" 2>/dev/null || cp "$cache/archives/$file" "$dest/$file"
  done <<<"$uris"
  # A flat repository index: each package's control fields plus where and what the file is.
  {
    for deb in "$dest"/*.deb; do
      dpkg-deb -f "$deb"
      echo "Filename: ./$(basename "$deb")"
      echo "Size: $(stat -c %s "$deb")"
      echo "SHA256: $(sha256sum "$deb" | cut -d' ' -f1)"
      echo
    done
  } >"$dest/Packages"
  echo "$stamp" >"$dest/.stamp"
  say "$set: $(find "$dest" -name '*.deb' | wc -l) packages, $(du -sm "$dest" | cut -f1) MB in deploy/debs/$set ($((SECONDS - t1)) s)"
done
