#!/usr/bin/env python3
"""Accuracy against cost, and where methods fail: runs the studies of tests/harness/studies.txt,
collects each run's summary.json into a CSV, and draws the charts from that CSV with gnuplot.

    tests/harness/harness.py list
    tests/harness/harness.py accuracy STUDY [options]
    tests/harness/harness.py stability STUDY [options]

accuracy: every series (scheme) of the study over its resolutions. Writes STUDY.csv (one row per
  run), STUDY_orders.csv (the observed order of each series) and two charts: STUDY_cost.png, the
  error against wall-clock seconds (log-log, one line per series, points labelled by resolution)
  and STUDY_particles.png, the error against the particle count, with the observed order in the
  legend (least-squares slope of log error over log h, h ∝ 1/n or dr, over the runs that ended
  "ok").
stability: every series over the grid of its two swept parameters. Writes STUDY.csv and one map
  per series, STUDY_SERIES.png: each cell is a run, green when it reached t_end, else coloured
  and labelled by the failure that stopped it (summary.json "failure": nan, escaped,
  wall_crossing, solver, clustering, energy, dt_collapse, ...), which clsph classifies itself.

options:
  --build DIR     the build whose clsph runs (default: build); give it several times
                  (e.g. build and build-float) for one series per scheme and precision
  --device N      OpenCL device index (clsph devices); several: one series per device
  --out DIR       where the runs go (default: out/harness/STUDY), one folder per run
  --results DIR   where the CSV and PNG files go (default: the --out folder); the charts kept
                  in the repository are in tests/validation
  --studies FILE  the study list (default: tests/harness/studies.txt next to this script)
  --rerun         run again even where a finished run's summary.json exists with the same
                  parameters (by default such runs are reused, so an interrupted sweep resumes)
  --collect       run nothing: collect the summary.json files there are and chart them
  --timeout S     wall-clock limit of one run, s (default 3600); a run past it is recorded as
                  failure "timeout"

Python 3 standard library only; charts need gnuplot (Debian package gnuplot-nox or gnuplot)."""
import csv
import json
import math
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

# Colours of the failure classes of a stability map (summary.json "failure"), stable first.
FAILURE_COLOURS = [
    ("none", "#2ca02c"), ("nan", "#d62728"), ("escaped", "#ff7f0e"),
    ("wall_crossing", "#9467bd"), ("solver", "#8c564b"), ("clustering", "#e377c2"),
    ("energy", "#bcbd22"), ("dt_collapse", "#17becf"), ("dt_bound", "#1f77b4"),
    ("neighbours", "#7f7f7f"), ("flow_control", "#aec7e8"), ("metrics", "#c5b0d5"),
    ("timeout", "#c49c94"), ("error", "#000000"),
]


class StudyError(Exception):
    pass


def parse_studies(path):
    """Lines of the study list: (kind, study, case, scheme, label, metric, fixed, swept, line)."""
    entries = []
    with open(path) as f:
        for number, raw in enumerate(f, 1):
            text = raw.split("#", 1)[0].split()
            if not text:
                continue
            where = f"{path}:{number}"
            if len(text) < 4 or text[0] not in ("accuracy", "stability"):
                raise StudyError(f"{where}: expected KIND STUDY CASE SCHEME KEY=VALUE..., KIND "
                                 "accuracy or stability")
            kind, study, case, scheme = text[:4]
            label, metric, fixed, swept = scheme, None, [], []
            for tok in text[4:]:
                if "=" not in tok:
                    raise StudyError(f"{where}: '{tok}' is not KEY=VALUE")
                key, value = tok.split("=", 1)
                if key == "label":
                    label = value
                elif key == "metric":
                    metric = value
                elif "," in value:
                    values = value.split(",")
                    for v in values:
                        float(v)  # numbers only: --set takes numbers
                    swept.append((key, values))
                else:
                    float(value)
                    fixed.append((key, value))
            want = 1 if kind == "accuracy" else 2
            if len(swept) != want:
                raise StudyError(f"{where}: a {kind} study sweeps {want} parameter(s) "
                                 f"(KEY=V1,V2,...), not {len(swept)}")
            if kind == "accuracy" and metric is None:
                raise StudyError(f"{where}: an accuracy study names its error: metric=NAME")
            entries.append(dict(kind=kind, study=study, case=case, scheme=scheme, label=label,
                                metric=metric, fixed=fixed, swept=swept, where=where))
    return entries


