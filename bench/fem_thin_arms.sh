#!/usr/bin/env bash
# Benchmark harness: the cost of the thin-arm FEM scenes on their default settings (the mesh that
# follows the arm, FEM/Polynomial degree = auto), REPS times each; prints the median model wall
# time (summary.json fem.wall_time_s), the DoFs and G_ss. Usage: bench/fem_thin_arms.sh [BUILD_DIR] [REPS]
set -euo pipefail
build=${1:-build}
reps=${2:-3}
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Each entry: scene[:Kinematics]; lefm_thin_composite:finite is the composite with
# FEM/Kinematics = finite (the cost of finite rotations on a thin-arm mesh). The two Gmsh
# specimens (mesh/dcb_specimen.geo) include meshing it with gmsh at the start of the model.
scenes="lefm_thin_composite lefm_thin_composite:finite fem_tapered_composite fem_end_blocks_composite fem_thin_epi fem_pva_control"
field() { awk -v k="\"$2\"" '/"fem": \{/{f=1} f&&index($0,k){gsub(/[^0-9.e+-]/,"",$2); print $2; exit}' "$1"; }
median() { sort -g | awk '{v[NR]=$1} END{print (NR%2)?v[(NR+1)/2]:(v[NR/2]+v[NR/2+1])/2}'; }
printf "%-29s %10s %8s %12s\n" scene median_s n_dofs G_ss_J_m2
for s in $scenes; do
  scene=${s%%:*}
  kinematics=small
  [[ $s == *:* ]] && kinematics=${s#*:}
  for rep in $(seq 1 "$reps"); do
    out="$work/$s-$rep"
    "$build/fiberbridge" run "$root/prm/$scene.prm" --set "Run=fem" --set "Output directory=$out" \
      --set "FEM/Output every=0" --set "FEM/Kinematics=$kinematics" > "$out.log" 2>&1
    echo "$(field "$out/summary.json" wall_time_s) $(field "$out/summary.json" n_dofs) $(field "$out/summary.json" G_ss_J_m2)" >> "$work/$s.txt"
  done
  m=$(awk '{print $1}' "$work/$s.txt" | median)
  read -r _ n g < <(head -1 "$work/$s.txt")
  printf "%-29s %10.3f %8d %12.4f\n" "$s" "$m" "$n" "$g"
done
