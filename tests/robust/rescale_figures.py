#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""How much a scene's units change its picture: each NFF file rendered as
it is (scale 1, left in its own units when in range) and with every length
multiplied by 10^4 (rescaled into the core's range), grey 128x96, and the
two pictures compared: the share of pixels that differ, the largest
difference in grey levels (of 256), and how many pixels differ by more
than 16 levels.

Usage: rescale_figures.py STIPPLE WORK_DIR NFF...
Prints one line per file and a last line "max: ..." over all of them.
"""
import os
import subprocess
import sys

SCALE = 1e4
# entity: which of its numbers are lengths (indices), None for the rest
LENGTHS = {"from": (0, 1, 2), "at": (0, 1, 2), "hither": (0,), "l": (0, 1, 2),
           "s": (0, 1, 2, 3), "c": (0, 1, 2, 3, 4, 5, 6, 7)}


def scaled(text, k):
    out, verts = [], 0  # verts: polygon vertex lines still to come (6 numbers: pp)
    for line in text.splitlines():
        words = line.split()
        if not words:
            out.append(line)
            continue
        if verts:
            nums = [float(w) for w in words]
            nums[:3] = [v * k for v in nums[:3]]
            out.append(" ".join(repr(v) for v in nums))
            verts -= 1
            continue
        if words[0] in ("p", "pp"):
            verts = int(words[1])
            out.append(line)
        elif words[0] in LENGTHS:
            idx = LENGTHS[words[0]]
            nums = words[1:]
            for i in idx:
                if i < len(nums):
                    nums[i] = repr(float(nums[i]) * k)
            out.append(" ".join([words[0]] + nums))
        else:
            out.append(line)
    return "\n".join(out) + "\n"


def grey(stipple, path, out):
    subprocess.run([stipple, "render", path, "-o", out, "-s", "128x96"], check=True)
    data = open(out, "rb").read()
    return data.split(b"\n", 3)[3]


def main():
    stipple, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    worst = [0.0, 0, 0]
    for path in sys.argv[3:]:
        name = os.path.basename(path)
        big = os.path.join(work, "big-" + name)
        with open(big, "w") as f:
            f.write(scaled(open(path).read(), SCALE))
        a = grey(stipple, path, os.path.join(work, "a.pgm"))
        b = grey(stipple, big, os.path.join(work, "b.pgm"))
        diff = [abs(x - y) for x, y in zip(a, b)]
        share = 100.0 * sum(d > 0 for d in diff) / len(diff)
        far = sum(d > 16 for d in diff)
        print(f"{name}: {share:.1f} % of pixels differ, at most {max(diff)} levels, "
              f"{far} by more than 16")
        worst = [max(worst[0], share), max(worst[1], max(diff)), max(worst[2], far)]
    print(f"max: {worst[0]:.1f} % {worst[1]} levels {worst[2]} pixels")


if __name__ == "__main__":
    main()
