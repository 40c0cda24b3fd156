#!/usr/bin/env python3
"""The water wheel (Leroy et al. 2014 sec 4.4, cases/water_wheel.lua): isph-usaw against
wcsph-usaw.

    python3 tests/validation/wheel_chart.py RUNS_DIR OUT_DIR

RUNS_DIR holds the runs of tests/validation/run_wheel.sh (isph_dr020, wcsph_dr020, each rendered
with `clsph render RUN --field speed --range 0,3`; on the torque chart also isph_dr020_rtol1e-6
and isph_dr020_cfl2, isph-usaw with a looser pressure solve and at the paper's C_CFL = 0.2).
Writes to OUT_DIR:
  wheel_torque.csv, wheel_torque.png  the torque of the fluid on the wheel against t+ = t √(g/H)
                                       (each sample, and its mean over a quarter turn, 1 s, as
                                       the paper smooths its force), the water's area against its
                                       start, and the wheel's work beside the fluid's energy gain
  wheel_t66.png                        the two schemes' frames at t+ = 66 (t = 20 s) side by side
  wheel_cost.png                       accuracy against cost: each scheme's (and time step's)
                                       worst change of the water's area over its run at
                                       dr = 0.02 m against the cost of 30 s at the paper's 3e4
                                       particles (results.py's, from the 1-s runs at
                                       dr = 0.0134 m), with the paper's times and the goal (10
                                       times faster)
and RUNS_DIR/wheel.mp4, the two movies side by side (ffmpeg).
"""
import csv
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import results  # noqa: E402  (the cost of 30 s, as RESULTS_wheel.md computes it)

G, H, OMEGA = 9.81, 0.9, math.pi / 2
RUNS = [("isph-usaw", "isph_dr020"), ("wcsph-usaw", "wcsph_dr020"),
        ("isph-usaw rtol 1e-6", "isph_dr020_rtol1e-6"),
        ("isph-usaw C_CFL 0.2", "isph_dr020_cfl2")]
FRAMES = ("isph-usaw", "wcsph-usaw")  # side by side at t+ = 66
# line colours: each sample (light), the 1 s mean (dark)
COLOURS = {"isph-usaw": ("#9ecae1", "#08519c"), "wcsph-usaw": ("#fdae6b", "#d94801"),
           "isph-usaw rtol 1e-6": ("#bcbddc", "#54278f"),
           "isph-usaw C_CFL 0.2": ("#a1d99b", "#006d2c")}


def series(run_dir):
    with open(os.path.join(run_dir, "series.csv")) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    runs_dir, out_dir = sys.argv[1], sys.argv[2]
    rows = []  # scheme, t+, torque, torque (1 s mean), area change, work, energy gain
    present = []
    for label, name in RUNS:
        path = os.path.join(runs_dir, name)
        if not os.path.exists(os.path.join(path, "series.csv")):
            continue
        present.append((label, path))
        s = series(path)
        work, a0, e0 = 0.0, s[0]["water_area"], s[0]["energy"]
        for i, r in enumerate(s):
            if i > 0:
                work -= 0.5 * (r["torque"] + s[i - 1]["torque"]) * OMEGA * (r["time"] - s[i - 1]["time"])
            window = [q["torque"] for q in s if abs(q["time"] - r["time"]) <= 0.5]
            rows.append((label, r["time"] * math.sqrt(G / H), r["torque"], sum(window) / len(window),
                         r["water_area"] / a0 - 1, work, r["energy"] - e0))
    csv_path = os.path.join(out_dir, "wheel_torque.csv")
    with open(csv_path, "w") as f:
        f.write("scheme,t_plus,torque,torque_1s,area_change,work,energy_gain\n")
        f.writelines(f"{r[0]},{r[1]:.5g},{r[2]:.6g},{r[3]:.6g},{r[4]:.6g},{r[5]:.6g},{r[6]:.6g}\n"
                     for r in rows)

    def plot(col, smooth=None):
        out = []
        for label, _ in present:
            if smooth is not None:
                out.append(f"'{csv_path}' using (strcol(1) eq '{label}' ? $2 : 1/0):{col} with lines "
                           f"lw 0.5 lc '{COLOURS[label][0]}' notitle")
                out.append(f"'{csv_path}' using (strcol(1) eq '{label}' ? $2 : 1/0):{smooth} with "
                           f"lines lw 2 lc '{COLOURS[label][1]}' "
                           f"title '{label} (1 s mean)'")
            else:
                out.append(f"'{csv_path}' using (strcol(1) eq '{label}' ? $2 : 1/0):{col} with lines "
                           f"lw 2 lc '{COLOURS[label][1]}' title '{label}'")
        return ", ".join(out)
    energy = ", ".join(
        f"'{csv_path}' using (strcol(1) eq '{label}' ? $2 : 1/0):6 with lines lw 2 "
        f"lc '{COLOURS[label][1]}' title '{label}: work', "
        f"'{csv_path}' using (strcol(1) eq '{label}' ? $2 : 1/0):7 with lines lw 2 dt 2 "
        f"lc '{COLOURS[label][1]}' title '{label}: energy gain'" for label, _ in present)
    script = f"""set terminal pngcairo size 1500,450 font ",10" noenhanced
set output '{os.path.join(out_dir, "wheel_torque.png")}'
set datafile separator ','
set multiplot layout 1,3 title 'Water wheel (Leroy et al. 2014 sec 4.4), dr = 0.02 m'
set grid
set key left bottom
set xlabel 't+ = t (g/H)^(1/2)'
set ylabel 'torque of the fluid on the wheel (N m/m)'
plot {plot(3, smooth=4)}
set key left top
set ylabel 'water area / its start - 1'
plot {plot(5)}
set ylabel 'J/m'
plot {energy}
unset multiplot
"""
    subprocess.run(["gnuplot"], input=script, text=True, check=True)
    # the frames at t = 20 s (snapshot 40 at output_every 0.5 s) side by side, and the movies
    frames = [os.path.join(p, "frames", "speed_000040.png") for l, p in present if l in FRAMES]
    if len(frames) == 2 and all(os.path.exists(f) for f in frames):
        subprocess.run(["ffmpeg", "-y", "-loglevel", "error", "-i", frames[0], "-i", frames[1],
                        "-filter_complex", "hstack", os.path.join(out_dir, "wheel_t66.png")],
                       check=True)
    movies = [os.path.join(p, "speed.mp4") for l, p in present if l in FRAMES]
    if len(movies) == 2 and all(os.path.exists(m) for m in movies):
        subprocess.run(["ffmpeg", "-y", "-loglevel", "error", "-i", movies[0], "-i", movies[1],
                        "-filter_complex", "hstack", os.path.join(runs_dir, "wheel.mp4")],
                       check=True)
    cost_chart(runs_dir, out_dir)
    print(f"wrote {csv_path} and its charts")


