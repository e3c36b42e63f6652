#!/bin/bash
# A 96-view orbit of the bunny rendered in PARTS parts at once by GNU parallel (Debian package
# `parallel`), each part a zrender process of one thread: docs/cluster.md.
#   tools/cluster/orbit-parallel.sh OUT [PARTS]
set -euo pipefail
out=${1:?usage: orbit-parallel.sh OUT [PARTS]}
parts=${2:-4}
size=${ORBIT_SIZE:-512}
parallel --will-cite --halt now,fail=1 \
  "${ZRENDER:-zrender}" bunny --fit --orbit 48 --orbit-elevations 0,30 --width "$size" \
  --height "$size" -o "$out/{scene}-{view:03}.png" --ids "$out/ids-{view:03}.png" \
  --cameras "$out/transforms.json" --threads 1 -q --shard {}/"$parts" \
  ::: $(seq 0 $((parts - 1)))
