#!/bin/bash
# Independent runs across ranks (issue 16, docs/cluster.md "Many runs across ranks"):
#  1. a small study (beam and FEM ladders, two stability cases with both models: 10 runs) on one
#     process and under `mpirun -np 2`: the same tables (every column but the wall times), both
#     ranks ran some of the runs, and the FEM levels took the one-rank path;
#  2. a control-law scene (beam, fem, compare) on a short specimen: under mpirun the beam and the
#     FEM run as two tasks (the FEM on its serial engine), compare.csv, closed_loop.csv and both
#     R curves identical to the one-process run, the report printed once;
#  3. a failing ladder level under mpirun: one input error naming the key, exit non-zero, no
#     summary.json.
# Usage: mpi_tasks_test.sh MPIEXEC FIBERBRIDGE SOURCE_DIR WORK_DIR
set -u
mpiexec=$1 bin=$2 src=$3 work=$4
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work"
study="$src/tests/app/scenes/study_mpi_small.prm"

"$bin" run "$study" --set "Output directory=$work/s1" > "$work/s1.log" 2>&1 \
  || { cat "$work/s1.log"; fail "study on one process"; }
"$mpiexec" -np 2 --oversubscribe "$bin" run "$study" --set "Output directory=$work/s2" \
  > "$work/s2.log" 2>&1 || { cat "$work/s2.log"; fail "study on 2 ranks"; }
python3 - "$work/s1" "$work/s2" <<'PY' || fail "study tables differ between 1 and 2 ranks"
import csv, json, os, sys
a, b = sys.argv[1], sys.argv[2]
def table(d, f):
    rows = [r for r in csv.reader(l for l in open(os.path.join(d, f)) if not l.startswith("#"))]
    keep = [i for i, h in enumerate(rows[0]) if "wall_time" not in h]  # timings differ
    return [[r[i] for i in keep] for r in rows]
for f in ["study_error_vs_time.csv", "stability.csv", "study_beam.csv", "study_fem.csv"]:
    ta, tb = table(a, f), table(b, f)
    # Exact text equality: the same serial code on the same input on either rank, and the
    # result crosses ranks bit for bit (result/result_archive.h), so no tolerance is needed.
    assert ta == tb, (f, [(x, y) for x, y in zip(ta, tb) if x != y][:3])
    assert len(ta) > 3, (f, len(ta))
s = json.load(open(os.path.join(b, "summary.json")))["study"]
assert s["ranks"] == 2, s["ranks"]
ranks = {r["rank"] for r in s["error_vs_time"] + s["stability"]}
assert ranks == {0, 1}, f"runs went to ranks {ranks} only"
print("study ok: same tables on 1 and 2 ranks; runs on ranks", sorted(ranks))
PY
[ "$(grep -c '^fiberbridge report' "$work/s2.log")" = 1 ] || fail "study report printed more than once"

short=(--set "Specimen/Length=120" --set "Specimen/Width=20" --set "Specimen/Height=20"
       --set "Specimen/Initial crack=40" --set "Cohesive law/Points=0.05:800, 0.3:300"
       --set "Cohesive law/Delta c=1.5" --set "FEM/Steady-state window=6"
       --set "Compare/Intervals=20" --set "FEM/Output every=0")
"$bin" run "$src/prm/control_pva.prm" --set "Output directory=$work/c1" "${short[@]}" \
  > "$work/c1.log" 2>&1 || { cat "$work/c1.log"; fail "control scene on one process"; }
"$mpiexec" -np 2 --oversubscribe "$bin" run "$src/prm/control_pva.prm" \
  --set "Output directory=$work/c2" "${short[@]}" > "$work/c2.log" 2>&1 \
  || { cat "$work/c2.log"; fail "control scene on 2 ranks"; }
for f in compare.csv closed_loop.csv rcurve_beam.csv rcurve_fem.csv; do
  cmp -s "$work/c1/$f" "$work/c2/$f" || fail "$f differs between 1 and 2 ranks"
done
python3 - "$work/c2" <<'PY' || fail "control scene summary"
import json, sys
s = json.load(open(sys.argv[1] + "/summary.json"))
t = s["simulation_tasks"]
assert t["ranks"] == 2 and sorted(i["item"] for i in t["items"]) == ["beam", "fem"], t
assert {i["rank"] for i in t["items"]} == {0, 1}, t
# one FEM engine (issue 14): a task runs it on MPI_COMM_SELF, i.e. on one rank
assert s["fem"]["n_ranks"] == 1, s["fem"]
print("control scene ok: beam and fem as tasks on ranks 0 and 1, same compare.csv")
PY
[ "$(grep -c '^fiberbridge report' "$work/c2.log")" = 1 ] || fail "control report printed more than once"

# A bad ladder value fails inside a task: every rank stops, the error names the key once.
if "$mpiexec" -np 2 --oversubscribe "$bin" run "$study" --set "Output directory=$work/bad" \
    --set "Study/FEM ladder=Element size = 4, -2, 1" > "$work/bad.log" 2>&1; then
  fail "a negative element size in the ladder was accepted"
fi
[ "$(grep -c 'input error' "$work/bad.log")" = 1 ] || { cat "$work/bad.log"; fail "the input error is not printed exactly once"; }
grep -q "FEM ladder" "$work/bad.log" || { cat "$work/bad.log"; fail "the error does not name the ladder"; }
[ ! -e "$work/bad/summary.json" ] || fail "a failed run left a summary.json"
echo "mpi tasks test passed"
