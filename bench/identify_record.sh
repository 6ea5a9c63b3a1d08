#!/usr/bin/env bash
# Benchmark harness (not a timed test): `identify` of each shared record alone with the beam
# model (prm/test_records.prm, Run = identify, one Test/Files entry), REPS times; prints per
# record the median of the identification's own wall_time_s, the misfit evaluations, the beam
# runs (misfit evaluations plus the 12 of the Jacobian) and the share of the time spent inside
# the beam model. Usage: bench/identify_record.sh [BUILD_DIR] [REPS]
set -euo pipefail
build=${1:-build}
reps=${2:-3}
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for rec in DCB-01 DCB-02 DCB-03 DCB-05; do
  times=()
  for rep in $(seq 1 "$reps"); do
    out="$work/${rec}_$rep"
    "$build/fiberbridge" run "$root/prm/test_records.prm" --set "Output directory=$out" \
      --set "Run=identify" --set "Identify/Per record=false" \
      --set "Test/Files=$root/data/dcb_records/${rec}_Toughness.csv" > "$out.log" 2>&1
    line=$(python3 -c "import json,sys; b=json.load(open('$out/summary.json'))['identify']; \
print(b['wall_time_s'], b['evaluations'], b['forward_runs'], b['forward_time_s'], b['load_rms_rel'])")
    times+=("$line")
  done
  printf '%s\n' "${times[@]}" | sort -n | awk -v rec="$rec" -v n="$reps" \
    'NR == int((n + 1) / 2) { printf "%s: wall %.1f s (median of %d), %d evaluations, %d beam runs (%.0f ms each), %.1f %% in the beam, load RMS %.2f %%\n", rec, $1, n, $2, $3, 1000 * $4 / $3, 100 * $4 / $1, 100 * $5 }'
done
