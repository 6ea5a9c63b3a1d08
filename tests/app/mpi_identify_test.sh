#!/bin/bash
# identify's independent runs across ranks (issue 16 section 2, docs/cluster.md "identify"):
# a small identification (tests/app/scenes/identify_mpi_small.prm) on one process and on 2 ranks,
#  1. one joint fit (Identify/Per record = false): its optimizer starts and Jacobian runs are
#     tasks across the ranks;
#  2. the joint fit and one fit per record (Per record = true): each fit is a task;
# and in both the same CSVs byte for byte and the same summary.json but for the wall times and
# the rank log (identify_tasks), both ranks ran some of the jobs, and rank 1 wrote nothing: the
# 2-rank runs are MPMD launches whose rank 1 gets an output directory of its own, which must
# stay empty. Then the per-record run resumed on 2 ranks restores all three fits (rank 0 kept
# the records of the fits rank 1 ran) and writes the same tables.
# Usage: mpi_identify_test.sh MPIEXEC FIBERBRIDGE SOURCE_DIR WORK_DIR
set -u
mpiexec=$1 bin=$2 src=$3 work=$4
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work"
scene="$src/tests/app/scenes/identify_mpi_small.prm"

# compare DIR1 DIR2: the same files (resume records aside: they hold the wall times), CSVs and
# text identical byte for byte, summary.json identical but for timings and identify_tasks.
compare() {
  python3 - "$1" "$2" <<'PY'
import json, os, sys
a, b = sys.argv[1], sys.argv[2]
def files(d):
    out = set()
    for root, _, fs in os.walk(d):
        for f in fs:
            rel = os.path.relpath(os.path.join(root, f), d)
            if not rel.startswith("resume" + os.sep):
                out.add(rel)
    return out
fa, fb = files(a), files(b)
assert fa == fb, ("different files", sorted(fa ^ fb))
csvs = [f for f in fa if f.endswith(".csv") or f.endswith(".txt") or f.endswith(".prm")]
assert any(f.startswith("identify_fit") for f in csvs), sorted(fa)
for f in sorted(csvs):
    if f == "parameters_used.prm":
        continue  # names the output directory
    ta, tb = open(os.path.join(a, f), "rb").read(), open(os.path.join(b, f), "rb").read()
    if f.endswith(".txt"):  # a text report may state wall times
        ta = b"\n".join(l for l in ta.split(b"\n") if b"wall" not in l and b" s)" not in l)
        tb = b"\n".join(l for l in tb.split(b"\n") if b"wall" not in l and b" s)" not in l)
    assert ta == tb, f + " differs"
def strip(j):
    if isinstance(j, dict):
        return {k: strip(v) for k, v in j.items()
                if k not in ("wall_time_s", "forward_time_s", "item_wall_time_s",
                             "identify_tasks", "resumed")}
    if isinstance(j, list):
        return [strip(v) for v in j]
    return j
sa = strip(json.load(open(os.path.join(a, "summary.json"))))
sb = strip(json.load(open(os.path.join(b, "summary.json"))))
assert sa == sb, [(k, sa.get(k), sb.get(k)) for k in sa if sa.get(k) != sb.get(k)][:2]
print("same outputs:", a, b, len(csvs), "tables")
PY
}

# run2 OUT [args...]: 2 ranks, rank 1 with its own output directory OUT.rank1.
run2() {
  local out=$1; shift
  "$mpiexec" --oversubscribe -np 1 "$bin" run "$scene" --set "Output directory=$out" "$@" : \
    -np 1 "$bin" run "$scene" --set "Output directory=$out.rank1" "$@" > "$out.log" 2>&1 \
    || { cat "$out.log"; fail "2 ranks: $out"; }
  [ -z "$(find "$out.rank1" -type f 2>/dev/null)" ] \
    || fail "rank 1 wrote files: $(find "$out.rank1" -type f | head -5)"
  [ "$(grep -c '^fiberbridge report' "$out.log")" = 1 ] || fail "$out: report not printed once"
}

# ranks_used DIR WHAT N_RANKS: the summary's rank log shows batches WHAT on ranks 0 and 1.
ranks_used() {
  python3 - "$1" "$2" "$3" <<'PY'
import json, sys
t = json.load(open(sys.argv[1] + "/summary.json"))["identify_tasks"]
assert t["ranks"] == int(sys.argv[3]), t
used = {r for b in t["batches"] if b["what"] == sys.argv[2] for r in b["ranks"]}
want = {0, 1} if int(sys.argv[3]) == 2 else {0}
assert used == want, (sys.argv[2], used, t)
print(sys.argv[2], "jobs on ranks", sorted(used))
PY
}

# 1. one joint fit: starts and Jacobian runs as tasks
"$bin" run "$scene" --set "Output directory=$work/a1" > "$work/a1.log" 2>&1 \
  || { cat "$work/a1.log"; fail "joint fit on one process"; }
run2 "$work/a2"
compare "$work/a1" "$work/a2" || fail "joint fit: outputs differ between 1 and 2 ranks"
ranks_used "$work/a1" jacobian 1 || fail "joint fit: rank log on one process"
ranks_used "$work/a2" starts 2 || fail "joint fit: the starts did not go to both ranks"
ranks_used "$work/a2" jacobian 2 || fail "joint fit: the Jacobian runs did not go to both ranks"

# 2. the joint fit and one per record: each fit a task
per=(--set "Identify/Per record=true")
"$bin" run "$scene" --set "Output directory=$work/b1" "${per[@]}" > "$work/b1.log" 2>&1 \
  || { cat "$work/b1.log"; fail "per-record fits on one process"; }
run2 "$work/b2" "${per[@]}"
compare "$work/b1" "$work/b2" || fail "per-record fits: outputs differ between 1 and 2 ranks"
ranks_used "$work/b2" fits 2 || fail "per-record fits: the fits did not go to both ranks"
[ "$(ls "$work/b2/resume" | wc -l)" = 3 ] || fail "rank 0 did not keep all three fits: $(ls "$work/b2/resume")"

# 3. resumed on 2 ranks (one output directory): all three fits restored, the same tables
"$mpiexec" --oversubscribe -np 2 "$bin" run "$scene" --set "Output directory=$work/b2" \
  "${per[@]}" --resume > "$work/b3.log" 2>&1 || { cat "$work/b3.log"; fail "resume on 2 ranks"; }
[ "$(grep -c 'restored from' "$work/b3.log")" = 3 ] || { cat "$work/b3.log"; fail "resume did not restore the three fits once each"; }
compare "$work/b1" "$work/b2" || fail "resumed per-record fits differ"
echo "mpi identify test passed"
