#!/usr/bin/env python3
"""Compare a fresh OpenFOAM channel CSV (run.sh) with the stored one (standard library only).

The rows must match one for one: the same key columns (every column before the sampled
quantities: setting, y_p, mesh, section, line, ...) and the same positions to 1e-6. U must agree
to RTOL = 1e-3 of |U|, or of FLOOR = 0.1 of the run's peak |U| where |U| is smaller (in a
recirculation, where U crosses zero: there to 1e-4 of the peak). Why 1e-3: the runs are
deterministic and stop at initial residuals of 1e-8, 1e-6 of U away from their converged state
(the CSV headers); another machine or OpenFOAM build changes the summation order and so U by far
less than 1e-3, while a change to the set-up (mesh, wall-function constants, schemes, entry
profile) moves U by more (E = 9.0 instead of 9.8 moves the straight channel's U by 4e-3).
k is reported, not checked.
    compare.py FRESH STORED      exit 0 (same), 1 (different), 2 (unreadable)
"""
import csv
import sys

RTOL = 1e-3
FLOOR = 0.1
QUANTITIES = ("U", "U_r", "V", "k", "epsilon", "nut", "u_tau")
POSITIONS = ("y", "s", "s_over_H", "x", "y_wall")


def read(path):
    with open(path) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    if not rows or "U" not in rows[0]:
        raise ValueError(f"{path}: no rows with a U column")
    return rows


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    try:
        fresh, stored = read(sys.argv[1]), read(sys.argv[2])
    except (OSError, ValueError) as e:
        print(f"compare.py: {e}")
        return 2
    cols = list(stored[0].keys())
    keys = [c for c in cols if c not in QUANTITIES and c not in POSITIONS]
    if len(fresh) != len(stored) or list(fresh[0].keys()) != cols:
        print(f"FAIL: {len(fresh)} rows x {list(fresh[0].keys())} against {len(stored)} x {cols}")
        return 1
    peak = {}
    for r in stored:
        g = tuple(r[c] for c in keys)
        peak[g] = max(peak.get(g, 0.0), abs(float(r["U"])))
    worst_u, worst_k, bad = 0.0, 0.0, 0
    for n, (a, b) in enumerate(zip(fresh, stored)):
        g = tuple(b[c] for c in keys)
        if tuple(a[c] for c in keys) != g or any(
                abs(float(a[c]) - float(b[c])) > 1e-6 for c in POSITIONS if c in b):
            print(f"FAIL: row {n + 1} is {a}, the stored one {b}")
            return 1
        du = abs(float(a["U"]) - float(b["U"])) / max(abs(float(b["U"])), FLOOR * peak[g])
        dk = abs(float(a["k"]) - float(b["k"])) / max(abs(float(b["k"])), 1e-300)
        worst_u, worst_k = max(worst_u, du), max(worst_k, dk)
        if du > RTOL:
            bad += 1
            if bad <= 5:
                print(f"U differs at row {n + 1} ({', '.join(f'{c}={b[c]}' for c in keys)}, "
                      f"position {[b[c] for c in POSITIONS if c in b]}): {a['U']} against "
                      f"{b['U']}")
    print(f"{len(stored)} rows: largest relative difference U {worst_u:.1e} (tolerance {RTOL:g}), "
          f"k {worst_k:.1e} (not checked)")
    if bad:
        print(f"FAIL: {bad} rows differ in U by more than {RTOL:g}")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
