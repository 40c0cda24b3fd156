#!/usr/bin/env python3
"""The dam break of Lobovsky et al. 2014 (H = 300 mm, cases/dam_break.lua): the pressure of the
downstream wall's sensors 1 to 4 (3, 15, 30 and 80 mm above the bed), p* = p/(ρ g H) against
t* = t √(g/H), one panel each, for the runs given and the experiment's event 5 (all sensors at
2 kHz: tests/data/lobovsky2014_H300_event5_all_sensors.csv, copied from ../shared/refdata with
its citation; sensor 1's impact peak is under-resolved at that rate: lobovsky_chart.py draws it
from every raw sample).

    python3 tests/validation/lobovsky_sensors_chart.py OUT_PREFIX LABEL=RUN_DIR [...]
writes OUT_PREFIX.csv (run, sensor, t_star, p_star; the experiment as run "experiment") and
OUT_PREFIX.png (gnuplot, from that CSV), and prints each run's sensor metrics (summary.json)."""
import csv
import json
import math
import os
import subprocess
import sys

G, H = 9.81, 0.3
EXPERIMENT = os.path.join(os.path.dirname(__file__), "..", "data",
                          "lobovsky2014_H300_event5_all_sensors.csv")
HEIGHTS = {1: 3, 2: 15, 3: 30, 4: 80}


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    prefix, runs = sys.argv[1], [a.split("=", 1) for a in sys.argv[2:]]
    for r in runs:
        if len(r) != 2 or any(c in r[0] for c in ",'\""):
            sys.exit(f"lobovsky_sensors_chart.py: '{'='.join(r)}' is not LABEL=DIR with a label "
                     "free of commas and quotes")
    rows, keys = [], []
    with open(EXPERIMENT) as f:
        lines = [ln for ln in f if not ln.startswith("#")]
    exp = list(csv.DictReader(lines))
    for k in HEIGHTS:  # each sensor's rows together: gnuplot breaks a line at a skipped row
        for r in exp:
            rows.append(("experiment", k, float(r["t_star"]), float(r[f"p_star_sensor{k}"])))
    for label, d in runs:
        with open(os.path.join(d, "summary.json")) as f:
            s = json.load(f)
        with open(os.path.join(d, "series.csv")) as f:
            data = list(csv.DictReader(f))
        for k in HEIGHTS:
            col = f"sensor_{k}_p_star"
            if data and col not in data[0]:
                sys.exit(f"{d}/series.csv has no {col}: a run from before the case had sensors 2-4")
            for r in data:
                v = r[col]
                if v in ("", "nan", "-nan"):
                    continue
                rows.append((label, k, float(r["time"]) * math.sqrt(G / H), float(v)))
        stopped = "" if s["status"] == "ok" or not data else \
            f" (stopped at t* = {float(data[-1]['time']) * math.sqrt(G / H):.2f})"
        keys.append((label, label + stopped))
        m = s.get("metrics", {})
        parts = []
        for k in HEIGHTS:
            first = m.get("impact_t_star" if k == 1 else f"sensor_{k}_t_star", math.nan)
            plateau = m.get("plateau_ratio" if k == 1 else f"sensor_{k}_plateau_ratio", math.nan)
            parts.append(f"sensor {k}: first p* > 0.1 at t* {first:.3f}, plateau {plateau:.3f}")
        print(f"{label}: status {s['status']}; " + "; ".join(parts))
    with open(prefix + ".csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["run", "sensor", "t_star", "p_star"])
        w.writerows(rows)
    panels = []
    for k, mm in HEIGHTS.items():
        plots = ", \\\n     ".join(  # the experiment last, on top of the runs
            [f"'{prefix}.csv' using (strcol(1) eq '{label}' && $2 == {k} ? $3 : 1/0):4 with "
             f"lines lw 1.5 title '{key}'" for label, key in keys] +
            [f"'{prefix}.csv' using (strcol(1) eq 'experiment' && $2 == {k} ? $3 : 1/0):4 with "
             f"lines lc rgb 'black' lw 2 title 'experiment (event 5)'"])
        panels.append(f"set title 'sensor {k}, {mm} mm above the bed'\nplot {plots}")
    script = f"""
set datafile separator ','
set terminal pngcairo size 1400,900 font 'DejaVu Sans,10'
set output '{prefix}.png'
set multiplot layout 2,2 title 'Dam break, Lobovsky et al. 2014 (H = 300 mm): the downstream wall'
set grid
set key top right
set xlabel 't* = t (g/H)^{{1/2}}'
set ylabel 'p* = p / ({{/Symbol r}} g H)'
set xrange [2:6.3]
set yrange [-0.5:3.5]
""" + "\n".join(panels) + "\nunset multiplot\n"
    subprocess.run(["gnuplot"], input=script, text=True, check=True)
    print(f"wrote {prefix}.csv and {prefix}.png")


if __name__ == "__main__":
    main()
