#!/usr/bin/env bash
# Renders the README's pictures into assets/ with zrender itself (after tools/setup.sh).
#   tools/make-assets.sh
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
z=build/zrender
mkdir -p assets
$z bunny -o assets/bunny.png --width 900 --height 900
for alg in zbuffer scanline interval hierarchical octree; do
  $z bunny --alg "$alg" -o "assets/bunny-$alg.png" --width 360 --height 360
done
$z spot --shading texture -o assets/spot.png --width 900 --height 900
$z teapot --shading phong -o assets/teapot.png --width 900 --height 900
# Many views: an orbit in two rings, tiled.
$z spot --fit --shading texture --orbit 6 --orbit-elevations 0,40 \
  -o "/tmp/zrender-orbit-{view:02}.png" --contact-sheet assets/orbit.png --width 300 --height 300 -q
rm -f /tmp/zrender-orbit-*.png
# Polygons drawn natively by the scan-line algorithms, triangulated by the others.
$z shapes -o assets/shapes.png
$z crowd -o assets/crowd.png --width 900 --height 900
# The deep scene of many objects: what the street shows, and its face ids.
$z city --shading id -o assets/city-ids.png --width 640 --height 360
# The viewer's window on a virtual display: the frames on screen at each key press and the last.
xvfb-run -a $z view spot --width 480 --height 480 --keys 2,t,3,t,4,t,5,m --key-interval 30 \
  --frames 270 --contact-sheet assets/view.png >/dev/null
