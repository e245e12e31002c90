#!/usr/bin/env bash
# Makes the Debian 12 base image that deploy/Dockerfile starts FROM (debian:bookworm-slim) on a
# machine that has no registry to pull it from: debootstrap (minbase, bookworm) into a folder,
# trim it the way the official slim image is trimmed, and `docker import` it.
#
#   deploy/base-image.sh            # only when the image is missing
#   deploy/base-image.sh --force    # rebuild it anyway
#
# The Debian mirror is read from this machine's apt configuration (/etc/apt/sources.list,
# sources.list.d/*.list or deb822 *.sources) at run time; --mirror URI overrides it. The same
# mirror entries (bookworm, bookworm-updates, bookworm-security) become the image's apt sources.
# Needs root (or sudo) for debootstrap, debootstrap itself (scripts/install-deps.sh installs it)
# and a running Docker engine. Exit codes: 0 ok (made or already present), 1 failure, 2 missing
# prerequisite or bad flag.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=deploy/lib.sh
source "$here/lib.sh"

image=debian:bookworm-slim
suite=bookworm
force=0
mirror=""
while (($#)); do
  case $1 in
    --force) force=1 ;;
    --image) image=${2:?--image needs a name}; shift ;;
    --mirror) mirror=${2:?--mirror needs a URI}; shift ;;
    -h | --help) sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) die 2 "unknown flag $1 (flags: --force, --image NAME, --mirror URI)" ;;
  esac
  shift
done

docker_engine_running || die 2 "no Docker engine answers (docker info failed); start it or run where one runs"
if ((force == 0)) && docker image inspect "$image" >/dev/null 2>&1; then
  say "$image is present"
  exit 0
fi
command -v debootstrap >/dev/null || die 2 "debootstrap is not installed; run scripts/install-deps.sh (or apt-get install debootstrap)"
if [[ -z $mirror ]]; then
  mirror=$(debian_mirror_for "$suite")
  [[ -n $mirror ]] || die 2 "no '$suite' entry in this machine's apt sources (/etc/apt/sources.list, sources.list.d/); pass --mirror URI"
fi
sudo=""
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || die 2 "debootstrap needs root; run as root or install sudo"
  sudo="sudo"
fi

rootfs=$(mktemp -d "${TMPDIR:-/var/tmp}/swarm-base-rootfs.XXXXXX")
cleanup() {
  # debootstrap mounts proc and sys inside the folder; never delete through a mount.
  local m
  for m in $(awk -v r="$rootfs/" 'index($2, r) == 1 { print $2 }' /proc/mounts | sort -r); do
    $sudo umount "$m" || $sudo umount -l "$m" || true
  done
  if awk -v r="$rootfs/" 'index($2, r) == 1 { found = 1 } END { exit !found }' /proc/mounts; then
    echo "$(basename "$0"): $rootfs still has mounts; left in place, remove it by hand" >&2
  else
    $sudo rm -rf --one-file-system "$rootfs"
  fi
}
trap cleanup EXIT

say "debootstrap --variant=minbase $suite from $mirror (about a minute)"
start=$SECONDS
if ! $sudo debootstrap --variant=minbase --arch="$(dpkg --print-architecture)" "$suite" "$rootfs" "$mirror" \
  >"$rootfs.log" 2>&1; then
  tail -n 20 "$rootfs.log" >&2
  rm -f "$rootfs.log"
  die 1 "debootstrap failed (last lines above)"
fi
rm -f "$rootfs.log"

# Trim and configure it like the official slim image: no docs, man pages or translations (now or
# from later installs), no apt caches left in layers, no services started by package scripts.
$sudo bash -euo pipefail -s "$rootfs" <<'TRIM'
r=$1
cat >"$r/etc/dpkg/dpkg.cfg.d/swarm-slim" <<'EOF'
# Keep images small: no documentation, manuals or translations (the copyright files stay).
path-exclude /usr/share/doc/*
path-include /usr/share/doc/*/copyright
path-exclude /usr/share/man/*
path-exclude /usr/share/info/*
path-exclude /usr/share/groff/*
path-exclude /usr/share/lintian/*
path-exclude /usr/share/locale/*
path-include /usr/share/locale/locale.alias
EOF
find "$r/usr/share/doc" -mindepth 1 -not -name copyright -not -type d -delete
find "$r/usr/share/doc" -mindepth 1 -type d -empty -delete
rm -rf "$r/usr/share/man/"* "$r/usr/share/info/"* "$r/usr/share/groff/"* "$r/usr/share/lintian/"*
find "$r/usr/share/locale" -mindepth 1 -maxdepth 1 -not -name locale.alias -exec rm -rf {} +
cat >"$r/etc/apt/apt.conf.d/swarm-slim" <<'EOF'
// Container image: no package caches or translations kept in layers, no recommends.
APT::Install-Recommends "false";
APT::Install-Suggests "false";
Acquire::Languages "none";
Dir::Cache::pkgcache "";
Dir::Cache::srcpkgcache "";
DPkg::Post-Invoke { "rm -f /var/cache/apt/archives/*.deb /var/cache/apt/archives/partial/*.deb || true"; };
EOF
printf '#!/bin/sh\n# No services start inside an image build.\nexit 101\n' >"$r/usr/sbin/policy-rc.d"
chmod 755 "$r/usr/sbin/policy-rc.d"
rm -rf "$r/var/lib/apt/lists/"* "$r/var/cache/apt/"*.bin "$r/var/cache/apt/archives/"*.deb \
  "$r/var/cache/debconf/"*-old "$r/var/lib/dpkg/"*-old "$r/var/log/"*.log "$r/var/log/apt/"* \
  "$r/tmp/"* "$r/root/".bash_history
# Docker provides these at run time.
rm -f "$r/etc/resolv.conf" "$r/etc/hostname" "$r/etc/hosts"
: >"$r/etc/machine-id"
TRIM

# The image's apt sources: this machine's Debian entries for the suite and its updates/security.
{
  echo "# Written by swarm deploy/base-image.sh from the build machine's apt configuration."
  apt_source_entries | awk -F'\t' -v s="$suite" '
    ($2 == s || $2 == s "-updates" || $2 == s "-security") && !seen[$1 FS $2]++ {
      printf "Types: deb\nURIs: %s\nSuites: %s\nComponents: %s\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n\n", $1, $2, $3
    }'
} | $sudo tee "$rootfs/etc/apt/sources.list.d/debian.sources" >/dev/null
$sudo rm -f "$rootfs/etc/apt/sources.list"
if ! grep -q '^URIs:' "$rootfs/etc/apt/sources.list.d/debian.sources"; then
  printf 'Types: deb\nURIs: %s\nSuites: %s\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' \
    "$mirror" "$suite" | $sudo tee "$rootfs/etc/apt/sources.list.d/debian.sources" >/dev/null
fi

say "importing it as $image"
$sudo tar -C "$rootfs" --numeric-owner --exclude='./dev/*' --exclude='./proc/*' --exclude='./sys/*' -c . |
  docker import \
    --change 'CMD ["bash"]' \
    --change 'ENV PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin' \
    --message "debootstrap --variant=minbase $suite, trimmed (swarm deploy/base-image.sh)" \
    - "$image" >/dev/null
size=$(docker image inspect -f '{{.Size}}' "$image")
say "made $image in $((SECONDS - start)) s ($((size / 1000000)) MB)"
