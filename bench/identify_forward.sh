#!/usr/bin/env bash
# Benchmark harness (not a timed test; issue 34 item 4): one shared record identified with the
# beam and with the FEM as forward model (Identify/Forward model = beam | fem), side by side in
# one run: the scene's wall time, identify's own wall_time_s, forward runs, chi^2, load and crack
# RMS and the identified parameters. The FEM route starts from the beam's identification (its
# notes give the beam route's figures) and uses the FEM section of prm/test_records.prm with
# FEM/Element size = auto (one law-free mesh for every trial, app/items/fem_forward_model.h) unless
# FEM_SIZE is given (mm).
# MAX_EVALUATIONS (environment) sets Identify/Max evaluations for both routes (default 300).
# Usage: bench/identify_forward.sh [BUILD_DIR] [RECORD] [FEM_SIZE]   (RECORD: DCB-05 by default)
set -euo pipefail
build=${1:-build}
rec=${2:-DCB-05}
size=${3:-auto}
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for model in beam fem; do
  out="$work/$model"
  start=$(date +%s.%N)
  "$build/fiberbridge" run "$root/prm/test_records.prm" --set "Output directory=$out" \
    --set "Run=identify" --set "Identify/Per record=false" --set "Identify/Forward model=$model" \
    --set "FEM/Element size=$size" --set "Identify/Max evaluations=${MAX_EVALUATIONS:-300}" \
    --set "Test/Files=$root/data/dcb_records/${rec}_Toughness.csv" > "$out.log" 2>&1
  end=$(date +%s.%N)
  python3 - "$out/summary.json" "$model" "$start" "$end" <<'PY'
import json, sys
b = json.load(open(sys.argv[1]))['identify']
t = b['trilinear']
print(f"{sys.argv[2]:4s}: scene {float(sys.argv[4]) - float(sys.argv[3]):.1f} s, identify "
      f"{b['wall_time_s']:.1f} s, {b['evaluations']} evaluations, {b['forward_runs']} forward runs "
      f"({1000 * b['forward_time_s'] / max(b['forward_runs'], 1):.0f} ms each); chi2 {b['chi2']:.1f}, "
      f"load RMS {100 * b['load_rms_rel']:.2f} %, crack RMS {b['crack_rms_mm']:.2f} mm; "
      f"d1 {t['d1_mm']:.4g} mm s1 {t['sigma1_kPa']:.4g} kPa d2 {t['d2_mm']:.4g} mm "
      f"s2 {t['sigma2_kPa']:.4g} kPa dc {t['delta_c_mm']:.4g} mm J_tip {b['J_tip_J_m2']:.4g} "
      f"G_ss {b['G_ss_J_m2']:.4g} J/m^2, E_L {b['records'][0]['E_L_effective_GPa']:.4g} GPa")
for n in b['notes']:
    if n.startswith('beam route'):
        print('      ' + n)
PY
done
