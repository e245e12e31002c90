#!/bin/sh
# Entrypoint of the cluster-node image (deploy/Dockerfile.node): starts a Docker engine inside
# this privileged container and stays in the foreground with it. Options for dockerd may follow
# (e.g. --storage-driver vfs); SWARM_NODE_MTU sets the MTU of the inner engine's networks.
set -eu
# The engine writes its containers' cgroups, which Docker mounts read-only in a container that is
# not --privileged. deploy/swarm-cluster.sh cannot use --privileged where the host engine lacks a
# capability (runc fails "unable to apply caps"): it grants every capability the host has and no
# seccomp or AppArmor filter instead, so the mounts can be made writable here.
mount -o remount,rw /sys 2>/dev/null || true
mount -o remount,rw /sys/fs/cgroup 2>/dev/null || true
for d in /sys/fs/cgroup/*; do
  if mountpoint -q "$d"; then
    mount -o remount,rw "$d" 2>/dev/null || mount -o remount,bind,rw "$d" 2>/dev/null ||
      { echo "swarm-node: cannot make $d writable: start the container with CAP_SYS_ADMIN" >&2; exit 1; }
  fi
done
# Stale pid files from an earlier start of this container (docker restart) stop dockerd.
rm -f /var/run/docker.pid /var/run/docker/containerd/containerd.pid
mtu=${SWARM_NODE_MTU:-1500}
case $mtu in '' | *[!0-9]*) echo "swarm-node: SWARM_NODE_MTU='$mtu' is not a number" >&2; exit 2 ;; esac
echo "swarm-node: dockerd on $(hostname) (mtu $mtu) $*"
exec dockerd --host unix:///var/run/docker.sock --mtu "$mtu" "$@"
