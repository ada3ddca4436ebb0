#!/usr/bin/env python3
"""Writes legacy_fall.bake: a file in the original project's .bake flavour (no header, OBJ part and '!',
object-major `id x y z` lines, %g numbers, CRLF), recorded at 200 steps per second.

The motion is closed-form so the reader test can check every line: the anchor plane stays put, the cube falls
from rest, y(t) = y0 - g t^2 / 2 with g = 9.81, t = k / 200, for k = 0 .. 40.
"""
import pathlib

OBJ = [
    "# Blender-like export",
    "o Anchor",
    "v -1 0 -1", "v 1 0 -1", "v 1 0 1", "v -1 0 1",
    "f 1 2 3 4",
    "o Cube.002",
    "v 0 2 0", "v 0.5 2 0", "v 0.5 2.5 0", "v 0 2.5 0",
    "v 0 2 0.5", "v 0.5 2 0.5", "v 0.5 2.5 0.5", "v 0 2.5 0.5",
    "f 5 6 7 8", "f 9 10 11 12", "f 5 6 10 9", "f 6 7 11 10", "f 7 8 12 11", "f 8 5 9 12",
]
STEPS = 41
RATE = 200.0
G = 9.81

lines = list(OBJ) + ["!"]
anchor = (0.0, 0.0, 0.0)
cube = (0.25, 2.25, 0.25)
for k in range(STEPS):
    lines.append("0 %g %g %g" % anchor)
for k in range(STEPS):
    t = k / RATE
    lines.append("1 %g %g %g" % (cube[0], cube[1] - 0.5 * G * t * t, cube[2]))
out = pathlib.Path(__file__).with_name("legacy_fall.bake")
out.write_bytes(("\r\n".join(lines) + "\r\n").encode("ascii"))