def number(text):
    v = float(text)
    return int(v) if v == int(v) else v


def fmt(v):
    return f"{v:g}" if isinstance(v, (int, float)) else str(v)


def run_name(entry, point, build_tag, device):
    parts = [entry["label"]] + [f"{k}{v}" for k, v in point]
    if build_tag:
        parts.append(build_tag)
    if device is not None:
        parts.append(f"dev{device}")
    return "_".join(parts).replace("/", "-")


def same_parameters(summary, sets):
    params = summary.get("parameters", {})
    return all(k in params and math.isclose(params[k], float(v), rel_tol=1e-12, abs_tol=1e-15)
               for k, v in sets)


def run_one(exe, case, sets, out, device, timeout, rerun, collect_only):
    """Runs clsph (unless a finished run with these parameters is there) and returns its
    summary, or a stand-in summary for a run that produced none (timeout, crash)."""
    path = os.path.join(out, "summary.json")
    if os.path.exists(path) and not rerun:
        with open(path) as f:
            s = json.load(f)
        if same_parameters(s, sets):
            return s, "reused"
    if collect_only:
        return None, "missing"
    # the harness decides what to reuse: a run it starts replaces what the folder held
    cmd = [exe, "run", os.path.join(ROOT, "cases", case + ".lua"), "--out", out, "--quiet",
           "--overwrite"]
    for k, v in sets:
        cmd += ["--set", f"{k}={v}"]
    if device is not None:
        cmd += ["--device", str(device)]
    if os.path.exists(path):
        os.remove(path)
    os.makedirs(out, exist_ok=True)
    try:
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                           timeout=timeout)
        log = p.stdout
    except subprocess.TimeoutExpired as e:
        log = (e.stdout or b"").decode() if isinstance(e.stdout, bytes) else (e.stdout or "")
        with open(os.path.join(out, "harness.log"), "w") as f:
            f.write(log)
        return dict(status=f"timeout after {timeout} s", failure="timeout"), "timeout"
    with open(os.path.join(out, "harness.log"), "w") as f:
        f.write(log)
    if not os.path.exists(path):
        last = log.strip().splitlines()[-1] if log.strip() else ""
        return dict(status=f"no summary.json (exit {p.returncode}): {last}",
                    failure="error"), "failed"
    with open(path) as f:
        return json.load(f), "ran"


def series_name(entry, summary, nbuilds, ndevices):
    name = entry["label"]
    if nbuilds > 1:
        name += f" ({summary.get('precision', '?')})"
    if ndevices > 1:
        name += f" [{summary.get('device', '?')}]"
    return name


def sweep(entries, study, opts):
    """Runs every point of every series of the study; yields (entry, point, summary, run_dir)."""
    builds = opts["builds"]
    devices = opts["devices"] or [None]
    for entry in entries:
        axes = entry["swept"]
        grid = [[]]
        for key, values in axes:
            grid = [g + [(key, v)] for g in grid for v in values]
        for b in builds:
            exe = os.path.join(b, "clsph")
            if not os.path.exists(exe) and not opts["collect"]:
                raise StudyError(f"{exe} does not exist: build clsph first (README)")
            tag = os.path.basename(os.path.normpath(b)) if len(builds) > 1 else ""
            for dev in devices:
                for point in grid:
                    sets = entry["fixed"] + point
                    name = run_name(entry, point, tag, dev if len(devices) > 1 else None)
                    out = os.path.join(opts["out"], "runs", name)
                    summary, how = run_one(exe, entry["case"], sets, out, dev, opts["timeout"],
                                           opts["rerun"], opts["collect"])
                    if summary is None:
                        print(f"  {name}: no run (--collect)")
                        continue
                    if how != "reused" or opts["verbose"]:
                        print(f"  {name}: {how}, {summary.get('status')}"
                              + (f", {summary['wall_seconds']:.1f} s" if "wall_seconds" in summary
                                 else ""), flush=True)
                    got = summary.get("scheme")
                    if got is not None and got != entry["scheme"]:
                        raise StudyError(f"{entry['where']}: the run {name} used scheme '{got}', "
                                         f"not '{entry['scheme']}': set the case's parameters "
                                         "that choose it")
                    yield entry, point, summary, out, series_name(entry, summary, len(builds),
                                                                  len(devices))


