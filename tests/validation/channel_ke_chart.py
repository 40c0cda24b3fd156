#!/usr/bin/env python3
"""The k-ε RANS validations of wcsph-riemann (Wang, Sun & Hu sec 5.1 and 5.3) on two charts.

1. The fully developed channel: u+ against y+ of the runs given (cases/channel_ke.lua with
   ub = 1: each run's u+ and y+ in its own friction velocity, the rows' means over the last
   snapshot, both halves folded), beside Lee & Moser's DNS at Re_tau = 543.5, the 1-D solver
   (tests/data/channel1d_re_tau543.csv; and on the rows of N_f = 40, channel1d_rows40.csv) and
   OpenFOAM's 20-cell run at the same U_b
   (tests/data/openfoam_channel_straight.csv, setting a, y_p = 0.05).
2. The half converging-diverging channel: u and k along x = 5 (over the platform) and x = 9.5
   (the exit section) of the runs given (cases/channel_hcd.lua: profile_platform.csv and
   profile_exit.csv, averaged over each run's own last `avg` s, as its metrics are), beside
   OpenFOAM's
   (tests/data/openfoam_channel_hcd.csv, the uniform entry).
3. The curved channels: u along the channel and k across the bend's exit plane and the last
   section before the exit of the runs given (cases/channel_curved.lua: profile_bend.csv and
   profile_outlet.csv, averaged over each run's own last `avg` s), beside OpenFOAM's
   (tests/data/openfoam_channel_{mild,strong}.csv at the run's y_p).

4. The HCD channel's stability map: the disturbance (the RMS along a line of u's spread in time,
   over U_b, and of k's over its mean: cases/channel_hcd.lua's u_unsteady_* and k_unsteady_*) in
   each 10-s window from t = 20 s (results.py's hcd_windows: one window is one sample of the
   flow behind the platform), their mean and range against N_f, one series for each momentum
   dissipation (ARD, or without it the fluid pairs' "reconstructed", "none" or "riemann"; the
   runs given as hcdmap:LABEL=RUN_DIR; a label other than "map" names a series beside them,
   e.g. the mirror's walls).

5. The HCD channel's floor: the first row's velocity along the floor, time-averaged over each
   run's last `avg` s, against OpenFOAM's wall cells (results.py's hcd_floor_run and
   hcd_floor_fv: the separation behind the platform and the reattachment).

    python3 tests/validation/channel_ke_chart.py OUT_DIR channel:LABEL=RUN_DIR ... \
        hcd:LABEL=RUN_DIR ... curved:LABEL=RUN_DIR ... hcdmap:LABEL=RUN_DIR ... \
        floor:LABEL=RUN_DIR ...
writes OUT_DIR/channel_ke_uplus.{csv,png}, OUT_DIR/channel_hcd_profiles.{csv,png},
OUT_DIR/channel_curved_profiles.{csv,png}, OUT_DIR/channel_hcd_map.{csv,png} and
OUT_DIR/channel_hcd_floor.{csv,png} (gnuplot).
"""
import csv
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from snapshot_fields import last_snapshot_fields  # noqa: E402
from results import hcd_dissipation, hcd_floor_fv, hcd_floor_run, hcd_windows  # noqa: E402

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
NU, DELTA, U_TAU_REF = 1e-4, 1.0, 0.0543496


