#!/usr/bin/env bash
# OpenFOAM v1912 reference for the periodic pool of a vertical-slot fish pass (Leroy et al. 2014
# sec 5.2), 2-D seen from above, no gravity, no free surface: b = 0.3 m slot, period 10 b along x
# (cyclic), width 8 b, two baffles (setup.py); nu = 1e-6, driven by a uniform body force of
# 1.885 m/s^2 along +x (constant/fvOptions); pimpleFoam from rest to t = 20 s, standard k-epsilon
# with wall functions (case/: 0, constant, system). Each cell size H (m) is a run in
# $OF_SCRATCH/h<H> (default ${TMPDIR:-/tmp}/of_fish_pass): blockMesh (setup.py), pimpleFoam,
# serial under nice. post.py then samples the first (main) mesh at t = 20 s into
# $OF_OUT/openfoam_fish_pass.csv (default tests/data) and compares the others with it.
# On one core (CPU time): h = 0.025 2.5 minutes, h = 0.0125 (the main mesh) 21 minutes;
# h = 0.00625 would take about 3 hours (not run). Scratch: 410 MB for h = 0.0125.
#   tests/validation/openfoam/fish_pass/run.sh [H_MAIN H_OTHER...]   default: 0.0125 0.025
#   tests/validation/openfoam/fish_pass/run.sh post [H_MAIN H_OTHER...]   the CSV from scratch
set -eo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../../.." && pwd)
scratch=${OF_SCRATCH:-${TMPDIR:-/tmp}/of_fish_pass}
out=${OF_OUT:-$root/tests/data}
export PYTHONDONTWRITEBYTECODE=1 # no __pycache__ in the source tree
made="tests/validation/openfoam/fish_pass/run.sh${*:+ $*}"

source "$here/../env.sh" # OpenFOAM v1912 and its environment
set -u

run() { # one cell size: copy the template, mesh it, solve
  local h=$1 dir=$scratch/h$1
  rm -rf "$dir"
  mkdir -p "$scratch"
  cp -r "$here/case" "$dir"
  python3 "$here/setup.py" mesh "$h" "$dir"
  cd "$dir"
  blockMesh > log.blockMesh 2>&1
  if ! checkMesh > log.checkMesh 2>&1; then
    echo "h$h: checkMesh failed (see $dir/log.checkMesh)"
    exit 1
  fi
  postProcess -func writeCellCentres -time 0 > log.writeCellCentres 2>&1
  nice -n 10 pimpleFoam > log.pimpleFoam 2>&1
  echo "h$h: $(grep -c '^Time = ' log.pimpleFoam) time steps," \
    "$(grep -h 'ClockTime' log.pimpleFoam | tail -n 1)"
  cd "$root"
}

post=no
if [ "${1:-}" = post ]; then post=yes; shift; fi
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(0.0125 0.025)
if [ $post = yes ]; then # name the runs' command too
  made+=" (the CSV from the runs of tests/validation/openfoam/fish_pass/run.sh ${sizes[*]})"
fi
if [ $post = no ]; then
  for h in "${sizes[@]}"; do run "$h"; done
fi
mkdir -p "$out"
python3 "$here/post.py" "$scratch" "$out/openfoam_fish_pass.csv" "$made" "${sizes[@]}"
# (post.py also writes $out/openfoam_fish_pass_flow.csv, the flow rate over time)
