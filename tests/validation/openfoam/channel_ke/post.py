#!/usr/bin/env python3
"""CSV references from run.sh's runs (standard library only).

Reads each run folder SCRATCH/RUN (setup.py names the runs of each case and rebuilds their
block structure; 0/C holds the cell centres, the latest time the fields, log.simpleFoam the
residuals) and writes OUTDIR/openfoam_channel_<case>.csv for each CASE (every case whose runs are
all in SCRATCH without).
    post.py SCRATCH OUTDIR [CASE...]
Samples are cell values, never interpolated across the wall cell:
- straight: the cells of one column, lower half (y = distance from the wall);
- curved: 'bend_end', the mean of the last bend cells and the first exit cells of each row (linear
  interpolation onto the bend's exit plane), and 'outlet', the last cells (dx/2 before the exit,
  where zero gradient makes the exit values theirs); s = distance from the inner wall, U = the
  velocity along the section's channel direction, U_r across it (towards the outer wall);
- hcd: per row, linear interpolation between the two cells whose centres bracket the line.
"""
import math
import os
import re
import sys

import foamio
import setup

HEAD = ("# OpenFOAM v1912 (Debian package openfoam), simpleFoam (SIMPLEC, steady), standard "
        "k-epsilon (Cmu 0.09, C1 1.44, C2 1.92, sigmak 1, sigmaEps 1.3) with the wall functions "
        "nutkWallFunction, kqRWallFunction and epsilonWallFunction (kappa 0.41, E 9.8: OpenFOAM's "
        "default and SPHinXsys's; the paper's eq 11 prints E = 0.9, a typo for 9.0 or 9.8; y*_lam "
        "= 11.53); "
        "schemes linearUpwind (U, k, epsilon), linear elsewhere; 2-D, one cell "
        "thick (empty front and back); every wall cell is 2 y_p high normal to its wall, so the "
        "first cell centre is at y_p (Wang, Sun & Hu: the FVM's first cell at y_p). Runs with an "
        "entry stop when every initial residual is below 1e-8; continuing mild_yp0.0007, "
        "strong_yp0.0009525 and hcd_developed from there to 1e-10 moved U by at most 1.3e-6 and k "
        "by 1.4e-5 (relative).\n")
RESIDUAL = 1e-8
FIELDS = ("Ux", "Uy", "p", "k", "epsilon")


def log_info(d):
    """Iterations, residual history {field: [(iteration, initial residual)]}, the mean-velocity
    pressure gradient per iteration, converged (bool), wall time (s)."""
    text = open(os.path.join(d, "log.simpleFoam")).read()
    hist = {f: [] for f in FIELDS}
    grad = []
    it = 0
    for block in text.split("\nTime = ")[1:]:
        it = int(block.split("\n", 1)[0])
        for f in FIELDS:
            m = re.search(r"Solving for " + f + r", Initial residual = ([\d.eE+-]+)", block)
            if m:
                hist[f].append((it, float(m.group(1))))
        m = re.findall(r"pressure gradient = ([\d.eE+-]+)", block)
        if m:
            grad.append((it, float(m[-1])))
    conv = re.search(r"SIMPLE solution converged in (\d+) iterations", text)
    clock = re.findall(r"ClockTime = (\d+) s", text)
    return dict(its=it, hist=hist, grad=grad, converged=conv is not None,
                clock=int(clock[-1]) if clock else None)


def below(hist, fields, tol=RESIDUAL):
    """First iteration from which every field's initial residual stays below tol."""
    first = 0
    for f in fields:
        h = hist[f]
        last_above = max((it for it, r in h if r >= tol), default=0)
        if last_above == h[-1][0]:
            return None
        first = max(first, last_above + 1)
    return first


def final(hist, fields):
    return ", ".join(f"{f} {hist[f][-1][1]:.1e}" for f in fields)


def load(scratch, name):
    run = setup.lookup(name)
    d = os.path.join(scratch, name)
    t = foamio.latest_time(d)
    f = {key: foamio.internal(os.path.join(d, t, key)) for key in ("U", "k", "epsilon", "nut")}
    f["C"] = foamio.internal(os.path.join(d, "0", "C"))
    stations, columns, sections = setup.geometry(run)
    return dict(run=run, d=d, t=t, f=f, log=log_info(d), stations=stations, columns=columns,
                sections=sections)


