#!/bin/bash
# identify on 1 vs N ranks, side by side (docs/cluster.md "identify"; not a ctest). Runs SCENE
# under `mpirun -np 1` and `mpirun -np N` in turn, RUNS times each (1, N, 1, N, ...), checks that
# every run writes the same identify_fit.csv and identify_law.csv, and prints the whole-process
# wall times, their medians, the share (median N-rank time / median 1-rank time), the median of
# the pair-by-pair ratios and the load average before and after.
# Usage: tests/app/identify_scaling.sh BUILD_DIR [N=2] [RUNS=3]
#                                      [SCENE=tests/app/scenes/identify_mpi_small.prm] [--set ...]
set -eu
build=$1; n=${2:-2}; runs=${3:-3}; src=$(cd "$(dirname "$0")/../.." && pwd)
scene=${4:-$src/tests/app/scenes/identify_mpi_small.prm}; shift $(( $# < 4 ? $# : 4 ))
out=${SCALING_OUT:-/tmp/fiberbridge_identify_scaling}
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
    [ -d "$out/reference" ] || cp -r "$out/np$np" "$out/reference"
    for f in identify_fit.csv identify_law.csv; do
      cmp -s "$out/np$np/$f" "$out/reference/$f" || { echo "$f differs (np $np, run $i)"; exit 1; }
    done
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
print("identify_fit.csv and identify_law.csv identical in every run on 1 and", n, "ranks")
for k in ("1", n):
    print(f"{k} rank(s): wall s {' '.join(f'{x:.2f}' for x in t[k])}; median {statistics.median(t[k]):.2f}")
print(f"share {n}/1 (ratio of medians): {statistics.median(t[n]) / statistics.median(t['1']):.3f}; "
      f"pair by pair: {' '.join(f'{b / a:.3f}' for a, b in zip(t['1'], t[n]))}")
s = json.load(open(f"{out}/np{n}/summary.json"))
print("last run: forward runs", s["identify"]["forward_runs"], "; batches",
      [(b["fit"], b["what"], b["ranks"]) for b in s["identify_tasks"]["batches"]])
# CPU seconds of the jobs (less sensitive to other load than wall times): on idle cores the
# N-rank identification takes about the sum over batches of its busiest rank's CPU seconds.
for k in ("1", n):
    b = json.load(open(f"{out}/np{k}/summary.json"))["identify_tasks"]["batches"]
    total = sum(sum(x["cpu_s"]) for x in b)
    busiest = 0.0
    for x in b:
        per = {}
        for r, c in zip(x["ranks"], x["cpu_s"]):
            per[r] = per.get(r, 0) + c
        busiest += max(per.values())
    print(f"last {k}-rank run: job CPU s {total:.2f}, sum over batches of the busiest rank {busiest:.2f}")
PY
