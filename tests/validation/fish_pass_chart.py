#!/usr/bin/env python3
"""The fish-pass (Leroy et al. 2014 sec 5.2, cases/fish_pass.lua) on one chart: u_x, u_y, p, k
and ε along the sections P1-P3 (columns) and the wall pressure along P4, with the flow rate
across P2 over time (OpenFOAM's: tests/data/openfoam_fish_pass_flow.csv), for the runs given and OpenFOAM's profiles (tests/data/openfoam_fish_pass.csv).
Each run's profiles are its profile_P*.csv rows at its last time; its pressure, like OpenFOAM's,
less its mean over the P1-P3 points (a periodic pool with walls only fixes p up to a constant).

    python3 tests/validation/fish_pass_chart.py OUT_DIR LABEL=RUN_DIR ...
writes OUT_DIR/fish_pass_profiles.{csv,png} (gnuplot).
"""
import csv
import os
import subprocess
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
LINES = ("P1", "P2", "P3")


def table(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def run_profiles(run_dir):
    """{line: [(s, x, y, u_x, u_y, p, k, ε)]} at the run's last time, p less its P1-P3 mean."""
    out = {}
    for name in LINES + ("P4",):
        rows = table(os.path.join(run_dir, f"profile_{name}.csv"))
        last = max(float(r["time"]) for r in rows)
        out[name] = [[float(r[c]) if r.get(c, "") != "" else float("nan")
                      for c in ("s", "x", "y", "vel_x", "vel_y", "p", "k", "epsilon")]
                     for r in rows if float(r["time"]) == last]
    ps = [v[5] for name in LINES for v in out[name] if v[5] == v[5]]
    mean = sum(ps) / len(ps)
    for rows in out.values():
        for v in rows:
            v[5] -= mean
    return out


def reference():
    rows = table(os.path.join(ROOT, "tests", "data", "openfoam_fish_pass.csv"))
    out = {}
    for r in rows:
        out.setdefault(r["line"], []).append(
            [float(r[c]) for c in ("s", "x", "y", "U_x", "U_y", "p", "k", "epsilon")])
    return out  # its p is already less its P1-P3 mean


def gnuplot(script):
    subprocess.run(["gnuplot"], input=script, text=True, check=True)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out_dir = sys.argv[1]
    series = [("OpenFOAM k-epsilon", reference(), None)]
    for arg in sys.argv[2:]:
        label, run_dir = arg.rsplit("=", 1)
        series.append((label, run_profiles(run_dir), run_dir))
    csv_path = os.path.join(out_dir, "fish_pass_profiles.csv")
    with open(csv_path, "w") as f:
        f.write("series,line,s,x,y,u_x,u_y,p,k,epsilon\n")
        for label, prof, _ in series:
            for name, rows in prof.items():
                for v in rows:
                    f.write(f"{label},{name}," + ",".join(f"{x:.6g}" for x in v) + "\n")
    flow_path = os.path.join(out_dir, "fish_pass_flow.csv")
    with open(flow_path, "w") as f:
        f.write("series,time,flow_rate\n")
        for r in table(os.path.join(ROOT, "tests", "data", "openfoam_fish_pass_flow.csv")):
            f.write(f"{series[0][0]},{r['time']},{r['flow_rate']}\n")
        for label, _, run_dir in series:
            if run_dir is None:
                continue
            for r in table(os.path.join(run_dir, "series.csv")):
                f.write(f"{label},{r['time']},{r['flow_rate']}\n")
    labels = [s[0] for s in series]

    def plots(line, col, path=csv_path, xcol=5):
        out = []
        for s in labels:
            style = "lines lw 2 lc rgb 'black'" if s.startswith("OpenFOAM") else "lines lw 1.5"
            sel = f"strcol(1) eq '{s}' && strcol(2) eq '{line}'"
            out.append(f"'{path}' using ({sel} ? ${xcol} : 1/0):{col} with {style} title '{s}'")
        return ", ".join(out)

    panels = []
    for col, what in ((6, "u_x (m/s)"), (7, "u_y (m/s)"), (8, "p (Pa, less the P1-P3 mean)"),
                      (9, "k (m2/s2)"), (10, "epsilon (m2/s3)")):
        for line in LINES:
            log = "set logscale y\n" if col == 10 else "unset logscale y\n"
            panels.append(f"{log}set title '{line}: {what}'\nset xlabel 'y (m)'\n"
                          f"plot {plots(line, col)}")
    panels.append("unset logscale y\nset title 'P4 (wall y = 0): p (Pa, less the P1-P3 mean)'\n"
                  f"set xlabel 'x (m)'\nplot {plots('P4', 8, xcol=4)}")
    flows = ", ".join(f"'{flow_path}' using (strcol(1) eq '{s}' ? $2 : 1/0):3 with lines "
                      + ("lw 2 lc rgb 'black'" if s.startswith("OpenFOAM") else "lw 1.5")
                      + f" title '{s}'" for s in labels)
    panels.append(f"set title 'flow rate across P2 (m2/s)'\nset xlabel 't (s)'\nplot {flows}")
    gnuplot(f"""set terminal pngcairo size 1500,2000 font ",9" noenhanced
set output '{os.path.join(out_dir, "fish_pass_profiles.png")}'
set datafile separator ','
set multiplot layout 6,3 title 'Fish-pass after 20 s (Leroy et al. 2014 sec 5.2): SPH against OpenFOAM'
set grid
set key left top font ",7"
""" + "\n".join(panels) + "\nunset multiplot\n")


if __name__ == "__main__":
    main()
