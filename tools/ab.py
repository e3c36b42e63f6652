#!/usr/bin/env python3
"""Compares zrender builds (or algorithms) by alternating their runs.

    tools/ab.py [--runs N] BINARY... -- ZRENDER-ARGS...

Runs `BINARY ZRENDER-ARGS --json` for each binary in turn, N rounds (default 7), so that a
burst of load on the machine falls on all of them alike, and prints per binary the medians over
the rounds of transform_ms, raster_ms, raster_ms_min and frame_ms (each run's own values are
already medians when ZRENDER-ARGS has --repeat). This is how the "alternated runs" of docs/performance.md
were measured, e.g.:

    cp build/zrender /tmp/zrender-before      # then change, rebuild, and:
    tools/ab.py /tmp/zrender-before build/zrender -- crowd --alg octree --repeat 9 -o /tmp/x.png

Give -o: without it every run writes SCENE.png into the current folder. Exit status 2 on bad
arguments or when a run fails or prints no JSON.
"""

import argparse
import json
import statistics
import subprocess
import sys

FIELDS = ("transform_ms", "visibility_ms", "shade_ms", "raster_ms", "raster_ms_min", "frame_ms")


def fail(message):
    print(f"ab.py: error: {message}", file=sys.stderr)
    sys.exit(2)


def run_once(binary, args):
    try:
        done = subprocess.run([binary, *args, "--json"], capture_output=True, text=True)
    except OSError as e:
        fail(f"{binary}: {e.strerror}")
    if done.returncode != 0:
        fail(f"{binary} exited with {done.returncode}: {done.stderr.strip()}")
    lines = [line for line in done.stdout.splitlines() if line.startswith("{")]
    if not lines:
        fail(f"{binary} printed no JSON object")
    return json.loads(lines[-1])


def main():
    argv = sys.argv[1:]
    if "--" not in argv:
        fail("expected BINARY... -- ZRENDER-ARGS...")
    split = argv.index("--")
    parser = argparse.ArgumentParser(prog="ab.py", description="alternated zrender runs")
    parser.add_argument("--runs", type=int, default=7, help="rounds (default 7)")
    parser.add_argument("binaries", nargs="+", help="zrender executables to compare")
    options = parser.parse_args(argv[:split])
    if options.runs < 1:
        fail("--runs must be at least 1")
    args = argv[split + 1:]
    if not args:
        fail("no zrender arguments after --")

    values = {b: {f: [] for f in FIELDS} for b in options.binaries}
    for _ in range(options.runs):
        for binary in options.binaries:
            result = run_once(binary, args)
            for field in FIELDS:
                if field in result:  # builds from before visibility_ms and shade_ms lack them
                    values[binary][field].append(result[field])
    width = max(len(b) for b in options.binaries)
    print(f"medians of {options.runs} alternated runs of: {' '.join(args)}")
    for binary in options.binaries:
        cells = "  ".join(f"{f} {statistics.median(values[binary][f]):8.3f}" for f in FIELDS
                          if values[binary][f])
        print(f"{binary:<{width}}  {cells}")


if __name__ == "__main__":
    main()
