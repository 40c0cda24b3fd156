#!/usr/bin/env python3
"""Checks results.py's reading of the HCD channel's floor (hcd_floor_foot, hcd_floor_fv,
crossings) on OpenFOAM's stored wall cells (tests/data/openfoam_channel_hcd.csv, line "floor"):
the foot and tangent of points over each piece of the floor, and the separation and reattachment
that the binned wall cells cross zero at, against the cells' own backflow range that post.py
wrote into the file's header for the uniform entry (one bin apart at most: the bins' centres
interpolate the crossings). Prints both; exit 1 where one disagrees.
    hcd_floor_check.py [CSV]"""
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import results  # noqa: E402


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "data", "openfoam_channel_hcd.csv")
    bad = []
    s30, c30 = math.sin(math.radians(30.0)), math.cos(math.radians(30.0))
    top = 1.5 * math.tan(math.radians(30.0))
    # (point, foot's x, tangent): the flat floor, both ramps 0.1 off them, the platform's top
    for (x, y), fx, t in (((1.0, 0.025), 1.0, (1.0, 0.0)),
                          ((3.75 - 0.1 * s30, top / 2 + 0.1 * c30), 3.75, (c30, s30)),
                          ((5.0, top + 0.025), 5.0, (1.0, 0.0)),
                          ((6.25 + 0.1 * s30, top / 2 + 0.1 * c30), 6.25, (c30, -s30)),
                          ((9.5, 0.025), 9.5, (1.0, 0.0))):
        gx, gt = results.hcd_floor_foot(x, y)
        if abs(gx - fx) > 1e-9 or math.dist(gt, t) > 1e-9:
            bad.append(f"the foot of ({x:g}, {y:g}) is at x = {gx:g} along {gt}, not {fx:g} along {t}")
    try:
        fv = results.hcd_floor_fv(path)
    except (OSError, ValueError) as e:
        sys.exit(f"hcd_floor_check.py: {e}")
    sep, att = results.crossings(fv, 5.0)
    with open(path) as f:
        head = f.read()
    m = re.search(r"# hcd(?:_fine)?_uniform:.*?backflow \(U_x < 0\) in the wall cells at x = ([^(]*)\(lower", head)
    if m is None:
        sys.exit(f"{path}: no backflow range of hcd_uniform's lower wall in the header")
    ranges = [tuple(float(v) for v in r.split(" to ")) for r in m.group(1).strip(" ,").split(", ")]
    a, b = max(ranges, key=lambda r: r[1] - r[0])  # the bubble behind the platform
    print(f"OpenFOAM's floor: {len(fv)} bins; binned crossings: separation {sep:.2f}, "
          f"reattachment {att:.2f}; the cells' backflow {a:.2f} to {b:.2f}")
    for what, got, want in (("separation", sep, a), ("reattachment", att, b)):
        if got is None or abs(got - want) > results.HCD_FLOOR_BIN:
            bad.append(f"the {what} at {got} is more than a bin from the cells' {want:g}")
    for line in bad:
        print("FAIL:", line)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
