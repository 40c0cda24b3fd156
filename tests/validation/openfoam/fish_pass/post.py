#!/usr/bin/env python3
"""The CSV reference of run.sh's fish-pass runs (standard library only).

    post.py SCRATCH OUT.csv COMMAND H_MAIN [H_OTHER...]

Reads SCRATCH/h<H> for each cell size (0/C: cell centres; the time folders: ASCII fields;
postProcessing: the per-step flow rate and max |U|; log.pimpleFoam) and writes OUT.csv: the main
mesh's profiles at t = 20 s, the other meshes only as sensitivity figures in the header.
Sampling reads the cell fields: bilinear interpolation between the four cell centres around the
point (uniform square cells, so the cell of centre (x, y) is (floor(x/h), floor(y/h))). P4 is the
wall y = 0: p there is its zeroGradient face value, i.e. the wall cell's p, linear in x between
the face (= wall-cell) centres; U is the wall's (no slip, 0); k, epsilon, nut are the wall cells'.
p in Pa: rho p_kinematic less the mean over the P1-P3 points (p is defined up to a constant).
"""
import math
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.append(os.path.join(here, "..", "channel_ke"))   # its foamio (setup is ours: here first)
import foamio  # noqa: E402
import setup  # noqa: E402

END = 20.0
WINDOW = (15.0, 20.0)          # the steadiness window and that of the time means
STEADY_TOL = 1e-3              # steady: Q, max|U| and the mean k move less (relative) over WINDOW
SECTIONS = (("P1", 1.6), ("P2", 2.2), ("P3", 2.8))
Y_SAMPLES = [0.025 * j for j in range(1, 96)]
P4_X = [1.175 + 0.05 * m for m in range(37)]
Q_X = 2.2
FIELDS = ("U", "p", "k", "epsilon", "nut")


def tname(t):
    return f"{t:g}"


