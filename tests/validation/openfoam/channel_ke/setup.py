#!/usr/bin/env python3
"""The runs of run.sh: their parameters, meshes and entry profiles (standard library only).

Every mesh is block-structured, 2-D (one cell thick in z, empty front and back), with three rows
of blocks across the channel: one cell of height 2 y_p on each wall (so the first cell centre is
at y_p, the wall-function distance of Wang, Sun & Hu), and a core of uniform cells between them
(round(H / (2 y_p)) - 2 cells unless a run says otherwise). Columns of blocks follow the channel:
one column for the periodic straight channel, entry / bend / exit for the curved channels, entry /
ramp / platform / ramp / exit for the HCD channel. At a corner of the wall the line between the
wall cell and the core is the miter of the two offset lines, so the wall cell keeps its height
2 y_p normal to the wall on both sides.
Vertex (station s, line r, level z) is 2 (4 s + r) + z; lines r = 0..3 are: first wall, first
wall + 2 y_p, second wall - 2 y_p, second wall. Blocks run column by column, rows inside; cell
(column c, row w, i, j) follows blockMesh's order (i along the channel fastest, then j).
    setup.py case RUN DIR      DIR/system/{blockMeshDict,caseParams}, constant/transportProperties
                               and, for a periodic run, constant/fvOptions
    setup.py inlet RUN DIR     DIR/constant/inlet/{U,k,epsilon}: the entry profile (needs DIR/0/C
                               and the source run's results in SCRATCH, DIR's parent)
    setup.py list NAME         the runs of straight, mild, strong, hcd or hcd_fine, in the order to run them
"""
import math
import os
import sys

import foamio

CMU = 0.09
INTENSITY = 0.05        # free-stream entry of SPHinXsys: k = 3/2 (I U)^2
LENGTH_RATIO = 0.07     # and epsilon = Cmu^(3/4) k^(3/2) / (0.07 H)
ASPECT = 4              # streamwise cell length / wall-normal cell height (2 y_p), curved channels


def straight(setting, nu, yp, ncore=None, E=9.8):
    return dict(kind="periodic", setting=setting, H=2.0, nu=nu, yp=yp, ncore=ncore, aspect=4, E=E)


def mild(yp, periodic=False):
    h = 0.0635
    return dict(kind="periodic" if periodic else "curved", setting="mild", H=h, nu=h / 60000,
                yp=yp, R1=99.5 * h, angle=43.0, L1=2.36 * h, L2=2.36 * h, aspect=ASPECT,
                src=None if periodic else f"mild_periodic_yp{yp:g}")


def strong(yp, periodic=False):
    h = 0.0762
    return dict(kind="periodic" if periodic else "curved", setting="strong", H=h, nu=h / 148400,
                yp=yp, R1=9.0 * h, angle=210.0, L1=3.0 * h, L2=9.0 * h, aspect=ASPECT,
                src=None if periodic else f"strong_periodic_yp{yp:g}")


def hcd(inlet):
    # SPHinXsys tests/extra_source_and_tests/2d_turbulent_HCD_channel: H = 2, entry 3 (1 + 2 of
    # extension) before a 30-degree ramp over 1.5 in x, a platform 1 long at height 1.5 tan 30,
    # a ramp down over 1.5, exit 5 (1 + 4); Re = U H / nu = 40000, y_p = 0.025.
    return dict(kind="hcd", setting="hcd", H=2.0, nu=2.0 / 40000, yp=0.025, aspect=1,
                src="straight_b_yp0.025" if inlet == "developed" else "uniform")


RUNS = {
    # straight (sec 5.1): (a) Lee & Moser's Re_tau = 543.5 (delta = 1, U_b = 1, nu = 1e-4);
    # (b) Re = U_b H / nu = 40000. fine: the same wall cell, a core 5 times finer.
    "straight_a_yp0.05": straight("a", 1e-4, 0.05),
    "straight_a_yp0.025": straight("a", 1e-4, 0.025),
    "straight_a_yp0.05_fine": straight("a", 1e-4, 0.05, ncore=90),
    "straight_b_yp0.025": straight("b", 5e-5, 0.025),
    "straight_b_yp0.05": straight("b", 5e-5, 0.05),
    # sensitivity to the log law's E (9.0, a reading of the paper's "E = 0.9"): header only
    "straight_a_yp0.05_E9.0": straight("a", 1e-4, 0.05, E=9.0),
    # curved (sec 5.2, Table 1): y_p of 20 and 40 particles across H (mild), H/40 and H/80 (strong)
    "mild_periodic_yp0.00159": mild(1.59e-3, periodic=True),
    "mild_periodic_yp0.0007": mild(7e-4, periodic=True),
    "mild_yp0.00159": mild(1.59e-3),
    "mild_yp0.0007": mild(7e-4),
    "strong_periodic_yp0.001905": strong(0.0762 / 40, periodic=True),
    "strong_periodic_yp0.0009525": strong(0.0762 / 80, periodic=True),
    "strong_yp0.001905": strong(0.0762 / 40),
    "strong_yp0.0009525": strong(0.0762 / 80),
    # HCD (sec 5.3): the fully developed entry of "straight_b_yp0.025", or SPHinXsys's uniform one
    "hcd_developed": hcd("developed"),
    "hcd_uniform": hcd("uniform"),
    # hcd_uniform's wall cells, its core and streamwise cells halved: the reference's convergence
    "hcd_fine_uniform": dict(hcd("uniform"), ncore=76, aspect=0.5),
}

