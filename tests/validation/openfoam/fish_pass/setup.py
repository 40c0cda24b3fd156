#!/usr/bin/env python3
"""The pool of run.sh (Leroy et al. 2014 sec 5.2) and its blockMeshDict (standard library only).

A periodic pool of a vertical-slot fish pass seen from above, 2-D: slot width b = 0.3 m, period
L = 10 b along x (cyclic x = 0 <-> x = L), width B = 8 b between the walls y = 0 and y = B. The
partition is two solid baffles: the long one x in [1.0, 1.15], y in [0, 1.8] on the wall y = 0,
the short one x in [1.0, 1.45], y in [2.1, 2.4] on the wall y = B; the slot is y in [1.8, 2.1].
Mesh: the grid of blocks on the x breaks XS and y breaks YS less the 3 solid blocks (9 blocks),
square cells of side h, one cell (of depth h) thick in z, empty front and back.
Vertex (column i, row j, level z) is 2 (len(YS) i + j) + z. Patches: left/right (cyclic),
lowerWall (y = 0), upperWall (y = B), baffleWall (the faces of both baffles), frontAndBack.
    setup.py mesh H DIR      DIR/system/blockMeshDict for cells of side H (m)
"""
import os
import sys

B_SLOT = 0.3
L = 10 * B_SLOT                     # 3.0
WIDTH = 8 * B_SLOT                  # 2.4
XS = (0.0, 1.0, 1.15, 1.45, L)
YS = (0.0, 1.8, 2.1, WIDTH)
SOLID = {(1, 0), (1, 2), (2, 2)}    # blocks (i, j) inside the baffles
FORCE = 1.885                       # body force along +x, m/s^2 (constant/fvOptions)
NU = 1e-6
RHO = 1000.0

# outward faces of a hex (v0..v7 as in hexa()), blockMesh's order
FACE = {"x0": (0, 4, 7, 3), "x1": (1, 2, 6, 5), "y0": (0, 1, 5, 4), "y1": (3, 7, 6, 2),
        "z0": (0, 3, 2, 1), "z1": (4, 5, 6, 7)}


def cells(h, span):
    n = round(span / h)
    if abs(n * h - span) > 1e-9:
        sys.exit(f"setup.py: cell size {h} does not divide {span:g}")
    return n


def fluid_blocks():
    return [(i, j) for i in range(len(XS) - 1) for j in range(len(YS) - 1)
            if (i, j) not in SOLID]


def is_fluid(i, j):
    return 0 <= i < len(XS) - 1 and 0 <= j < len(YS) - 1 and (i, j) not in SOLID


def hexa(i, j):
    def v(a, b, z):
        return 2 * (len(YS) * a + b) + z
    return (v(i, j, 0), v(i + 1, j, 0), v(i + 1, j + 1, 0), v(i, j + 1, 0),
            v(i, j, 1), v(i + 1, j, 1), v(i + 1, j + 1, 1), v(i, j + 1, 1))


def block_mesh(h):
    def face(i, j, side):
        vs = hexa(i, j)
        return "(" + " ".join(str(vs[k]) for k in FACE[side]) + ")"

    patches = {"left": [], "right": [], "lowerWall": [], "upperWall": [], "baffleWall": [],
               "frontAndBack": []}
    for i, j in fluid_blocks():
        for side, nb in (("x0", (i - 1, j)), ("x1", (i + 1, j)), ("y0", (i, j - 1)),
                             ("y1", (i, j + 1))):
            if is_fluid(*nb):
                continue                        # internal: blockMesh merges the shared face
            if side == "x0" and i == 0:
                patches["left"].append(face(i, j, side))
            elif side == "x1" and i == len(XS) - 2:
                patches["right"].append(face(i, j, side))
            elif side == "y0" and j == 0:
                patches["lowerWall"].append(face(i, j, side))
            elif side == "y1" and j == len(YS) - 2:
                patches["upperWall"].append(face(i, j, side))
            else:
                patches["baffleWall"].append(face(i, j, side))
        patches["frontAndBack"] += [face(i, j, "z0"), face(i, j, "z1")]
    out = [f"// Fish-pass pool, cells of side {h:g} m: made by setup.py (see its docstring).",
           "FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }",
           "", "scale 1;", "", "vertices", "("]
    for x in XS:
        for y in YS:
            for z in (0.0, h):
                out.append(f"    ({x:.12g} {y:.12g} {z:.12g})")
    out += [");", "", "blocks", "("]
    for i, j in fluid_blocks():
        nx, ny = cells(h, XS[i + 1] - XS[i]), cells(h, YS[j + 1] - YS[j])
        out.append(f"    hex ({' '.join(map(str, hexa(i, j)))}) ({nx} {ny} 1) "
                   "simpleGrading (1 1 1)")
    out += [");", "", "edges ();", "", "boundary", "("]
    kinds = {"left": "cyclic; neighbourPatch right", "right": "cyclic; neighbourPatch left",
             "frontAndBack": "empty"}
    for name, faces in patches.items():
        out.append(f"    {name} {{ type {kinds.get(name, 'wall')}; faces ({' '.join(faces)}); }}")
    out += [");", "", "mergePatchPairs ();", ""]
    return "\n".join(out)


def n_cells(h):
    return sum(cells(h, XS[i + 1] - XS[i]) * cells(h, YS[j + 1] - YS[j])
               for i, j in fluid_blocks())


def main():
    if len(sys.argv) != 4 or sys.argv[1] != "mesh":
        sys.exit(__doc__)
    h, d = float(sys.argv[2]), sys.argv[3]
    os.makedirs(os.path.join(d, "system"), exist_ok=True)
    with open(os.path.join(d, "system", "blockMeshDict"), "w") as f:
        f.write(block_mesh(h))


if __name__ == "__main__":
    main()
