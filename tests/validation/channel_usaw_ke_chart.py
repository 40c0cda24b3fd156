#!/usr/bin/env python3
"""The k-ε channel of the USAW schemes (Leroy et al. 2014 sec 5.1) on one chart of three panels.

u+ against y+, k+ and ε+ against y/e of the runs given (cases/channel_usaw_ke.lua: the rows'
means over the last snapshot, both halves folded; u* = 1 m/s and e = 1 m, so u+ = u, k+ = k,
ε+ = ε), beside the 1-D reference of the same model and wall law (tests/data/channel1d_leroy640.csv
or channel1d_leroy543.csv, as the run's re_tau) and Lee & Moser's DNS at Re_tau = 543.5
(tests/data/channel_dns_LM550.csv; the paper's e+ = 640 DNS is Kawamura's, not stored here).

    python3 tests/validation/channel_usaw_ke_chart.py OUT_DIR LABEL=RUN_DIR ...
writes OUT_DIR/channel_usaw_ke.{csv,png} (gnuplot).
"""
import csv
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from snapshot_fields import last_snapshot_fields  # noqa: E402

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")


def table(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def snapshot_rows(run_dir, n):
    """(y, u, k, ε) per particle row of the last snapshot, folded at the centreline."""
    kind, pos, vel, k, eps = last_snapshot_fields(run_dir, "kind", "pos", "vel", "k", "epsilon")
    dr = 1.0 / n
    acc = {}
    for i, kd in enumerate(kind):
        if kd != 0:
            continue
        y = pos[2 * i + 1]
        d = min(y, 2.0 - y)
        r = int(d / dr)
        a = acc.setdefault(r, [0.0, 0.0, 0.0, 0])
        a[0] += vel[2 * i]
        a[1] += k[i]
        a[2] += eps[i]
        a[3] += 1
    return [((r + 0.5) * dr, a[0] / a[3], a[1] / a[3], a[2] / a[3]) for r, a in sorted(acc.items())]


def gnuplot(script):
    subprocess.run(["gnuplot"], input=script, text=True, check=True)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out_dir = sys.argv[1]
    rows = []  # series, y, y+, u+, k+, eps+
    refs = set()
    for arg in sys.argv[2:]:
        label, run_dir = arg.rsplit("=", 1)
        with open(os.path.join(run_dir, "summary.json")) as f:
            params = json.load(f)["parameters"]
        n, re_tau = int(params["n"]), float(params["re_tau"])
        refs.add(re_tau)
        for y, u, k, e in snapshot_rows(run_dir, n):
            rows.append((label, y, y * re_tau, u, k, e))
    for re_tau in sorted(refs):
        name = "channel1d_leroy640.csv" if re_tau == 640 else "channel1d_leroy543.csv"
        for r in table(os.path.join(ROOT, "tests", "data", name))[::10]:  # 320 of 3200 nodes
            rows.append((f"1-D reference, e+ {re_tau:g}".replace(",", ""), float(r["y"]), float(r["y_plus"]),
                         float(r["u_plus"]), float(r["k_plus"]), float(r["epsilon"])))
    for r in table(os.path.join(ROOT, "tests", "data", "channel_dns_LM550.csv")):
        if float(r["y_plus"]) > 0:
            rows.append(("DNS (Lee & Moser) Re_tau 543.5", float(r["y_over_delta"]), float(r["y_plus"]),
                         float(r["U_plus"]), float(r["k_plus"]), float("nan")))
    csv_path = os.path.join(out_dir, "channel_usaw_ke.csv")
    with open(csv_path, "w") as f:
        f.write("series,y_over_e,y_plus,u_plus,k_plus,eps_plus\n")
        f.writelines(f"{s},{y:.6g},{yp:.6g},{u:.6g},{k:.6g},{e:.6g}\n"
                     for s, y, yp, u, k, e in rows)
    series = list(dict.fromkeys(r[0] for r in rows))

    def plots(xcol, ycol, skip_dns=False):
        out = []
        for s in series:
            if skip_dns and s.startswith("DNS"):
                continue
            style = "lines lw 2" if s.startswith(("DNS", "1-D")) else "linespoints pt 7 ps 0.7"
            out.append(f"'{csv_path}' using (strcol(1) eq '{s}' ? ${xcol} : 1/0):{ycol} "
                       f"with {style} title '{s}'")
        return ", ".join(out)

    gnuplot(f"""set terminal pngcairo size 1500,500 font ",10" noenhanced
set output '{os.path.join(out_dir, "channel_usaw_ke.png")}'
set datafile separator ','
set multiplot layout 1,3 title 'Turbulent channel, k-epsilon with the semi-analytical walls (Leroy et al. 2014 sec 5.1)'
set grid
set key left top
set logscale x
set xrange [1:700]
set xlabel 'y+'
set ylabel 'u+'
plot {plots(3, 4)}
unset logscale x
set xrange [0:1]
set yrange [0:*]
set xlabel 'y/e'
set ylabel 'k+'
set key right top
plot {plots(2, 5)}
set logscale y
set yrange [0.5:200]
set ylabel 'epsilon+'
plot {plots(2, 6, skip_dns=True)}
unset multiplot
""")


if __name__ == "__main__":
    main()
