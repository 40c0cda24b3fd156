#!/usr/bin/env python3
"""Square cylinder in a channel (Hosseini & Feng 2011 sec 4.3, Figure 11): the drag coefficient
against the Reynolds number, each square_cylinder run of RUNS_DIR in Breuer et al.'s geometry
(length 32 D, the cylinder 8 D from the entry) that ended well, one series per projection and
exit, against Breuer et al. 2000 (tests/data/breuer2000_square_cylinder_cd.csv, digitised, with
its uncertainty as error bars). Runs that stopped are listed with where they stopped.

    python3 tests/validation/square_cylinder_chart.py OUT_PREFIX [RUNS_DIR]
writes OUT_PREFIX.csv (series, Re, C_D, n, status) and OUT_PREFIX.png (gnuplot, log-log)."""
import csv
import glob
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
BREUER = os.path.join(HERE, "..", "data", "breuer2000_square_cylinder_cd.csv")


def series_name(p, scheme):
    proj = "homogeneous" if p.get("homogeneous", 0) == 1 else "rotational"
    if scheme == "wcsph-riemann":
        proj = "wcsph-riemann"
    exit_ = "parabolic exit" if p.get("exit_parabolic", 0) == 1 else "natural exit"
    start = " / developed start" if p.get("developed", 0) == 1 else ""
    return f"{proj} / {exit_} / H/{p.get('n', 0):g}{start}"  # no commas: a CSV field for gnuplot


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    prefix = sys.argv[1]
    runs_dir = sys.argv[2] if len(sys.argv) > 2 else "out/validation"
    rows = []
    for path in sorted(glob.glob(os.path.join(runs_dir, "*", "summary.json"))):
        with open(path) as f:
            s = json.load(f)
        p = s.get("parameters", {})
        if s.get("case") != "square_cylinder" or p.get("length") != 32:
            continue
        cd = s.get("metrics", {}).get("cd")
        rows.append((series_name(p, s.get("scheme")), p["re"], cd if s["status"] == "ok" else None, p["n"],
                     s["status"].replace(",", ";"), s["sim_time"]))
    rows.sort(key=lambda r: (r[0], r[1]))
    with open(prefix + ".csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["series", "re", "cd", "n", "status", "reached_t"])
        w.writerows(rows)
    names = sorted({r[0] for r in rows if r[2] is not None})
    for r in rows:
        state = f"C_D = {r[2]:.4g}" if r[2] is not None else f"stopped at t = {r[5]:.3g}: {r[4]}"
        print(f"{r[0]}, Re = {r[1]:g}: {state}")
    plots = [f"'< grep -v \"^#\" {BREUER}' using 1:2:($2*$3/100) with yerrorbars pt 5 ps 1.2 "
             f"lc rgb 'black' title 'Breuer et al. 2000 (finite volume, digitised)'"]
    for k, name in enumerate(names):
        plots.append(f"'{prefix}.csv' using (strcol(1) eq '{name}' && strcol(3) ne '' ? $2 : 1/0):3 "
                     f"with linespoints lw 2 pt {7 + k} ps 1.3 title 'clsph: {name}'")
    script = f"""
set datafile separator ','
set terminal pngcairo size 900,560 font 'DejaVu Sans,11'
set output '{prefix}.png'
set title 'Square cylinder in a channel (H = 8 D): drag coefficient on the peak inflow velocity'
set logscale xy
set grid
set key top right
set xrange [0.8:130]
set xlabel 'Re = U_0 D / {{/Symbol n}}'
set ylabel 'C_D'
plot {", ".join(plots)}
"""
    subprocess.run(["gnuplot"], input=script, text=True, check=True)
    print(f"wrote {prefix}.csv and {prefix}.png")


if __name__ == "__main__":
    main()
