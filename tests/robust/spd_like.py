#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes NFF scenes laid out as the Standard Procedural Databases' programs
write them (issue 13): "b" before "v", the view one field per line, lights
"l x y z", a cone's eight numbers on the "c" line, "p n" then one vertex per
line, numbers in %g.  The shapes are this file's own small stand-ins for the
SPD databases (rings of spheres and cylinders, a tree of cones, jacks, a
lattice, shells, a sombrero mesh, a sphereflake), growing with the size
factor like theirs; rings puts "at" right next to the eye as SPD rings does.

usage: spd_like.py DATABASE SIZE [--scale K] [--crlf] [--bom] > out.nff
"""
import math
import sys


def g(*xs):
    return " ".join("%g" % x for x in xs)


class Out:
    def __init__(self, scale):
        self.k = scale
        self.lines = []

    def w(self, s):
        self.lines.append(s)

    def p(self, *xyz):
        return [c * self.k for c in xyz]

    def header(self, frm, at, lights, bg=(0.078, 0.361, 0.753)):
        self.w("b " + g(*bg))
        self.w("v")
        self.w("from " + g(*self.p(*frm)))
        self.w("at " + g(*self.p(*at)))
        self.w("up 0 0 1")
        self.w("angle 45")
        self.w("hither " + g(0.01 * self.k))
        self.w("resolution 512 512")
        for l in lights:
            self.w("l " + g(*self.p(*l)))

    def material(self, r, gr, b, kd=0.8, ks=0.2, shine=10, t=0, ior=1):
        self.w("f " + g(r, gr, b, kd, ks, shine, t, ior))

    def sphere(self, c, r):
        self.w("s " + g(*self.p(*c), r * self.k))

    def cone(self, b, rb, a, ra):
        self.w("c " + g(*self.p(*b), rb * self.k, *self.p(*a), ra * self.k))

    def polygon(self, pts, normals=None):
        self.w(("pp %d" if normals else "p %d") % len(pts))
        for i, q in enumerate(pts):
            if normals:
                self.w(g(*self.p(*q), *normals[i]))
            else:
                self.w(g(*self.p(*q)))

    def floor(self, half, z):
        self.material(1, 0.75, 0.33, 0.8, 0, 0, 0, 1)
        self.polygon([(half, half, z), (-half, half, z), (-half, -half, z), (half, -half, z)])


def rings(o, n):
    frm = (-4.0, -5.0, 4.5)
    d = [0 - frm[0], 0 - frm[1], 0.6 - frm[2]]
    at = tuple(frm[i] + 0.01 * d[i] for i in range(3))  # next to the eye
    o.header(frm, at, [(-5, 5, 10), (6, -3, 8), (2, 6, 5)])
    o.floor(6, -0.3)
    m = n + 1
    for i in range(m):
        for j in range(m):
            cx, cy = (i - (m - 1) / 2) * 2.2 / m * 2, (j - (m - 1) / 2) * 2.2 / m * 2
            cz = 0.4 + 0.3 * ((i + j) % 2)
            o.material(0.5 + 0.5 * (i % 2), 0.5, 0.5 + 0.5 * (j % 2), 0.7, 0.3, 30, 0.3 * (j % 2), 1.3)
            rr, pts = 0.9 / m * 1.5, []
            for k in range(10):
                a = 2 * math.pi * k / 10
                pts.append((cx + rr * math.cos(a), cy + rr * math.sin(a), cz + 0.2 * math.sin(2 * a)))
            for k in range(10):
                o.sphere(pts[k], 0.12 / m * 1.5)
                o.cone(pts[k], 0.06 / m * 1.5, pts[(k + 1) % 10], 0.06 / m * 1.5)


def tree(o, n):
    o.header((4.5, 3.5, 3.5), (0, 0, 1.4), [(-6, 4, 12), (5, -5, 9)])
    o.floor(6, 0)
    o.material(0.55, 0.35, 0.2, 0.9, 0.1, 5)

    def branch(base, d, length, r, depth):
        tip = tuple(base[i] + d[i] * length for i in range(3))
        o.cone(base, r, tip, r * 0.6)
        if depth == 0:
            o.sphere(tip, r * 1.5)
            return
        for k in range(3):
            a = 2 * math.pi * k / 3 + depth
            nd = (d[0] * 0.5 + 0.6 * math.cos(a), d[1] * 0.5 + 0.6 * math.sin(a), d[2] * 0.7)
            ln = math.sqrt(sum(c * c for c in nd))
            branch(tip, tuple(c / ln for c in nd), length * 0.7, r * 0.6, depth - 1)

    branch((0, 0, 0), (0, 0, 1), 1.2, 0.15, n + 1)


def jacks(o, n):
    o.header((3.0, 4.0, 3.5), (0, 0, 0.3), [(-4, 6, 9), (6, -2, 7), (1, 1, 12)])
    o.floor(5, -1.2)

    def jack(c, s, depth):
        o.material(0.8, 0.2 + 0.2 * depth, 0.3, 0.7, 0.3, 20)
        for ax in range(3):
            a = list(c)
            b = list(c)
            a[ax] -= s
            b[ax] += s
            o.cone(a, s * 0.08, b, s * 0.08)
            o.sphere(a, s * 0.18)
            o.sphere(b, s * 0.18)
        if depth > 0:
            for ax in range(3):
                for sign in (-1, 1):
                    q = list(c)
                    q[ax] += sign * s * 1.35
                    jack(q, s * 0.35, depth - 1)

    jack((0, 0, 0), 1.0, n)


def lattice(o, n):
    o.header((4.0, 3.2, 2.8), (0, 0, 0), [(-5, 5, 8), (6, 2, -4)])
    m = n + 1
    step = 2.0 / m
    pts = {}
    o.material(0.9, 0.9, 0.2, 0.7, 0.3, 40, 0, 1.5)
    for i in range(m + 1):
        for j in range(m + 1):
            for k in range(m + 1):
                pts[(i, j, k)] = (-1 + i * step, -1 + j * step, -1 + k * step)
                o.sphere(pts[(i, j, k)], step * 0.18)
    o.material(0.3, 0.5, 0.9, 0.7, 0.3, 40)
    for (i, j, k), p in pts.items():
        for d in ((1, 0, 0), (0, 1, 0), (0, 0, 1)):
            q = (i + d[0], j + d[1], k + d[2])
            if q in pts:
                o.cone(p, step * 0.06, pts[q], step * 0.06)


def shells(o, n):
    o.header((5.0, 2.5, 3.0), (0, 0, 0.5), [(-4, 5, 9), (5, -4, 6), (0, 0, 10)])
    o.floor(5, -0.6)
    count = 30 * 4 ** (n - 1)
    for i in range(count):
        t = i / count
        a = 2 * math.pi * 3 * t
        r = 0.2 + 1.6 * t
        o.material(0.9, 0.3 + 0.6 * t, 0.3, 0.6, 0.4, 50, 0.2 if i % 3 == 0 else 0, 1.4)
        o.sphere((r * math.cos(a), r * math.sin(a), 2.2 * (1 - t) - 0.3), 0.05 + 0.25 * t)


def sombrero(o, n):
    o.header((4.0, 3.0, 3.4), (0, 0, 0), [(-6, 4, 10), (3, -6, 6)])
    o.material(0.7, 0.7, 0.9, 0.8, 0.2, 20)
    m = 8 * 2 ** n

    def h(x, y):
        r = math.hypot(x, y) * 4 + 1e-9
        return math.sin(r) / r

    def nrm(x, y, e=1e-4):
        dx = (h(x + e, y) - h(x - e, y)) / (2 * e)
        dy = (h(x, y + e) - h(x, y - e)) / (2 * e)
        ln = math.sqrt(dx * dx + dy * dy + 1)
        return (-dx / ln, -dy / ln, 1 / ln)

    for i in range(m):
        for j in range(m):
            x0, x1 = -2 + 4 * i / m, -2 + 4 * (i + 1) / m
            y0, y1 = -2 + 4 * j / m, -2 + 4 * (j + 1) / m
            for tri in (((x0, y0), (x1, y0), (x1, y1)), ((x0, y0), (x1, y1), (x0, y1))):
                o.polygon([(x, y, h(x, y)) for x, y in tri], [nrm(x, y) for x, y in tri])


def balls(o, n):
    o.header((2.1, 1.3, 1.7), (0, 0, 0), [(4, 3, 2), (1, -4, 4), (-3, 1, 5)])
    o.floor(12, -0.5)
    o.material(1, 0.9, 0.7, 0.5, 0.5, 3.0827, 0, 1)

    def flake(c, r, d, depth):
        o.sphere(c, r)
        if depth == 0:
            return
        # nine children around the sphere, away from the parent
        ax = d
        e = (1, 0, 0) if abs(ax[0]) < 0.9 else (0, 1, 0)
        u = (ax[1] * e[2] - ax[2] * e[1], ax[2] * e[0] - ax[0] * e[2], ax[0] * e[1] - ax[1] * e[0])
        lu = math.sqrt(sum(x * x for x in u))
        u = tuple(x / lu for x in u)
        v = (ax[1] * u[2] - ax[2] * u[1], ax[2] * u[0] - ax[0] * u[2], ax[0] * u[1] - ax[1] * u[0])
        for k in range(9):
            a = 2 * math.pi * k / 6 if k < 6 else 2 * math.pi * (k - 6) / 3 + 0.5
            el = 0.0 if k < 6 else 0.9
            cd = tuple(math.cos(el) * (math.cos(a) * u[i] + math.sin(a) * v[i]) + math.sin(el) * ax[i]
                       for i in range(3))
            cr = r / 3
            flake(tuple(c[i] + cd[i] * (r + cr) for i in range(3)), cr, cd, depth - 1)

    flake((0, 0, 0), 0.5, (0, 0, 1), n)


DATABASES = {"rings": rings, "tree": tree, "jacks": jacks, "lattice": lattice,
             "shells": shells, "sombrero": sombrero, "balls": balls}


def main():
    args = sys.argv[1:]
    if len(args) < 2 or args[0] not in DATABASES:
        sys.stderr.write(__doc__)
        return 2
    scale = 1.0
    if "--scale" in args:
        scale = float(args[args.index("--scale") + 1])
    o = Out(scale)
    DATABASES[args[0]](o, int(args[1]))
    eol = "\r\n" if "--crlf" in args else "\n"
    text = eol.join(o.lines) + eol
    data = text.encode()
    if "--bom" in args:
        data = b"\xef\xbb\xbf" + data
    sys.stdout.buffer.write(data)
    return 0


if __name__ == "__main__":
    sys.exit(main())