def cost_chart(runs_dir, out_dir):
    """wheel_cost.png: per scheme and cfl, the worst area change of the longest run at dr = 0.02 m
    against the cost of 30 s at the paper's count (the 1-s runs at dr = 0.0134 m)."""
    runs = [s for s in results.load_runs(runs_dir) if s.get("case") == "water_wheel"]
    full = results.wheel_full_runs(runs)
    rows = []  # label, hours, worst area change %, crossing steps
    for s in runs:
        if abs(s["parameters"].get("dr", 0) - 0.0134) > 1e-9 or s["status"] != "ok":
            continue
        ref = full.get(results.wheel_key(s))
        hours = results.wheel_cost_hours(s, ref)
        if hours is None or "water_area_worst" not in ref.get("metrics", {}):
            continue
        hours *= 3e4 / s["fluid_particles"]  # as RESULTS_wheel.md: to the paper's 3e4 (2%)
        label = results.wheel_label(s)
        rows.append((label, hours, 100 * ref["metrics"]["water_area_worst"],
                     ref["metrics"].get("crossed_wall", 0)))
    if not rows:
        return
    csv_path = os.path.join(out_dir, "wheel_cost.csv")
    with open(csv_path, "w") as f:
        f.write("label,hours_30s_paper_count,area_worst_percent,crossing_steps\n")
        f.writelines(f"{r[0]},{r[1]:.4g},{r[2]:.4g},{r[3]:g}\n" for r in rows)
    lines = []
    for k, (label, _, _, _) in enumerate(rows):
        lines.append(f"'{csv_path}' every ::{k + 1}::{k + 1} using 2:3 with points pt 7 ps 2 "
                     f"title sprintf('{label}: %d steps with a crossing', {rows[k][3]})")
    marks = []
    for scheme, h in results.WHEEL_PAPER_HOURS.items():
        marks.append(f"set arrow from {h:g}, graph 0 to {h:g}, graph 1 nohead dt 2 lc 'gray'\n"
                     f"set label '{scheme}: paper {h:g} h' at {h:g}, graph 0.03 left rotate by 90 "
                     "offset -0.5,0 tc 'gray'\n"
                     f"set arrow from {h / 10:g}, graph 0 to {h / 10:g}, graph 1 nohead dt 3 "
                     "lc 'black'\n"
                     f"set label '{scheme}: goal {h / 10:g} h' at {h / 10:g}, graph 0.03 left "
                     "rotate by 90 offset -0.5,0\n")
    script = f"""set terminal pngcairo size 900,550 font ",10" noenhanced
set output '{os.path.join(out_dir, "wheel_cost.png")}'
set datafile separator ','
set title 'Water wheel: accuracy against cost (2 cores; the paper: one CPU)'
set logscale x
set xrange [0.3:200]
set yrange [0:*]
set grid
set key right top box opaque
set xlabel "hours for 30 s at the paper's 3e4 particles (1-s runs at dr = 0.0134 m)"
set ylabel 'worst water-area change over the run at dr = 0.02 m (%)'
{"".join(marks)}
plot {", ".join(lines)}
"""
    subprocess.run(["gnuplot"], input=script, text=True, check=True)


if __name__ == "__main__":
    main()
