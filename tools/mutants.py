#!/usr/bin/env python3
"""Mutation check of the test suite: each mutant below changes one rule of the renderer the way
a plausible bug would; the suite must fail on it ("killed"). A mutant that survives shows a
rule no test pins down, unless it is marked equivalent (it cannot change any output; the
reason is given).

Works in a git worktree of HEAD in a temporary folder (the checkout is never touched), set up
by tools/setup.sh (reference models linked, Release build), and ctest for each mutant.
About a minute per mutant on 2 cores. Not part of CI.

    tools/mutants.py               every mutant
    tools/mutants.py M4 M12        the mutants named

Exit status 1 when a mutant that is not equivalent survives.
"""
import dataclasses
import os
import shutil
import subprocess
import sys
import tempfile
from typing import Optional


@dataclasses.dataclass
class Mutant:
    name: str       # "M4 what it breaks"
    path: str       # file, relative to the project
    old: str        # text that must occur exactly once
    new: str
    equivalent: Optional[str] = None  # why it cannot change any output


MUTANTS = [
    Mutant("M1 top-left: horizontal top edge rule", "include/zrender/raster/RasterRules.hpp",
           "((dy == 0) & (dx <= 0))",
           "((dy == 0) & (dx < 0))",
           equivalent='dy == 0 and dx == 0 is a zero-length edge, which no real triangle has'),
    Mutant("M2 top-left: left edge rule", "include/zrender/raster/RasterRules.hpp",
           "int64_t((dy > 0) |",
           "int64_t((dy >= 0) |"),
    Mutant("M3 pyramid rejects ties", "src/raster/DepthPyramid.cpp",
           "if (key > maxOver(level",
           "if (key >= maxOver(level"),
    Mutant("M4 octree box depth margin upward", "src/visibility/OctreeNodeTest.cpp",
           "z0 - 1e-6 * (1.0 + std::abs(z0))",
           "z0 + 1e-6 * (1.0 + std::abs(z0))"),
    Mutant("M5 octree rejects boxes crossing near", "src/visibility/OctreeNodeTest.cpp",
           "w0 > 0.0)) return false;",
           "w0 > -1e300)) return false;",
           equivalent='the inFront test above already requires w > 0 at every corner'),
    Mutant("M6 octree box less slack", "src/visibility/OctreeNodeTest.cpp",
           "std::floor(x0 - 1.5)",
           "std::floor(x0 + 0.5)"),
    Mutant("M7 cull front faces", "include/zrender/transform/FaceAssembler.hpp",
           "if (cull_ && area > 0) {",
           "if (cull_ && area < 0) {"),
    Mutant("M8 tie-break by larger id", "include/zrender/raster/RasterRules.hpp",
           "return (DepthKey(floatBits(depth)) << 32) | faceId;",
           "return (DepthKey(floatBits(depth)) << 32) | (0xffffffffu - faceId);"),
    Mutant("M9 sparse clear scan inverted", "src/raster/DepthPyramid.cpp",
           "if (row[x] == kClearKey) {",
           "if (row[x] != kClearKey) {"),
    Mutant("M10 parents never lowered (conservative)", "src/raster/DepthPyramid.cpp",
           "    if (node == m) return;\n    node = m;",
           "    if (node >= m) return;\n    node = m;"),
    Mutant("M11 parent ignores right child", "src/raster/DepthPyramid.cpp",
           "const int cx1 = std::min(cx0 + 1, cw - 1)",
           "const int cx1 = cx0"),
    Mutant("M12 tile rescan result not propagated", "src/raster/DepthPyramid.cpp",
           "  levels_[0][t] = best;\n  propagate(tx, ty);",
           "  levels_[0][t] = best;"),
    Mutant("M13 texture v not flipped", "src/shading/SurfaceKernelAvx2.cpp",
           "_mm256_fmadd_ps(vv, splat(-float(f.textureHeight)), splat(float(f.textureHeight) - 0.5f));",
           "_mm256_fmadd_ps(vv, splat(float(f.textureHeight)), splat(-0.5f));"),
    Mutant("M14 texel centres off by half", "src/shading/SurfaceKernelAvx2.cpp",
           "const F tx = _mm256_fmadd_ps(uu, splat(float(f.textureWidth)), splat(-0.5f));",
           "const F tx = _mm256_mul_ps(uu, splat(float(f.textureWidth)));"),
    Mutant("M15 triangle test key by id+1", "include/zrender/visibility/HzbRasterizer.hpp",
           "makeDepthKey(nearestDepth, faceId)))",
           "makeDepthKey(nearestDepth, faceId + 1)))",
           equivalent='a larger key ties only with samples of the same face, which it cannot change'),
    Mutant("M16 specular exponent 32", "src/shading/SurfaceKernelAvx2.cpp",
           "for (int k = 0; k < 6; ++k) specular = _mm256_mul_ps(specular, specular);",
           "for (int k = 0; k < 5; ++k) specular = _mm256_mul_ps(specular, specular);"),
    Mutant("M17 bilinear weights swapped", "src/shading/SurfaceKernelAvx2.cpp",
           "const F top = _mm256_fmadd_ps(_mm256_sub_ps(cb, ca), fx, ca);",
           "const F top = _mm256_fmadd_ps(_mm256_sub_ps(ca, cb), fx, cb);"),
    Mutant("M18 interval no error margin", "src/visibility/IntervalAlgorithm.cpp",
           "const double threshold = 2.0 * (winBound + bound(c));",
           "const double threshold = 0.0 * (winBound + bound(c));"),
    Mutant("M19 interval run past crossing", "src/visibility/IntervalAlgorithm.cpp",
           "std::floor(crossing) - 1.0;",
           "std::floor(crossing) + 1.0;"),
    Mutant("M20 interval same plane larger id", "src/visibility/IntervalAlgorithm.cpp",
           "samePlane(*c.plane, *win.plane) && win.id < c.id",
           "samePlane(*c.plane, *win.plane) && win.id > c.id",
           equivalent='the winner has the least key at the left end, so with the same plane it has the smaller id; the guard only saves work'),
    Mutant("M21 ambient 0.2", "src/shading/SurfaceKernelAvx2.cpp",
           "const F light = _mm256_fmadd_ps(splat(0.9f), diffuse, splat(0.1f));",
           "const F light = _mm256_fmadd_ps(splat(0.8f), diffuse, splat(0.2f));"),
    Mutant("M22 texture clamps instead of wrapping", "src/shading/SurfaceKernelAvx2.cpp",
           "const F uu = _mm256_max_ps(_mm256_sub_ps(u, _mm256_floor_ps(u)), zero);",
           "const F uu = _mm256_min_ps(_mm256_max_ps(u, zero), splat(1.0f));"),
    Mutant("M23 msaa mean truncated", "src/shading/Shader.cpp",
           "uchar((sum[i] + 2) / 4)",
           "uchar(sum[i] / 4)"),
    Mutant("M24 near clip plane moved", "src/transform/Clipping.cpp",
           "[](const Vec4& p) { return p[2] + p[3]; }",
           "[](const Vec4& p) { return p[2] + 0.99 * p[3]; }"),
    Mutant("M25 turntable turns the other way", "src/scene/Camera.cpp",
           "rotation(degrees, camera.up)",
           "rotation(-degrees, camera.up)"),
    Mutant("M26 fit margin 10%", "src/scene/Transforms.cpp",
           "constexpr double kFitMargin = 1.05;",
           "constexpr double kFitMargin = 1.10;"),
    Mutant("M27 fit uses the larger half-angle", "src/scene/Transforms.cpp",
           "std::sin(std::min(halfY, halfX))",
           "std::sin(std::max(halfY, halfX))"),
    Mutant("M28 grid y offset not centred", "src/scene/Scene.cpp",
           "(j - (g.count[1] - 1) / 2.0) * g.spacing[1]",
           "(j - (g.count[1] - 1) / 2) * g.spacing[1]"),
    Mutant("M29 16-bit depth truncated", "src/io/images/ImageOutput.cpp",
           "uint16_t(std::lround(double(d) * 65535.0))",
           "uint16_t(double(d) * 65535.0)"),
    Mutant("M30 aspect setting ignored", "src/scene/Camera.cpp",
           "cam.aspect = s.aspect > 0.0 ? s.aspect :",
           "cam.aspect = s.aspect > 1e300 ? s.aspect :"),
    Mutant("M31 default width 1000", "include/zrender/scene/SceneSettings.hpp",
           "int width = 1024; ",
           "int width = 1000; "),
    Mutant("M32 negative index off by one", "src/io/obj/ObjLoader.cpp",
           "if (index < 0) return static_cast<int32_t>(static_cast<int64_t>(count) + index);",
           "if (index < 0) return static_cast<int32_t>(static_cast<int64_t>(count) + index + 1);"),
    Mutant("M33 ear test ignores points on the edge", "src/transform/Triangulation.cpp",
           "if (insideOrOn(a, pts[ic], c, pts[q])) ear = false;",
           "if (false) ear = false;"),
    Mutant("M34 a coincident copy hides the smaller id", "src/visibility/CoincidentTriangles.cpp",
           "if (e.id < t.id) return true;",
           "if (e.id > t.id) return true;"),
    Mutant("M35 fit replaces a --near the user gave", "src/scene/Camera.cpp",
           "if (!keep.near) cam.near = depths.near;",
           "cam.near = depths.near;"),
]


