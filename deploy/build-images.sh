#!/usr/bin/env bash
# Builds the swarm image (deploy/Dockerfile) on a machine that can reach a Debian mirror but no
# container registry, with no network inside `docker build`:
#   1. deploy/base-image.sh makes debian:bookworm-slim with debootstrap when it is missing;
#   2. deploy/fetch-debs.sh downloads on the host the .deb files the stages install;
#   3. the build context is the repository's own files (git ls-files: tracked and new, not
#      ignored, so no build trees) plus those .deb files, sent to `docker build` as a tar stream.
#
#   deploy/build-images.sh                          # compile from source in the image (~16 min cold, 2 cores)
#   deploy/build-images.sh --prebuilt build/bin     # binaries built on this Debian 12 host (~4 min cold)
#
# Flags: --tag IMAGE (default swarm:latest), --jobs N (compile jobs, default 2: ~1 GB each),
# --online (skip steps 1 and 2: the base image is pulled and packages come from the image's apt
# sources, for machines with a registry). Exit codes: 0 ok, 1 build failed, 2 bad input.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
# shellcheck source=deploy/lib.sh
source "$here/lib.sh"

tag=swarm:latest
prebuilt=""
jobs=2
online=0
while (($#)); do
  case $1 in
    --tag) tag=${2:?--tag needs an image name}; shift ;;
    --prebuilt) prebuilt=${2:?--prebuilt needs the folder holding swarm and swarm-* binaries}; shift ;;
    --jobs) jobs=${2:?--jobs needs a number}; shift ;;
    --online) online=1 ;;
    -h | --help) sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) die 2 "unknown flag $1 (see --help)" ;;
  esac
  shift
done
[[ $jobs =~ ^[1-9][0-9]*$ ]] || die 2 "--jobs '$jobs' is not a positive number"
roles=(swarm swarm-sim swarm-gcs swarm-leader swarm-member)
if [[ -n $prebuilt ]]; then
  for b in "${roles[@]}"; do
    [[ -x $prebuilt/$b ]] || die 2 "--prebuilt $prebuilt has no executable $b; build first (scripts/build.sh)"
  done
fi
docker_engine_running || die 2 "no Docker engine answers (docker info failed); start it or run where one runs"

start=$SECONDS
sets=(runtime)
[[ -n $prebuilt ]] || sets+=(build)
if ((online == 0)); then
  "$here/base-image.sh"
  "$here/fetch-debs.sh" "${sets[@]}"
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/swarm-image-context.XXXXXX")
trap 'rm -rf "$work"' EXIT
# The repository's files as they are in the working tree (what a developer would build).
if git -C "$root" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  git -C "$root" ls-files -z --cached --others --exclude-standard |
    while IFS= read -r -d '' f; do [[ -e $root/$f || -L $root/$f ]] && printf '%s\0' "$f"; done >"$work/files"
else
  (cd "$root" && find . \( -path ./.git -o -path './build*' -o -path ./runs -o -path ./deploy/.cache \
    -o -path ./deploy/debs \) -prune -o \( -type f -o -type l \) -print0) >"$work/files"
fi
# The fetched packages: only the sets this build installs from, and only without --online.
for set in runtime build; do
  printf 'deploy/debs/%s/.keep\0' "$set" >>"$work/files"
  if ((online == 0)) && [[ " ${sets[*]} " == *" $set "* ]]; then
    (cd "$root" && find "deploy/debs/$set" -type f \( -name '*.deb' -o -name Packages \) -print0) >>"$work/files"
  fi
done
mkdir -p "$root/deploy/debs/runtime" "$root/deploy/debs/build"
touch "$root/deploy/debs/runtime/.keep" "$root/deploy/debs/build/.keep"
sort -zu "$work/files" -o "$work/files"
tar -C "$root" --null -T "$work/files" -cf "$work/context.tar"
build_args=(--build-arg "SWARM_BUILD_JOBS=$jobs")
# Offline means offline: the build's RUN steps get no network at all, so a step that tried to
# download would fail instead of quietly using the mirror.
((online)) || build_args+=(--network none)
if [[ -n $prebuilt ]]; then
  mkdir -p "$work/prebuilt/.prebuilt/bin"
  for b in "${roles[@]}"; do cp "$prebuilt/$b" "$work/prebuilt/.prebuilt/bin/"; done
  tar -C "$work/prebuilt" -rf "$work/context.tar" .prebuilt
  build_args+=(--build-arg SWARM_PREBUILT=.prebuilt/bin)
fi
say "building $tag ($( ((${#prebuilt})) && echo "binaries from $prebuilt" || echo "compiling from source, $jobs jobs"); context $(($(stat -c %s "$work/context.tar") / 1000000)) MB)"
build_start=$SECONDS
if ! docker build --force-rm -f deploy/Dockerfile -t "$tag" "${build_args[@]}" - <"$work/context.tar"; then
  die 1 "docker build failed (output above)"
fi
size=$(docker image inspect -f '{{.Size}}' "$tag")
say "built $tag: $((size / 1000000)) MB; docker build $((SECONDS - build_start)) s, all steps $((SECONDS - start)) s"
