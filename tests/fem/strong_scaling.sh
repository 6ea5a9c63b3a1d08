#!/bin/bash
# Strong scaling of the distributed FEM, 1 -> N ranks, in one run (docs/cluster.md; not a ctest:
# it takes minutes). Runs the same 3D scene on 1 and on N ranks, checks that the R curves agree,
# and prints the wall-time ratio, the time breakdown and the peak memory per rank.
# Usage: tests/fem/strong_scaling.sh BUILD_DIR [N=2] [extra --set options...]
# Example (the docs/cluster.md numbers):
#   tests/fem/strong_scaling.sh build 2 --set "Cohesive law/Type=none" --set "FEM/Element size=2.5" \
#       --set "FEM/Width elements=14"
set -eu
build=$1; n=${2:-2}; shift 2 || shift $#
src=$(cd "$(dirname "$0")/../.." && pwd)
out=${SCALING_OUT:-/tmp/fiberbridge_scaling}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
for np in 1 "$n"; do
  mpirun -np "$np" --oversubscribe "$build/fiberbridge" run "$src/prm/fem3d_pva_control.prm" \
    --set "Output directory=$out/np$np" --set "FEM/Output every=0" "$@" > "$out.np$np.log" 2>&1 \
    || { cat "$out.np$np.log"; exit 1; }
done
python3 - "$out" "$n" <<'PY'
import json, sys, csv
out, n = sys.argv[1], sys.argv[2]
def load(np):
    f = json.load(open(f"{out}/np{np}/summary.json"))["fem"]
    rows = [r for r in csv.DictReader(l for l in open(f"{out}/np{np}/rcurve_fem.csv") if not l.startswith("#"))]
    return f, rows
f1, r1 = load(1); fn, rn = load(n)
diff = max(abs(float(a["R_J_J_m2"]) / float(b["R_J_J_m2"]) - 1) for a, b in zip(r1, rn))
assert len(r1) == len(rn), (len(r1), len(rn))
print(f"dofs {f1['n_dofs']}, cells {f1['n_cells']}, {len(r1)} tip advances; R_J max rel diff 1 vs {n} ranks: {diff:.2e}")
for f, k in ((f1, 1), (fn, n)):
    t = f["time_breakdown_s"]
    print(f"{k} rank(s): wall {f['wall_time_s']:.2f} s (" + ", ".join(f"{a} {b:.2f}" for a, b in t.items()) +
          f"), factorizations {f['factorizations']}, peak memory {f['peak_memory_MB_all_ranks']:.0f} MB all ranks, {f['peak_memory_MB_max_rank']:.0f} MB max rank")
print(f"speed-up 1 -> {n} ranks: {f1['wall_time_s'] / fn['wall_time_s']:.2f} (parallel efficiency {f1['wall_time_s'] / fn['wall_time_s'] / int(n):.2f})")
PY
