#!/usr/bin/env python3
"""Dam break over a wedge (Leroy et al. 2014 sec 4.3, Figure 12): the pressure force on the left
side of the wedge against time, eq 71 (F = Σ_s p_s S_s over the segments of the side), for the
runs given, on one chart. The force is the pressure part of group "wedge_left" in forces.csv,
projected on the side's inward normal (1, −1)/√2 (cases/dam_break_wedge.lua: the side rises at
45° from (1.2, 0) to (1.5, 0.3)). Time is shown as t+ = t √(g/H), H = 1 m, as in the paper.

    python3 tests/validation/wedge_chart.py OUT_PREFIX LABEL=RUN_DIR [LABEL=RUN_DIR ...]
writes OUT_PREFIX.csv (label, t, t+, F) and OUT_PREFIX.png (gnuplot, from that CSV); a run that
stopped early (summary.json status) is drawn up to where it stopped and named so in the key."""
import csv
import json
import math
import os
import subprocess
import sys

G, H = 9.81, 1.0


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    prefix, runs = sys.argv[1], [a.split("=", 1) for a in sys.argv[2:]]
    rows, keys = [], []
    for label, d in runs:
        with open(os.path.join(d, "summary.json")) as f:
            status = json.load(f)["status"]
        with open(os.path.join(d, "forces.csv")) as f:
            data = list(csv.DictReader(f))
        n = 0
        for r in data:
            fx, fy = float(r["wedge_left:fx_pressure"]), float(r["wedge_left:fy_pressure"])
            t = float(r["time"])
            rows.append((label, t, t * math.sqrt(G / H), (fx - fy) / math.sqrt(2.0)))
            n += 1
        peak = max((r for r in rows if r[0] == label), key=lambda r: r[3])
        stopped = "" if status == "ok" else f" (stopped at t+ = {rows[-1][2]:.2f})"
        keys.append((label, label + stopped))
        print(f"{label}: {n} samples, status {status}; largest F = {peak[3]:.4g} N/m at "
              f"t+ = {peak[2]:.3g}")
    with open(prefix + ".csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["run", "t", "t_plus", "force"])
        w.writerows(rows)
    plots = ", \\\n     ".join(
        f"'{prefix}.csv' using (strcol(1) eq '{label}' ? $3 : 1/0):4 with lines lw 2 "
        f"title '{key}'" for label, key in keys)
    script = f"""
set datafile separator ','
set terminal pngcairo size 900,500 font 'DejaVu Sans,11'
set output '{prefix}.png'
set title 'Dam break over a wedge: pressure force on the left side of the wedge (eq 71)'
set grid
set key top right
set xlabel 't^+ = t (g/H)^{{1/2}}'
set ylabel 'F (N/m)'
plot {plots}
"""
    subprocess.run(["gnuplot"], input=script, text=True, check=True)
    print(f"wrote {prefix}.csv and {prefix}.png")


if __name__ == "__main__":
    main()
