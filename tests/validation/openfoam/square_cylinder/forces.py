#!/usr/bin/env python3
"""Drag and lift of the square cylinder from OpenFOAM's forces output (run.sh's runs).

Reads each run folder RUN = re<Re>_d<n> under SCRATCH (postProcessing/forces/*/force.dat, the
logs, system/meshParams, constant/transportProperties) and writes CSV to OUT (stdout without).
Units D = U0 = rho = 1, span 1 D (the mesh's thickness): C = F / (1/2 rho U0^2 D) = 2 F.
- Steady run (simpleFoam): the forces of the last iteration.
- Transient run (pimpleFoam): St = f D / U0 from the upward zero crossings of C_L - mean over
  the last N_PERIODS shedding periods (checked against the lift spectrum's peak), C_D and its
  parts the means over those periods, cl_amplitude = (mean of the periods' maxima - mean of
  their minima) / 2.
    forces.py SCRATCH [OUT]
"""
import glob
import os
import re
import sys

import numpy as np

N_PERIODS = 10
Q = 0.5  # 1/2 rho U0^2 D x span


def read_forces(run):
    """Time, total, pressure and viscous force vectors, one row per time (restarts merged)."""
    rows = {}
    files = glob.glob(os.path.join(run, "postProcessing", "forces", "*", "force.dat"))
    for path in sorted(files, key=lambda p: float(p.split(os.sep)[-2])):
        with open(path) as f:
            for line in f:
                if line.startswith("#") or not line.strip():
                    continue
                v = [float(x) for x in line.replace("(", " ").replace(")", " ").split()]
                rows[v[0]] = v[1:10]
    t = np.array(sorted(rows))
    f = np.array([rows[k] for k in t])
    return t, f[:, 0:3], f[:, 3:6], f[:, 6:9]


def grep(path, pattern):
    """The first group of the last match of pattern in the file, or None."""
    hits = re.findall(pattern, open(path).read()) if os.path.exists(path) else []
    return hits[-1] if hits else None


def shedding(t, cd, cdp, cdv, cl):
    """St, mean C_D (total, pressure, viscous), C_L amplitude, window, drift over the window."""
    tu = np.linspace(t[0], t[-1], 8 * len(t))  # uniform resampling of the adjustable steps
    clu = np.interp(tu, t, cl)
    c = clu - clu[tu >= 0.5 * (t[0] + t[-1])].mean()  # about the mean of the second half
    up = np.nonzero((c[:-1] < 0) & (c[1:] >= 0))[0]
    cross = tu[up] - c[up] * (tu[up + 1] - tu[up]) / (c[up + 1] - c[up])
    if len(cross) < N_PERIODS + 1:
        return None
    t0, t1 = cross[-N_PERIODS - 1], cross[-1]
    st = N_PERIODS / (t1 - t0)

    def mean(y, a=t0, b=t1):  # time average over [a, b] (on the uniform resampling)
        s = (tu >= a) & (tu <= b)
        x, v = tu[s], np.interp(tu[s], t, y)
        return np.sum((v[1:] + v[:-1]) * np.diff(x)) / 2 / (x[-1] - x[0])

    edges = cross[-N_PERIODS - 1:]
    hi = [cl[(t >= a) & (t <= b)].max() for a, b in zip(edges[:-1], edges[1:])]
    lo = [cl[(t >= a) & (t <= b)].min() for a, b in zip(edges[:-1], edges[1:])]
    # spectrum of C_L over the window (zero padded 16x): the dominant frequency
    sel = (tu >= t0) & (tu <= t1)
    y = clu[sel] - clu[sel].mean()
    dt = tu[1] - tu[0]
    spec = np.abs(np.fft.rfft(y, 16 * len(y)))
    freq = np.fft.rfftfreq(16 * len(y), dt)
    st_fft = freq[np.argmax(spec)]
    # drift: mean C_D over the first and the last 3 periods of the window
    a = [mean(cd, edges[0], edges[3]), mean(cd, edges[-4], edges[-1])]
    return dict(st=st, st_fft=st_fft, cd=mean(cd), cdp=mean(cdp), cdv=mean(cdv),
                cla=(np.mean(hi) - np.mean(lo)) / 2, clmean=mean(cl), t0=t0, t1=t1,
                cd_first=a[0], cd_last=a[1], cla_first=(hi[0] - lo[0]) / 2,
                cla_last=(hi[-1] - lo[-1]) / 2)


