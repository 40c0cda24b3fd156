#!/usr/bin/env python3
"""The dam break of Lobovsky et al. 2014 (H = 300 mm, cases/dam_break.lua): sensor 1's pressure
p* = p/(ρ g H) against t* = t √(g/H) for the runs given and the experiment's event 5
(tests/data/lobovsky2014_sensor1.csv, copied from ../shared/refdata with its citation), on one
chart, with a second panel zoomed on the impact (t* from 2.2 to 3.2).

    python3 tests/validation/lobovsky_chart.py [--h600] OUT_PREFIX LABEL=RUN_DIR [...]
writes OUT_PREFIX.csv (run, t_star, p_star; the experiment as run "experiment") and
OUT_PREFIX.png (gnuplot, from that CSV); a run that stopped early (summary.json status) is drawn up
to where it stopped and named so in the key. The runs' series are series.csv's sensor_1_p_star
(sampled every `every` s of the case, 0.001 s by default).
--h600: runs of the 600 mm column (dam_break.lua H = 0.6, t* and p* with H = 0.6 m), which has no
time history in the refdata: the chart marks the median peak over the repeats instead, p* = 3.15
(lobovsky2014_geometry.md, "UNVERIFIED": one secondary source), and zooms on t* 1.3-2.3."""
import csv
import json
import math
import os
import subprocess
import sys

G, H = 9.81, 0.3
EXPERIMENT = os.path.join(os.path.dirname(__file__), "..", "data", "lobovsky2014_sensor1.csv")


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    h600 = sys.argv[1] == "--h600"
    args = sys.argv[2:] if h600 else sys.argv[1:]
    if len(args) < 2:
        sys.exit(__doc__)
    height = 0.6 if h600 else H
    prefix, runs = args[0], [a.split("=", 1) for a in args[1:]]
    for r in runs:
        # the label is the CSV's first column and gnuplot's selector: no separator, no quote
        if len(r) != 2 or any(c in r[0] for c in ",'\""):
            sys.exit(f"lobovsky_chart.py: '{'='.join(r)}' is not LABEL=DIR with a label free of "
                     "commas and quotes")
    rows, keys = [], []
    with open(EXPERIMENT) as f:
        lines = [ln for ln in f if not ln.startswith("#")]
    for r in csv.DictReader(lines) if not h600 else []:
        rows.append(("experiment", float(r["t_star"]), float(r["p_star"])))
    for label, d in runs:
        with open(os.path.join(d, "summary.json")) as f:
            s = json.load(f)
        with open(os.path.join(d, "series.csv")) as f:
            data = [r for r in csv.DictReader(f) if r.get("sensor_1_p_star") not in (None, "")]
        for r in data:
            rows.append((label, float(r["time"]) * math.sqrt(G / height),
                         float(r["sensor_1_p_star"])))
        last = data[-1] if data else None
        stopped = "" if s["status"] == "ok" or last is None else \
            f" (stopped at t* = {float(last['time']) * math.sqrt(G / height):.2f})"
        keys.append((label, label + stopped))
        m = s.get("metrics", {})
        print(f"{label}: {len(data)} samples, status {s['status']}; impact t* "
              f"{m.get('impact_t_star', float('nan')):.4g}, peak ratio "
              f"{m.get('peak_ratio', float('nan')):.3g}"
              + (f", impulse ratio {m.get('impulse_ratio', float('nan')):.3g}" if h600 else "")
              + f", wall {s['wall_seconds']:.1f} s")
    with open(prefix + ".csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["run", "t_star", "p_star"])
        w.writerows(rows)
    reference = (f"3.15 with lines lc rgb '#888888' dt 2 lw 1 title 'median peak over the "
                 f"repeats (unverified)'" if h600 else
                 f"'{prefix}.csv' using (strcol(1) eq 'experiment' ? $2 : 1/0):3 with lines lc rgb "
                 f"'#888888' lw 1 title 'experiment (event 5)'")
    plots = ", \\\n     ".join(
        [reference] +
        [f"'{prefix}.csv' using (strcol(1) eq '{label}' ? $2 : 1/0):3 with lines lw 2 "
         f"title '{key}'" for label, key in keys])
    script = f"""
set datafile separator ','
set terminal pngcairo size 1000,800 font 'DejaVu Sans,11'
set output '{prefix}.png'
set multiplot layout 2,1 title 'Dam break, Lobovsky et al. 2014 (H = {round(height * 1000)} mm): sensor 1'
set grid
set key top right
set xlabel 't* = t (g/H)^{{1/2}}'
set ylabel 'p* = p / ({{/Symbol r}} g H)'
set xrange [{"1.2:3.1" if h600 else "0:6.3"}]
set yrange [-0.5:{6 if h600 else 4}]
plot {plots}
set xrange [{"1.3:2.3" if h600 else "2.2:3.2"}]
set yrange [-1:10]
set title 'the impact'
plot {plots}
unset multiplot
"""
    subprocess.run(["gnuplot"], input=script, text=True, check=True)
    print(f"wrote {prefix}.csv and {prefix}.png")


if __name__ == "__main__":
    main()
