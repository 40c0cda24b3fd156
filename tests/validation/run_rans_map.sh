#!/usr/bin/env bash
# The HCD channel's stability map (Wang, Sun & Hu sec 5.3, figs 24-27) at N_f = 40, 60 and 80,
# the walls' pressure the gradient: ARD on (its indicator averaged over the last `avg` s), ARD off
# with the model's default momentum dissipation ("reconstructed", md = -1), and ARD off without
# the Riemann dissipation in the momentum equation (md = 0: the eddy viscosity alone, the scheme
# the paper's sec 3.1 and fig 2 show without Riemann dissipation), and ARD off with eq 19's full
# jump beside the eddy viscosity (md = 1: the Riemann solver SPHinXsys's channels keep without
# ARD); then RESULTS_rans_map.md, channel_hcd_map.{csv,png} (the disturbance in 10-s windows by
# dissipation and N_f), channel_hcd_ard_indicator.png and channel_hcd_k_dissipation.png. About
# 2.5 h on 2 cores, two runs side by side.
#   tests/validation/run_rans_map.sh [BUILD_DIR] [charts]     (default build; "charts": the
#   tables and charts of the runs already in out/validation_rans_map, without running)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
out=out/validation_rans_map
mkdir -p "$out"
source tests/validation/lib.sh
if [ "${2:-}" != charts ]; then
# without ARD (reconstructed, none) every resolution to t = 60 s, the disturbance in four 10-s
# windows, the profiles averaged over the last 10 s at N_f = 60 and 80 (this session's went to
# 30 s and on from their checkpoints, which keep avg); ARD
# on and "riemann" at N_f = 60 and 80 to 30 s (one window)
(
  run channel_hcd_nf80_ard0_md0 channel_hcd nf=80 ard=0 md=0 t_end=60 avg=10 wallp=1
  run channel_hcd_nf80_ard0 channel_hcd nf=80 ard=0 t_end=60 avg=10 wallp=1
  run channel_hcd_nf40_ard0 channel_hcd nf=40 ard=0 t_end=60 avg=20 wallp=1
  run channel_hcd_nf40_ard1 channel_hcd nf=40 ard=1 t_end=60 avg=20 wallp=1
  run channel_hcd_nf80_ard0_md1 channel_hcd nf=80 ard=0 md=1 t_end=30 avg=10 wallp=1
) &
(
  run channel_hcd_nf40_ard0_md0 channel_hcd nf=40 ard=0 md=0 t_end=60 avg=20 wallp=1
  run channel_hcd_nf60_ard0_md0 channel_hcd nf=60 ard=0 md=0 t_end=60 avg=10 wallp=1
  run channel_hcd_nf80_ard1 channel_hcd nf=80 ard=1 t_end=30 avg=10 wallp=1
  run channel_hcd_nf60_ard0 channel_hcd nf=60 ard=0 t_end=60 avg=10 wallp=1
  run channel_hcd_nf60_ard1 channel_hcd nf=60 ard=1 t_end=30 avg=10 wallp=1
  run channel_hcd_nf40_ard0_md1 channel_hcd nf=40 ard=0 md=1 t_end=60 avg=20 wallp=1
  run channel_hcd_nf60_ard0_md1 channel_hcd nf=60 ard=0 md=1 t_end=30 avg=10 wallp=1
) &
wait
fi
python3 tests/validation/results.py "$out" tests/validation/RESULTS_rans_map.md
python3 tests/validation/channel_ke_chart.py tests/validation \
  $(for nf in 40 60 80; do for r in ard1 ard0 ard0_md0 ard0_md1; do echo "hcdmap:map=$out/channel_hcd_nf${nf}_$r"; done; done)
# the last snapshot of each run drawn (clsph render) and the frames stacked (ffmpeg): the ARD
# indicator at N_f = 40, 60, 80 (the paper's fig 27) and k at N_f = 80 with ARD and with each
# dissipation without it (figs 25-26)
frames=$(mktemp -d)
# the labels' font: fontconfig's DejaVu Sans, else Debian's fonts-dejavu-core path (the README's
# packages; fc-match comes with the fontconfig package, which they need not pull in)
font=$(fc-match -f '%{file}' "DejaVu Sans" 2>/dev/null || true)
[ -n "$font" ] || font=/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf
[ -r "$font" ] || { echo "run_rans_map.sh: no DejaVu Sans for the frames' labels ($font)" >&2; exit 1; }
last_frame() { # run field range label -> the frame's path, the label drawn over its title line
  local run=$1 field=$2 range=$3 label=$4 snap dir
  snap=$(ls "$out/$run"/snap_*.h5 | tail -1)
  dir="$frames/$run-$field"
  mkdir -p "$dir"
  cp "$snap" "$dir/"
  "$build/clsph" render "$dir" --field "$field" --range "$range" --size 1600x400 --no-movie \
    >/dev/null
  ffmpeg -loglevel error -y -i "$dir"/frames/*.png \
    -vf "drawtext=fontfile=$font:text='$label':x=300:y=8:fontsize=20:fontcolor=black" "$dir/labelled.png"
  echo "$dir/labelled.png"
}
stack() { # output input...
  local dest=$1 args=() n=0
  shift
  for f in "$@"; do args+=(-i "$f"); n=$((n + 1)); done
  # stacked, 1200 pixels wide and in 64 colours (a quarter of the bytes of the full frames)
  ffmpeg -loglevel error -y "${args[@]}" -filter_complex \
    "vstack=inputs=$n,scale=1200:-1:flags=area,split[a][b];[a]palettegen=max_colors=64[p];[b][p]paletteuse=dither=none" \
    "$dest"
}
stack tests/validation/channel_hcd_ard_indicator.png \
  $(for nf in 40 60 80; do last_frame "channel_hcd_nf${nf}_ard1" ard 0,20 "N_f = $nf, ARD on"; done)
stack tests/validation/channel_hcd_k_dissipation.png \
  "$(last_frame channel_hcd_nf80_ard1 k 0,0.2 "N_f = 80, ARD on")" \
  "$(last_frame channel_hcd_nf80_ard0 k 0,0.2 "N_f = 80, ARD off, reconstructed dissipation")" \
  "$(last_frame channel_hcd_nf80_ard0_md0 k 0,0.2 "N_f = 80, ARD off, no Riemann dissipation")" \
  "$(last_frame channel_hcd_nf80_ard0_md1 k 0,0.2 "N_f = 80, ARD off, full Riemann dissipation")"
rm -rf "$frames"
