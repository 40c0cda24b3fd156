#!/usr/bin/env bash
# The ctest of tests/openfoam.cmake for the fish-pass reference: re-run run.sh (both meshes) into
# WORKDIR (its runs in WORKDIR/scratch, its CSVs in WORKDIR) and compare the fresh profiles with
# tests/data/openfoam_fish_pass.csv: the same rows, and U_x, U_y within 1e-2 of the stored
# profiles' largest |U| (a transient from rest to 20 s, not a converged steady state: another
# machine's summation order moves it more than a converged run's 1e-6, a change to the set-up,
# mesh, schemes, wall functions or the drive, far more). Exit 77 (skip) without OpenFOAM.
#   tests/validation/openfoam/fish_pass/check.sh WORKDIR
set -eo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../../.." && pwd)
[ $# -eq 1 ] || { sed -n '2,8p' "$0"; exit 2; }
work=$1
if [ ! -f /usr/share/openfoam/etc/bashrc ] && ! command -v pimpleFoam > /dev/null; then
  echo "OpenFOAM is not installed (apt-get install openfoam): skipped"
  exit 77
fi
rm -rf "$work"
mkdir -p "$work"
OF_SCRATCH="$work/scratch" OF_OUT="$work" "$here/run.sh"
python3 - "$work/openfoam_fish_pass.csv" "$root/tests/data/openfoam_fish_pass.csv" <<'PY'
import csv, sys
def read(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))
fresh, stored = read(sys.argv[1]), read(sys.argv[2])
if len(fresh) != len(stored):
    sys.exit(f"{len(fresh)} rows against the stored {len(stored)}")
peak = max((float(r["U_x"]) ** 2 + float(r["U_y"]) ** 2) ** 0.5 for r in stored)
worst = 0.0
for a, b in zip(fresh, stored):
    if a["line"] != b["line"] or abs(float(a["x"]) - float(b["x"])) > 1e-6 \
            or abs(float(a["y"]) - float(b["y"])) > 1e-6:
        sys.exit(f"row {a['line']} ({a['x']}, {a['y']}) against the stored {b['line']} ({b['x']}, {b['y']})")
    for c in ("U_x", "U_y"):
        worst = max(worst, abs(float(a[c]) - float(b[c])) / peak)
print(f"largest difference in U over the stored peak |U| {peak:.4f}: {worst:.2e}")
sys.exit(0 if worst <= 1e-2 else 1)
PY