def main():
    scratch = sys.argv[1]
    out = open(sys.argv[2], "w") if len(sys.argv) > 2 else sys.stdout
    runs = sorted(glob.glob(os.path.join(scratch, "re*_d*")),
                  key=lambda p: (-int(re.search(r"re(\d+)", p).group(1)),
                                 int(re.search(r"_d(\d+)", p).group(1))))
    head, rows = [], []
    for run in runs:
        name = os.path.basename(run)
        nu = float(grep(os.path.join(run, "constant", "transportProperties"), r"\bnu\s+([\d.eE+-]+);"))
        nc = int(grep(os.path.join(run, "system", "meshParams"), r"nCyl\s+(\d+);"))
        cells = int(grep(os.path.join(run, "log.blockMesh"), r"nCells:\s*(\d+)"))
        solver = "pimpleFoam" if os.path.exists(os.path.join(run, "log.pimpleFoam")) else "simpleFoam"
        log = os.path.join(run, "log." + solver)
        clock = grep(log, r"ClockTime = (\d+) s")
        if not os.path.exists(os.path.join(run, "postProcessing")):
            print(f"{name}: no forces output, skipped", file=sys.stderr)
            continue
        t, ft, fp, fv = read_forces(run)
        red = round(1 / nu)
        mesh = f"D/{nc}"
        if solver == "simpleFoam":
            conv = grep(log, r"SIMPLE solution converged in (\d+) iterations")
            cd, cdp, cdv = ft[-1, 0] / Q, fp[-1, 0] / Q, fv[-1, 0] / Q
            rows.append(f"{red},{mesh},{cells},{cd:.4f},{cdp:.4f},{cdv:.4f},,")
            head.append(f"# Re = {red}, {mesh}: simpleFoam (SIMPLEC, steady), {cells} cells, "
                        f"h = D/{nc} at the cylinder; "
                        f"{'converged (residuals p < 1e-6, U < 1e-7) in ' + conv + ' iterations' if conv else 'NOT converged after ' + str(int(t[-1])) + ' iterations'}"
                        f", forces of the last one; C_L = {ft[-1, 1] / Q:.1e}; wall time {clock} s")
            print(f"{name}: cd {cd:.4f} (pressure {cdp:.4f}, viscous {cdv:.4f}), "
                  f"cells {cells}, {clock} s", file=sys.stderr)
        else:
            s = shedding(t, ft[:, 0] / Q, fp[:, 0] / Q, fv[:, 0] / Q, ft[:, 1] / Q)
            dts = [float(x) for x in re.findall(r"deltaT = ([\d.eE+-]+)", open(log).read())]
            dt = np.median(dts[len(dts) // 2:])
            if s is None:
                print(f"{name}: fewer than {N_PERIODS} shedding periods, skipped", file=sys.stderr)
                continue
            start = ("from rest (a box behind the cylinder moving up: setFields)" if t[0] < 1 else
                     f"from the D/40 run's fields at t = {t[0]:.0f} (mapFields)")
            rows.append(f"{red},{mesh},{cells},{s['cd']:.4f},{s['cdp']:.4f},{s['cdv']:.4f},"
                        f"{s['st']:.4f},{s['cla']:.4f}")
            head.append(f"# Re = {red}, {mesh}: pimpleFoam (PISO, backward), {cells} cells, "
                        f"h = D/{nc} at the cylinder; {start} to t = {t[-1]:.0f} D/U0, dt adjusted "
                        f"to Co <= 0.5 ({dt:.4f} D/U0 once shedding); means over the last "
                        f"{N_PERIODS} periods of C_L, t = {s['t0']:.2f} to {s['t1']:.2f}; "
                        f"St from their zero crossings (spectral peak {s['st_fft']:.4f}); "
                        f"mean C_L {s['clmean']:.1e}; C_D over the window's first and last 3 "
                        f"periods {s['cd_first']:.4f} and {s['cd_last']:.4f}, C_L amplitude in its "
                        f"first and last period {s['cla_first']:.4f} and {s['cla_last']:.4f}; "
                        f"wall time {clock} s")
            print(f"{name}: cd {s['cd']:.4f} (pressure {s['cdp']:.4f}, viscous {s['cdv']:.4f}), "
                  f"St {s['st']:.4f} (spectrum {s['st_fft']:.4f}), cl_amplitude {s['cla']:.4f}, "
                  f"window {s['t0']:.2f}-{s['t1']:.2f}, cd first/last 3 periods "
                  f"{s['cd_first']:.4f}/{s['cd_last']:.4f}, cl amplitude first/last period "
                  f"{s['cla_first']:.4f}/{s['cla_last']:.4f}, dt {dt:.5f}, cells {cells}, {clock} s",
                  file=sys.stderr)
    out.write("# OpenFOAM v1912 (Debian package openfoam) reference for cases/square_cylinder.lua with "
              "length=32 xc=8: channel H = 8 D, square cylinder of side D centred at (8, 4), "
              "parabolic entry of peak U0 at x = 0, no-slip walls, zero-gradient exit with p = 0 at "
              "x = 32; D = U0 = rho = 1, nu = 1/Re.\n"
              "# Block-structured 2D meshes graded geometrically towards the cylinder (mesh = cell "
              "size at its faces); C = F / (1/2 rho U0^2 D), F per unit span from the forces "
              "function object (pressure + viscous); strouhal = f D / U0 of C_L; cl_amplitude = "
              "half the peak-to-peak C_L.\n")
    out.write("\n".join(head) + "\n")
    out.write("# Made by: tests/validation/openfoam/square_cylinder/run.sh\n")
    out.write("re,mesh,cells,cd,cd_pressure,cd_viscous,strouhal,cl_amplitude\n")
    out.write("\n".join(rows) + "\n")


if __name__ == "__main__":
    main()