def table(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def snapshot_rows(run_dir, nf, y_p):
    """(y, mean u) per particle row of the last snapshot, folded at the centreline (h5dump)."""
    kind, pos, vel = last_snapshot_fields(run_dir, "kind", "pos", "vel")
    dr = (2 * DELTA - 2 * y_p) / (nf - 1)
    off = y_p - dr / 2
    acc = {}
    for i, k in enumerate(kind):
        if k != 0:
            continue
        y = pos[2 * i + 1]
        d = min(y, 2 * DELTA - y)
        r = int((d - off) // dr)
        a = acc.setdefault(r, [0.0, 0.0, 0])
        a[0] += d
        a[1] += vel[2 * i]
        a[2] += 1
    return [(a[0] / a[2], a[1] / a[2]) for r, a in sorted(acc.items()) if r < nf // 2]


def channel_chart(out_dir, runs):
    rows = []
    for label, run_dir in runs:
        summary = finished(run_dir, "the chart")
        if summary is None:
            continue
        params, metrics = summary["parameters"], summary["metrics"]
        ut = metrics.get("u_tau", U_TAU_REF)
        for y, u in snapshot_rows(run_dir, int(params["nf"]), params["y_p"]):
            rows.append((label, y * ut / NU, u / ut))
    for r in table(os.path.join(ROOT, "tests/data/channel_dns_LM550.csv")):
        if float(r["y_plus"]) > 1:
            rows.append(("DNS (Lee & Moser)", float(r["y_plus"]), float(r["U_plus"])))
    for r in table(os.path.join(ROOT, "tests/data/channel1d_re_tau543.csv")):
        rows.append(("1-D solver", float(r["y_plus"]), float(r["u_plus"])))
    for r in table(os.path.join(ROOT, "tests/data/channel1d_rows40.csv")):
        rows.append(("1-D solver on the 40 rows", float(r["y_plus"]), float(r["u_plus"])))
    for r in table(os.path.join(ROOT, "tests/data/openfoam_channel_straight.csv")):
        if r["setting"] == "a" and float(r["y_p"]) == 0.05 and r["mesh"] == "uniform_20":
            ut = float(r["u_tau"])
            rows.append(("OpenFOAM 20 cells", float(r["y"]) * ut / NU, float(r["U"]) / ut))
    csv_path = os.path.join(out_dir, "channel_ke_uplus.csv")
    with open(csv_path, "w") as f:
        f.write("series,y_plus,u_plus\n")
        f.writelines(f"{s},{y:.6g},{u:.6g}\n" for s, y, u in rows)
    series = list(dict.fromkeys(s for s, _, _ in rows))
    plots = []
    for s in series:
        style = "lines lw 2" if s in ("DNS (Lee & Moser)", "1-D solver") else "linespoints pt 7 ps 0.8"
        plots.append(f"'{csv_path}' using (strcol(1) eq '{s}' ? $2 : 1/0):3 with {style} "
                     f"title '{s}'")
    gnuplot(f"""set terminal pngcairo size 900,600 font ",11" noenhanced
set output '{os.path.join(out_dir, "channel_ke_uplus.png")}'
set datafile separator ','
set logscale x
set xrange [1:600]
set xlabel 'y+'
set ylabel 'u+'
set key left top
set grid
set title 'Fully developed channel, U_b = 1, Re_tau = 543.5 (DNS), y_p = 0.05: k-epsilon'
plot {", ".join(plots)}
""")


def averaged(run_dir, line, t0):
    acc, times = {}, set()
    for r in table(os.path.join(run_dir, f"profile_{line}.csv")):
        t = float(r["time"])
        if t < t0:
            continue
        times.add(t)
        a = acc.setdefault(float(r["y"]), [0.0, 0.0])
        a[0] += float(r["vel_x"])
        a[1] += float(r["k"])
    return [(y, a[0] / len(times), a[1] / len(times)) for y, a in sorted(acc.items())]


def hcd_chart(out_dir, runs):
    rows = []
    for label, run_dir in runs:
        summary = json_load(os.path.join(run_dir, "summary.json"))
        t0 = summary["sim_time"] - summary["parameters"]["avg"]
        for line in ("platform", "exit"):
            got = averaged(run_dir, line, t0 - 1e-9)
            if not got:
                sys.exit(f"channel_ke_chart.py: {run_dir} has no {line} profile after t = {t0:g}")
            rows += [(label, line, y, u, k) for y, u, k in got]
    for r in table(os.path.join(ROOT, "tests/data/openfoam_channel_hcd.csv")):
        if r["inlet"] == "uniform" and r["line"] in ("platform", "exit"):
            rows.append(("OpenFOAM", r["line"], float(r["y"]), float(r["U"]), float(r["k"])))
    csv_path = os.path.join(out_dir, "channel_hcd_profiles.csv")
    with open(csv_path, "w") as f:
        f.write("series,line,y,u,k\n")
        f.writelines(f"{s},{l},{y:.6g},{u:.6g},{k:.6g}\n" for s, l, y, u, k in rows)
    series = list(dict.fromkeys(s for s, *_ in rows))
    panels = []
    for line, where in (("platform", "x = 5 (platform)"), ("exit", "x = 9.5")):
        for col, name in ((4, "u / U_b"), (5, "k / U_b^2")):
            plots = []
            for s in series:
                style = "lines lw 2 dt 2" if s == "OpenFOAM" else "lines lw 2"
                plots.append(f"'{csv_path}' using (strcol(1) eq '{s}' && strcol(2) eq '{line}' ? "
                             f"${col} : 1/0):3 with {style} title '{s}'")
            panels.append(f"set title '{name} along {where}'\nset xlabel '{name}'\n"
                          f"set ylabel 'y'\nplot {', '.join(plots)}")
    gnuplot(f"""set terminal pngcairo size 1200,900 font ",10" noenhanced
set output '{os.path.join(out_dir, "channel_hcd_profiles.png")}'
set datafile separator ','
set grid
set key bottom right
set multiplot layout 2,2
{chr(10).join(panels)}
unset multiplot
""")


def curved_averaged(run_dir, line, t0, y_p):
    """(s from the inner wall, mean u along the channel, mean k) over the outputs at t >= t0:
    the line runs from the inner wall outwards, the channel's direction is its own turned by
    +90° (the bend turns anticlockwise)."""
    rows = [r for r in table(os.path.join(run_dir, f"profile_{line}.csv"))
            if float(r["time"]) >= t0 - 1e-9]
    first = [r for r in rows if float(r["s"]) == 0.0]
    last = max(rows, key=lambda r: float(r["s"]))
    ex, ey = float(last["x"]) - float(first[0]["x"]), float(last["y"]) - float(first[0]["y"])
    n = (ex * ex + ey * ey) ** 0.5
    tx, ty = -ey / n, ex / n
    acc, times = {}, set()
    for r in rows:
        times.add(float(r["time"]))
        a = acc.setdefault(float(r["s"]), [0.0, 0.0])
        a[0] += float(r["vel_x"]) * tx + float(r["vel_y"]) * ty
        a[1] += float(r["k"])
    return [(y_p + s, a[0] / len(times), a[1] / len(times)) for s, a in sorted(acc.items())]


def curved_chart(out_dir, runs):
    rows, shown = [], set()
    names = {1: ("mild", 0.0635), 2: ("strong", 0.0762)}
    for label, run_dir in runs:
        summary = finished(run_dir, "the chart")
        if summary is None:
            continue
        params, metrics = summary["parameters"], summary["metrics"]
        name, height = names[int(params.get("setting", 1))]
        t0 = summary["sim_time"] - metrics["avg"]
        for line in ("bend", "outlet"):
            rows += [(name, f"{label}", line, s / height, u, k)
                     for s, u, k in curved_averaged(run_dir, line, t0, metrics["y_p"])]
        if (name, metrics["y_p"]) in shown:
            continue
        shown.add((name, metrics["y_p"]))
        for r in table(os.path.join(ROOT, f"tests/data/openfoam_channel_{name}.csv")):
            if abs(float(r["y_p"]) - metrics["y_p"]) < 1e-9 and r["section"] in ("bend_end",
                                                                                  "outlet"):
                line = "bend" if r["section"] == "bend_end" else "outlet"
                rows.append((name, f"OpenFOAM y_p {metrics['y_p']:g}", line,
                             float(r["s_over_H"]), float(r["U"]), float(r["k"])))
    csv_path = os.path.join(out_dir, "channel_curved_profiles.csv")
    with open(csv_path, "w") as f:
        f.write("channel,series,line,s_over_H,u,k\n")
        f.writelines(f"{c},{s},{l},{y:.6g},{u:.6g},{k:.6g}\n" for c, s, l, y, u, k in rows)
    channels = list(dict.fromkeys(c for c, *_ in rows))
    panels = []
    for c in channels:
        series = list(dict.fromkeys(s for cc, s, *_ in rows if cc == c))
        for col, what in ((5, "u along the channel / U_b"), (6, "k / U_b^2")):
            plots = []
            for s in series:
                for line, dash in (("bend", "dt 3"), ("outlet", "")):
                    style = "points pt 6 ps 0.7" if s.startswith("OpenFOAM") else f"lines lw 2 {dash}"
                    plots.append(f"'{csv_path}' using (strcol(1) eq '{c}' && strcol(2) eq '{s}' && "
                                 f"strcol(3) eq '{line}' ? $4 : 1/0):{col} with {style} "
                                 f"title '{s}, {line}'")
            panels.append(f"set title '{c} channel: {what}'\nset xlabel 's / H from the inner "
                          f"wall'\nset ylabel '{what}'\nplot {', '.join(plots)}")
    gnuplot(f"""set terminal pngcairo size 1200,{450 * len(channels)} font ",10" noenhanced
set output '{os.path.join(out_dir, "channel_curved_profiles.png")}'
set datafile separator ','
set grid
set key bottom center font ",8"
set multiplot layout {len(channels)},2
{chr(10).join(panels)}
unset multiplot
""")


def hcd_map_chart(out_dir, runs):
    rows = []
    for label, run_dir in runs:
        summary = finished(run_dir, "the map")
        if summary is None:
            continue
        p = summary["parameters"]
        plat, exit_ = hcd_windows(run_dir, "platform"), hcd_windows(run_dir, "exit")
        if not plat or not exit_:
            print(f"channel_ke_chart.py: {run_dir} has no whole window of outputs: left out of the "
                  "map")
            continue
        series = hcd_dissipation(p) + ("" if label == "map" else f" {label}")
        cols = []
        for vals in ([u for u, _ in plat], [u for u, _ in exit_], [k for _, k in plat],
                     [k for _, k in exit_]):
            cols += [sum(vals) / len(vals), min(vals), max(vals)]
        rows.append((series, int(p["nf"]), len(exit_), cols))
    rows.sort()
    csv_path = os.path.join(out_dir, "channel_hcd_map.csv")
    names = ("u_unsteady_platform", "u_unsteady_exit", "k_unsteady_platform", "k_unsteady_exit")
    with open(csv_path, "w") as f:
        f.write("series,nf,windows," + ",".join(f"{n},{n}_min,{n}_max" for n in names) + "\n")
        f.writelines(f"{r[0]},{r[1]},{r[2]}," + ",".join(f"{v:.6g}" for v in r[3]) + "\n"
                     for r in rows)
    panels = []
    for i, what in enumerate(("u spread, x = 5", "u spread, x = 9.5", "k spread, x = 5",
                              "k spread, x = 9.5")):
        col = 4 + 3 * i
        series = sorted({r[0] for r in rows})  # each series a little apart along N_f
        plots = [f"'{csv_path}' using (strcol(1) eq '{s}' ? $2 + {0.8 * (j - (len(series) - 1) / 2):g} "
                 f": 1/0):{col}:{col + 1}:{col + 2} with yerrorlines lw 2 pt 7 title '{s}'"
                 for j, s in enumerate(series)]
        panels.append(f"set title '{what}'\nplot {', '.join(plots)}")
    gnuplot(f"""set terminal pngcairo size 1000,700 font ",10" noenhanced
set output '{os.path.join(out_dir, "channel_hcd_map.png")}'
set datafile separator ','
set grid
set key top right
set xlabel 'N_f (rows across the entry)'
set ylabel 'RMS spread (10-s windows)'
set xrange [30:90]
set yrange [0:*]
set multiplot layout 2,2 title 'HCD channel: the disturbance by the momentum dissipation (a steady RANS flow holds still)'
{chr(10).join(panels)}
unset multiplot
""")


def hcd_floor_chart(out_dir, runs):
    rows = []
    for label, run_dir in runs:
        summary = finished(run_dir, "the floor chart")
        if summary is not None:
            rows += [(label, x, u) for x, u in hcd_floor_run(run_dir, summary)]
    rows += [("OpenFOAM wall cells", x, u) for x, u in hcd_floor_fv()]
    csv_path = os.path.join(out_dir, "channel_hcd_floor.csv")
    with open(csv_path, "w") as f:
        f.write("series,x,u\n")
        f.writelines(f"{s},{x:.6g},{u:.6g}\n" for s, x, u in rows)
    series = list(dict.fromkeys(s for s, *_ in rows))
    plots = [f"'{csv_path}' using (strcol(1) eq '{s}' ? $2 : 1/0):3 with "
             f"{'points pt 6 ps 0.8 lc black' if s.startswith('OpenFOAM') else 'lines lw 2'} "
             f"title '{s}'" for s in series]
    gnuplot(f"""set terminal pngcairo size 1100,500 font ",10" noenhanced
set output '{os.path.join(out_dir, "channel_hcd_floor.png")}'
set datafile separator ','
set grid
set key top right font ",9"
set title "HCD channel: the first row along the floor (time mean) and OpenFOAM's wall cells (y_p off the wall)"
set xlabel 'x (the foot on the floor; platform: ramp 3-4.5, top 4.5-5.5, ramp 5.5-7)'
set ylabel 'u along the floor / U_b'
set xzeroaxis lt -1
plot {', '.join(plots)}
""")


def finished(run_dir, what):
    """A run's summary.json, or None (said) for a run still going: the N_f = 40 ones take hours."""
    path = os.path.join(run_dir, "summary.json")
    if not os.path.exists(path):
        print(f"channel_ke_chart.py: {run_dir} has no summary.json: left out of {what}")
        return None
    return json_load(path)


def json_load(path):
    import json
    with open(path) as f:
        return json.load(f)


def gnuplot(script):
    subprocess.run(["gnuplot"], input=script, text=True, check=True)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out_dir = sys.argv[1]
    channel, hcd, curved, hcdmap, floor = [], [], [], [], []
    for a in sys.argv[2:]:
        kind, rest = a.split(":", 1)
        label, run_dir = rest.rsplit("=", 1)
        if "," in label:
            sys.exit(f"channel_ke_chart.py: a label may not hold a comma (the CSV's separator): {label}")
        kinds = {"channel": channel, "hcd": hcd, "curved": curved, "hcdmap": hcdmap,
                 "floor": floor}
        if kind not in kinds:
            sys.exit(f"channel_ke_chart.py: '{kind}' is not channel, hcd, curved, hcdmap or floor: "
                     f"{a}")
        kinds[kind].append((label, run_dir))
    if channel:
        channel_chart(out_dir, channel)
    if hcd:
        hcd_chart(out_dir, hcd)
    if curved:
        curved_chart(out_dir, curved)
    if hcdmap:
        hcd_map_chart(out_dir, hcdmap)
    if floor:
        hcd_floor_chart(out_dir, floor)
    print(f"wrote the charts into {out_dir}")


if __name__ == "__main__":
    main()
