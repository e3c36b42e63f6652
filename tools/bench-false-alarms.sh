#!/usr/bin/env bash
# How often `zrender bench --baseline` calls the same build slower on this machine: PAIRS pairs of
# runs of the bunny at 256x256 (default 20), the second of each compared with the first. Prints
# the cells called "slower" and the pairs that --max-slowdown 10, 25 and 50 would fail (both
# 95% intervals, of wall time and in probe units, above the limit; docs/bench.md, False alarms).
# A measurement, not a test: it exits 0 unless a run fails for another reason.
#   tools/bench-false-alarms.sh ZRENDER [PAIRS]
set -euo pipefail
zrender=$(realpath "$1")
pairs=${2:-20}
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/zrender-false-alarms.XXXXXX")
trap 'rm -rf "$work"' EXIT
cd "$root"
for ((i = 1; i <= pairs; i++)); do
  "$zrender" bench bunny --width 256 --height 256 --json "$work/a.json" >/dev/null 2>&1
  status=0
  "$zrender" bench bunny --width 256 --height 256 --baseline "$work/a.json" --max-slowdown 10 \
    --csv "$work/b$i.csv" >/dev/null 2>&1 || status=$?
  [[ $status -eq 0 || $status -eq 3 ]] || { echo "pair $i: zrender exited $status" >&2; exit 1; }
done
python3 - "$work" "$pairs" <<'PY'
import csv, glob, sys
work, pairs = sys.argv[1], int(sys.argv[2])
limits = [1.10, 1.25, 1.50]
slower = cells = 0
failing = [0] * len(limits)
wallOnly = [0] * len(limits)  # what wall time alone would fail, without the probe
for path in sorted(glob.glob(work + "/b*.csv")):
    rows = list(csv.DictReader(open(path, newline="")))
    cells += len(rows)
    slower += sum(r["verdict"] == "slower" for r in rows)
    for i, limit in enumerate(limits):
        failing[i] += any(float(r["ratio_low"]) > limit and float(r["probed_low"]) > limit
                          for r in rows)
        wallOnly[i] += any(float(r["ratio_low"]) > limit for r in rows)
print(f"bench false alarms: {pairs} pairs of the same build, {cells} cells: "
      f"{slower} cells called slower; pairs failing at --max-slowdown 10: {failing[0]}, "
      f"25: {failing[1]}, 50: {failing[2]} (on wall time alone: {wallOnly[0]}, {wallOnly[1]}, "
      f"{wallOnly[2]})")
PY
