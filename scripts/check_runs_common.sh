# Sourced by the output checks' run scripts (refactor_check_runs.sh, fem_solver_check_runs.sh):
# BINARY and OUTROOT from their arguments, a fresh OUTROOT, and run NAME ARGS... which runs
# `BINARY run ARGS` into OUTROOT/NAME (its log beside it) and says its exit status.
set -u
bin=$(realpath "$1")
root=$2
rm -rf "$root"
mkdir -p "$root"
run() {
  local name=$1
  shift
  "$bin" run "$@" --set "Output directory=$root/$name" >"$root/$name.log" 2>&1
  echo "$name rc=$?"
}
