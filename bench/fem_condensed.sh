#!/usr/bin/env bash
# Benchmark harness (issue 34 item 3): the FEM R curve of the seed PVA control scene
# (prm/fem_pva_control.prm, Q1 2 mm, 3624 dofs) with FEM/Linear solver = condensed (the arms
# condensed onto the crack plane) against klu (the full system), interleaved, REPS times. Prints
# the median model time (summary.json wall_time_s, without process start-up), the ratio, G_ss and
# the two runs' largest relative R_J difference, and the median time_breakdown_s of each (setup,
# assembly, factorize, solve, J integrals, output): the split before and after.
# Usage: bench/fem_condensed.sh [BUILD_DIR] [REPS]
set -euo pipefail
build=${1:-build}
reps=${2:-5}
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
solvers="klu condensed"
for rep in $(seq 1 "$reps"); do
  for ls in $solvers; do
    out="$work/${ls}_$rep"
    "$build/fiberbridge" run "$root/prm/fem_pva_control.prm" --set "Output directory=$out" \
      --set "FEM/Linear solver=$ls" --set "FEM/Output every=0" > "$out.log" 2>&1
    python3 - "$out/summary.json" "$ls" >> "$work/times.txt" <<'PY'
import json, sys
f = json.load(open(sys.argv[1]))["fem"]
b = f["time_breakdown_s"]
print(sys.argv[2], f["wall_time_s"], f["G_ss_J_m2"],
      *(b[k] for k in ("setup", "assembly", "factorize", "solve", "J_integrals", "output")))
PY
  done
done
python3 - "$work" "$reps" <<'PY'
import csv, statistics, sys
work, reps = sys.argv[1], int(sys.argv[2])
rows = [l.split() for l in open(f"{work}/times.txt")]
cols = ["wall", "G_ss", "setup", "assembly", "factorize", "solve", "J_integrals", "output"]
med = {}
for s in ("klu", "condensed"):
    vals = [list(map(float, r[1:])) for r in rows if r[0] == s]
    med[s] = {c: statistics.median(v[i] for v in vals) for i, c in enumerate(cols)}
def rj(s):
    with open(f"{work}/{s}_1/rcurve_fem.csv") as fh:
        r = csv.DictReader(l for l in fh if not l.startswith("#"))
        key = next(k for k in r.fieldnames if k.startswith("R_J"))
        return [float(x[key]) for x in r]
a, b = rj("klu"), rj("condensed")
diff = max(abs(x - y) / abs(x) for x, y in zip(a, b)) if len(a) == len(b) else float("nan")
print(f"seed PVA FEM, {reps} interleaved runs each, medians (model time, s)")
print(f"{'solver':<10} {'model_s':>8} {'ratio':>6} {'G_ss_J_m2':>14}  " +
      " ".join(f"{c:>11}" for c in cols[2:]))
for s in ("klu", "condensed"):
    m = med[s]
    print(f"{s:<10} {m['wall']:8.3f} {m['wall'] / med['klu']['wall']:6.3f} {m['G_ss']:14.8f}  " +
          " ".join(f"{m[c]:11.4f}" for c in cols[2:]))
print(f"speed-up klu/condensed: {med['klu']['wall'] / med['condensed']['wall']:.2f}x; "
      f"largest relative R_J difference: {diff:.2e} over {len(a)} advances")
PY
