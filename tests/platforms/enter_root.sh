#!/usr/bin/env bash
# Runs a command as root in a Debian root folder, as if that folder were the machine's / :
#
#   enter_root.sh ROOT COMMAND [ARGUMENTS...]
#
# The mounts it needs (/proc, /dev with /dev/pts, /sys, a tmpfs on /tmp) are made in mount and
# process namespaces of its own (unshare), never in the machine's: they vanish with the command's
# last process, whether it ends, fails or is killed, and nothing is ever left mounted below ROOT
# for `rm -rf build` to walk into. --kill-child kills the command's processes when unshare dies,
# and the kernel kills the rest of the process namespace with its first process.
#
# The root becomes the namespaces' / with pivot_root rather than chroot: the kernel refuses a user
# namespace to a chrooted process, and bubblewrap, the grader's sandbox, makes one ("Failed to
# make / slave" or "No permissions to create a new namespace" inside a plain chroot). The /proc
# mounted here is a fresh one with nothing mounted over it, which a nested sandbox's own /proc
# requires. The network is the machine's (apt-get reaches the archive).
set -euo pipefail
if [ $# -lt 2 ]; then
    echo "usage: enter_root.sh ROOT COMMAND [ARGUMENTS...]" >&2
    exit 2
fi
root=$(realpath "$1")
shift
exec unshare --mount --propagation private --pid --fork --kill-child -- /bin/bash -euc '
root=$1
shift
mount --bind "$root" "$root"     # pivot_root needs the new root to be a mount point
mount -t proc proc "$root/proc"
mount --rbind /dev "$root/dev"
mount -t sysfs -o ro sysfs "$root/sys"
mount -t tmpfs -o mode=1777 tmpfs "$root/tmp"
# The machine name server; never written through a link in the root to a file of the machine.
cp -L --remove-destination /etc/resolv.conf "$root/etc/resolv.conf"
cd "$root"
mkdir -p .machine
pivot_root . .machine
cd /
umount -l /.machine               # from here on only the root is visible
rmdir /.machine
exec /usr/bin/env -i PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    HOME=/root LANG=C.UTF-8 TERM=dumb ${http_proxy:+http_proxy="$http_proxy"} \
    ${https_proxy:+https_proxy="$https_proxy"} ${no_proxy:+no_proxy="$no_proxy"} "$@"
' enter_root.sh "$root" "$@"