def rows_cells(r, c, i):
    """Cells of column c at index i, from the first wall to the second."""
    run, columns = r["run"], r["columns"]
    return [setup.cell(run, columns, c, w, i, j)
            for w, ny in enumerate(setup.rows(run)) for j in range(ny)]


def mesh_words(r):
    run, columns = r["run"], r["columns"]
    n = sum(setup.rows(run))
    core = (run["H"] - 2 * run["l"]) / run["ncore"]
    return (f"{n} x {sum(nx for nx, _ in columns)} cells (across x along): wall cells "
            f"{run['l']:.6g} high, core {run['ncore']} x {core:.6g}")


def u_tau_wall(r, patch):
    """Friction velocity sqrt(|tau_w|) at each face of a wall patch, with the face centres."""
    tau = foamio.patch_value(os.path.join(r["d"], r["t"], "wallShearStress"), patch)
    cf = foamio.patch_value(os.path.join(r["d"], "0", "C"), patch)
    return [(c, math.sqrt(math.hypot(t[0], t[1]))) for c, t in zip(cf, tau)]


def convergence_words(r):
    lg = r["log"]
    if lg["converged"]:
        return (f"converged: initial residuals of p, U, k and epsilon below {RESIDUAL:g} after "
                f"{lg['its']} iterations (last: {final(lg['hist'], FIELDS)})")
    return f"NOT converged after {lg['its']} iterations (last: {final(lg['hist'], FIELDS)})"


# straight --------------------------------------------------------------------------------------

