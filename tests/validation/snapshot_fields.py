"""The particle fields of a run's last snapshot, read with h5dump (the charts' helper).

    from snapshot_fields import last_snapshot_fields
    kind, pos, vel = last_snapshot_fields(run_dir, "kind", "pos", "vel")
each a flat list of floats (a vector field's components one after the other, particle by
particle)."""
import os
import subprocess


def last_snapshot_fields(run_dir, *names):
    snaps = sorted(p for p in os.listdir(run_dir) if p.startswith("snap_") and p.endswith(".h5"))
    path = os.path.join(run_dir, snaps[-1])

    def get(name):
        out = subprocess.run(["h5dump", "-d", f"/particles/{name}", "-y", "-w", "0", path],
                             capture_output=True, text=True, check=True).stdout
        start = out.index("DATA {") + 6
        body = out[start:out.index("}", start)]
        return [float(v) for v in body.replace("\n", " ").replace(",", " ").split() if v]

    return [get(n) for n in names]