class Run:
    def __init__(self, scratch, h):
        self.h = h
        self.d = os.path.join(scratch, f"h{h:g}")
        c = foamio.internal(os.path.join(self.d, "0", "C"))
        self.nx, self.ny = round(setup.L / h), round(setup.WIDTH / h)
        self.cell = {(math.floor(x / h), math.floor(y / h)): n for n, (x, y, _) in enumerate(c)}
        self.ncells = len(c)
        self.times = sorted(float(n) for n in os.listdir(self.d)
                            if re.fullmatch(r"[0-9.e+-]+", n) and float(n) > 0)
        self.f = self.fields(END)
        self.log = open(os.path.join(self.d, "log.pimpleFoam")).read()

    def fields(self, t, names=FIELDS):
        return {k: foamio.internal(os.path.join(self.d, tname(t), k)) for k in names}

    def at(self, v, x, y):
        """Bilinear interpolation of cell field v at (x, y); periodic in x; at a wall (a point
        between the wall and the first cell centre) the wall cell's value across."""
        h = self.h
        fx, fy = x / h - 0.5, y / h - 0.5
        i0, j0 = math.floor(fx), math.floor(fy)
        wx, wy = fx - i0, fy - j0
        total, wsum = None, 0.0
        for di, a in ((0, 1 - wx), (1, wx)):
            for dj, b in ((0, 1 - wy), (1, wy)):
                n = self.cell.get(((i0 + di) % self.nx, j0 + dj))
                if n is None or a * b == 0:
                    continue
                val = v[n]
                w = a * b
                total = (tuple(w * q for q in val) if total is None else
                         tuple(s + w * q for s, q in zip(total, val))) if isinstance(val, tuple) \
                    else (w * val if total is None else total + w * val)
                wsum += w
        if total is None:
            raise ValueError(f"h {h}: no fluid cell around ({x}, {y})")
        return tuple(s / wsum for s in total) if isinstance(total, tuple) else total / wsum

    def flow_rate(self, u):
        """Integral over y of U_x on x = Q_X (midpoint rule on the cell rows)."""
        return sum(self.at(u, Q_X, (j + 0.5) * self.h)[0] for j in range(self.ny)) * self.h

    def history(self):
        """[(t, Q at x = 2.2, max |U|, mean k over the pool)] at every written time (equal
        cells: the plain mean is the area mean)."""
        out = []
        for t in self.times:
            f = self.fields(t, ("U", "k"))
            out.append((t, self.flow_rate(f["U"]),
                        max(math.sqrt(a * a + b * b) for a, b, _ in f["U"]),
                        sum(f["k"]) / len(f["k"])))
        return out

    def step_series(self):
        """Every time step's flow rate through the cyclic patch (sum phi / dz) and max |U|."""
        def dat(name, col):
            path = os.path.join(self.d, "postProcessing", name, "0",
                                "surfaceFieldValue.dat" if name == "flowRate" else
                                "fieldMinMax.dat")
            rows = [ln.split() for ln in open(path) if not ln.startswith("#")]
            return [(float(r[0]), float(r[col])) for r in rows if r]
        q = [(t, v / self.h) for t, v in dat("flowRate", 1)]
        return q, dat("maxU", 2)

    def samples(self, f, mean=False):
        """Rows (line, x, y, s, U_x, U_y, p, k, epsilon, nut), p kinematic, not yet levelled."""
        sfx = "Mean" if mean else ""
        u, p, k, e, nut = (f[n + sfx] for n in FIELDS)
        rows = []
        for name, x in SECTIONS:
            for y in Y_SAMPLES:
                uu = self.at(u, x, y)
                rows.append([name, x, y, y - Y_SAMPLES[0], uu[0], uu[1], self.at(p, x, y),
                             self.at(k, x, y), self.at(e, x, y), self.at(nut, x, y)])
        yw = self.h / 2                         # the wall cells' centres
        for x in P4_X:
            rows.append(["P4", x, 0.0, x - P4_X[0], 0.0, 0.0, self.at(p, x, yw),
                         self.at(k, x, yw), self.at(e, x, yw), self.at(nut, x, yw)])
        return rows

    def clock(self):
        m = re.findall(r"ExecutionTime = ([\d.]+) s\s+ClockTime = (\d+) s", self.log)
        return float(m[-1][0]), int(m[-1][1])

    def steps(self):
        dts = [float(x) for x in re.findall(r"^deltaT = ([\d.eE+-]+)", self.log, re.M)]
        co = [float(x) for x in re.findall(r"Courant Number mean: \S+ max: (\S+)", self.log)]
        return len(re.findall(r"^Time = ", self.log, re.M)), min(dts), max(dts), max(co[1:])

    def bounding(self):
        """Time steps where k or epsilon went negative and was bounded, and the last time."""
        times = [float(m) for m in re.findall(r"^Time = (\S+)\n(?:(?!^Time = ).*\n)*?bounding",
                                               self.log, re.M)]
        return len(times), max(times, default=0.0)

    def residuals(self):
        last = self.log.rsplit("\nTime = ", 1)[1]
        out = []
        for fld in ("Ux", "Uy", "p", "k", "epsilon"):
            m = re.findall(r"Solving for " + fld + r", Initial residual = ([\d.eE+-]+)", last)
            out.append(f"{fld} {float(m[0]):.1e}")
        return ", ".join(out)

    def yplus(self):
        vals = []
        for patch in ("lowerWall", "upperWall", "baffleWall"):
            v = foamio.patch_value(os.path.join(self.d, tname(END), "yPlus"), patch)
            vals += v if isinstance(v, list) else [v]
        return min(vals), max(vals)


def level(rows):
    """p in Pa, less the mean over the P1-P3 rows."""
    ref = sum(r[6] for r in rows if r[0] != "P4") / sum(1 for r in rows if r[0] != "P4")
    for r in rows:
        r[6] = setup.RHO * (r[6] - ref)
    return setup.RHO * ref


