#!/usr/bin/python3
"""zrender's frame time beside Mesa's llvmpipe (llvmpipe-ref) on the same frames.

For each scene and shading mode and each thread count, runs zrender and llvmpipe-ref in turn,
--rounds times, and prints the medians of the rounds as a markdown table (--json: one object).
"Beyond flat" is a mode's frame minus flat's frame, same program, scene and threads: what the
shading costs on top of visibility. The ratio and beyond flat are medians of each round's own
values (a scene's modes run one after another in a round).

--images renders both at 1800x1800 (--image-size N: NxN) and counts the pixels that differ by
more than 1/255 in a channel, over the whole image and away from edges (pixels whose 3x3
neighbourhood in zrender's face-id image holds one id only, background counting as an id).
--check: exit status 1, after the tables, when a pixel away from edges differs (ctest's
Llvmpipe.ImagesAgree runs --images-only --image-size 900 --check).

Needs only the standard library: images are exchanged as binary PPM, which both programs write.
Run with /usr/bin/python3 from anywhere: tools/llvmpipe/compare.py --images --rounds 3.
"""

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CASES = [("bunny", "flat"), ("bunny", "phong"), ("spot", "flat"), ("spot", "texture"),
         ("spot", "phong")]


def find_program(given, candidates):
    for path in ([given] if given else candidates):
        path = os.path.join(ROOT, path)
        if os.path.isfile(path) and os.access(path, os.X_OK):
            return path
    sys.exit("compare.py: not found: " + (given or " or ".join(candidates)))


def run(command, env=None):
    result = subprocess.run(command, cwd=ROOT, env=env, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit("compare.py: failed (%d): %s\n%s" % (result.returncode, " ".join(command),
                                                     result.stderr))
    return result


def last_json(stdout):
    lines = [line for line in stdout.splitlines() if line.startswith("{")]
    return json.loads(lines[-1])


class Scene:
    """A scene of settings.json: its model, texture and camera manifest."""

    def __init__(self, name, args, folder):
        with open(os.path.join(ROOT, "settings.json")) as f:
            settings = json.load(f)[name]
        self.name = name
        self.model = os.path.join(ROOT, settings["path"])
        self.texture = os.path.join(ROOT, settings["texture"]) if "texture" in settings else None
        self.args = args
        self.cameras = os.path.join(folder, name + "-cameras.json")
        self.image_cameras = os.path.join(folder, name + "-cameras-%d.json" % args.image_size)
        run([args.zrender, name, "--cameras", self.cameras, "--cameras-only"])
        size = ["--width", str(args.image_size), "--height", str(args.image_size)]
        run([args.zrender, name, "--cameras", self.image_cameras, "--cameras-only"] + size)

    def zrender(self, mode, threads, repeat, output, extra=()):
        command = [self.args.zrender, self.name, "--shading", mode, "--threads", str(threads),
                   "--repeat", str(repeat), "--json", "-q", "-o", output] + list(extra)
        if self.args.alg:
            command += ["--alg", self.args.alg]
        return last_json(run(command).stdout)

    def reference(self, mode, threads, repeat, output=None, cameras=None):
        command = [self.args.ref, self.model, cameras or self.cameras, "--mode", mode,
                   "--repeat", str(repeat)]
        if mode == "texture" and self.texture:
            command += ["--texture", self.texture]
        if output:
            command += ["-o", output]
        env = dict(os.environ)
        if threads:
            env["LP_NUM_THREADS"] = str(threads)
        return last_json(run(command, env).stdout)


def measure(scenes, args, folder):
    """{(scene, mode, threads): {"zrender": [ms per round], "llvmpipe": [...]}}"""
    times = {}
    scratch = os.path.join(folder, "frame.png")
    # A scene's modes one after another at each thread count, so that a mode and flat run
    # close together in every round.
    order = [(scene, mode, threads) for scene in dict.fromkeys(s for s, _ in CASES)
             for threads in args.threads for s, mode in CASES if s == scene]
    for r in range(args.rounds):
        for scene, mode, threads in order:
            cell = times.setdefault((scene, mode, threads), {"zrender": [], "llvmpipe": []})
            z = scenes[scene].zrender(mode, threads, args.repeat, scratch)
            cell["zrender"].append(z["frame_ms"])
            ref = scenes[scene].reference(mode, threads, args.repeat)
            cell["llvmpipe"].append(ref["frame_ms"])
            print("round %d/%d %s %s %d threads: zrender %.2f ms, llvmpipe %.2f ms"
                  % (r + 1, args.rounds, scene, mode, threads, z["frame_ms"],
                     ref["frame_ms"]), file=sys.stderr)
    rows = []
    for (scene, mode, threads), cell in times.items():
        flat = times.get((scene, "flat", threads))
        # Ratios and differences per round, then their medians: the machine's speed changes
        # from one round to the next, less within one.
        row = {"scene": scene, "mode": mode, "threads": threads,
               "zrender_ms": statistics.median(cell["zrender"]),
               "llvmpipe_ms": statistics.median(cell["llvmpipe"]),
               "ratio": statistics.median(l / z for l, z in zip(cell["llvmpipe"],
                                                                cell["zrender"]))}
        for program, key in (("zrender", "zrender_beyond_flat_ms"),
                             ("llvmpipe", "llvmpipe_beyond_flat_ms")):
            row[key] = (statistics.median(m - f for m, f in zip(cell[program], flat[program]))
                        if flat and mode != "flat" else None)
        rows.append(row)
    return rows


def read_ppm(path):
    """(width, height, bytes of RGB rows) of a binary PPM (P6, maxval 255)."""
    with open(path, "rb") as f:
        data = f.read()
    fields, at = [], 0
    while len(fields) < 4:  # P6, width, height, maxval; '#' comments are not written by either
        while data[at:at + 1].isspace():
            at += 1
        end = at
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[at:end])
        at = end
    if fields[0] != b"P6" or fields[3] != b"255":
        sys.exit("compare.py: %s: not an 8-bit binary PPM" % path)
    width, height = int(fields[1]), int(fields[2])
    return width, height, data[at + 1:at + 1 + 3 * width * height]