CASES = {
    "straight": ["straight_a_yp0.05", "straight_a_yp0.025", "straight_a_yp0.05_fine",
                 "straight_b_yp0.025", "straight_b_yp0.05", "straight_a_yp0.05_E9.0"],
    "mild": ["mild_periodic_yp0.00159", "mild_periodic_yp0.0007", "mild_yp0.00159",
             "mild_yp0.0007"],
    "strong": ["strong_periodic_yp0.001905", "strong_periodic_yp0.0009525", "strong_yp0.001905",
               "strong_yp0.0009525"],
    "hcd": ["straight_b_yp0.025", "hcd_developed", "hcd_uniform"],
    "hcd_fine": ["hcd_fine_uniform"],
}


def lookup(name):
    """The parameters of run NAME, with the derived ones (l = 2 y_p, ncore, dz) filled in."""
    if name not in RUNS:
        sys.exit(f"setup.py: unknown run '{name}' (runs: {', '.join(RUNS)})")
    run = dict(RUNS[name], name=name)
    run["l"] = 2 * run["yp"]
    if run.get("ncore") is None:
        run["ncore"] = round(run["H"] / run["l"]) - 2
    run["dz"] = run["l"]
    run.setdefault("E", 9.8)
    return run


def unit(v):
    n = math.hypot(v[0], v[1])
    return (v[0] / n, v[1] / n)


def miter(corner, n1, n2, l):
    """The point at distance l from both walls meeting at corner, with unit normals n1, n2."""
    c = 1 + n1[0] * n2[0] + n1[1] * n2[1]
    return (corner[0] + l * (n1[0] + n2[0]) / c, corner[1] + l * (n1[1] + n2[1]) / c)


def geometry(run):
    """Stations (4 points each, lines 0..3), columns [(nx, arc midpoint station or None)], and
    the sections post.py samples: {name: ("station", s) or ("x", X, column)}."""
    H, l = run["H"], run["l"]
    if run["kind"] == "periodic":
        length = 4 * run["aspect"] * l
        stations = [[(x, 0.0), (x, l), (x, H - l), (x, H)] for x in (0.0, length)]
        return stations, [(4, None)], {"profile": ("station", 0)}
    if run["kind"] == "curved":
        r = [run["R1"], run["R1"] + l, run["R1"] + H - l, run["R1"] + H]
        theta = math.radians(run["angle"])
        nb = math.ceil(run["angle"] / 90.0)           # bend blocks of at most 90 degrees
        dx = run["aspect"] * l
        rm = run["R1"] + H / 2

        def arc(phi):
            return [(ri * math.sin(phi), ri * math.cos(phi)) for ri in r]

        stations = [[(-run["L1"], ri) for ri in r]] + [arc(theta * m / nb) for m in range(nb + 1)]
        t = (math.cos(theta), -math.sin(theta))         # the bend's exit direction
        stations.append([(p[0] + run["L2"] * t[0], p[1] + run["L2"] * t[1]) for p in stations[-1]])
        columns = [(round(run["L1"] / dx), None)]
        columns += [(round(rm * theta / nb / dx), arc(theta * (m + 0.5) / nb)) for m in range(nb)]
        columns.append((round(run["L2"] / dx), None))
        return stations, columns, {"bend_end": ("station", nb + 1),
                                   "outlet": ("station", nb + 2)}
    # HCD: corners G, F, E, D of the lower wall; the upper wall is flat at y = H
    h1 = 1.5 * math.tan(math.radians(30.0))
    lower = [(0.0, 0.0), (3.0, 0.0), (4.5, h1), (5.5, h1), (7.0, 0.0), (12.0, 0.0)]
    normals = [unit((-(b[1] - a[1]), b[0] - a[0])) for a, b in zip(lower[:-1], lower[1:])]
    stations = []
    for m, p in enumerate(lower):
        if m == 0 or m == len(lower) - 1:
            q = (p[0], p[1] + l)
        else:
            q = miter(p, normals[m - 1], normals[m], l)
        stations.append([p, q, (q[0], H - l), (q[0], H)])
    columns = [(round(math.dist(a, b) / (run["aspect"] * l)), None)
               for a, b in zip(lower[:-1], lower[1:])]
    return stations, columns, {"platform": ("x", 5.0, 2), "exit": ("x", 9.5, 4)}


