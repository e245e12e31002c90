#!/bin/sh
# Runs inside an image build (deploy/Dockerfile): installs the packages named in LIST.
#   apt-install.sh LIST DEBDIR
# When DEBDIR holds a Packages index (deploy/fetch-debs.sh made it on the host), apt installs
# from that folder only, as a local repository, and touches no network. Otherwise (an empty
# DEBDIR, e.g. on a machine where the Debian mirror is reachable from builds) it installs from
# the image's own apt sources. Either way the same apt-get install command resolves the same list.
set -eu
list=$1
debs=$2
pkgs=$(sed -e 's/#.*//' "$list" | tr -s ' \t\n' '   ')
export DEBIAN_FRONTEND=noninteractive
if [ -f "$debs/Packages" ]; then
  echo "apt-install: offline, from $(ls "$debs" | grep -c '\.deb$') .deb files fetched on the host"
  mkdir -p /tmp/apt-local/parts
  echo "deb [trusted=yes] file:$debs ./" >/tmp/apt-local/sources.list
  set -- -o Dir::Etc::SourceList=/tmp/apt-local/sources.list -o Dir::Etc::SourceParts=/tmp/apt-local/parts
else
  echo "apt-install: online, from the image's apt sources"
  set --
fi
# Slim images have no /usr/share/man/man1; openjdk's postinst (fastddsgen needs Java) registers a
# man page link there with update-alternatives, which fails when the folder is missing.
mkdir -p /usr/share/man/man1
apt-get "$@" -q update
# No fsync per file: a failed image build is simply run again (as Debian's own images do).
# shellcheck disable=SC2086 # one word per package
apt-get "$@" -q -y --no-install-recommends -o Dpkg::Options::=--force-unsafe-io install $pkgs
apt-get clean
rm -rf /var/lib/apt/lists/* /tmp/apt-local