def agreement(zrender_image, reference_image, ids_image):
    """Differing pixels (> 1/255 in a channel) overall and away from edges, and the largest
    difference away from edges."""
    width, height, z = read_ppm(zrender_image)
    w2, h2, ref = read_ppm(reference_image)
    w3, h3, ids_rgb = read_ppm(ids_image)
    if (w2, h2) != (width, height) or (w3, h3) != (width, height):
        sys.exit("compare.py: image sizes differ")
    stride = 3 * width
    ids = [ids_rgb[i] | ids_rgb[i + 1] << 8 | ids_rgb[i + 2] << 16  # id + 1, R the low byte
           for i in range(0, len(ids_rgb), 3)]

    def edge(x, y):
        centre = ids[y * width + x]
        for yy in range(max(y - 1, 0), min(y + 2, height)):
            for xx in range(max(x - 1, 0), min(x + 2, width)):
                if ids[yy * width + xx] != centre:
                    return True
        return False

    differing = inner = largest = 0
    for y in range(height):
        a, b = z[y * stride:(y + 1) * stride], ref[y * stride:(y + 1) * stride]
        if a == b:
            continue
        for x in range(width):
            i = 3 * x
            d = max(abs(a[i] - b[i]), abs(a[i + 1] - b[i + 1]), abs(a[i + 2] - b[i + 2]))
            if d > 1:
                differing += 1
                if not edge(x, y):
                    inner += 1
                    largest = max(largest, d)
    pixels = width * height
    return {"differing": differing / pixels, "differing_pixels": differing,
            "differing_inner": inner / pixels, "differing_inner_pixels": inner,
            "largest_inner": largest}


def compare_images(scenes, args, folder):
    rows = []
    keep = os.path.abspath(args.keep_images or folder)  # the programs run in ROOT
    os.makedirs(keep, exist_ok=True)
    size = ["--width", str(args.image_size), "--height", str(args.image_size)]
    for name in dict.fromkeys(scene for scene, _ in CASES):
        scene = scenes[name]
        ids = os.path.join(keep, name + "-ids.ppm")
        # The id shading writes the --ids image's encoding (face id + 1, R the low byte), here
        # as PPM, which needs no PNG decoder.
        scene.zrender("id", 2, 1, ids, size)
        for _, mode in (case for case in CASES if case[0] == name):
            z = os.path.join(keep, "%s-%s-zrender.ppm" % (name, mode))
            ref = os.path.join(keep, "%s-%s-llvmpipe.ppm" % (name, mode))
            scene.zrender(mode, 2, 1, z, size)
            scene.reference(mode, 0, 1, ref, scene.image_cameras)
            row = {"scene": name, "mode": mode}
            row.update(agreement(z, ref, ids))
            rows.append(row)
    return rows


