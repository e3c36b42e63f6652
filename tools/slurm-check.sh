#!/bin/bash
# The Slurm job array recipe of docs/cluster.md, tested (CI runs this as root): a one-node Slurm
# started on this machine (tools/slurm-local.sh) runs tools/cluster/orbit.sbatch as an array of
# 4 tasks, whose files must equal, byte for byte, those of the recipe run in one part outside
# Slurm; everything started is stopped. If Slurm cannot run here, this says why and fails.
#   tools/slurm-check.sh [ZRENDER_BINARY]     (default: build/zrender)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
binary=${1:-$root/build/zrender}
zrender=$(cd "$(dirname "$binary")" && pwd)/$(basename "$binary")
"$root/tools/cluster/in-docs.sh" "$root/tools/cluster/orbit.sbatch" "$root/docs/cluster.md"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
chmod 755 "$work"  # the tasks run as root, but keep the folder readable for a look afterwards
cd "$root"  # the project's settings.json and models/
export ZRENDER=$zrender ORBIT_SIZE=128
start=$(date +%s)
SLURM_ARRAY_TASK_ID=0 SLURM_ARRAY_TASK_COUNT=1 bash tools/cluster/orbit.sbatch "$work/whole" \
  > "$work/whole.log" 2>&1 || { cat "$work/whole.log"; exit 1; }
mkdir -p "$work/logs"
if ! tools/slurm-local.sh run -- sbatch --wait --array=0-3 --chdir="$root" \
  --output="$work/logs/task-%a.log" tools/cluster/orbit.sbatch "$work/parts"; then
  echo "slurm-check: the job array failed; its tasks' logs:"
  tail -n 5 "$work"/logs/*.log 2>/dev/null || true
  exit 1
fi
count=$(find "$work/whole" -type f | wc -l)
if [ "$count" -ne 193 ]; then
  echo "slurm-check: the whole run wrote $count files, not 96 images, 96 id images and a manifest"
  exit 1
fi
if ! "$root/tools/cluster/compare-runs.py" "$work/whole" "$work/parts"; then
  keep=$(mktemp -d /tmp/slurm-check-kept.XXXXXX)
  cp -r "$work/whole" "$work/parts" "$work/logs" "$keep/"
  echo "slurm-check: the files differ; both runs kept in $keep"
  exit 1
fi
tasks=$(find "$work/logs" -name "task-*.log" | wc -l)
echo "slurm-check: $tasks array tasks wrote the whole run's $count files, byte for byte" \
  "($(($(date +%s) - start)) s)"
