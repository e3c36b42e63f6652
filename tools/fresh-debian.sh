#!/usr/bin/env bash
# Checks the README's two commands on a fresh Debian 12: debootstraps a minimal bookworm
# (--variant=minbase: no compiler, no git, no sudo) into a folder, puts a clone of HEAD at
# /work/main inside it with ../shared bind-mounted read-only beside it, and runs, as root:
#   tools/setup.sh && build/zrender bunny        then   tools/test.sh
# and then both once more, to show they are safe to run twice. Needs root, network access to
# the Debian mirror this machine's apt uses (read from its sources, which the new system gets
# too) and about 2 GB of disk; takes a few minutes. Not part of CI (CI itself starts
# from a clean checkout and lets tools/test.sh install what is missing).
#   tools/fresh-debian.sh [FOLDER]      default /tmp/zrender-fresh-debian (removed first)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
shared=$(cd "$root/../shared" && pwd)
dest=${1:-/tmp/zrender-fresh-debian}

[ "$(id -u)" -eq 0 ] || { echo "fresh-debian: error: must run as root (debootstrap, chroot)" >&2; exit 2; }
command -v debootstrap >/dev/null || { apt-get update -qq && apt-get install -y -qq debootstrap >/dev/null; }

mounts=()
cleanup() {
  local i
  for ((i = ${#mounts[@]} - 1; i >= 0; i--)); do umount "${mounts[i]}" 2>/dev/null || true; done
}
trap cleanup EXIT
rm -rf "$dest"
mirror=$("$root/tools/debian-mirror.sh")
[ -n "$mirror" ] || { echo "fresh-debian: error: no bookworm source in /etc/apt" >&2; exit 2; }
echo "fresh-debian: mirror $mirror (from this machine's apt sources)"
debootstrap --variant=minbase bookworm "$dest" "$mirror" >/dev/null
"$root/tools/debian-mirror.sh" --copy-sources "$dest"
cp /etc/resolv.conf "$dest/etc/resolv.conf"
mkdir -p "$dest/work/shared"
mount -t proc proc "$dest/proc" && mounts+=("$dest/proc")
mount --bind /dev "$dest/dev" && mounts+=("$dest/dev")
mount -t devpts devpts "$dest/dev/pts" && mounts+=("$dest/dev/pts")
mount -t tmpfs tmpfs "$dest/tmp" && mounts+=("$dest/tmp")
mount --bind "$shared" "$dest/work/shared" && mounts+=("$dest/work/shared")
mount -o remount,bind,ro "$dest/work/shared"
git clone -q "$root" "$dest/work/main"

for round in 1 2; do
  echo "fresh-debian: round $round: tools/setup.sh && build/zrender bunny"
  chroot "$dest" bash -c 'cd /work/main && tools/setup.sh >/dev/null && build/zrender bunny'
  [ -s "$dest/work/main/bunny.png" ] || { echo "fresh-debian: error: no bunny.png" >&2; exit 1; }
  echo "fresh-debian: round $round: tools/test.sh"
  chroot "$dest" bash -c 'cd /work/main && tools/test.sh' | tail -3
done
echo "fresh-debian: both commands passed twice in $dest ($((SECONDS / 60)) min $((SECONDS % 60)) s)"
