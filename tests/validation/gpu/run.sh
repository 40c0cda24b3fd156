#!/bin/sh
# run.sh: the GPU checks of issues 22 and 23 on a lent machine (the device tool: carry .gpu,
# made by pack.sh here), each run under its own time limit, the figures into $OUT:
#   devices.txt   what OpenCL sees
#   figures.txt   per run: particles, steps, wall s, particle-steps/s, kernel launches and
#                 blocking reads a step, device and host-and-waiting shares, solver iterations
#   runs.tar.xz   each run's summary.json and log (not its snapshots)
# Usage (the device tool's command): sh tests/validation/gpu/run.sh [SECONDS]
# SECONDS (default 420) bounds the whole; runs that would start past it are skipped.
set -u
OUT=${OUT:-/tmp/clsph_gpu_out}
LIMIT=${1:-420}
START=$(date +%s)
D=/tmp/clsph_gpu
mkdir -p "$OUT" "$D/runs"
tar -C "$D" -xJf .gpu/deps.tar.xz || { echo "run.sh: no .gpu/deps.tar.xz (pack.sh, carry .gpu)"; exit 2; }
export LD_LIBRARY_PATH="$D/lib"
# the OpenCL loader (ocl-icd, carried) reads its vendors from OCL_ICD_VENDORS: NVIDIA's library
# from the driver's folder or the system's
mkdir -p "$D/vendors"
nv=""
for f in /usr/local/nvidia/lib64/libnvidia-opencl.so.1 /usr/local/nvidia/lib/libnvidia-opencl.so.1 \
  /usr/lib/x86_64-linux-gnu/libnvidia-opencl.so.1 /usr/lib64/libnvidia-opencl.so.1; do
  [ -e "$f" ] && { nv=$f; break; }
done
[ -z "$nv" ] && nv=$(find / -name 'libnvidia-opencl.so*' 2>/dev/null | head -1)
echo "NVIDIA OpenCL library: ${nv:-none found (the system's OpenCL vendors)}" | tee "$OUT/devices.txt"
if [ -n "$nv" ]; then
  echo "$nv" >"$D/vendors/nvidia.icd"
  export OCL_ICD_VENDORS="$D/vendors"
fi
"$D/clsph" devices 2>&1 | tee -a "$OUT/devices.txt"
export CLSPH_DEVICE=${CLSPH_DEVICE:-0}

# one run: NAME BINARY SECONDS CASE SETS...; its figures appended to figures.txt
one() {
  name=$1 bin=$2 secs=$3 case=$4
  shift 4
  now=$(date +%s)
  if [ $((now - START + secs)) -gt "$LIMIT" ]; then
    echo "$name: skipped (time)" >>"$OUT/figures.txt"
    return
  fi
  sets=""
  for s in "$@"; do sets="$sets --set $s"; done
  # shellcheck disable=SC2086
  timeout "$secs" "$D/$bin" run "$case" $sets --profile --out "$D/runs/$name" --overwrite \
    >"$D/runs/$name.log" 2>&1
  echo "$name: rc $?" >>"$D/runs/$name.log"
  python3 - "$name" "$D/runs/$name/summary.json" >>"$OUT/figures.txt" <<'PY'
import json, sys
name, path = sys.argv[1], sys.argv[2]
try:
    d = json.load(open(path))
except Exception as e:
    print(f"{name}: no summary ({e})")
    sys.exit(0)
p = d.get("profile", {})
k = {x["name"]: x["launches"] for x in p.get("kernels", [])}
st = max(d.get("steps", 0), 1)
kern = sum(v for n, v in k.items() if not n.startswith("("))
w, dev = p.get("wall_seconds", 0.0), p.get("device_seconds", 0.0)
its = d.get("solver", {}).get("iterations_mean")
print(f"{name}: {d.get('device')}, {d.get('precision')}, status {d.get('status')}, "
      f"particles {d.get('particles')}, steps {st}, wall {w:.2f} s, "
      f"{d.get('particle_steps_per_second', 0):.3g} particle-steps/s, "
      f"{kern / st:.1f} kernel launches and {k.get('(read)', 0) / st:.2f} blocking reads a step, "
      f"device {dev / w if w else 0:.2f} of the wall, solver its {its}")
PY
}

one cavity40_separate clsph 60 cases/cavity.lua n=40 t_end=0.5 fuse=2
one cavity40_fused clsph 60 cases/cavity.lua n=40 t_end=0.5 fuse=1
one cavity240_re1000 clsph 120 cases/cavity.lua n=240 re=1000 t_end=0.5
one cavity240_re1000_float clsph-float 120 cases/cavity.lua n=240 re=1000 t_end=0.5
one cavity480_re1000 clsph 150 cases/cavity.lua n=480 re=1000 t_end=0.1
one wedge_isph clsph 120 cases/dam_break_wedge.lua
one wedge_wcsph clsph 120 cases/dam_break_wedge.lua wcsph=1
(cd "$D/runs" && tar -cJf "$OUT/runs.tar.xz" ./*.log ./*/summary.json 2>/dev/null)
cat "$OUT/figures.txt"
