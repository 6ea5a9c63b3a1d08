#!/usr/bin/env bash
# Benchmark harness: the FEM R curve of the seed PVA control scene (prm/fem_pva_control.prm) with
# each linear/nonlinear solver combination, interleaved, REPS times; prints the median run time
# (the model's own wall_time_s, without process start-up) and the ratio to klu + newton measured
# in the same script, plus G_ss and its error. Usage: bench/fem_seed_pva.sh [BUILD_DIR] [REPS]
set -euo pipefail
build=${1:-build}
reps=${2:-5}
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
combos="klu:newton klu:kinsol umfpack:newton umfpack:kinsol"
for rep in $(seq 1 "$reps"); do
  for c in $combos; do
    ls=${c%%:*}; nl=${c##*:}
    out="$work/${ls}_${nl}_$rep"
    "$build/fiberbridge" run "$root/prm/fem_pva_control.prm" --set "Output directory=$out" \
      --set "FEM/Linear solver=$ls" --set "FEM/Nonlinear solver=$nl" \
      --set "FEM/Output every=0" > "$out.log" 2>&1
    # summary.json is written with one key per line: pick the fem block's numbers.
    t=$(awk '/"fem": \{/{f=1} f&&/"wall_time_s"/{gsub(/[^0-9.e+-]/,"",$2); print $2; exit}' "$out/summary.json")
    g=$(awk '/"fem": \{/{f=1} f&&/"G_ss_J_m2"/{gsub(/[^0-9.e+-]/,"",$2); print $2; exit}' "$out/summary.json")
    n=$(awk '/"fem": \{/{f=1} f&&/"n_dofs"/{gsub(/[^0-9]/,"",$2); print $2; exit}' "$out/summary.json")
    echo "$ls+$nl $t $g $n" >> "$work/times.txt"
  done
done
median() { sort -g | awk '{v[NR]=$1} END{print (NR%2)?v[(NR+1)/2]:(v[NR/2]+v[NR/2+1])/2}'; }
ref=$(grep "^klu+newton " "$work/times.txt" | awk '{print $2}' | median)
printf "%-16s %10s %8s %12s %10s %7s\n" solvers median_s ratio G_ss_J_m2 G_ss_err n_dofs
for c in $combos; do
  key="${c%%:*}+${c##*:}"
  m=$(grep "^$key " "$work/times.txt" | awk '{print $2}' | median)
  g=$(grep "^$key " "$work/times.txt" | awk '{print $3}' | head -1)
  n=$(grep "^$key " "$work/times.txt" | awk '{print $4}' | head -1)
  awk -v k="$key" -v m="$m" -v r="$ref" -v g="$g" -v n="$n" \
    'BEGIN{printf "%-16s %10.3f %8.3f %12.4f %10.2e %7d\n", k, m, m/r, g, (g-1082.15)/1082.15, n}'
done
