#!/usr/bin/env bash
# Benchmark harness: the MPM R curve of the seed PVA control scene (prm/mpm_pva_control.prm, MPM
# only) at one cell size, with 1 and 2 threads of the particle loops (MPM/Threads; the MPM's own
# work team, source/mpm/work_team.cc). Prints the model's wall time
# (without process start-up), particle-steps per second, G_ss and its error against
# J_tip + law area (1082.15 J/m^2 for this law), and the user CPU time of the process (on a
# shared machine the CPU time is the steadier number).
# Usage: bench/mpm_pva_threads.sh [BUILD_DIR] [CELL_MM]
set -euo pipefail
build=${1:-build}
cell=${2:-2.5}
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf "%-8s %8s %10s %12s %12s %10s %10s\n" threads cell_mm wall_s psteps_per_s G_ss_J_m2 G_ss_err cpu_user_s
for threads in 1 2; do
  out="$work/t$threads"
  /usr/bin/time -f "%U" -o "$out.cpu" "$build/fiberbridge" run \
    "$root/prm/mpm_pva_control.prm" --set "Output directory=$out" --set "Run=mpm" \
    --set "MPM/Cell size=$cell" --set "MPM/Threads=$threads" --set "MPM/VTU every advances=0" \
    > "$out.log" 2>&1
  # summary.json is written with one key per line: pick the mpm block's numbers.
  t=$(awk '/"mpm": \{/{f=1} f&&/"wall_time_s"/{gsub(/[^0-9.e+-]/,"",$2); print $2; exit}' "$out/summary.json")
  g=$(awk '/"mpm": \{/{f=1} f&&/"G_ss_J_m2"/{gsub(/[^0-9.e+-]/,"",$2); print $2; exit}' "$out/summary.json")
  ps=$(grep -o "[0-9.e+]* particle-steps per second" "$out/summary.json" | head -1 | awk '{print $1}')
  awk -v n="$threads" -v c="$cell" -v t="$t" -v p="$ps" -v g="$g" -v u="$(cat "$out.cpu")" \
    'BEGIN{printf "%-8s %8s %10.1f %12s %12.1f %10.2e %10s\n", n, c, t, p, g, (g-1082.15)/1082.15, u}'
done
