#!/usr/bin/env python3
"""Pressure in the lid-driven cavity along y = 1/2 and along the diagonal, isph-usaw against
wcsph-usaw (Leroy et al. 2014 sec 4.1 compare them at Re = 400): reads the last sample of
profile_v_centreline.csv and profile_diagonal.csv of two runs, writes one CSV with both and a
PNG chart drawn by gnuplot from that CSV.

The pressure level of a closed cavity is arbitrary (isph-usaw fixes it by its reinforced
diagonal, wcsph-usaw by its equation of state and background pressure), so each profile is shown
as (p − p_c)/(ρ U²), p_c the pressure at the centre of the cavity (U = 1, ρ = 1 in cases/cavity.lua).

    python3 tests/validation/cavity_pressure.py ISPH_RUN_DIR WCSPH_RUN_DIR OUT_PREFIX
writes OUT_PREFIX.csv and OUT_PREFIX.png, and prints the RMS difference of the two schemes along
each line."""
import csv
import math
import os
import subprocess
import sys


def last_profile(path):
    """(s, p) along the line at the last time of a profile CSV."""
    with open(path) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"{path}: no samples")
    t = max(float(r["time"]) for r in rows)
    pts = [(float(r["s"]), float(r["p"])) for r in rows if float(r["time"]) == t]
    return t, pts


def centred(pts):
    """(p − p at the middle of the line): both lines pass through the centre of the cavity."""
    mid = min(pts, key=lambda q: abs(q[0] - 0.5 * pts[-1][0]))[1]
    return [(s, p - mid) for s, p in pts]


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    isph, wcsph, prefix = sys.argv[1:]
    lines = {"y=1/2": "profile_v_centreline.csv", "diagonal": "profile_diagonal.csv"}
    table, report = [], []
    for name, fname in lines.items():
        ti, pi = last_profile(os.path.join(isph, fname))
        tw, pw = last_profile(os.path.join(wcsph, fname))
        if len(pi) != len(pw):
            sys.exit(f"{fname}: the runs sample {len(pi)} and {len(pw)} points")
        pi, pw = centred(pi), centred(pw)
        rms = math.sqrt(sum((a[1] - b[1]) ** 2 for a, b in zip(pi, pw)) / len(pi))
        spread = max(abs(a[1]) for a in pi)
        report.append(f"{name}: t = {ti:g} s (isph-usaw), {tw:g} s (wcsph-usaw); RMS difference "
                      f"{rms:.4g} ρU² (isph-usaw range ±{spread:.4g} ρU²)")
        for a, b in zip(pi, pw):
            table.append((name, a[0], a[1], b[1]))
    with open(prefix + ".csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["line", "s", "p_isph_usaw", "p_wcsph_usaw"])
        w.writerows(table)
    # gnuplot draws the chart from the CSV (one panel per line)
    script = f"""
set datafile separator ','
set terminal pngcairo size 1200,500 font 'DejaVu Sans,11'
set output '{prefix}.png'
set multiplot layout 1,2 title 'Lid-driven cavity: pressure, isph-usaw against wcsph-usaw'
set grid
set key top left
set ylabel '(p - p_c) / ({{/Symbol r}} U^2)'
set xlabel 'x along y = 1/2'
plot '{prefix}.csv' using ($1 eq "y=1/2" ? $2 : 1/0):3 with lines lw 2 title 'isph-usaw', \\
     '' using ($1 eq "y=1/2" ? $2 : 1/0):4 with lines lw 2 dt 2 title 'wcsph-usaw'
set xlabel 'distance along the diagonal from (0, 0)'
plot '{prefix}.csv' using ($1 eq "diagonal" ? $2 : 1/0):3 with lines lw 2 title 'isph-usaw', \\
     '' using ($1 eq "diagonal" ? $2 : 1/0):4 with lines lw 2 dt 2 title 'wcsph-usaw'
unset multiplot
"""
    script = script.replace('$1 eq "y=1/2"', 'strcol(1) eq "y=1/2"').replace(
        '$1 eq "diagonal"', 'strcol(1) eq "diagonal"')
    subprocess.run(["gnuplot"], input=script, text=True, check=True)
    print("\n".join(report))
    print(f"wrote {prefix}.csv and {prefix}.png")


if __name__ == "__main__":
    main()
