#!/usr/bin/env python3
"""The walls a run's snapshots record where they stand (tests/render.cmake, render_walls_moved):
the dam break's gate (cases/dam_break.lua gate = 1, lifted H + 0.1 = 0.4 m at 4.53 m/s from t = 0)
in its first and last snapshots, after the lift (t >= 0.0883 s).
  walls_moved.py 3 RUN_DIR   a 3-D run: /walls3 holds the tank's 12 faces and the gate's 12, the
                             tank's the same in both, the gate's moved by exactly (0, 0, 0.4) m;
                             every face is counter-clockwise seen from the fluid (the tank's
                             normals point into the tank, the gate's out of the plate)
  walls_moved.py 2 RUN_DIR   a 2-D run: the gate's polyline (/walls/wall_001) moved by (0, 0.4)
The snapshots are read with h5dump (hdf5-tools)."""
import glob
import re
import subprocess
import sys

LIFT = 0.4


def dataset(path, name):
    out = subprocess.run(["h5dump", "-d", name, "-y", "-w", "0", path], check=True,
                         capture_output=True, text=True).stdout
    body = out[out.index("DATA {") + 6:]
    body = body[:body.index("}")]
    return [float(v) for v in re.findall(r"[-+0-9.eE]+", body)]


def main():
    dim, run = sys.argv[1], sys.argv[2]
    snaps = sorted(glob.glob(run + "/snap_*.h5"))
    if len(snaps) < 2:
        sys.exit("need two snapshots in %s" % run)
    first, last = snaps[0], snaps[-1]
    bad = []
    if dim == "2":
        a, b = dataset(first, "/walls/wall_001"), dataset(last, "/walls/wall_001")
        for k in range(0, len(a), 2):
            if abs(b[k] - a[k]) > 1e-12 or abs(b[k + 1] - a[k + 1] - LIFT) > 1e-12:
                bad.append("gate point %d: (%g, %g) -> (%g, %g)" % (k // 2, a[k], a[k + 1], b[k],
                                                                    b[k + 1]))
    else:
        a, b = dataset(first, "/walls3"), dataset(last, "/walls3")
        if len(a) != 24 * 9 or len(b) != 24 * 9:
            sys.exit("walls3 holds %d and %d numbers, not 24 triangles" % (len(a), len(b)))
        for t in range(24):
            shift = (0.0, 0.0, LIFT if t >= 12 else 0.0)
            for k in range(9):
                if abs(b[9 * t + k] - a[9 * t + k] - shift[k % 3]) > 1e-12:
                    bad.append("triangle %d, coordinate %d: %g -> %g" % (t, k, a[9 * t + k],
                                                                        b[9 * t + k]))
            # the normal (v1 - v0) x (v2 - v0) against the direction into the fluid: into the
            # tank from its faces (towards the tank's centre), out of the gate's plate
            v = [a[9 * t + 3 * j:9 * t + 3 * j + 3] for j in range(3)]
            e1 = [v[1][i] - v[0][i] for i in range(3)]
            e2 = [v[2][i] - v[0][i] for i in range(3)]
            n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                 e1[0] * e2[1] - e1[1] * e2[0]]
            lo = [min(a[9 * s + i] for s in range(t // 12 * 12, t // 12 * 12 + 12) for i in
                      range(j, 9, 3)) for j in range(3)]
            hi = [max(a[9 * s + i] for s in range(t // 12 * 12, t // 12 * 12 + 12) for i in
                      range(j, 9, 3)) for j in range(3)]
            centre = [(lo[i] + hi[i]) / 2 for i in range(3)]
            mid = [(v[0][i] + v[1][i] + v[2][i]) / 3 for i in range(3)]
            inward = sum(n[i] * (centre[i] - mid[i]) for i in range(3))
            if (inward > 0) != (t < 12):
                bad.append("triangle %d faces away from the fluid" % t)
    if bad:
        sys.exit("%s and %s:\n  " % (first, last) + "\n  ".join(bad[:10]))
    print("%s -> %s: the gate lifted by %g m, the rest in place%s"
          % (first, last, LIFT, ", the faces towards the fluid" if dim == "3" else ""))


main()
