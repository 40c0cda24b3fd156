# The validation scripts' shared helper (sourced): run NAME CASE [SET ...] runs cases/CASE.lua
# with --set SET for each SET into $out/NAME (the scripts set $build and $out; $run_extra adds
# options, e.g. --profile), quietly, over an earlier run; a run that fails or stops early leaves
# its summary.json and the script goes on.
run() { # name case sets...
  local name=$1 case=$2
  shift 2
  local args=()
  for s in "$@"; do args+=(--set "$s"); done
  # shellcheck disable=SC2086 # $run_extra: zero or more options
  "$build/clsph" run "cases/$case.lua" "${args[@]}" --out "$out/$name" --quiet ${run_extra:-} \
    --overwrite || true
}
