#!/usr/bin/env bash
# Builds the cluster-node image (deploy/Dockerfile.node: Debian 12's Docker engine in a container)
# offline, as build-images.sh builds the swarm image: base image, the node set's .deb files
# fetched on the host, `docker build --network none` on a context of exactly the files it needs.
#
#   deploy/node-image.sh                    # swarm-node:latest, only when missing
#   deploy/node-image.sh --force            # rebuild it anyway
#
# Flags: --tag IMAGE (default swarm-node:latest), --force. Exit codes: 0 ok, 1 build failed, 2 bad
# input or no Docker engine.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
# shellcheck source=deploy/lib.sh
source "$here/lib.sh"

tag=swarm-node:latest
force=0
while (($#)); do
  case $1 in
    --tag) tag=${2:?--tag needs an image name}; shift ;;
    --force) force=1 ;;
    -h | --help) sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) die 2 "unknown flag $1 (see --help)" ;;
  esac
  shift
done
docker_engine_running || die 2 "no Docker engine answers (docker info failed); start it or run where one runs"
if ((force == 0)) && docker image inspect "$tag" >/dev/null 2>&1; then
  say "$tag is present"
  exit 0
fi
start=$SECONDS
"$here/base-image.sh"
"$here/fetch-debs.sh" node
work=$(mktemp -d "${TMPDIR:-/tmp}/swarm-node-context.XXXXXX")
trap 'rm -rf "$work"' EXIT
(cd "$root" && tar -cf "$work/context.tar" deploy/Dockerfile.node deploy/apt-install.sh \
  deploy/packages-node.txt deploy/node-entrypoint.sh deploy/debs/node)
docker build --force-rm -f deploy/Dockerfile.node -t "$tag" --network none - <"$work/context.tar" ||
  die 1 "docker build of $tag failed (output above)"
say "built $tag: $(($(docker image inspect -f '{{.Size}}' "$tag") / 1000000)) MB in $((SECONDS - start)) s"