def straight(scratch, names):
    head, rows = [], []
    for name in names:
        r = load(scratch, name)
        run, f, lg = r["run"], r["f"], r["log"]
        cells = rows_cells(r, 0, 0)
        y = [f["C"][n][1] for n in cells]
        u = [f["U"][n][0] for n in cells]
        delta = run["H"] / 2
        tau = [t for _, t in u_tau_wall(r, "lowerWall") + u_tau_wall(r, "upperWall")]
        ut = sum(tau) / len(tau)
        ut_dp = math.sqrt(lg["grad"][-1][1] * delta)
        back = [g for it, g in lg["grad"] if it <= lg["its"] - 1000]
        drift = abs(math.sqrt(back[-1] * delta) / ut_dp - 1) if back else float("nan")
        ystar = foamio.patch_value(os.path.join(r["d"], r["t"], "yPlus"), "lowerWall")
        ystar = sum(ystar) / len(ystar)
        uc = setup.interp(y, u, delta)
        sym = max(abs(u[j] - u[-1 - j]) for j in range(len(u)))
        steady = below(lg["hist"], ("Ux", "k", "epsilon"))
        n = len(cells)
        mesh = f"uniform_{n}" if run["ncore"] + 2 == n and abs(
            (run["H"] - 2 * run["l"]) / run["ncore"] - run["l"]) < 1e-12 else f"refined_{n}"
        if run["E"] != 9.8:       # a sensitivity run: its numbers in the header, no rows
            head.append(
                f"# {name}: as straight_a_yp0.05 but with E = {run['E']:g}: u_tau = {ut:.6f}, "
                f"y+ = {ut * run['yp'] / run['nu']:.3f}, y* = {ystar:.3f}, centreline U = "
                f"{uc:.5f} (no rows)")
            print(f"{name}: u_tau {ut:.5f}, y+ {ut * run['yp'] / run['nu']:.2f}, y* {ystar:.2f}",
                  file=sys.stderr)
            continue
        head.append(
            f"# {name}: setting {run['setting']}, nu = {run['nu']:g}, y_p = {run['yp']:g}, mesh "
            f"{mesh}: {mesh_words(r)}, periodic length {r['stations'][1][0][0]:g} (4 cells); "
            f"steady: initial residuals of Ux, k and epsilon below {RESIDUAL:g} from iteration "
            f"{steady}, {final(lg['hist'], ('Ux', 'k', 'epsilon'))} at {lg['its']} (v and p are "
            f"round-off, their normalised residuals meaningless); u_tau = {ut:.6f} from the wall "
            f"shear stress, {ut_dp:.6f} from the driving pressure gradient (delta dp/dx), "
            f"changed by {drift:.1e} over the last 1000 iterations; y+ = u_tau y_p / nu = "
            f"{ut * run['yp'] / run['nu']:.3f}, y* = Cmu^(1/4) k_p^(1/2) y_p / nu = {ystar:.3f} "
            f"(OpenFOAM's yPlus); Re_tau = u_tau delta / nu = {ut * delta / run['nu']:.1f}; "
            f"centreline U = {uc:.5f}; U symmetric about the centreline to {sym:.0e}; wall time "
            f"{lg['clock']} s")
        for j in range(n):
            if y[j] < delta:
                c = cells[j]
                rows.append(f"{run['setting']},{run['nu']:g},{run['yp']:g},{mesh},{ut:.6f},"
                            f"{y[j]:.6g},{u[j]:.6f},{f['k'][c]:.6e},{f['epsilon'][c]:.6e},"
                            f"{f['nut'][c]:.6e}")
        print(f"{name}: u_tau {ut:.5f} (dp/dx {ut_dp:.5f}), y+ {ut * run['yp'] / run['nu']:.2f}, "
              f"y* {ystar:.2f}, U_c {uc:.4f}, steady from {steady}, {lg['clock']} s",
              file=sys.stderr)
    intro = (HEAD +
             "# Wang, Sun & Hu sec 5.1: the fully developed straight channel, periodic (cyclic) in "
             "x, half-height delta = 1 (H = 2), bulk velocity U_b = 1 held by fvOptions "
             "meanVelocityForce. Setting a: nu = 1e-4 (Lee & Moser's Re_tau = 543.5); setting b: "
             "nu = 5e-5 (Re = U_b H / nu = 40000). The paper's FVM: u_tau = 0.0530, y+ = 26.40 at "
             "the wall-adjacent location (its SPH: 0.0536, 26.69).\n")
    cols = ("# Columns: setting; nu; y_p; mesh (uniform_N: N equal cells across H; refined_N: the "
            "same wall cells and a 5x finer core); u_tau (wall shear stress); y = distance from "
            "the wall of the cell centre (lower half); U; k; epsilon; nut.\n"
            "setting,nu,y_p,mesh,u_tau,y,U,k,epsilon,nut\n")
    return intro, head, cols, rows


# curved ----------------------------------------------------------------------------------------

def section(r, key):
    """Cells (pairs to average) of a curved run's section, its origin point (inner wall), the
    unit vector across (inner to outer) and along the channel."""
    stations, columns = r["stations"], r["columns"]
    s = r["sections"][key][1]
    last = len(columns) - 1
    if s == len(stations) - 1:
        pairs = [(n, n) for n in rows_cells(r, last, columns[last][0] - 1)]
    else:
        pairs = list(zip(rows_cells(r, s - 1, columns[s - 1][0] - 1), rows_cells(r, s, 0)))
    a, b = stations[s][0], stations[s][3]
    e = setup.unit((b[0] - a[0], b[1] - a[1]))
    return pairs, a, e, (e[1], -e[0])