def window(series):
    vals = [v for t, v in series if WINDOW[0] - 1e-9 <= t <= WINDOW[1] + 1e-9]
    mean = sum(vals) / len(vals)
    return min(vals), max(vals), mean, (max(vals) - min(vals)) / abs(mean)


def compare(a, b):
    """RMS and max |difference| of |U|, k, p over the P1-P3 rows of two sample sets."""
    out = {}
    for name, get in (("|U|", lambda r: math.hypot(r[4], r[5])), ("k", lambda r: r[7]),
                      ("p", lambda r: r[6])):
        d = [get(p) - get(q) for p, q in zip(a, b) if p[0] != "P4"]
        m = max(range(len(d)), key=lambda i: abs(d[i]))
        ref = max(abs(get(p)) for p in a if p[0] != "P4")
        out[name] = (math.sqrt(sum(x * x for x in d) / len(d)), abs(d[m]), a[m][0], a[m][2], ref)
    return out


def describe(run, hist, q_step, u_step):
    ex, clock = run.clock()
    nsteps, dtmin, dtmax, comax = run.steps()
    q20, u20 = hist[-1][1], hist[-1][2]
    qw, uw = window(q_step), window(u_step)
    qh = window([(t, q) for t, q, _, _ in hist])
    uh = window([(t, u) for t, _, u, _ in hist])
    k15 = [k for t, _, _, k in hist if abs(t - WINDOW[0]) < 1e-9][0]
    yp = run.yplus()
    nb, tb = run.bounding()
    return dict(
        steady=max(qw[3], uw[3], abs(hist[-1][3] / k15 - 1)) < STEADY_TOL,
        q20=q20, u20=u20, clock=clock,
        text=(f"cells of side {run.h:g} m: {run.nx} x {run.ny} less the baffles = {run.ncells} "
              f"cells; {nsteps} time steps, deltaT {dtmin:.2e} to {dtmax:.2e} s (max Co "
              f"{comax:.2f}); k or epsilon bounded (negative values clipped) in {nb} steps, the last at "
              f"t = {tb:.2f} s; initial residuals of the last step {run.residuals()}; at t = 20 s "
              f"Q(x = 2.2) = integral of U_x over y = {q20:.5f} m^2/s, max |U| = {u20:.4f} m/s, "
              f"y* (OpenFOAM's yPlus, all walls) {yp[0]:.0f} to {yp[1]:.0f}; over 15-20 s: Q at "
              f"the written times (every 0.5 s) {qh[0]:.5f} to {qh[1]:.5f} (range "
              f"{100 * qh[3]:.2g}% of the mean), every time step (sum of phi on the cyclic patch "
              f"/ dz) {qw[0]:.5f} to {qw[1]:.5f} ({100 * qw[3]:.2g}%); max |U| written "
              f"{uh[0]:.4f} to {uh[1]:.4f} ({100 * uh[3]:.2g}%), every step {uw[0]:.4f} to "
              f"{uw[1]:.4f} ({100 * uw[3]:.2g}%); mean k over the pool {k15:.5f} at 15 s, "
              f"{hist[-1][3]:.5f} at 20 s ({100 * (hist[-1][3] / k15 - 1):+.2g}%); wall "
              f"time {clock} s (CPU {ex:.0f} s)"))


