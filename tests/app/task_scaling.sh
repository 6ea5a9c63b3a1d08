#!/bin/bash
# Independent runs across ranks, 1 vs N ranks, side by side (docs/cluster.md "Many runs across
# ranks"; not a ctest: it takes minutes). Runs SCENE under `mpirun -np 1` and `mpirun -np N` in
# turn, RUNS times each (1, N, 1, N, ...), checks that every run gives the same study tables
# (wall-time columns aside), and prints the whole-process wall times, their medians, the
# median of the pair-by-pair ratios N/1, the load average before and after, and, from the
# summary of the last N-rank run, which rank ran which task.
# Usage: tests/app/task_scaling.sh BUILD_DIR [N=2] [RUNS=5] [SCENE=prm/study_fem.prm] [--set ...]
# Example (the docs/cluster.md table):
#   tests/app/task_scaling.sh build 2 5
#   tests/app/task_scaling.sh build 2 5 prm/study_fem.prm --set "Study/Stability models="
set -eu
build=$1; n=${2:-2}; runs=${3:-5}; src=$(cd "$(dirname "$0")/../.." && pwd)
scene=${4:-$src/prm/study_fem.prm}; shift $(( $# < 4 ? $# : 4 ))
out=${SCALING_OUT:-/tmp/fiberbridge_task_scaling}
rm -rf "$out" && mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
for ((i = 0; i < runs; ++i)); do
  for np in 1 "$n"; do
    t0=$(date +%s.%N)
    mpirun -np "$np" --oversubscribe "$build/fiberbridge" run "$scene" \
      --set "Output directory=$out/np$np" "$@" > "$out/np$np.log" 2>&1 \
      || { cat "$out/np$np.log"; exit 1; }
    t1=$(date +%s.%N)
    echo "$np $t0 $t1" >> "$out/times.txt"
    python3 - "$out/np$np" "$out/reference" <<'PY'
import csv, os, shutil, sys
run, ref = sys.argv[1], sys.argv[2]
def table(d, f):
    rows = list(csv.reader(l for l in open(os.path.join(d, f)) if not l.startswith("#")))
    keep = [i for i, h in enumerate(rows[0]) if "wall_time" not in h]
    return [[r[i] for i in keep] for r in rows]
files = [f for f in ("study_error_vs_time.csv", "stability.csv") if os.path.exists(os.path.join(run, f))]
if not os.path.exists(ref):
    shutil.copytree(run, ref)
for f in files:
    assert table(run, f) == table(ref, f), f"{f} differs from the first run"
PY
  done
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
python3 - "$out" "$n" <<'PY'
import json, statistics, sys
out, n = sys.argv[1], sys.argv[2]
t = {"1": [], n: []}
for line in open(f"{out}/times.txt"):
    k, t0, t1 = line.split()
    t[k].append(float(t1) - float(t0))
ratios = [b / a for a, b in zip(t["1"], t[n])]
print("tables identical in every run on 1 and", n, "ranks")
for k in ("1", n):
    print(f"{k} rank(s): wall s {' '.join(f'{x:.2f}' for x in t[k])}; median {statistics.median(t[k]):.2f}")
print(f"ratio {n}/1 pair by pair: {' '.join(f'{r:.3f}' for r in ratios)}; median {statistics.median(ratios):.3f}")
# CPU seconds per rank (the work, less sensitive to other load than the wall time): on idle
# cores the N-rank run takes about the start-up plus the busiest rank's CPU seconds.
for k in ("1", n):
    s = json.load(open(f"{out}/np{k}/summary.json")).get("study", {})
    busy, cpu = {}, {}
    for r in s.get("error_vs_time", []) + s.get("stability", []):
        busy[r["rank"]] = busy.get(r["rank"], 0) + r["wall_time_s"]
        cpu[r["rank"]] = cpu.get(r["rank"], 0) + r["cpu_s"]
    print(f"last {k}-rank run: busy wall s per rank {({a: round(b, 2) for a, b in sorted(busy.items())})}, "
          f"CPU s per rank {({a: round(b, 2) for a, b in sorted(cpu.items())})}")
PY
