#!/usr/bin/env bash
# Benchmark harness (issue 34 item 3): the "J integrals" and "output" sections of the FEM on a
# scene (default the seed PVA control, prm/fem_pva_control.prm) for two fiberbridge binaries,
# before and after, interleaved REPS times with FEM/Output every = 0 (the final VTU and
# fem_interface.csv only). Prints the medians of the model time (summary.json wall_time_s,
# without process start-up), of the two sections (time_breakdown_s) and of the rest, their
# ratios, and the largest relative difference of any R-curve column between the two.
# Usage: bench/fem_j_output.sh BEFORE_BINARY AFTER_BINARY [REPS] [SCENE.prm] [--set ...]
set -euo pipefail
before=$1
after=$2
reps=${3:-5}
root=$(cd "$(dirname "$0")/.." && pwd)
scene=${4:-$root/prm/fem_pva_control.prm}
shift $(($# < 4 ? $# : 4))
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for rep in $(seq 1 "$reps"); do
  for which in before after; do
    out="$work/${which}_$rep"
    bin=$before
    [ "$which" = after ] && bin=$after
    "$bin" run "$scene" --set "Output directory=$out" --set "FEM/Output every=0" "$@" \
      > "$out.log" 2>&1
    python3 - "$out/summary.json" "$which" >> "$work/times.txt" <<'PY'
import json, sys
f = json.load(open(sys.argv[1]))["fem"]
b = f["time_breakdown_s"]
print(sys.argv[2], f["wall_time_s"], b["J_integrals"], b["output"])
PY
  done
done
python3 - "$work" "$reps" <<'PY'
import csv, statistics, sys
work, reps = sys.argv[1], int(sys.argv[2])
rows = [l.split() for l in open(f"{work}/times.txt")]
med = {}
for w in ("before", "after"):
    v = [list(map(float, r[1:])) for r in rows if r[0] == w]
    med[w] = [statistics.median(x[i] for x in v) for i in range(3)]
    med[w].append(statistics.median(x[0] - x[1] - x[2] for x in v))
def table(w):
    with open(f"{work}/{w}_1/rcurve_fem.csv") as fh:
        r = list(csv.reader(l for l in fh if not l.startswith("#")))
    return r[0], r[1:]
(ha, a), (hb, b) = table("before"), table("after")
worst, where = 0.0, "-"
if ha != hb or len(a) != len(b):
    worst, where = float("inf"), "columns or advances differ"
else:
    for ra, rb in zip(a, b):
        for k, x, y in zip(ha, ra, rb):
            try:
                x, y = float(x), float(y)
            except ValueError:
                continue
            # Relative to the column's scale: a near-zero balance (dissipated_J at the first
            # advance) is round-off of a sum of joules.
            scale = max(max(abs(float(r[ha.index(k)] or 0)) for r in a), 1e-300)
            if abs(x - y) / scale > worst:
                worst, where = abs(x - y) / scale, k
print(f"{reps} interleaved runs each, medians (model time, s)")
print(f"{'':<7} {'model_s':>8} {'J_integrals':>12} {'output':>8} {'rest':>8}")
for w in ("before", "after"):
    print(f"{w:<7} " + " ".join(f"{x:{n}.4f}" for x, n in zip(med[w], (8, 12, 8, 8))))
print("ratio   " + " ".join(f"{med['before'][i] / med['after'][i]:{n}.2f}"
                            for i, n in zip(range(4), (8, 12, 8, 8))))
print(f"largest R-curve difference (relative to the column's largest value): {worst:.1e} ({where}) "
      f"over {len(a)} advances")
PY
