#!/usr/bin/env python3
"""Compares zrender builds (or algorithms) by alternating their runs.

    tools/ab.py [--runs N] BINARY... -- ZRENDER-ARGS...

Runs `BINARY ZRENDER-ARGS --json` for each binary in turn, N rounds (default 7), every other
round in reverse order, so that a burst of load on the machine falls on all of them alike and no
binary always runs first, and prints per binary the medians over the rounds of transform_ms,
raster_ms, raster_ms_min and frame_ms (each run's own values are already medians when
ZRENDER-ARGS has --repeat), and, given several binaries, the median over the rounds of each
one's shade_ms and frame_ms divided by the first binary's in the same round: the figure to
judge a change by, as this machine's speed drifts between rounds. This is how the "alternated
runs" of docs/performance.md were measured, e.g.:

    cp build/zrender /tmp/zrender-before      # then change, rebuild, and:
    tools/ab.py /tmp/zrender-before build/zrender -- crowd --alg octree --repeat 9 -o /tmp/x.png

With --wall it times the whole command instead (start to exit, as a user waits for it; no
--json added; every other round runs the binaries in reverse order) and prints per binary the
median, least and most wall time of the rounds, and the median over the rounds of its time
divided by the first binary's in the same round, e.g. a turntable:

    tools/ab.py --wall --runs 9 /tmp/zrender-before build/zrender -- bunny --turntable 24 \
        --threads 2 -o /tmp/t/%03d.png

With --idle, each round waits (up to a minute) until the machine has been idle for half a
second (the other processes using under a tenth of the processors), so that a round does not
start while another job is building or testing; the rounds that could not wait are counted.

With --variant ARGS (repeated), each binary runs once per variant in every round, the
variant's arguments added to ZRENDER-ARGS, and each line also gives the median over the rounds
of the first line's frame_ms divided by its own: e.g. the speed-up of two threads over one,
frames rendered one after another as --repeat renders them (docs/performance.md, Two threads in
the bench and alone):

    tools/ab.py --variant "--threads 1" --variant "--threads 2" build/zrender -- bunny \
        --alg interval --repeat 9 -o /tmp/x.png

Give -o: without it every run writes SCENE.png into the current folder. Exit status 2 on bad
arguments or when a run fails or prints no JSON.
"""

import argparse
import json
import shlex
import statistics
import subprocess
import sys
import time

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


def busy_fraction(seconds=0.5):
    """The fraction of the processors' time that was not idle over `seconds`."""
    def ticks():
        with open("/proc/stat") as f:
            fields = [int(x) for x in f.readline().split()[1:]]
        return sum(fields), fields[3] + fields[4]  # idle and iowait
    total0, idle0 = ticks()
    time.sleep(seconds)
    total1, idle1 = ticks()
    return 1.0 - (idle1 - idle0) / max(total1 - total0, 1)


def wait_idle(limit=60.0):
    """Waits until the machine is idle; False if it was not within `limit` seconds."""
    start = time.perf_counter()
    while busy_fraction() > 0.1:
        if time.perf_counter() - start > limit:
            return False
    return True


def wall_once(binary, args):
    start = time.perf_counter()
    try:
        done = subprocess.run([binary, *args], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                              text=True)
    except OSError as e:
        fail(f"{binary}: {e.strerror}")
    seconds = time.perf_counter() - start
    if done.returncode != 0:
        fail(f"{binary} exited with {done.returncode}: {done.stderr.strip()}")
    return seconds


def main():
    argv = sys.argv[1:]
    if "--" not in argv:
        fail("expected BINARY... -- ZRENDER-ARGS...")
    split = argv.index("--")
    parser = argparse.ArgumentParser(prog="ab.py", description="alternated zrender runs")
    parser.add_argument("--runs", type=int, default=7, help="rounds (default 7)")
    parser.add_argument("--wall", action="store_true", help="time whole runs (seconds)")
    parser.add_argument("--idle", action="store_true", help="start each round on an idle machine")
    parser.add_argument("--variant", action="append", default=[],
                        help="arguments added to ZRENDER-ARGS: one run per variant and binary")
    parser.add_argument("binaries", nargs="+", help="zrender executables to compare")
    options = parser.parse_args(argv[:split])
    if options.runs < 1:
        fail("--runs must be at least 1")
    args = argv[split + 1:]
    if not args:
        fail("no zrender arguments after --")
    # What runs in each round, in order: a binary with a variant's arguments (label, argv).
    variants = [(v, shlex.split(v)) for v in options.variant] or [("", [])]
    labels = {(b, v): f"{b} {v}".strip() for b in options.binaries for v, _ in variants}
    variant_of = {label: v for (b, v), label in labels.items()}
    runs = [(labels[(b, v)], b, extra) for b in options.binaries for v, extra in variants]

    busy_rounds = 0
    if options.wall:
        seconds = {label: [] for label, _, _ in runs}
        for round_ in range(options.runs):
            if options.idle and not wait_idle():
                busy_rounds += 1
            # Every other round in reverse order, so that no binary always runs first.
            for label, binary, extra in runs if round_ % 2 == 0 else runs[::-1]:
                seconds[label].append(wall_once(binary, args + extra))
        width = max(len(label) for label in seconds)
        print(f"wall seconds of {options.runs} alternated runs of: {' '.join(args)}")
        if options.idle:
            print(f"rounds started on a busy machine (waited a minute): {busy_rounds}")
        first = seconds[runs[0][0]]
        for label, s in seconds.items():
            # The ratio within each round, whose runs are back to back: steadier than the ratio
            # of the medians when the machine's load drifts between rounds.
            ratio = statistics.median(b / a for a, b in zip(first, s))
            print(f"{label:<{width}}  median {statistics.median(s):7.3f}  min {min(s):7.3f}  "
                  f"max {max(s):7.3f}  median ratio to the first {ratio:6.3f}")
        return

    values = {label: {f: [] for f in FIELDS} for label, _, _ in runs}
    for round_ in range(options.runs):
        if options.idle and not wait_idle():
            busy_rounds += 1
        # Every other round in reverse order, as --wall does.
        for label, binary, extra in runs if round_ % 2 == 0 else runs[::-1]:
            result = run_once(binary, args + extra)
            for field in FIELDS:
                if field in result:  # builds from before visibility_ms and shade_ms lack them
                    values[label][field].append(result[field])
    width = max(len(label) for label in values)
    print(f"medians of {options.runs} alternated runs of: {' '.join(args)}")
    if options.idle:
        print(f"rounds started on a busy machine (waited a minute): {busy_rounds}")
    first = values[runs[0][0]]["frame_ms"]
    for label, v in values.items():
        cells = "  ".join(f"{f} {statistics.median(v[f]):8.3f}" for f in FIELDS if v[f])
        if options.variant:
            # Within each round, as --wall does.
            ratio = statistics.median(a / b for a, b in zip(first, v["frame_ms"]))
            cells += f"  first/this {ratio:6.3f}"
        if len(options.binaries) > 1:
            # Against the first binary with the same variant, within each round: the machine's
            # speed drifts between rounds, and a ratio of medians would carry the drift.
            ref = values[labels[(options.binaries[0], variant_of[label])]]
            for f in ("shade_ms", "frame_ms"):
                if v[f] and ref[f]:
                    r = statistics.median(b / a for a, b in zip(ref[f], v[f]))
                    cells += f"  {f}/first's {r:6.3f}"
        print(f"{label:<{width}}  {cells}")


if __name__ == "__main__":
    main()