def rows(run):
    return [1, run["ncore"], 1]


def cell(run, columns, c, w, i, j):
    """Index of cell (column c, row w, i, j) in blockMesh's numbering."""
    ny = rows(run)
    before = sum(nx for nx, _ in columns[:c]) * sum(ny) + columns[c][0] * sum(ny[:w])
    return before + i + columns[c][0] * j


def block_mesh(run):
    stations, columns, _ = geometry(run)
    ny, dz = rows(run), run["dz"]

    def v(s, r, z):
        return 2 * (4 * s + r) + z

    def hexa(c, w):
        return (v(c, w, 0), v(c + 1, w, 0), v(c + 1, w + 1, 0), v(c, w + 1, 0),
                v(c, w, 1), v(c + 1, w, 1), v(c + 1, w + 1, 1), v(c, w + 1, 1))

    def face(*idx):
        return "(" + " ".join(str(i) for i in idx) + ")"

    last = len(columns) - 1
    walls = ("lowerWall", "upperWall") if run["kind"] != "curved" else ("innerWall", "outerWall")
    out = [f"// {run['name']}: made by setup.py (see its docstring for the layout).",
           "FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }",
           "", "scale 1;", "", "vertices", "("]
    for st in stations:
        for p in st:
            for z in (0.0, dz):
                out.append(f"    ({p[0]:.12g} {p[1]:.12g} {z:.12g})")
    out += [");", "", "blocks", "("]
    for c, (nx, _) in enumerate(columns):
        for w in range(3):
            out.append(f"    hex {face(*hexa(c, w))} ({nx} {ny[w]} 1) simpleGrading (1 1 1)")
    out += [");", "", "edges", "("]
    for c, (_, mid) in enumerate(columns):
        if mid is None:
            continue
        for r in range(4):
            for z in (0, 1):
                p = mid[r]
                out.append(f"    arc {v(c, r, z)} {v(c + 1, r, z)} "
                           f"({p[0]:.12g} {p[1]:.12g} {z * dz:.12g})")
    out += [");", "", "boundary", "("]

    def patch(name, ptype, faces, extra=""):
        out.append(f"    {name} {{ type {ptype};{extra} faces ({' '.join(faces)}); }}")

    entry = [face(v(0, w, 0), v(0, w, 1), v(0, w + 1, 1), v(0, w + 1, 0)) for w in range(3)]
    exit_ = [face(v(last + 1, w, 0), v(last + 1, w + 1, 0), v(last + 1, w + 1, 1),
                  v(last + 1, w, 1)) for w in range(3)]
    if run["kind"] == "periodic":
        patch("left", "cyclic", entry, " neighbourPatch right;")
        patch("right", "cyclic", exit_, " neighbourPatch left;")
    else:
        patch("inlet", "patch", entry)
        patch("outlet", "patch", exit_)
    patch(walls[0], "wall", [face(v(c, 0, 0), v(c + 1, 0, 0), v(c + 1, 0, 1), v(c, 0, 1))
                             for c in range(last + 1)])
    patch(walls[1], "wall", [face(v(c, 3, 0), v(c, 3, 1), v(c + 1, 3, 1), v(c + 1, 3, 0))
                             for c in range(last + 1)])
    blocks = [(c, w) for c in range(last + 1) for w in range(3)]
    patch("frontAndBack", "empty",
          [face(*(hexa(c, w)[k] for k in (0, 3, 2, 1))) for c, w in blocks]
          + [face(*(hexa(c, w)[k] for k in (4, 5, 6, 7))) for c, w in blocks])
    out += [");", "", "mergePatchPairs ();", ""]
    return "\n".join(out)


def free_stream(run):
    """SPHinXsys's free-stream entry (and everyone's initial field): k, epsilon."""
    k = 1.5 * (INTENSITY * 1.0) ** 2
    return k, CMU ** 0.75 * k ** 1.5 / (LENGTH_RATIO * run["H"])


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


