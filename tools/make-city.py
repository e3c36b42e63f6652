#!/usr/bin/env python3
"""Writes the `city` scene into settings.json: a street seen from eye height, lined by four rows
of buildings on each side, gates across it, and the reference models on it and, out of sight, in
the courtyards between the rows of buildings (345 objects). Deterministic: run again, the same
scene. Usage: tools/make-city.py [settings.json]"""
import json
import random
import sys

path = sys.argv[1] if len(sys.argv) > 1 else "settings.json"
rng = random.Random(46)
objects = []


def box(x, y, z, w, h, d):
    """A box from (x, y, z), w wide (x), h high (y), d deep (z), metres."""
    objects.append({"path": "models/city/box.obj", "translate": [x, y, z], "scale": [w, h, d]})


def place(model, x, z, turn, scale, lift):
    objects.append({"path": model, "translate": [x, lift, z], "rotate": [turn, [0, 1, 0]],
                    "scale": scale})


box(-60.0, -0.1, -215.0, 120.0, 0.1, 220.0)  # the ground
for side in (-1, 1):  # buildings: four rows deep on each side, 12 along the street, taller away
    for row in range(4):
        for i in range(12):
            w, d, h = 10.0, 12.0, round(rng.uniform(8.0, 16.0) + 8.0 * row, 1)
            x = side * (8.0 + 14.0 * row) - (w if side < 0 else 0.0)
            box(x, 0.0, -8.0 - 16.0 * i - d, w, h, d)
for i in range(40):  # gates across the street: a wall on each side of a 2.5 m gap
    gap = rng.uniform(-4.0, 4.0)  # the gap's centre, x
    box(-8.0, 0.0, -14.0 - 4.5 * i, gap - 1.25 + 8.0, 12.0, 0.4)
    box(gap + 1.25, 0.0, -14.0 - 4.5 * i, 8.0 - gap - 1.25, 12.0, 0.4)
for i in range(30):  # bollards along both kerbs
    box(-6.5 if i % 2 else 6.2, 0.0, -3.0 - 6.0 * i, 0.3, 0.9, 0.3)


def models(count, x0, x1, z0, z1, size):
    """`count` of the reference models, mixed, `size` times life size, in the box x0..x1,
    z0..z1 on the ground."""
    kinds = [("models/bunny/bunny.obj", 8.0, -0.26), ("models/teapot/teapot.obj", 0.25, 0.0),
             ("models/spot/spot_triangulated_good.obj", 1.0, 0.737)]
    for n in range(count):
        model, scale, lift = kinds[n % 3]
        place(model, rng.uniform(x0, x1), rng.uniform(z0, z1), rng.uniform(0, 360), scale * size,
              lift * size)


models(18, -5.0, 5.0, -13.0, -2.0, 1.0)  # on the street, in sight
for side in (-1, 1):  # in the courtyards between the rows of buildings, out of sight
    for row in range(3):
        x = side * (18.0 + 14.0 * row + 2.0)
        models(20, x - 1.0, x + 1.0, -190.0, -10.0, 3.0)  # statues: 2.4 to 3.6 m tall

with open(path) as f:
    settings = json.load(f)
settings["city"] = {
    "objects": objects,
    "width": 1280,
    "height": 720,
    "eye": [0.0, 1.7, 4.0],
    "target": [0.0, 1.5, -100.0],
    "project": [45.0, 0.0, -0.1, -300.0],  # aspect 0: width / height
    "bench": True,
}
with open(path, "w") as f:
    f.write(json.dumps(settings, indent=2) + "\n")
print(f"{path}: scene 'city' with {len(objects)} objects")
