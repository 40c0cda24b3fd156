#!/usr/bin/env bash
# One ctest of tests/openfoam.cmake: re-run a case of run.sh into WORKDIR (its runs in
# WORKDIR/scratch, its CSV in WORKDIR) and compare the fresh CSV with tests/data's (compare.py:
# U to 1e-3). Exit 77 (skip) where OpenFOAM is not installed.
#   tests/validation/openfoam/channel_ke/check.sh CASE WORKDIR
set -eo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../../.." && pwd)
[ $# -eq 2 ] || { sed -n '2,5p' "$0"; exit 2; }
case=$1
work=$2
if [ ! -f /usr/share/openfoam/etc/bashrc ] && ! command -v simpleFoam > /dev/null; then
  echo "OpenFOAM is not installed (apt-get install openfoam): skipped"
  exit 77
fi
rm -rf "$work"
mkdir -p "$work"
OF_SCRATCH="$work/scratch" OF_OUT="$work" "$here/run.sh" "$case"
python3 "$here/compare.py" "$work/openfoam_channel_$case.csv" \
  "$root/tests/data/openfoam_channel_$case.csv"