def write_case(run, d):
    k0, eps0 = free_stream(run)
    u0 = "(1 0 0)" if run["kind"] == "periodic" else "(0 0 0)"
    end = 3000 if run["kind"] == "periodic" else 20000    # iterations at most
    write(os.path.join(d, "system", "blockMeshDict"), block_mesh(run))
    write(os.path.join(d, "system", "caseParams"),
          f"// {run['name']}: initial fields (free stream: k = 3/2 (0.05 U_b)^2, "
          f"epsilon = Cmu^(3/4) k^(3/2) / (0.07 H))\n"
          f"U0 {u0};\nk0 {k0:.9g};\nepsilon0 {eps0:.9g};\n"
          f"endTime {end};\nwriteInterval {300 if run['kind'] == 'periodic' else 100};\n"
          f"E {run['E']:g};\n")
    write(os.path.join(d, "constant", "transportProperties"),
          f"// {run['name']}: nu = U_b H / Re\n"
          "FoamFile { version 2.0; format ascii; class dictionary; object transportProperties; }\n"
          f"\ntransportModel Newtonian;\nnu {run['nu']:.9g};\n")
    if run["kind"] == "periodic":
        write(os.path.join(d, "constant", "fvOptions"),
              "// The body force that keeps the bulk velocity at U_b = 1 (its pressure\n"
              "// gradient is the wall shear stress over delta: u_tau^2 = delta dp/dx).\n"
              "FoamFile { version 2.0; format ascii; class dictionary; object fvOptions; }\n\n"
              "momentumSource\n{\n    type meanVelocityForce;\n    selectionMode all;\n"
              "    fields (U);\n    Ubar (1 0 0);\n}\n")


def profile(scratch, src):
    """The fully developed profile of periodic run src: [(y, u, k, epsilon)] over the height."""
    run = lookup(src)
    d = os.path.join(scratch, src)
    t = foamio.latest_time(d)
    c = foamio.internal(os.path.join(d, "0", "C"))
    u = foamio.internal(os.path.join(d, t, "U"))
    k = foamio.internal(os.path.join(d, t, "k"))
    e = foamio.internal(os.path.join(d, t, "epsilon"))
    _, columns, _ = geometry(run)
    out = []
    for w, ny in enumerate(rows(run)):
        for j in range(ny):
            n = cell(run, columns, 0, w, 0, j)
            out.append((c[n][1], u[n][0], k[n], e[n]))
    return out


def interp(xs, ys, x):
    """Linear interpolation in increasing xs; x may pass an end by round-off (1e-9 of the span)."""
    tol = 1e-9 * (xs[-1] - xs[0])
    if xs[0] - tol <= x <= xs[0]:
        return ys[0]
    if xs[-1] <= x <= xs[-1] + tol:
        return ys[-1]
    for a in range(len(xs) - 1):
        if xs[a] <= x <= xs[a + 1]:
            f = (x - xs[a]) / (xs[a + 1] - xs[a])
            return ys[a] + f * (ys[a + 1] - ys[a])
    raise ValueError(f"{x} outside [{xs[0]}, {xs[-1]}]")


def write_inlet(run, d):
    """The entry values: the source run's profile at the entry faces' distances from the first
    wall (the same cell heights, so the values are the source's own), or the free stream."""
    out = os.path.join(d, "constant", "inlet")
    if run["src"] == "uniform":
        k, e = free_stream(run)
        write(os.path.join(out, "U"), "value uniform (1 0 0);\n")
        write(os.path.join(out, "k"), f"value uniform {k:.9g};\n")
        write(os.path.join(out, "epsilon"), f"value uniform {e:.9g};\n")
        return
    prof = profile(os.path.dirname(os.path.abspath(d)), run["src"])
    ys = [p[0] for p in prof]
    stations, _, _ = geometry(run)
    a, b = stations[0][0], stations[0][3]
    e = unit((b[0] - a[0], b[1] - a[1]))
    faces = foamio.patch_value(os.path.join(d, "0", "C"), "inlet")
    s = [(f[0] - a[0]) * e[0] + (f[1] - a[1]) * e[1] for f in faces]
    u = [interp(ys, [p[1] for p in prof], x) for x in s]
    k = [interp(ys, [p[2] for p in prof], x) for x in s]
    eps = [interp(ys, [p[3] for p in prof], x) for x in s]
    n = len(s)
    write(os.path.join(out, "U"), f"value nonuniform List<vector> {n}\n(\n"
          + "".join(f"({x:.12g} 0 0)\n" for x in u) + ");\n")
    write(os.path.join(out, "k"), f"value nonuniform List<scalar> {n}\n(\n"
          + "".join(f"{x:.12g}\n" for x in k) + ");\n")
    write(os.path.join(out, "epsilon"), f"value nonuniform List<scalar> {n}\n(\n"
          + "".join(f"{x:.12g}\n" for x in eps) + ");\n")


def main():
    if len(sys.argv) == 3 and sys.argv[1] == "list":
        if sys.argv[2] not in CASES:
            sys.exit(f"setup.py: unknown case '{sys.argv[2]}' (cases: {', '.join(CASES)})")
        print(" ".join(CASES[sys.argv[2]]))
    elif len(sys.argv) == 4 and sys.argv[1] == "case":
        write_case(lookup(sys.argv[2]), sys.argv[3])
    elif len(sys.argv) == 4 and sys.argv[1] == "inlet":
        write_inlet(lookup(sys.argv[2]), sys.argv[3])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
