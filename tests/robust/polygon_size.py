#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Time `stipple render` of one OBJ polygon against its vertex count.

Usage: polygon_size.py STIPPLE OUT_DIR [COUNT...]

Writes three polygons per count into OUT_DIR and prints one line per file:
shape, vertices, seconds (wall clock of the whole command: reading,
preparing, rendering 128x64), exit status.  Shapes: a circle (convex:
a fan of pieces), a star (every other vertex reflex: ear clipping) and a
comb (teeth along one side: reflex vertices in a row).
"""
import math
import subprocess
import sys
import time


def circle(n):
    return [(math.cos(2 * math.pi * i / n), math.sin(2 * math.pi * i / n)) for i in range(n)]


def star(n):
    out = []
    for i in range(n):
        r = 1.0 if i % 2 == 0 else 0.6
        a = 2 * math.pi * i / n
        out.append((r * math.cos(a), r * math.sin(a)))
    return out


def comb(n):
    teeth = (n - 2) // 2
    out = []
    for i in range(teeth):
        x = i / teeth
        out.append((x, 1.0 if i % 2 == 0 else 0.2))
        out.append((x + 0.5 / teeth, 1.0 if i % 2 == 0 else 0.2))
    out += [(1.0, 0.0), (0.0, 0.0)]
    return out


def main():
    stipple, out_dir = sys.argv[1], sys.argv[2]
    counts = [int(c) for c in sys.argv[3:]] or [1000, 10000, 100000, 1000000]
    for n in counts:
        for name, shape in (("circle", circle), ("star", star), ("comb", comb)):
            path = f"{out_dir}/{name}{n}.obj"
            pts = shape(n)
            with open(path, "w") as f:
                f.writelines(f"v {x:.9f} {y:.9f} 0\n" for x, y in pts)
                f.write("f " + " ".join(str(i + 1) for i in range(len(pts))) + "\n")
            t = time.monotonic()
            rc = subprocess.run([stipple, "render", path, "-o", f"{out_dir}/out.pgm"],
                                stdout=subprocess.DEVNULL, stderr=subprocess.PIPE).returncode
            print(f"{name:7s} {len(pts):8d} {time.monotonic() - t:8.2f} s  exit {rc}", flush=True)


if __name__ == "__main__":
    main()
