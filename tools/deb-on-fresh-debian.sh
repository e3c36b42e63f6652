#!/usr/bin/env bash
# Checks that the .deb installs and runs on a fresh Debian 12: debootstraps a minimal bookworm
# (--variant=minbase, from this machine's mirror: tools/debian-mirror.sh), installs the package
# with apt (which brings the dependencies it declares, nothing else), and renders a model file
# to .png, .jpg, a .tif depth image and an .mp4, and an OFF file through the assimp plugin, in a
# folder of its own. Needs root, network
# access to the mirror and about 1.5 GB of disk; not part of CI.
#   tools/deb-on-fresh-debian.sh [DEB [FOLDER]]   default: the newest build/zrender_*.deb,
#                                                 /tmp/zrender-deb-debian (removed first)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
deb=${1:-$(ls -t "$root"/build/zrender_*.deb 2>/dev/null | head -1)}
dest=${2:-/tmp/zrender-deb-debian}
[ -f "$deb" ] || { echo "deb-on-fresh-debian: error: no .deb (cd build && cpack -G DEB)" >&2; exit 2; }
[ "$(id -u)" -eq 0 ] || { echo "deb-on-fresh-debian: error: must run as root" >&2; exit 2; }
command -v debootstrap >/dev/null || { apt-get update -qq && apt-get install -y -qq debootstrap >/dev/null; }

mounts=()
cleanup() {
  local i
  for ((i = ${#mounts[@]} - 1; i >= 0; i--)); do umount "${mounts[i]}" 2>/dev/null || true; done
}
trap cleanup EXIT
rm -rf "$dest"
debootstrap --variant=minbase bookworm "$dest" "$("$root/tools/debian-mirror.sh")" >/dev/null
"$root/tools/debian-mirror.sh" --copy-sources "$dest"
cp /etc/resolv.conf "$dest/etc/resolv.conf"
mount -t proc proc "$dest/proc" && mounts+=("$dest/proc")
mount --bind /dev "$dest/dev" && mounts+=("$dest/dev")
mount -t tmpfs tmpfs "$dest/tmp" && mounts+=("$dest/tmp")
cp "$deb" "$dest/tmp/zrender.deb"
mkdir -p "$dest/root/elsewhere"
cp "$root/models/shapes/shapes.obj" "$dest/root/elsewhere/"
chroot "$dest" bash -c 'apt-get update -qq && DEBIAN_FRONTEND=noninteractive \
  apt-get install -y -qq --no-install-recommends /tmp/zrender.deb >/dev/null'
chroot "$dest" bash -c 'cd /root/elsewhere && zrender --version &&
  zrender shapes.obj -o a.png && zrender shapes.obj -o a.jpg --depth d.tif &&
  zrender shapes.obj --turntable 4 -o v.mp4 &&
  printf "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n" >t.off && zrender t.off -o off.png &&
  ls -l a.png a.jpg d.tif v.mp4 off.png'
echo "deb-on-fresh-debian: $(basename "$deb") installed and ran on a fresh bookworm in $dest ($((SECONDS / 60)) min $((SECONDS % 60)) s)"
