#!/usr/bin/env bash
# OpenFOAM v1912 references for the k-epsilon RANS channels of Wang, Sun & Hu (sec 5.1-5.3):
# simpleFoam, standard k-epsilon, wall functions nutkWallFunction / kqRWallFunction /
# epsilonWallFunction (kappa 0.41, E 9.8), 2-D meshes whose wall cells are 2 y_p high (first cell
# centre at y_p). Cases (setup.py lists their runs and builds their meshes):
#   straight  the periodic fully developed channel, delta = 1, U_b = 1 (meanVelocityForce):
#             (a) nu = 1e-4 (Lee & Moser's Re_tau = 543.5) with y_p = 0.05, 0.025 and 0.05 with a
#             5x finer core; (b) nu = 5e-5 (Re = 40000) with y_p = 0.025 and 0.05; and (a) at
#             y_p = 0.05 with E = 9.0 (a reading of the paper's "E = 0.9"; in the header only)
#   mild      curved channel of Table 1, Re = 60000, y_p = 1.59e-3 and 7e-4
#   strong    curved channel of Table 1, Re = 148400, y_p = H/40 and H/80
#   hcd       the half converging-diverging channel of SPHinXsys, Re = 40000, y_p = 0.025
#   hcd_fine  hcd's uniform entry on a mesh with the same wall cells and a core and streamwise
#             cells twice as fine: how far the reference is from its mesh limit
# The curved and HCD entries take the fully developed profile (U, k, epsilon) of a periodic run at
# the same Re and y_p (run first: mild_periodic_*, strong_periodic_*, straight_b_yp0.025); hcd
# also runs SPHinXsys's uniform entry. Each run is made in $OF_SCRATCH/<run> (default
# /tmp/of_channel_ke), run serial under nice, then post.py writes
# $OF_OUT/openfoam_channel_<case>.csv (default tests/data). On one core, all the runs of a case:
# straight 15 s, mild 1 minute, strong 20 s, hcd 25 s, hcd_fine 4 minutes.
#   tests/validation/openfoam/channel_ke/run.sh CASE...   run these cases, then their CSVs
#   tests/validation/openfoam/channel_ke/run.sh post      the CSVs of every case found in scratch
set -eo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../../.." && pwd)
scratch=${OF_SCRATCH:-/tmp/of_channel_ke}
out=${OF_OUT:-$root/tests/data}
export PYTHONDONTWRITEBYTECODE=1 # post.py imports setup.py: no __pycache__ in the source tree

source "$here/../env.sh" # OpenFOAM v1912 and its environment
set -u

run() { # one run: copy the template, mesh it, write its entry profile, solve
  local name=$1 dir=$scratch/$1
  rm -rf "$dir"
  mkdir -p "$scratch"
  cp -r "$here/case" "$dir"
  python3 "$here/setup.py" case "$name" "$dir"
  cd "$dir"
  blockMesh > log.blockMesh 2>&1
  if ! checkMesh > log.checkMesh 2>&1; then
    echo "$name: checkMesh failed (see $dir/log.checkMesh)"
    exit 1
  fi
  postProcess -func writeCellCentres -time 0 > log.writeCellCentres 2>&1
  if grep -qw inlet constant/polyMesh/boundary; then
    python3 "$here/setup.py" inlet "$name" "$dir"
  fi
  nice -n 10 simpleFoam > log.simpleFoam 2>&1
  local its conv clock
  its=$(grep -c '^Time = ' log.simpleFoam)
  conv=$(grep -h 'SIMPLE solution converged' log.simpleFoam || echo 'stopped at endTime')
  clock=$(grep -h 'ClockTime' log.simpleFoam | tail -n 1)
  echo "$name: $its iterations ($conv), $clock"
  cd "$root"
}

[ $# -gt 0 ] || { sed -n '2,/^set -eo/p' "$0" | sed '$d'; exit 2; }
cases=()
done_runs=" "
for c in "$@"; do
  [ "$c" = post ] && continue
  cases+=("$c")
  runs=$(python3 "$here/setup.py" list "$c")
  for r in $runs; do
    case "$done_runs" in *" $r "*) continue ;; esac
    run "$r"
    done_runs+="$r "
  done
done
mkdir -p "$out"
python3 "$here/post.py" "$scratch" "$out" ${cases[@]+"${cases[@]}"}