def curved(scratch, names):
    head, rows = [], []
    for name in names:
        r = load(scratch, name)
        run, f, lg = r["run"], r["f"], r["log"]
        H = run["H"]
        src = load(scratch, run["src"])
        tau_src = [t for _, t in u_tau_wall(src, "lowerWall")]
        words = []
        # the entry: the periodic run's developed profile, as setup.py inlet imposed it
        for y, u, k, e in setup.profile(scratch, run["src"]):
            rows.append(f"{run['yp']:g},{sum(setup.rows(run))}x"
                        f"{sum(nx for nx, _ in r['columns'])},entry,{y:.6e},{y / H:.6f},"
                        f"{u:.6f},{0.0:.6e},{k:.6e},{e:.6e},{0.09 * k * k / e:.6e}")
        for key in ("bend_end", "outlet"):
            pairs, a, e, t = section(r, key)
            best = None
            for n1, n2 in pairs:

                def mean(v):
                    return tuple((p + q) / 2 for p, q in zip(v[n1], v[n2])) if isinstance(
                        v[n1], tuple) else (v[n1] + v[n2]) / 2
                c, u = mean(f["C"]), mean(f["U"])
                s = (c[0] - a[0]) * e[0] + (c[1] - a[1]) * e[1]
                ut = u[0] * t[0] + u[1] * t[1]
                ur = u[0] * e[0] + u[1] * e[1]
                rows.append(f"{run['yp']:g},{sum(setup.rows(run))}x"
                            f"{sum(nx for nx, _ in r['columns'])},{key},{s:.6e},{s / H:.6f},"
                            f"{ut:.6f},{ur:.6e},{mean(f['k']):.6e},{mean(f['epsilon']):.6e},"
                            f"{mean(f['nut']):.6e}")
                if best is None or ut > best[1]:
                    best = (s / H, ut)
            inner = min(u_tau_wall(r, "innerWall"), key=lambda q: math.dist(q[0][:2], a))[1]
            b = r["stations"][r["sections"][key][1]][3]
            outer = min(u_tau_wall(r, "outerWall"), key=lambda q: math.dist(q[0][:2], b))[1]
            words.append(f"{key}: U_max {best[1]:.4f} at s/H = {best[0]:.3f}, u_tau inner "
                         f"{inner:.5f} outer {outer:.5f}")
        head.append(
            f"# {name}: y_p = {run['yp']:g}, nu = {run['nu']:.6g}, mesh {mesh_words(r)}, "
            f"streamwise cells {run['aspect']} x 2 y_p long (on the mean radius in the bend); "
            f"entry from {run['src']} (u_tau {sum(tau_src) / len(tau_src):.5f}); "
            f"{convergence_words(r)}; " + "; ".join(words) +
            f"; wall time {lg['clock']} s")
        print(f"{name}: " + "; ".join(words) + f", {lg['its']} its, "
              f"{'converged' if lg['converged'] else 'NOT converged'}, {lg['clock']} s",
              file=sys.stderr)
    run = setup.lookup(names[0])
    H = run["H"]
    intro = (HEAD +
             f"# Wang, Sun & Hu sec 5.2, Table 1, the {run['setting']}ly curved channel: "
             f"H = {H:g} m, "
             f"inner radius R1 = {run['R1'] / H:g} H, outer R2 = {run['R1'] / H + 1:g} H, straight "
             f"entry {run['L1'] / H:g} H, bend of {run['angle']:g} degrees, straight exit "
             f"{run['L2'] / H:g} H; U_b = 1 m/s, nu = U_b H / Re with Re = {round(H / run['nu'])}. "
             "Entry: the fully developed profile (U, k, epsilon) of a periodic straight channel "
             "run (meanVelocityForce, U_b = 1) at the same H, nu and y_p on the same cell heights "
             "across, copied face by face onto the entry (setup.py inlet; a linear interpolation "
             "in the distance from the inner wall, exact here); exit: zero gradient with p = 0. "
             "Streamwise cells 4 x 2 y_p long: 2 x 2 y_p moves U of strong_yp0.0009525 by at most "
             "4.9e-4 and k by 0.4%.\n")
    cols = ("# Columns: y_p; mesh (cells across x along); section (entry: the developed profile "
            "imposed on the entry, its periodic run's cells, nut = Cmu k^2 / epsilon; bend_end: the "
            "bend's exit plane; outlet: the last cells before the exit); s = distance from the inner wall "
            "(cell centre); s/H; U = velocity along the channel (tangential); U_r = velocity "
            "across it, towards the outer wall; k; epsilon; nut.\n"
            "y_p,mesh,section,s,s_over_H,U,U_r,k,epsilon,nut\n")
    return intro, head, cols, rows


# hcd -------------------------------------------------------------------------------------------

