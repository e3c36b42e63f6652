#!/usr/bin/env bash
# Renders a fixed set of outputs (every algorithm and shading mode, MSAA, depth and id images,
# a turntable, the README's pictures) and prints the SHA-256 of each, so that a change meant to
# leave behaviour alone can be checked byte for byte: run it before and after, and diff.
#   tools/output-digests.sh [ZRENDER]       (default build/zrender; after tools/setup.sh)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
z="$(realpath "${1:-$root/build/zrender}")"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
cd "$root"
n=0
render() {  # render NAME ARGS...: one run, its outputs named after NAME
  local name=$1
  shift
  "$z" "$@" -o "$out/$name.png" >/dev/null
}
for alg in zbuffer scanline interval hierarchical octree; do
  for shading in normal flat phong random texture id depth; do
    render "spot-$alg-$shading" spot --alg "$alg" --shading "$shading" --width 300 --height 300
  done
  render "bunny-$alg-msaa" bunny --alg "$alg" --msaa 4 --width 240 --height 240 \
    --depth "$out/bunny-$alg-depth.tif" --ids "$out/bunny-$alg-ids.png"
  render "teapot-$alg-nocull" teapot --alg "$alg" --shading phong --no-cull --width 320 \
    --height 200 --depth "$out/teapot-$alg-depth.png"
  render "crowd-$alg" crowd --alg "$alg" --width 300 --height 300
  render "shapes-$alg" shapes --alg "$alg"
done
"$z" spot --shading texture --turntable 6 -o "$out/turn-%02d.png" --width 120 --height 120 \
  --contact-sheet "$out/turn-sheet.png" >/dev/null
"$z" teapot --shading texture --turntable 3 -o "$out/turn.avi" --width 64 --height 64 >/dev/null
"$z" models/coincident/coincident.obj --alg octree --width 128 --height 128 -o "$out/coincident.png" >/dev/null
"$z" bench bunny spot --repeat 1 --width 200 --height 200 --json "$out/bench.json" >/dev/null
# The bench's JSON holds timings; keep what must not change.
python3 - "$out/bench.json" >"$out/bench-results.txt" <<'PY'
import json, sys
for cell in json.load(open(sys.argv[1]))["cells"]:
    print({k: v for k, v in sorted(cell.items()) if "_ms" not in k})
PY
rm "$out/bench.json"
cd "$out"
sha256sum $(ls | sort)