def main():
    if len(sys.argv) < 5:
        sys.exit(__doc__)
    scratch, out, command = sys.argv[1:4]
    sizes = [float(h) for h in sys.argv[4:]]
    runs = [Run(scratch, h) for h in sizes]
    info, samples, mean_samples = [], [], []
    for r in runs:
        hist = r.history()
        q_step, u_step = r.step_series()
        info.append(describe(r, hist, q_step, u_step))
        rows = r.samples(r.f)
        level(rows)
        samples.append(rows)
        mean_samples.append(r.samples(r.fields(END, tuple(n + "Mean" for n in FIELDS)), True))
        level(mean_samples[-1])
        print(f"h {r.h:g}: " + info[-1]["text"], file=sys.stderr)
        print("  t Q max|U| mean-k: " + "; ".join(f"{t:g} {q:.4f} {u:.3f} {k:.4f}"
                                                   for t, q, u, k in hist), file=sys.stderr)
    main_run, main_rows = runs[0], samples[0]
    steady = info[0]["steady"]
    mean_rows = mean_samples[0]
    drift = "; ".join(f"{q} RMS {v[0]:.3e}, max {v[1]:.3e} (at {v[2]} y = {v[3]:.3f})"
                      for q, v in compare(main_rows, mean_rows).items())
    head = [
        "# OpenFOAM v1912 (Debian package openfoam) reference for the periodic pool of a "
        "vertical-slot fish pass, Leroy et al. 2014 sec 5.2, seen from above, 2-D (one cell "
        "thick, empty front and back), no gravity, no free surface: slot width b = 0.3 m, pool "
        "period L = 10 b = 3 m along x (cyclic x = 0 <-> 3), walls y = 0 and y = B = 8 b = 2.4 m; "
        "solid baffles (walls): long x in [1.0, 1.15], y in [0, 1.8]; short x in [1.0, 1.45], "
        "y in [2.1, 2.4]; slot y in [1.8, 2.1]. Incompressible, nu = 1e-6 m^2/s, rho = 1000 "
        "kg/m^3; driven by a uniform body force 1.885 m/s^2 along +x (fvOptions "
        "vectorSemiImplicitSource, volumeMode specific, selectionMode all, injectionRateSuSp "
        "U ((1.885 0 0) 0)). From rest: U = 0, k = 1e-4 m^2/s^2, epsilon = 5.48e-6 m^2/s^3 "
        "(Cmu^0.75 k^1.5 / 0.03 m).",
        "# pimpleFoam (PISO mode: 1 outer iteration, 2 pressure correctors), transient from rest "
        "to t = 20 s (the paper compares after 20 s), time step adjusted to max Co 0.8 (maxDeltaT "
        "0.05 s), backward in time; standard k-epsilon (Cmu 0.09, C1 1.44, C2 1.92, sigmak 1, "
        "sigmaEps 1.3); walls (y = 0, y = 2.4, baffles): U noSlip, p zeroGradient, "
        "nutkWallFunction (Cmu 0.09, kappa 0.41, E 9.8; y*_lam = 11.53), kqRWallFunction, "
        "epsilonWallFunction; schemes linearUpwind for U, k, epsilon, linear elsewhere "
        "(gradients, interpolation, laplacian corrected); p fixed to 0 in cell 0 (pRefCell), the "
        "level then removed as below. Mesh: blockMesh, 9 blocks on the x breaks {0, 1, 1.15, "
        "1.45, 3} and y breaks {0, 1.8, 2.1, 2.4} less the 3 solid ones, uniform square cells.",
    ]
    for name, r, i in zip(["main mesh"] + ["sensitivity mesh"] * (len(runs) - 1), runs, info):
        head.append(f"# {name} h{r.h:g}: " + i["text"])
    head.append(
        f"# Steadiness (main mesh): {'steady' if steady else 'NOT steady'} by t = 15-20 s "
        f"(criterion: Q and max |U| vary by less than {100 * STEADY_TOL:g}% of their means over "
        f"every time step of 15-20 s, and the pool's mean k by less than that from 15 to 20 s); "
        f"the P1-P3 samples at t = 20 s less their 15-20 s time "
        f"means: {drift}" +
        ("" if steady else "; the *_mean columns are the time means over 15-20 s (fieldAverage, "
         "weighted by the time step), sampled and levelled like the instantaneous values") + ".")
    for r, rows in zip(runs[1:], samples[1:]):
        c = compare(main_rows, rows)
        words = "; ".join(
            f"{q} RMS {v[0]:.3e}, max {v[1]:.3e} (at {v[2]} y = {v[3]:.3f}; largest value on "
            f"P1-P3 {v[4]:.3e})" for q, v in c.items())
        cm = compare(mean_rows, mean_samples[runs.index(r)])
        words += "; of the 15-20 s time means: " + "; ".join(
            f"{q} RMS {v[0]:.3e}, max {v[1]:.3e}" for q, v in cm.items())
        i = info[runs.index(r)]
        head.append(
            f"# Mesh sensitivity, h{r.h:g} - h{main_run.h:g} at t = 20 s on the P1-P3 points "
            f"(|U| in m/s, k in m^2/s^2, p in Pa, each levelled on its own mesh): {words}. "
            f"Q(x = 2.2): {i['q20']:.5f} (h{r.h:g}) vs {info[0]['q20']:.5f} (h{main_run.h:g}) "
            f"m^2/s; max |U| {i['u20']:.4f} vs {info[0]['u20']:.4f} m/s.")
    head.append(f"# Made by: {command}")
    head.append(
        "# Sampling: read from the cell fields at t = 20 s (no OpenFOAM sample): bilinear "
        "between the 4 cell centres around each point. P1, P2, P3: the sections x = 1.6, 2.2, "
        "2.8 at y = 0.025 j, j = 1..95. P4: the wall y = 0 downstream of the long baffle, x = "
        "1.175 to 2.975 step 0.05: p is the wall's zeroGradient face value (= the wall cell's), "
        "linear in x between face centres; U = 0 (no slip); k, epsilon, nut those of the wall "
        "cells (centres at y = h/2), linear in x.")
    cols = ["line", "x", "y", "s", "U_x", "U_y", "p", "k", "epsilon", "nut"]
    words = ("# Columns: line (P1/P2/P3/P4); x, y (m); s = distance along the line from its "
             "first point (m); U_x, U_y (m/s); p (Pa) = 1000 x kinematic p less the mean of p over "
             "all the P1-P3 points (the same levelling on every mesh; use it for the SPH run too); "
             "k (m^2/s^2); epsilon (m^2/s^3); nut (m^2/s)")
    if not steady:
        cols += [c + "_mean" for c in cols[4:]]
        words += "; *_mean: the same quantities' time means over 15-20 s (p_mean levelled alike)"
    head.append(words + ".")
    with open(out, "w") as f:
        f.write("\n".join(head) + "\n" + ",".join(cols) + "\n")
        for m, r in enumerate(main_rows):
            vals = r[4:] + ([] if steady else mean_rows[m][4:])
            f.write(f"{r[0]},{r[1]:.6g},{r[2]:.6g},{r[3]:.6g}," +
                    ",".join(f"{v:.6e}" for v in vals) + "\n")
    print(f"wrote {out}", file=sys.stderr)
    # the main mesh's flow rate over time, every 0.05 s (the step nearest each), for the SPH
    # runs' start-up (cases/fish_pass.lua: flow_rate_dev_t compares at any t_end)
    q_step = main_run.step_series()[0]
    flow = os.path.join(os.path.dirname(out), "openfoam_fish_pass_flow.csv")
    with open(flow, "w") as f:
        f.write(f"# OpenFOAM v1912 pimpleFoam, the fish-pass of {os.path.basename(out)} (its header "
                f"says what ran): main mesh h{main_run.h:g}, the flow rate Q = sum of phi over the "
                "cyclic patch / dz (the flow through any section x, by continuity) and the pool's "
                "largest |U| are logged at every time step; here the step nearest each multiple of "
                "0.05 s.\n")
        f.write(f"# Made by: {command}\n")
        f.write("# Columns: time (s, the step's own); flow_rate (m^2/s).\n")
        f.write("time,flow_rate\n")
        j = 0
        for m in range(0, 401):
            t = 0.05 * m
            while j + 1 < len(q_step) and abs(q_step[j + 1][0] - t) <= abs(q_step[j][0] - t):
                j += 1
            if m == 0:
                f.write("0,0\n")
            else:
                f.write(f"{q_step[j][0]:.6g},{q_step[j][1]:.6e}\n")
    print(f"wrote {flow}", file=sys.stderr)


if __name__ == "__main__":
    main()