def gnuplot(script):
    if shutil.which("gnuplot") is None:
        raise StudyError("gnuplot is not installed (apt-get install gnuplot-nox)")
    subprocess.run(["gnuplot"], input=script, text=True, check=True)


def esc(text):
    return text.replace("\\", "\\\\").replace("'", "''")


def fit_order(points):
    """Least-squares slope p of log e = p log h + c over (h, e) with e > 0: None if < 2 points."""
    pts = [(math.log(h), math.log(e)) for h, e in points if e > 0 and h > 0]
    if len(pts) < 2:
        return None
    mx = sum(x for x, _ in pts) / len(pts)
    my = sum(y for _, y in pts) / len(pts)
    sxx = sum((x - mx) ** 2 for x, _ in pts)
    if sxx == 0:
        return None
    return sum((x - mx) * (y - my) for x, y in pts) / sxx


ACCURACY_COLUMNS = ["study", "series", "case", "scheme", "precision", "device", "resolution",
                    "value", "h", "particles", "fluid_particles", "steps", "sim_time",
                    "wall_seconds", "particle_steps_per_second", "solver_iterations_mean",
                    "status", "failure", "metric", "error", "run"]


def accuracy(study, entries, opts):
    rows = []
    for entry, point, s, out, series in sweep(entries, study, opts):
        key, value = point[0]
        v = float(value)
        h = v if key in ("dr", "h") else 1.0 / v
        err = s.get("metrics", {}).get(entry["metric"], "")
        rows.append(dict(study=study, series=series, case=entry["case"], scheme=entry["scheme"],
                         precision=s.get("precision", ""), device=s.get("device", ""),
                         resolution=key, value=number(value), h=f"{h:.9g}",
                         particles=fmt(s.get("particles", "")),
                         fluid_particles=fmt(s.get("fluid_particles", "")),
                         steps=fmt(s.get("steps", "")), sim_time=fmt(s.get("sim_time", "")),
                         wall_seconds=(f"{s['wall_seconds']:.4g}" if "wall_seconds" in s else ""),
                         particle_steps_per_second=(f"{s['particle_steps_per_second']:.4g}"
                                                    if "particle_steps_per_second" in s else ""),
                         solver_iterations_mean=(f"{s['solver']['iterations_mean']:.4g}"
                                                 if "solver" in s else ""),
                         status=s.get("status", ""), failure=s.get("failure", ""),
                         metric=entry["metric"], error=(f"{err:.6g}" if err != "" else ""),
                         run=os.path.relpath(out, opts["out"])))
    rows.sort(key=lambda r: (r["series"], float(r["h"]) * -1))
    os.makedirs(opts["results"], exist_ok=True)
    csv_path = os.path.join(opts["results"], f"{study}.csv")
    with open(csv_path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=ACCURACY_COLUMNS)
        w.writeheader()
        w.writerows(rows)
    draw_accuracy(study, csv_path, opts)


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def read_peers(study, metric, folder=os.path.join(ROOT, "tests", "data")):
    """Other codes' measured figures for a study (FOLDER/peers_STUDY.csv, '#' lines are its
    citation), the rows of the study's metric: drawn as points on the cost chart."""
    path = os.path.join(folder, f"peers_{study}.csv")
    if not os.path.exists(path):
        return None, []
    with open(path, newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    need = ("code", "version", "scheme", "threads", "resolution", "value", "wall_seconds",
            "metric", "error")
    for k, r in enumerate(rows, 2):
        missing = [c for c in need if not r.get(c)]
        if missing:
            raise StudyError(f"{path}: row {k} lacks {', '.join(missing)}")
        for c in ("wall_seconds", "error"):
            try:
                float(r[c])
            except ValueError:
                raise StudyError(f"{path}: row {k}: {c} '{r[c]}' is not a number")
    return path, [r for r in rows if r["metric"] == metric]


def draw_accuracy(study, csv_path, opts):
    """Both charts and the orders, from the CSV alone."""
    rows = read_csv(csv_path)
    ok = [r for r in rows if r["status"] == "ok" and r["error"] not in ("", "nan")]
    series = []
    for r in rows:
        if r["series"] not in series:
            series.append(r["series"])
    metric = rows[0]["metric"] if rows else "error"
    res_name = rows[0]["resolution"] if rows else "n"
    orders = []
    for name in series:
        pts = [(float(r["h"]), float(r["error"])) for r in ok if r["series"] == name]
        p = fit_order(pts)
        orders.append(dict(series=name, runs=len(pts), order=("" if p is None else f"{p:.3f}")))
    order_path = os.path.join(opts["results"], f"{study}_orders.csv")
    with open(order_path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=["series", "runs", "order"])
        w.writeheader()
        w.writerows(orders)
    case = rows[0]["case"] if rows else study
    base = os.path.join(opts["results"], study)
    cols = {c: i + 1 for i, c in enumerate(ACCURACY_COLUMNS)}
    ok_test = f"strcol({cols['status']}) eq 'ok'"

    def sel(name, col):
        return (f"((strcol({cols['series']}) eq '{esc(name)}' && {ok_test} && "
                f"strcol({cols['error']}) ne '') ? ${cols[col]} : 1/0)")

    common = f"""
set datafile separator ','
set terminal pngcairo noenhanced size 900,600 font 'DejaVu Sans,11'
set grid
set logscale xy
set key bottom left box opaque
set ylabel '{esc(metric)} (error against the reference)'
"""
    def style(k):
        """gnuplot's 8 line colours, then the same colours dashed with another point shape"""
        return f"lw 2 pt {(7, 5, 9, 13)[k // 8 % 4]} dt {k // 8 + 1} lc {k % 8 + 1}"

    def shown(name):
        """a series none of whose runs ended "ok" has no line: its title says so"""
        return name if any(r["series"] == name for r in ok) else f"{name} (no run ended ok)"

    plots = []
    for k, name in enumerate(series):
        plots.append(f"'{esc(csv_path)}' every ::1 using {sel(name, 'wall_seconds')}:"
                     f"{cols['error']} with linespoints {style(k)} title '{esc(shown(name))}'")
        plots.append(f"'{esc(csv_path)}' every ::1 using {sel(name, 'wall_seconds')}:"
                     f"{cols['error']}:('{esc(res_name)}='.strcol({cols['value']})) with labels "
                     f"offset 0.8,0.8 font ',9' tc lt {k % 8 + 1} notitle")
    peers_path, peers = read_peers(study, metric)
    groups = []
    for r in peers:
        title = f"{r['code']} {r['version']} {r['scheme']}, {r['threads']} threads (measured)"
        if title not in [g[0] for g in groups]:
            groups.append((title, []))
        next(g for g in groups if g[0] == title)[1].append(r)
    for k, (title, pts) in enumerate(groups):
        data = "\n".join(f"{r['wall_seconds']},{r['error']},{r['resolution']}={r['value']}"
                         for r in pts)
        block = f"$peer{k}"
        common += f"{block} << EOD\n{data}\nEOD\n"
        plots.append(f"{block} using 1:2 with points pt 5 ps 1.6 lc rgb 'black' "
                     f"title '{esc(title)}'")
        plots.append(f"{block} using 1:2:3 with labels offset 0.8,-0.8 font ',9' notitle")
    if peers:
        print(f"  peers: {len(peers)} measured figure(s) from {os.path.relpath(peers_path, ROOT)}")
    gnuplot(common + f"""
set output '{esc(base)}_cost.png'
{"set key top right box opaque" if peers else ""}
{"set offsets graph 0.02, graph 0.02, graph 0.06, graph 0.06" if peers else ""}
set title '{esc(case)}: error against cost ({esc(study)})'
set xlabel 'wall-clock seconds'
plot {', '.join(plots)}
""")
    plots = []
    for k, (name, o) in enumerate(zip(series, orders)):
        title = shown(name)
        if o["order"]:
            title += f", observed order {float(o['order']):.2f} in h"
        plots.append(f"'{esc(csv_path)}' every ::1 using {sel(name, 'fluid_particles')}:"
                     f"{cols['error']} with linespoints {style(k)} title '{esc(title)}'")
    gnuplot(common + f"""
set output '{esc(base)}_particles.png'
set title '{esc(case)}: error against resolution ({esc(study)})'
set xlabel 'fluid particles'
plot {', '.join(plots)}
""")
    for o in orders:
        print(f"  {o['series']}: observed order {o['order'] or '-'} over {o['runs']} runs")
    print(f"wrote {csv_path}, {order_path}, {base}_cost.png, {base}_particles.png")


STABILITY_COLUMNS = ["study", "series", "case", "scheme", "precision", "device", "x_name", "x",
                     "x_index", "y_name", "y", "y_index", "status", "failure", "steps",
                     "sim_time", "t_end", "wall_seconds", "wall_crossing_steps",
                     "wall_crossing_deepest_dr", "kinetic_energy_ratio_max",
                     "nearest_spacing_min_dr", "clustered_fraction_max", "run"]


def stability(study, entries, opts):
    rows = []
    for entry, point, s, out, series in sweep(entries, study, opts):
        (xk, xv), (yk, yv) = point
        xs, ys = entry["swept"][0][1], entry["swept"][1][1]
        wc, h = s.get("wall_crossings", {}), s.get("health", {})
        t_end = dict(entry["fixed"] + point).get("t_end", s.get("parameters", {}).get("t_end", ""))
        rows.append(dict(study=study, series=series, case=entry["case"], scheme=entry["scheme"],
                         precision=s.get("precision", ""), device=s.get("device", ""),
                         x_name=xk, x=number(xv), x_index=xs.index(xv), y_name=yk, y=number(yv),
                         y_index=ys.index(yv), status=s.get("status", ""),
                         failure=s.get("failure", "error"), steps=fmt(s.get("steps", "")),
                         sim_time=fmt(s.get("sim_time", "")), t_end=fmt(number(str(t_end)))
                         if t_end != "" else "",
                         wall_seconds=(f"{s['wall_seconds']:.4g}" if "wall_seconds" in s else ""),
                         wall_crossing_steps=fmt(wc.get("steps", "")),
                         wall_crossing_deepest_dr=fmt(wc.get("deepest_dr", "")),
                         kinetic_energy_ratio_max=fmt(h.get("kinetic_energy_ratio_max", "")),
                         nearest_spacing_min_dr=fmt(h.get("nearest_spacing_min_dr", "")),
                         clustered_fraction_max=fmt(h.get("clustered_fraction_max", "")),
                         run=os.path.relpath(out, opts["out"])))
    os.makedirs(opts["results"], exist_ok=True)
    csv_path = os.path.join(opts["results"], f"{study}.csv")
    with open(csv_path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=STABILITY_COLUMNS)
        w.writeheader()
        w.writerows(rows)
    draw_stability(study, csv_path, opts)


def draw_stability(study, csv_path, opts):
    """One map per series, from the CSV alone."""
    rows = read_csv(csv_path)
    cols = {c: i + 1 for i, c in enumerate(STABILITY_COLUMNS)}
    series = []
    for r in rows:
        if r["series"] not in series:
            series.append(r["series"])
    known = [f for f, _ in FAILURE_COLOURS]
    colour = " : ".join(f"s eq '{f}' ? {int(c[1:], 16)}" for f, c in FAILURE_COLOURS) + " : 0"
    for name in series:
        mine = [r for r in rows if r["series"] == name]
        xs = sorted({(int(r["x_index"]), r["x"]) for r in mine})
        ys = sorted({(int(r["y_index"]), r["y"]) for r in mine})
        xname, yname = mine[0]["x_name"], mine[0]["y_name"]
        present = [f for f in known if any(r["failure"] == f for r in mine)]
        present += sorted({r["failure"] for r in mine} - set(known))
        legend = ", ".join(
            f"NaN with boxes fs solid fc rgb '{dict(FAILURE_COLOURS).get(f, '#000000')}' "
            f"title '{'stable' if f == 'none' else esc(f)}'" for f in present)
        sel = (f"(strcol({cols['series']}) eq '{esc(name)}' ? ${cols['x_index']} : 1/0)")
        label = (f"(strcol({cols['failure']}) eq 'none' ? 'stable' : "
                 f"strcol({cols['failure']}).sprintf(\"\\nt = %.3g s\", column({cols['sim_time']})))")
        safe = "".join(c if c.isalnum() or c in "-_" else "_" for c in name)
        png = os.path.join(opts["results"], f"{study}_{safe}.png")
        gnuplot(f"""
set datafile separator ','
set terminal pngcairo noenhanced size 900,650 font 'DejaVu Sans,11'
set output '{esc(png)}'
set title '{esc(mine[0]['case'])}: {esc(name)}, what stops the run ({esc(study)}; t_end = {esc(mine[0]['t_end'])} s)'
set xlabel '{esc(xname)}'
set ylabel '{esc(yname)}'
set xrange [-0.5:{len(xs) - 0.5}]
set yrange [-0.5:{len(ys) - 0.5}]
set xtics ({', '.join(f"'{esc(v)}' {i}" for i, v in xs)})
set ytics ({', '.join(f"'{esc(v)}' {i}" for i, v in ys)})
set key outside right top box
set style fill solid 1.0 border rgb 'white'
colour(s) = {colour}
plot '{esc(csv_path)}' every ::1 using {sel}:{cols['y_index']}:(0.5):(0.5):(colour(strcol({cols['failure']}))) \\
       with boxxyerror fc rgb variable notitle, \\
     '' every ::1 using {sel}:{cols['y_index']}:{label} with labels font ',10' notitle, \\
     {legend}
""")
        counts = {}
        for r in mine:
            counts[r["failure"]] = counts.get(r["failure"], 0) + 1
        print(f"  {name}: " + ", ".join(f"{('stable' if k == 'none' else k)} {v}"
                                         for k, v in sorted(counts.items())))
        print(f"wrote {png}")
    print(f"wrote {csv_path}")


def main(argv):
    if len(argv) < 1 or argv[0] in ("-h", "--help"):
        print(__doc__)
        return 0 if argv else 2
    command, rest = argv[0], argv[1:]
    opts = dict(builds=[], devices=[], out=None, results=None, rerun=False, collect=False,
                timeout=3600.0, verbose=False, studies=os.path.join(HERE, "studies.txt"))
    study = None
    i = 0
    while i < len(rest):
        a = rest[i]
        if a in ("--build", "--device", "--out", "--results", "--studies", "--timeout"):
            if i + 1 >= len(rest):
                print(f"harness: {a} needs a value", file=sys.stderr)
                return 2
            v = rest[i + 1]
            if a == "--build":
                opts["builds"].append(v)
            elif a == "--device":
                opts["devices"].append(int(v))
            elif a == "--timeout":
                opts["timeout"] = float(v)
            else:
                opts[a[2:]] = v
            i += 2
            continue
        if a in ("--rerun", "--collect", "--verbose"):
            opts[a[2:]] = True
        elif a.startswith("-"):
            print(f"harness: unknown option {a} (--help)", file=sys.stderr)
            return 2
        elif study is None:
            study = a
        else:
            print(f"harness: one study at a time, not '{a}' too", file=sys.stderr)
            return 2
        i += 1
    try:
        entries = parse_studies(opts["studies"])
    except (StudyError, ValueError) as e:
        print(f"harness: {e}", file=sys.stderr)
        return 2
    if command == "list":
        for kind in ("accuracy", "stability"):
            names = []
            for e in entries:
                if e["kind"] == kind and e["study"] not in names:
                    names.append(e["study"])
            for n in names:
                ser = [e["label"] for e in entries if e["study"] == n]
                print(f"{kind:10s} {n:18s} {', '.join(ser)}")
        return 0
    if command not in ("accuracy", "stability"):
        print(f"harness: unknown command '{command}' (list, accuracy, stability)", file=sys.stderr)
        return 2
    mine = [e for e in entries if e["study"] == study and e["kind"] == command]
    if study is None or not mine:
        names = sorted({e["study"] for e in entries if e["kind"] == command})
        print(f"harness: no {command} study '{study}' in {opts['studies']}; "
              f"{command} studies: {', '.join(names)}", file=sys.stderr)
        return 2
    opts["builds"] = opts["builds"] or [os.path.join(ROOT, "build")]
    opts["out"] = opts["out"] or os.path.join(ROOT, "out", "harness", study)
    opts["results"] = opts["results"] or opts["out"]
    try:
        (accuracy if command == "accuracy" else stability)(study, mine, opts)
    except (StudyError, subprocess.CalledProcessError) as e:
        print(f"harness: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
