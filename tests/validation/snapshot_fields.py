"""The particle fields of a run's snapshots, read with h5dump (the charts' and results.py's helper).

    from snapshot_fields import last_snapshot_fields, snapshot_fields, snapshot_time
    kind, pos, vel = last_snapshot_fields(run_dir, "kind", "pos", "vel")
    kind, pos = snapshot_fields(path, "kind", "pos")   # one snapshot file
    t = snapshot_time(path)
each field a flat list of floats (a vector field's components one after the other, particle by
particle)."""
import os
import re
import subprocess


def snapshot_fields(path, *names):
    def get(name):
        out = subprocess.run(["h5dump", "-d", f"/particles/{name}", "-y", "-w", "0", path],
                             capture_output=True, text=True, check=True).stdout
        start = out.index("DATA {") + 6
        body = out[start:out.index("}", start)]
        return [float(v) for v in body.replace("\n", " ").replace(",", " ").split() if v]

    return [get(n) for n in names]


def snapshot_time(path):
    """The simulated time of one snapshot (its attribute /time)."""
    out = subprocess.run(["h5dump", "-a", "/time", "-w", "0", path], capture_output=True,
                         text=True, check=True).stdout
    return float(re.search(r"\(0\): ([-0-9.eE+]+)", out).group(1))


def last_snapshot_fields(run_dir, *names):
    snaps = sorted(p for p in os.listdir(run_dir) if p.startswith("snap_") and p.endswith(".h5"))
    return snapshot_fields(os.path.join(run_dir, snaps[-1]), *names)
