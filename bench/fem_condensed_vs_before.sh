#!/usr/bin/env bash
# Benchmark harness (issue 34 item 3): the seed PVA FEM R curve (prm/fem_pva_control.prm, Q1 2 mm)
# with FEM/Linear solver = klu (the full system) and condensed (the arms condensed onto the crack
# plane), each with a binary before and after a change, all four interleaved REPS times. Prints
# the medians (min, max) of the model time (summary.json fem.wall_time_s, without process
# start-up), the Newton iterations and the ratios that matter: the condensed FEM after against
# the full FEM before and after, and each solver after against before.
# Usage: bench/fem_condensed_vs_before.sh OLD_BINARY NEW_BINARY [REPS]
set -euo pipefail
old=$1
new=$2
reps=${3:-7}
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for rep in $(seq 1 "$reps"); do
  for which in old new; do
    bin=$old
    [ "$which" = new ] && bin=$new
    for ls in klu condensed; do
      out="$work/${which}_${ls}"
      rm -rf "$out"
      "$bin" run "$root/prm/fem_pva_control.prm" --set "Output directory=$out" \
        --set "FEM/Output every=0" --set "FEM/Linear solver=$ls" > "$out.log" 2>&1
      python3 - "$out/summary.json" "$which" "$ls" >> "$work/times.txt" <<'PY'
import json, sys
f = json.load(open(sys.argv[1]))["fem"]
print(sys.argv[2], sys.argv[3], f["wall_time_s"], f["newton_iterations"], f["G_ss_J_m2"])
PY
    done
  done
done
python3 - "$work/times.txt" "$reps" <<'PY'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
med = {}
print(f"seed PVA FEM, {sys.argv[2]} interleaved runs each: model time [s]")
for which in ("old", "new"):
    for ls in ("klu", "condensed"):
        r = [x for x in rows if x[0] == which and x[1] == ls]
        t = [float(x[2]) for x in r]
        med[which, ls] = statistics.median(t)
        print(f"{which:4s} {ls:10s} median {med[which, ls]:.3f} (min {min(t):.3f}, max {max(t):.3f}), "
              f"Newton {r[0][3]}, G_ss {float(r[0][4]):.8f} J/m^2")
c = med["new", "condensed"]
print(f"condensed after against klu before {med['old', 'klu'] / c:.2f}x, against klu after "
      f"{med['new', 'klu'] / c:.2f}x; condensed after/before {med['old', 'condensed'] / c:.2f}x; "
      f"klu after/before {med['old', 'klu'] / med['new', 'klu']:.2f}x")
PY