def print_tables(timings, images, args):
    def ms(value):
        return "—" if value is None else "%.2f" % value

    if timings:
        print("| scene | mode | threads | zrender ms | llvmpipe ms | llvmpipe / zrender "
              "| zrender beyond flat ms | llvmpipe beyond flat ms |")
        print("|---|---|---:|---:|---:|---:|---:|---:|")
        for r in timings:
            print("| %s | %s | %d | %s | %s | %.2f | %s | %s |"
                  % (r["scene"], r["mode"], r["threads"], ms(r["zrender_ms"]),
                     ms(r["llvmpipe_ms"]), r["ratio"], ms(r["zrender_beyond_flat_ms"]),
                     ms(r["llvmpipe_beyond_flat_ms"])))
        algorithm = "--alg " + args.alg if args.alg else "its default algorithm"
        print("\nMedians of %d rounds, each the median of --repeat %d frames; zrender %s."
              % (args.rounds, args.repeat, algorithm))
    if images:
        print("\n| scene | mode | differing pixels | away from edges | largest difference there |")
        print("|---|---|---:|---:|---:|")
        for r in images:
            print("| %s | %s | %.5f%% (%d) | %.5f%% (%d) | %d |"
                  % (r["scene"], r["mode"], 100 * r["differing"], r["differing_pixels"],
                     100 * r["differing_inner"], r["differing_inner_pixels"], r["largest_inner"]))
        print("\n%dx%d; a pixel differs when a channel differs by more than 1/255." %
              (args.image_size, args.image_size))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--zrender", help="zrender (default build/zrender)")
    parser.add_argument("--ref", help="llvmpipe-ref (default: beside zrender, else build/ or "
                        "build-llvmpipe/)")
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--repeat", type=int, default=10, help="frames per run")
    parser.add_argument("--threads", default="1,2", help="thread counts, comma-separated")
    parser.add_argument("--alg", help="zrender's --alg (default: its own)")
    parser.add_argument("--images", action="store_true", help="also compare the images")
    parser.add_argument("--images-only", action="store_true", help="compare the images only")
    parser.add_argument("--image-size", type=int, default=1800, metavar="N",
                        help="images of NxN pixels (default 1800)")
    parser.add_argument("--keep-images", metavar="DIR", help="write the images to DIR")
    parser.add_argument("--check", action="store_true", help="exit 1 when a pixel away from "
                        "edges differs (with --images or --images-only)")
    parser.add_argument("--json", action="store_true", help="print one JSON object instead")
    args = parser.parse_args()
    if args.check and not (args.images or args.images_only):
        parser.error("--check needs --images or --images-only")
    if args.image_size < 1:
        parser.error("--image-size must be positive")
    args.zrender = find_program(args.zrender, ["build/zrender"])
    # The reference of zrender's own build first: one configure builds both.
    beside = os.path.join(os.path.dirname(args.zrender), "llvmpipe-ref")
    args.ref = find_program(args.ref, [beside, "build/llvmpipe-ref", "build-llvmpipe/llvmpipe-ref"])
    args.threads = [int(t) for t in args.threads.split(",")]

    with tempfile.TemporaryDirectory(prefix="llvmpipe-compare-") as folder:
        scenes = {name: Scene(name, args, folder) for name in dict.fromkeys(s for s, _ in CASES)}
        timings = [] if args.images_only else measure(scenes, args, folder)
        images = compare_images(scenes, args, folder) if args.images or args.images_only else []
    if args.json:
        print(json.dumps({"rounds": args.rounds, "repeat": args.repeat, "timings": timings,
                          "images": images}, indent=1))
    else:
        print_tables(timings, images, args)
    differing = ["%s %s (%d pixels, by up to %d/255)" % (r["scene"], r["mode"],
                 r["differing_inner_pixels"], r["largest_inner"])
                 for r in images if r["differing_inner_pixels"]]
    if args.check and differing:
        sys.stdout.flush()
        sys.exit("compare.py: differing away from edges: " + ", ".join(differing))


if __name__ == "__main__":
    main()
