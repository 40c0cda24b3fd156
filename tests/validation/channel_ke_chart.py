#!/usr/bin/env python3
"""The k-ε RANS validations of wcsph-riemann (Wang, Sun & Hu sec 5.1 and 5.3) on two charts.

1. The fully developed channel: u+ against y+ of the runs given (cases/channel_ke.lua with
   ub = 1: each run's u+ and y+ in its own friction velocity, the rows' means over the last
   snapshot, both halves folded), beside Lee & Moser's DNS at Re_tau = 543.5, the 1-D solver
   (tests/data/channel1d_re_tau543.csv) and OpenFOAM's 20-cell run at the same U_b
   (tests/data/openfoam_channel_straight.csv, setting a, y_p = 0.05).
2. The half converging-diverging channel: u and k along x = 5 (over the platform) and x = 9.5
   (the exit section) of the runs given (cases/channel_hcd.lua: profile_platform.csv and
   profile_exit.csv, averaged over the outputs at t >= T0), beside OpenFOAM's
   (tests/data/openfoam_channel_hcd.csv, the uniform entry).

    python3 tests/validation/channel_ke_chart.py OUT_DIR T0 channel:LABEL=RUN_DIR ... \
        hcd:LABEL=RUN_DIR ...
writes OUT_DIR/channel_ke_uplus.{csv,png} and OUT_DIR/channel_hcd_profiles.{csv,png} (gnuplot).
"""
import csv
import os
import subprocess
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
NU, DELTA, U_TAU_REF = 1e-4, 1.0, 0.0543496


def table(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def snapshot_rows(run_dir, nf, y_p):
    """(y, mean u) per particle row of the last snapshot, folded at the centreline (h5dump)."""
    snaps = sorted(p for p in os.listdir(run_dir) if p.startswith("snap_") and p.endswith(".h5"))
    path = os.path.join(run_dir, snaps[-1])

    def get(name):
        out = subprocess.run(["h5dump", "-d", f"/particles/{name}", "-y", "-w", "0", path],
                             capture_output=True, text=True, check=True).stdout
        start = out.index("DATA {") + 6
        body = out[start:out.index("}", start)]
        return [float(v) for v in body.replace("\n", " ").replace(",", " ").split() if v]

    kind, pos, vel = get("kind"), get("pos"), get("vel")
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
        summary = json_load(os.path.join(run_dir, "summary.json"))
        params, metrics = summary["parameters"], summary["metrics"]
        ut = metrics.get("u_tau", U_TAU_REF)
        for y, u in snapshot_rows(run_dir, int(params["nf"]), params["y_p"]):
            rows.append((label, y * ut / NU, u / ut))
    for r in table(os.path.join(ROOT, "tests/data/channel_dns_LM550.csv")):
        if float(r["y_plus"]) > 1:
            rows.append(("DNS (Lee & Moser)", float(r["y_plus"]), float(r["U_plus"])))
    for r in table(os.path.join(ROOT, "tests/data/channel1d_re_tau543.csv")):
        rows.append(("1-D solver", float(r["y_plus"]), float(r["u_plus"])))
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


def hcd_chart(out_dir, t0, runs):
    rows = []
    for label, run_dir in runs:
        for line in ("platform", "exit"):
            rows += [(label, line, y, u, k) for y, u, k in averaged(run_dir, line, t0)]
    for r in table(os.path.join(ROOT, "tests/data/openfoam_channel_hcd.csv")):
        if r["inlet"] == "uniform":
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


def json_load(path):
    import json
    with open(path) as f:
        return json.load(f)


def gnuplot(script):
    subprocess.run(["gnuplot"], input=script, text=True, check=True)


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    out_dir, t0 = sys.argv[1], float(sys.argv[2])
    channel, hcd = [], []
    for a in sys.argv[3:]:
        kind, rest = a.split(":", 1)
        label, run_dir = rest.rsplit("=", 1)
        if "," in label:
            sys.exit(f"channel_ke_chart.py: a label may not hold a comma (the CSV's separator): {label}")
        (channel if kind == "channel" else hcd).append((label, run_dir))
    if channel:
        channel_chart(out_dir, channel)
    if hcd:
        hcd_chart(out_dir, t0, hcd)
    print(f"wrote the charts into {out_dir}")


if __name__ == "__main__":
    main()