def line(r, X, c):
    """Per row of column c: (x, y, U, k, epsilon, nut) interpolated to x = X between the two cells
    whose centres bracket it."""
    out = []
    nx = r["columns"][c][0]
    cols = [rows_cells(r, c, i) for i in range(nx)]
    f = r["f"]
    for j in range(len(cols[0])):
        xs = [f["C"][cols[i][j]][0] for i in range(nx)]
        i = max(i for i in range(nx - 1) if xs[i] <= X)
        n1, n2 = cols[i][j], cols[i + 1][j]
        w = (X - xs[i]) / (xs[i + 1] - xs[i])

        def lerp(v):
            if isinstance(v[n1], tuple):
                return tuple(p + w * (q - p) for p, q in zip(v[n1], v[n2]))
            return v[n1] + w * (v[n2] - v[n1])
        out.append((X, lerp(f["C"])[1], lerp(f["U"]), lerp(f["k"]), lerp(f["epsilon"]),
                    lerp(f["nut"])))
    return out


def recirculation(r, w, j):
    """x ranges where the wall cells of row (w, j) flow backwards (U_x < 0)."""
    f, ranges, start = r["f"], [], None
    cells = [n for c, (nx, _) in enumerate(r["columns"]) for i in range(nx)
             for n in [setup.cell(r["run"], r["columns"], c, w, i, j)]]
    for n in cells:
        x, back = f["C"][n][0], f["U"][n][0] < 0
        if back and start is None:
            start = x
        if not back and start is not None:
            ranges.append((start, prev))
            start = None
        prev = x
    if start is not None:
        ranges.append((start, prev))
    return ", ".join(f"{a:.2f} to {b:.2f}" for a, b in ranges) or "none"


def wall_distance(wall, x, y):
    """The distance of (x, y) from the polyline wall [(x, y), ...]."""
    best = math.inf
    for (ax, ay), (bx, by) in zip(wall, wall[1:]):
        dx, dy = bx - ax, by - ay
        t = min(max(((x - ax) * dx + (y - ay) * dy) / (dx * dx + dy * dy), 0.0), 1.0)
        best = min(best, math.hypot(x - ax - t * dx, y - ay - t * dy))
    return best


