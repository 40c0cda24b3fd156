#!/usr/bin/env bash
# OpenFOAM v1912 reference for cases/square_cylinder.lua with length=32 xc=8: laminar channel
# flow past a square cylinder (H = 8 D, centre (8, 4), parabolic entry of peak U0 = 1 at x = 0,
# no-slip walls, zero-gradient exit with p = 0 at x = 32; D = U0 = rho = 1, nu = 1/Re).
# Re = 20: steady, simpleFoam; Re = 100: vortex shedding, pimpleFoam from rest to t = 150 D/U0
# at Co <= 0.5. Case files: re20/ and re100/ (0, constant, system), mesh/ (blockMeshDict and
# the mesh sizes d40, d50, d60: D/40, D/50, D/60 at the cylinder). Each run is made in
# $OF_SCRATCH/<run> (default /tmp/of_sc), then forces.py writes
# tests/data/openfoam_square_cylinder.csv. Not part of the test suite: on one core (CPU time)
# 6 minutes for the three Re = 20 runs, 21 and 26 minutes for re100_d40 and re100_d50.
#   tests/validation/openfoam/square_cylinder/run.sh            all runs, then the CSV
#   tests/validation/openfoam/square_cylinder/run.sh RUN...     only these (re20_d40, re100_d50, ...)
#   tests/validation/openfoam/square_cylinder/run.sh post       the CSV from the runs in scratch
# re100_d50 starts from re100_d40's fields at t = 100 (mapFields; its shedding is developed by
# then) and runs to t = 190.
set -eo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../../.." && pwd)
scratch=${OF_SCRATCH:-/tmp/of_sc}
all=(re20_d40 re20_d50 re20_d60 re100_d40 re100_d50)

source "$here/../env.sh" # OpenFOAM v1912 and its environment
set -u

run() { # re<Re>_d<n>: copy the case, mesh it, solve
  local name=$1 re=${1%_*} mesh=${1#*_} dir=$scratch/$1
  rm -rf "$dir"
  mkdir -p "$scratch"
  cp -r "$here/$re" "$dir"
  cp "$here/mesh/blockMeshDict" "$dir/system/blockMeshDict"
  cp "$here/mesh/$mesh" "$dir/system/meshParams"
  cd "$dir"
  blockMesh > log.blockMesh 2>&1
  checkMesh > log.checkMesh 2>&1
  if [ "$re" = re100 ]; then
    if [ "$mesh" = d50 ]; then # from the developed shedding of D/40, 90 D/U0 on
      sed -i 's/^startTime 0;/startTime 100;/; s/^endTime 150;/endTime 190;/' system/controlDict
      mapFields "$scratch/re100_d40" -consistent -sourceTime 100 > log.mapFields 2>&1
      rm -rf 0
    else
      setFields > log.setFields 2>&1
    fi
    pimpleFoam > log.pimpleFoam 2>&1
  else
    simpleFoam > log.simpleFoam 2>&1
  fi
  echo "$name: $(grep -h 'ClockTime' log.*Foam | tail -n 1)"
  cd "$root"
}

case "${1:-}" in
  post) ;;
  "") for r in "${all[@]}"; do run "$r"; done ;;
  *) for r in "$@"; do run "$r"; done ;;
esac
python3 "$here/forces.py" "$scratch" "$root/tests/data/openfoam_square_cylinder.csv"
