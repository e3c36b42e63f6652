#!/usr/bin/python3
"""Runs the CI recipes of docs/ci.md as CI would, in order, so the page cannot drift.

    tools/ci/recipe-check.py ZRENDER_BUILD_DIR PROJECT_DIR

For each recipe (GitHub Actions, GitLab CI): a run of main with an empty cache (it must pass
and fill the cache), a pull request compared with it (it must compare; the same build may
still be called slower, so exit 3 is allowed there), and a pull request against a baseline five
times faster than this build (it must fail with exit status 3, its files all written). Steps
that set up the machine (tools/setup.sh) are skipped: the build is given. Actions that CI
provides (checkout, cache, upload) are played by this script.
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

import yaml

build, root = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
text = open(os.path.join(root, "docs", "ci.md")).read()
blocks = re.findall(r"```yaml\n(.*?)```", text, re.S)
assert len(blocks) == 2, "docs/ci.md: expected two yaml blocks, GitHub's and GitLab's"
github, gitlab = yaml.safe_load(blocks[0]), yaml.safe_load(blocks[1])
files = ["bench.json", "bench.svg", "bench.xml", "bench.csv"]


def fail(message):
    print("recipe-check: " + message, file=sys.stderr)
    sys.exit(1)


made = []  # the folders made, removed at the end


def workdir():
    """A fresh checkout: the project's settings and models, and the build."""
    d = tempfile.mkdtemp(prefix="zrender-recipe.")
    made.append(d)
    for name in ["settings.json", "models"]:
        os.symlink(os.path.join(root, name), os.path.join(d, name))
    os.symlink(build, os.path.join(d, "build"))
    return d


def bash(script, cwd, env):
    # The tables go nowhere; the one-line summaries and any error stay on stderr.
    return subprocess.run(["bash", "-eo", "pipefail", "-c", script], cwd=cwd,
                          env={**os.environ, **env}, stdout=subprocess.DEVNULL).returncode


def slow_baseline(cache):
    """The cached results with every time x 0.2: this build is five times slower than it."""
    path = os.path.join(cache, "bench-main.json")
    run = json.load(open(path))
    for cell in run["cells"]:
        for timing in ["frame_ms", "transform_ms", "visibility_ms", "shade_ms", "raster_ms"]:
            cell[timing]["samples"] = [v * 0.2 for v in cell[timing]["samples"]]
    json.dump(run, open(path, "w"))


def github_run(cache, ref):
    """One run of the workflow's steps; returns (status of the job, work folder)."""
    steps = github["jobs"]["bench"]["steps"]
    d = workdir()
    summary, output = os.path.join(d, "summary.md"), os.path.join(d, "output.txt")
    open(output, "w").close()
    env = {"GITHUB_STEP_SUMMARY": summary, "GITHUB_OUTPUT": output}
    outputs, failed = {}, 0
    for step in steps:
        condition = step.get("if", "")
        if condition == "github.ref == 'refs/heads/main'" and ref != "refs/heads/main":
            continue
        m = re.fullmatch(r"steps\.(\w+)\.outputs\.(\w+) == '(\w+)'", condition)
        if m and outputs.get(m.group(1), {}).get(m.group(2)) != m.group(3):
            continue
        if condition not in ("", "always()", "github.ref == 'refs/heads/main'") and not m:
            fail("unknown condition " + condition)
        if failed and condition != "always()":
            continue
        uses = step.get("uses", "")
        if uses.startswith("actions/checkout"):
            continue
        if uses.startswith("actions/cache/restore"):
            if os.path.exists(os.path.join(cache, "bench-main.json")):
                shutil.copy(os.path.join(cache, "bench-main.json"), d)
            continue
        if uses.startswith("actions/cache/save"):
            shutil.copy(os.path.join(d, "bench-main.json"), cache)
            continue
        if uses.startswith("actions/upload-artifact"):
            for f in step["with"]["path"].split():
                if not os.path.exists(os.path.join(d, f)):
                    fail(f"GitHub: the artifact {f} was not written")
            continue
        if uses:
            fail("unknown action " + uses)
        script = step["run"]
        if script.strip() == "tools/setup.sh":
            continue
        status = bash(script, d, env)
        if "id" in step:
            outputs[step["id"]] = dict(
                line.split("=", 1) for line in open(output).read().split() if "=" in line)
        if status:
            failed = status
    return failed, d


def gitlab_run(cache, branch):
    job = gitlab["bench"]
    d = workdir()
    cached = os.path.join(cache, "bench-main.json")
    if os.path.exists(cached):
        shutil.copy(cached, d)
    env = {"CI_COMMIT_BRANCH": branch, "CI_DEFAULT_BRANCH": "main"}
    status = 0
    for script in job["script"]:
        if script.strip() == "tools/setup.sh":
            continue
        status = bash(script, d, env)
        if status:
            break
    for f in job["artifacts"]["paths"]:
        if not os.path.exists(os.path.join(d, f)):
            fail(f"GitLab: the artifact {f} was not written")
    if status == 0 and os.path.exists(os.path.join(d, "bench-main.json")):
        shutil.copy(os.path.join(d, "bench-main.json"), cache)  # the cache, saved on success
    return status, d


def check(name, run, main, pr, summary):
    cache = tempfile.mkdtemp(prefix="zrender-recipe-cache.")
    made.append(cache)
    status, d = run(cache, main)
    if status or not os.path.exists(os.path.join(cache, "bench-main.json")):
        fail(f"{name}: main's run failed ({status}) or did not fill the cache")
    status, d = run(cache, pr)
    compared = open(os.path.join(d, summary)).read()
    if status not in (0, 3) or "Compared with bench-main.json" not in compared:
        fail(f"{name}: the pull request's run exited {status} or did not compare")
    slow_baseline(cache)
    status, d = run(cache, pr)
    junit = open(os.path.join(d, "bench.xml")).read()
    if status != 3 or 'type="slowdown"' not in junit:
        fail(f"{name}: a pull request five times slower exited {status}, not 3")
    print(f"recipe-check: {name}: main, a pull request, and a slower one as documented")


try:
    check("GitHub Actions", github_run, "refs/heads/main", "refs/pull/1/merge", "summary.md")
    check("GitLab CI", gitlab_run, "main", "feature", "bench.md")
finally:
    for folder in made:
        shutil.rmtree(folder, ignore_errors=True)
