#!/usr/bin/env python3
"""Writes the STL surfaces of the cases and tests (run from the repository root):
  cases/stl/sphere.stl        unit sphere: an icosahedron subdivided 3 times (1280 facets, its
                              vertices on the sphere), binary STL
  cases/stl/cube.stl          unit cube [0, 1]^3 (12 facets), ASCII STL
  tests/case/stl/open.stl     the cube less one facet (not closed)
  tests/case/stl/inverted.stl the cube with every facet reversed (normals inward)
  tests/case/stl/flipped.stl  the cube with one facet reversed (orientation inconsistent)
  tests/case/stl/junk.stl     a text file that is no STL
  tests/case/stl/nan.stl      the cube with one vertex NaN (its edges then match nothing)
Facets run counter-clockwise seen from outside (the STL convention)."""
import math
import struct

CUBE_V = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
CUBE_F = [(0, 3, 2), (0, 2, 1), (4, 5, 6), (4, 6, 7), (0, 1, 5), (0, 5, 4), (2, 3, 7), (2, 7, 6),
          (1, 2, 6), (1, 6, 5), (0, 4, 7), (0, 7, 3)]


def normal(a, b, c):
    u = [b[k] - a[k] for k in range(3)]
    v = [c[k] - a[k] for k in range(3)]
    n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    m = math.sqrt(sum(x * x for x in n)) or 1.0
    return [x / m for x in n]


def ascii_stl(path, name, tris):
    with open(path, "w") as f:
        f.write("solid %s\n" % name)
        for t in tris:
            f.write(" facet normal %g %g %g\n  outer loop\n" % tuple(normal(*t)))
            for v in t:
                f.write("   vertex %.9g %.9g %.9g\n" % tuple(v))
            f.write("  endloop\n endfacet\n")
        f.write("endsolid %s\n" % name)


def binary_stl(path, tris):
    with open(path, "wb") as f:
        f.write(b"clsph unit sphere".ljust(80, b" "))
        f.write(struct.pack("<I", len(tris)))
        for t in tris:
            f.write(struct.pack("<3f", *normal(*t)))
            for v in t:
                f.write(struct.pack("<3f", *v))
            f.write(b"\0\0")


def icosphere(levels):
    p = (1 + math.sqrt(5)) / 2
    v = [(-1, p, 0), (1, p, 0), (-1, -p, 0), (1, -p, 0), (0, -1, p), (0, 1, p), (0, -1, -p),
         (0, 1, -p), (p, 0, -1), (p, 0, 1), (-p, 0, -1), (-p, 0, 1)]
    v = [tuple(x / math.sqrt(sum(y * y for y in w)) for x in w) for w in v]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
         (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9),
         (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(levels):
        mid = {}

        def m(a, b):
            key = (min(a, b), max(a, b))
            if key not in mid:
                c = [(v[a][k] + v[b][k]) / 2 for k in range(3)]
                r = math.sqrt(sum(x * x for x in c))
                v.append(tuple(x / r for x in c))
                mid[key] = len(v) - 1
            return mid[key]

        g = []
        for a, b, c in f:
            ab, bc, ca = m(a, b), m(b, c), m(c, a)
            g += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        f = g
    return [(v[a], v[b], v[c]) for a, b, c in f]


cube = [tuple(CUBE_V[i] for i in t) for t in CUBE_F]
ascii_stl("cases/stl/cube.stl", "cube", cube)
binary_stl("cases/stl/sphere.stl", icosphere(3))
ascii_stl("tests/case/stl/open.stl", "open", cube[:3] + cube[4:])
ascii_stl("tests/case/stl/inverted.stl", "inverted", [(a, c, b) for a, b, c in cube])
ascii_stl("tests/case/stl/flipped.stl", "flipped",
          [(a, c, b) if k == 5 else (a, b, c) for k, (a, b, c) in enumerate(cube)])
nan = list(cube)
nan[2] = ((float("nan"), 1, 1),) + nan[2][1:]  # the first vertex of the top's first facet
ascii_stl("tests/case/stl/nan.stl", "nan", nan)
with open("tests/case/stl/junk.stl", "w") as f:
    f.write("this is no STL file\n")
