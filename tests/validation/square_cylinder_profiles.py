#!/usr/bin/env python3
"""Square cylinder at Re = 1 (Hosseini & Feng 2011 sec 4.3.1-4.3.2, Figures 7-9): the centreline
profiles u(x) and p(x), time-averaged over the recorded outputs at t >= T0 (the paper averages
over 1 <= t <= 10), for the runs given, on one chart of two panels. p is zeroed at the exit, as in
the paper; the cylinder occupies xc ± D/2 (shaded, no samples there). The paper compares each profile with its own
finite-element solution, which is not published as data: this chart compares the projections
and resolutions with one another.

    python3 tests/validation/square_cylinder_profiles.py OUT_PREFIX T0 LABEL=RUN_DIR [...]
writes OUT_PREFIX.csv (label, x, u, p) and OUT_PREFIX.png (gnuplot)."""
import csv
import json
import os
import subprocess
import sys


def averaged(run_dir, t0):
    with open(os.path.join(run_dir, "profile_centreline.csv")) as f:
        rows = list(csv.DictReader(f))
    acc, times = {}, set()
    for r in rows:
        t = float(r["time"])
        if t < t0:
            continue
        times.add(t)
        x = float(r["x"])
        a = acc.setdefault(x, [0.0, 0.0])
        a[0] += float(r["vel_x"])
        a[1] += float(r["p"])
    n = len(times)
    if n == 0:
        sys.exit(f"{run_dir}: no profile recorded at t >= {t0}")
    xs = sorted(acc)
    p_exit = acc[xs[-1]][1] / n
    return [(x, acc[x][0] / n, acc[x][1] / n - p_exit) for x in xs], n


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    prefix, t0 = sys.argv[1], float(sys.argv[2])
    runs = [a.split("=", 1) for a in sys.argv[3:]]
    rows, labels, xc = [], [], None
    for label, d in runs:
        with open(os.path.join(d, "summary.json")) as f:
            s = json.load(f)
        xc = s["parameters"].get("xc", 12)
        prof, n = averaged(d, t0)
        prof = [r for r in prof if abs(r[0] - xc) > 0.5]  # not inside the cylinder
        rows += [(label, x, u, p) for x, u, p in prof]
        labels.append(label)
        pmax = max(p for _, _, p in prof)
        print(f"{label}: {n} outputs averaged; u at x = {xc - 1:g}: "
              f"{min(prof, key=lambda r: abs(r[0] - (xc - 1)))[1]:.4f}; largest p {pmax:.4g}")
    with open(prefix + ".csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["run", "x", "u", "p"])
        w.writerows(rows)

    def plot(col):
        return ", \\\n     ".join(
            f"'{prefix}.csv' using (strcol(1) eq '{lab}' ? $2 : 1/0):{col} with lines lw 2 "
            f"title '{lab}'" for lab in labels)

    script = f"""
set datafile separator ','
set terminal pngcairo size 1000,800 font 'DejaVu Sans,11'
set output '{prefix}.png'
set multiplot layout 2,1 title 'Square cylinder, Re = 1: centreline profiles averaged over t >= {t0:g} D/U_0'
set object 1 rect from {xc - 0.5},graph 0 to {xc + 0.5},graph 1 fc rgb '#dddddd' fs solid behind
set grid
set key top right
set xlabel 'x / D'
set ylabel 'u / U_0'
plot {plot(3)}
set ylabel 'p / (ρ U_0^2), zero at the exit'
plot {plot(4)}
unset multiplot
"""
    subprocess.run(["gnuplot"], input=script, text=True, check=True)
    print(f"wrote {prefix}.csv and {prefix}.png")


if __name__ == "__main__":
    main()