def hcd(scratch, names):
    head, rows = [], []
    for name in names:
        r = load(scratch, name)
        run, lg = r["run"], r["log"]
        h1 = r["stations"][2][0][1]
        for key, (_, X, c) in r["sections"].items():
            pts = line(r, X, c)
            floor = h1 if key == "platform" else 0.0
            for x, y, u, k, e, nut in pts:
                rows.append(f"{run['src'] if run['src'] == 'uniform' else 'developed'},{key},"
                            f"{x:g},{y:.6f},{y - floor:.6f},{u[0]:.6f},{u[1]:.6e},{k:.6e},"
                            f"{e:.6e},{nut:.6e}")
        # the lower wall's wall cells from the entry to the exit: the near-wall flow along it
        # (y_wall: the cell centre's distance from the wall, y_p by construction but at the
        # platform's corners)
        wall = [st[0] for st in r["stations"]]  # the lower wall's corners (setup.geometry)
        f = r["f"]
        for c, (nx, _) in enumerate(r["columns"]):
            for i in range(nx):
                n = setup.cell(run, r["columns"], c, 0, i, 0)
                x, y = f["C"][n][0], f["C"][n][1]
                rows.append(f"{run['src'] if run['src'] == 'uniform' else 'developed'},floor,"
                            f"{x:g},{y:.6f},{wall_distance(wall, x, y):.6f},{f['U'][n][0]:.6f},"
                            f"{f['U'][n][1]:.6e},{f['k'][n]:.6e},{f['epsilon'][n]:.6e},"
                            f"{f['nut'][n]:.6e}")
        yp = {w: foamio.patch_value(os.path.join(r["d"], r["t"], "yPlus"), w)
              for w in ("lowerWall", "upperWall")}
        ut = {w: [t for _, t in u_tau_wall(r, w)] for w in ("lowerWall", "upperWall")}
        ny = setup.rows(run)
        words = (f"y* (OpenFOAM's yPlus, k-based as the paper's eq 10) lower wall "
                 f"{min(yp['lowerWall']):.1f} to {max(yp['lowerWall']):.1f}, upper "
                 f"{min(yp['upperWall']):.1f} to {max(yp['upperWall']):.1f}; y+ = u_tau y_p / nu "
                 f"lower {min(ut['lowerWall']) * run['yp'] / run['nu']:.1f} to "
                 f"{max(ut['lowerWall']) * run['yp'] / run['nu']:.1f}, upper "
                 f"{min(ut['upperWall']) * run['yp'] / run['nu']:.1f} to "
                 f"{max(ut['upperWall']) * run['yp'] / run['nu']:.1f}; backflow (U_x < 0) in the "
                 f"wall cells at x = {recirculation(r, 0, 0)} (lower wall), "
                 f"{recirculation(r, 2, ny[2] - 1)} (upper wall)")
        entry = ("the fully developed profile of straight_b_yp0.025 (Re 40000, y_p 0.025, the "
                 "same 40 cells across), copied face by face" if run["src"] != "uniform" else
                 "SPHinXsys's: uniform U = 1, k = 3/2 (0.05 U)^2 = 3.75e-3, epsilon = Cmu^(3/4) "
                 "k^(3/2) / (0.07 H) = 2.695e-4")
        gap = run["H"] - h1 - 2 * run["l"]
        head.append(f"# {name}: entry {entry}; mesh {mesh_words(r)} (the core is finer over the "
                    f"platform: {run['ncore']} cells in {gap:.4g}), streamwise cells "
                    f"{run['aspect'] * run['l']:g} on the lower wall; "
                    f"{convergence_words(r)}; {words}; wall time {lg['clock']} s")
        print(f"{name}: {words}, {lg['its']} its, "
              f"{'converged' if lg['converged'] else 'NOT converged'}, {lg['clock']} s",
              file=sys.stderr)
    intro = (HEAD +
             "# Wang, Sun & Hu sec 5.3, the half converging-diverging (HCD) channel, geometry and "
             "monitoring lines of SPHinXsys tests/extra_source_and_tests/2d_turbulent_HCD_channel "
             "(github.com/Xiangyu-Hu/SPHinXsys): H = 2, flat upper wall y = 2, lower wall y = 0 "
             "with a platform: ramp up at 30 degrees from x = 3 to 4.5, top y = 1.5 tan 30 = "
             "0.866025 from 4.5 to 5.5, ramp down to 7; entry x = 0 (SPHinXsys's point A), exit "
             "x = 12 (zero gradient, p = 0); U_b = 1, nu = U_b H / Re = 5e-5 (Re = 40000), "
             "y_p = 0.025. "
             "SPHinXsys's lines: x = 5 (mid platform, platform to upper wall) and x = 9.5 (mid "
             "exit section, wall to wall).\n")
    cols = ("# Columns: inlet (developed or uniform); line (platform: x = 5; exit: x = 9.5; floor: "
            "the lower wall's wall cells from the entry to the exit, one per column of cells); x; "
            "y (cell-centre row); y_wall = y - lower wall height (0.866025 on the platform; on "
            "the floor line the centre's distance from the wall); U; V; k; epsilon; nut.\n"
            "inlet,line,x,y,y_wall,U,V,k,epsilon,nut\n")
    return intro, head, cols, rows


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    scratch, outdir = sys.argv[1], sys.argv[2]
    wanted = sys.argv[3:]
    make = {"straight": straight, "mild": curved, "strong": curved, "hcd": hcd, "hcd_fine": hcd}
    for case in make:
        names = [n for n in setup.CASES[case] if case == "straight" or n.startswith(case)]
        names = [n for n in names if "periodic" not in n]
        have = all(os.path.exists(os.path.join(scratch, n, "log.simpleFoam")) for n in names)
        if (wanted and case not in wanted) or (not wanted and not have):
            continue
        intro, head, cols, rows = make[case](scratch, names)
        path = os.path.join(outdir, f"openfoam_channel_{case}.csv")
        with open(path, "w") as out:
            out.write(intro)
            out.write("\n".join(head) + "\n")
            out.write(f"# Made by: tests/validation/openfoam/channel_ke/run.sh {case}\n")
            out.write(cols)
            out.write("\n".join(rows) + "\n")
        print(f"wrote {path}", file=sys.stderr)


if __name__ == "__main__":
    main()
