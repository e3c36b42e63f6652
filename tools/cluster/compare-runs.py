#!/usr/bin/env python3
"""Compares the files of two runs of the same views, byte for byte.

    tools/cluster/compare-runs.py WHOLE PARTS

Exit 0 when both folders hold the same files with the same bytes. Otherwise it lists each
difference, and for a PNG whose bytes differ it says whether its pixels differ too (the zlib
streams inflated and compared): a file whose pixels are equal but whose compressed bytes are
not is an encoder that chose another, equivalent, match (docs/cluster.md, Measured).
"""

import os
import struct
import sys
import zlib


def png_pixels(path):
    data = open(path, "rb").read()
    i, idat = 8, b""
    while i + 8 <= len(data):
        (n,) = struct.unpack(">I", data[i : i + 4])
        if data[i + 4 : i + 8] == b"IDAT":
            idat += data[i + 8 : i + 8 + n]
        i += 12 + n
    return zlib.decompress(idat)


def main():
    whole, parts = sys.argv[1], sys.argv[2]
    a, b = sorted(os.listdir(whole)), sorted(os.listdir(parts))
    problems = [f"only in {whole}: {n}" for n in sorted(set(a) - set(b))]
    problems += [f"only in {parts}: {n}" for n in sorted(set(b) - set(a))]
    for name in sorted(set(a) & set(b)):
        x = open(os.path.join(whole, name), "rb").read()
        y = open(os.path.join(parts, name), "rb").read()
        if x == y:
            continue
        note = ""
        if name.endswith(".png"):
            same = png_pixels(os.path.join(whole, name)) == png_pixels(os.path.join(parts, name))
            note = " (the same pixels, other compressed bytes)" if same else " (pixels differ)"
        problems.append(f"{name} differs{note}")
    for p in problems:
        print(f"compare-runs: {p}")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
