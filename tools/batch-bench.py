#!/usr/bin/env python3
"""Measures zrender as a batch renderer (docs/cluster.md, Measured): many views in one process
against one process per view, the time a run spends beyond its frames, and its memory.

    tools/batch-bench.py [--rounds N] [--views V] [--size S] [--scene bunny] BINARY

Each round, alternated so that load on the machine falls on all alike:
  - one process renders V views (--orbit V) at 1 thread and at 2, with --json: its wall time,
    the sum of its views' frame_ms, and views per second;
  - V processes, one after another, each render one of the same views (--azimuth 360 k / V),
    at 1 thread and at 2;
Then, once: the peak RSS of an orbit of 10 views and of 1000 (the JSON's peak_rss_mb).

Prints the medians over the rounds: the ratio of V processes' wall time to one process's, and
the time beyond the frames, (wall - sum of frame_ms) / sum of frame_ms, at 1 thread; at 2
threads, where views render at once, (2 x wall - sum) / sum. Writing the PNGs is part of the
time beyond the frames. The images of both ways are compared byte for byte in the first round.
"""

import argparse
import filecmp
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time


def run(cmd):
    start = time.perf_counter()
    done = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.perf_counter() - start
    if done.returncode != 0:
        sys.exit(f"batch-bench: {' '.join(cmd)} failed: {done.stderr.strip()}")
    return wall, done.stdout


def frames_sum_ms(stdout):
    return sum(json.loads(line)["frame_ms"] for line in stdout.splitlines() if line.strip())


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("binary")
    p.add_argument("--rounds", type=int, default=5)
    p.add_argument("--views", type=int, default=100)
    p.add_argument("--size", type=int, default=512)
    p.add_argument("--scene", default="bunny")
    a = p.parse_args()
    work = tempfile.mkdtemp(prefix="zrender-batch-")
    common = [a.binary, a.scene, "--width", str(a.size), "--height", str(a.size), "-q"]
    results = {"one1": [], "one2": [], "many1": [], "many2": [], "over1": [], "over2": [],
               "vps1": [], "vps2": []}
    try:
        for r in range(a.rounds):
            for threads in (1, 2):
                out = os.path.join(work, f"one{threads}")
                wall, stdout = run(common + ["--orbit", str(a.views), "--threads", str(threads),
                                            "-o", out + "/{view:03}.png", "--json"])
                frames = frames_sum_ms(stdout) / 1000.0
                results[f"one{threads}"].append(wall)
                results[f"vps{threads}"].append(a.views / wall)
                results[f"over{threads}"].append((threads * wall - frames) / frames)
            many = os.path.join(work, "many")
            for threads in (1, 2):
                start = time.perf_counter()
                for k in range(a.views):
                    azimuth = repr(360.0 * k / a.views)
                    run(common + ["--azimuth", azimuth, "--threads", str(threads),
                                  "-o", f"{many}/{k:03d}.png"])
                results[f"many{threads}"].append(time.perf_counter() - start)
            if r == 0:
                _, mismatch, errors = filecmp.cmpfiles(
                    many, os.path.join(work, "one1"), [f"{k:03d}.png" for k in range(a.views)],
                    shallow=False)
                if mismatch or errors:
                    sys.exit(f"batch-bench: images differ between the two ways: {mismatch + errors}")
        rss = {}
        for views in (10, 1000):
            _, stdout = run(common + ["--orbit", str(views), "--threads", "1", "-o",
                                      os.path.join(work, f"rss{views}") + "/{view:04}.png",
                                      "--json"])
            rss[views] = json.loads(stdout.splitlines()[-1])["peak_rss_mb"]
    finally:
        shutil.rmtree(work)
    m = {k: statistics.median(v) for k, v in results.items()}
    print(f"{a.scene} {a.size}x{a.size}, {a.views} views, {a.rounds} rounds (medians)")
    print(f"  one process, 1 thread:   {m['one1']:.2f} s, {m['vps1']:.1f} views/s, "
          f"beyond the frames {100 * m['over1']:.0f}% of their sum")
    print(f"  one process, 2 threads:  {m['one2']:.2f} s, {m['vps2']:.1f} views/s, "
          f"beyond the frames {100 * m['over2']:.0f}% (2 x wall - sum) / sum")
    for threads in (1, 2):
        ratio = m[f"many{threads}"] / m[f"one{threads}"]
        print(f"  {a.views} processes, {threads} thread(s) each: {m[f'many{threads}']:.2f} s, "
              f"{ratio:.1f}x one process at {threads}")
    print(f"  peak RSS: 10 views {rss[10]:.1f} MB, 1000 views {rss[1000]:.1f} MB "
          f"({100 * (rss[1000] / rss[10] - 1):+.1f}%)")


if __name__ == "__main__":
    main()
