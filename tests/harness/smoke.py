#!/usr/bin/env python3
"""Smoke test of the harness (ctest label harness): the study `smoke` of studies.txt (two tiny
cavity runs), then its CSV and charts: one row per run with status ok, a positive finite error,
the particle count and the wall time; the observed order; each chart a PNG of 900 x 600 pixels
(the PNG signature and the IHDR chunk read from the file).

    python3 tests/harness/smoke.py BUILD_DIR OUT_DIR
exits 0 (pass) or 1 (fail), printing what it compared."""
import csv
import math
import os
import struct
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    if len(head) < 24 or head[:8] != b"\x89PNG\r\n\x1a\n" or head[12:16] != b"IHDR":
        raise ValueError(f"{path} is not a PNG (no signature and IHDR chunk)")
    return struct.unpack(">II", head[16:24])


def peers(out):
    """The peer figures: the cavity's file parses (2 rows of u, 1 of v), a row without its error
    is refused with the file and row named."""
    sys.path.insert(0, HERE)
    import harness
    failures = []
    _, u = harness.read_peers("cavity_re100", "u_rms_vs_ghia")
    _, v = harness.read_peers("cavity_re100", "v_rms_vs_ghia")
    print(f"peers of cavity_re100: {len(u)} u rows, {len(v)} v rows")
    if len(u) != 2 or len(v) != 1 or any(float(r["error"]) <= 0 for r in u + v):
        failures.append("tests/data/peers_cavity_re100.csv: not 2 u rows and 1 v row with errors")
    bad = os.path.join(out, "peers_bad.csv")
    with open(bad, "w") as f:
        f.write("# a row without its error\n"
                "code,version,scheme,threads,resolution,value,wall_seconds,metric,error\n"
                "X,1,Y,2,n,30,10,u_rms_vs_ghia,\n")
    try:
        harness.read_peers("bad", "u_rms_vs_ghia", out)
        failures.append("a peer row without its error was accepted")
    except harness.StudyError as e:
        print(f"refused as expected: {e}")
        if "row 2 lacks error" not in str(e):
            failures.append(f"the refusal does not name the row and column: {e}")
    return failures


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    build, out = sys.argv[1], sys.argv[2]
    cmd = [sys.executable, os.path.join(HERE, "harness.py"), "accuracy", "smoke", "--build",
           build, "--out", out, "--rerun"]
    print("running:", " ".join(cmd), flush=True)
    p = subprocess.run(cmd)
    failures = []
    if p.returncode != 0:
        print(f"FAIL: the harness exited with {p.returncode}")
        return 1
    with open(os.path.join(out, "smoke.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    if len(rows) != 2:
        failures.append(f"smoke.csv has {len(rows)} rows, not 2")
    for r in rows:
        err = float(r["error"]) if r["error"] else math.nan
        print(f"row: series {r['series']}, n = {r['value']}, {r['particles']} particles, "
              f"{r['wall_seconds']} s, status {r['status']}, failure {r['failure']}, "
              f"{r['metric']} = {r['error']}")
        if r["status"] != "ok" or r["failure"] != "none":
            failures.append(f"run {r['run']}: status '{r['status']}', failure '{r['failure']}'")
        if not (math.isfinite(err) and err > 0):
            failures.append(f"run {r['run']}: error '{r['error']}' is not a positive number")
        if not int(r["particles"]) > 0 or not float(r["wall_seconds"]) > 0:
            failures.append(f"run {r['run']}: no particles or no wall time")
    if sorted(int(r["value"]) for r in rows) != [8, 10]:
        failures.append("the runs are not n = 8 and n = 10")
    with open(os.path.join(out, "smoke_orders.csv"), newline="") as f:
        orders = list(csv.DictReader(f))
    print(f"orders: {orders}")
    if len(orders) != 1 or orders[0]["order"] == "":
        failures.append("smoke_orders.csv has no observed order")
    for chart in ("smoke_cost.png", "smoke_particles.png"):
        path = os.path.join(out, chart)
        try:
            w, h = png_size(path)
            print(f"{chart}: PNG {w} x {h}, {os.path.getsize(path)} bytes")
            if (w, h) != (900, 600):
                failures.append(f"{chart} is {w} x {h}, not 900 x 600")
            if os.path.getsize(path) < 5000:
                failures.append(f"{chart} is too small to hold a chart")
        except (OSError, ValueError) as e:
            failures.append(str(e))
    failures += peers(out)
    for f in failures:
        print("FAIL:", f)
    if not failures:
        print("harness smoke test: 2 runs, CSV rows, orders and 2 charts as expected")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
