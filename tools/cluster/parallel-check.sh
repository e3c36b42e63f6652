#!/bin/bash
# The GNU parallel recipe of docs/cluster.md, tested (ctest runs this): 4 parts at once write
# the same files, byte for byte, as the recipe in one part (one process, the whole orbit), and
# the recipe in the docs is the script's own text.
#   tools/cluster/parallel-check.sh ZRENDER_BINARY SOURCE_DIR
set -euo pipefail
zrender=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
source=$(cd "$2" && pwd)
if ! command -v parallel > /dev/null; then
  echo "parallel-check: GNU parallel is not installed (apt-get install parallel; tools/test.sh does)"
  exit 1
fi
"$source/tools/cluster/in-docs.sh" "$source/tools/cluster/orbit-parallel.sh" "$source/docs/cluster.md"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$source"  # the project's settings.json and models/
export ZRENDER=$zrender ORBIT_SIZE=128
tools/cluster/orbit-parallel.sh "$work/whole" 1
tools/cluster/orbit-parallel.sh "$work/parts" 4
count=$(find "$work/whole" -type f | wc -l)
if [ "$count" -ne 193 ]; then
  echo "parallel-check: the whole run wrote $count files, not 96 images, 96 id images and a manifest"
  exit 1
fi
"$source/tools/cluster/compare-runs.py" "$work/whole" "$work/parts"
echo "parallel-check: 4 parts by GNU parallel wrote the whole run's $count files, byte for byte"