def run(args, cwd):
    return subprocess.run(args, cwd=cwd, text=True, capture_output=True)


def failingTests(ctestOutput):
    """Names listed under ctest's "The following tests FAILED:" ("  5 - Name (Failed)")."""
    lines = [line.strip() for line in ctestOutput.splitlines()]
    heading = "The following tests FAILED:"
    if heading not in lines:
        return []
    rest = lines[lines.index(heading) + 1:]
    return [line.split(" - ", 1)[1].rsplit(" (", 1)[0] for line in rest if " - " in line]


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    wanted = set(sys.argv[1:])
    chosen = [m for m in MUTANTS if not wanted or m.name.split()[0] in wanted]
    work = tempfile.mkdtemp(prefix="zrender-mutants-")
    tree = os.path.join(work, "main")
    run(["git", "worktree", "add", "--detach", tree, "HEAD"], root)
    try:
        # ../shared beside the worktree, as beside the checkout, so that tools/setup.sh links
        # the reference models and makes the Release build exactly as the README's commands do.
        os.symlink(os.path.join(os.path.dirname(root), "shared"), os.path.join(work, "shared"))
        build = os.path.join(tree, "build")
        if run([os.path.join(tree, "tools", "setup.sh")], tree).returncode:
            sys.exit("mutants: the unchanged project does not build")
        if run(["ctest", "-j2"], build).returncode:
            sys.exit("mutants: the unchanged project fails its tests")
        survivors = 0
        for m in chosen:
            path = os.path.join(tree, m.path)
            with open(path) as f:
                text = f.read()
            if text.count(m.old) != 1:
                print(f"{m.name}: the text to change occurs {text.count(m.old)} times", flush=True)
                survivors += 1
                continue
            with open(path, "w") as f:
                f.write(text.replace(m.old, m.new))
            try:
                if run(["ninja", "-C", build], tree).returncode:
                    print(f"{m.name}: does not compile", flush=True)
                    survivors += 1  # a broken mutant checks nothing
                    continue
                result = run(["ctest", "-j2", "--timeout", "300"], build)
                failed = failingTests(result.stdout)
                if result.returncode:
                    shown = ", ".join(failed[:3]) + (", ..." if len(failed) > 3 else "")
                    tests = "test" if len(failed) == 1 else "tests"
                    print(f"{m.name}: killed by {len(failed)} {tests} ({shown})", flush=True)
                elif m.equivalent:
                    print(f"{m.name}: survived, equivalent: {m.equivalent}", flush=True)
                else:
                    print(f"{m.name}: SURVIVED", flush=True)
                    survivors += 1
            finally:
                with open(path, "w") as f:
                    f.write(text)
        print(f"mutants: {len(chosen)} run, {survivors} not killed and not equivalent")
        sys.exit(1 if survivors else 0)
    finally:
        run(["git", "worktree", "remove", "--force", tree], root)
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
