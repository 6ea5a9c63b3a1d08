#!/usr/bin/env bash
# Old against new MPM kernel, side by side: runs two fiberbridge binaries in turn (A B A B ...,
# so that both see the same machine load) on
#   default  the 5 mm default-scene MPM (prm/default.prm: extract and fit, then the fitted law in
#            the MPM; the model's own wall time is read, without the extraction),
#   pva      the seed PVA control scene at CELL mm cells, shortened to the first END_MM mm of
#            growth (MPM/Minimum ligament), or the whole R curve with END_MM = full.
# Prints per run the model wall time, the whole process's user CPU time, particle-steps per
# second, the G_ss error against J_tip + law area and R_J against Eq. 2 (n/a when a shortened run
# has no steady state), then the median ratios new/old of the wall and of the CPU time (on cores
# shared with other work the wall time mostly measures the load: compare CPU times there), the
# new binary's cost split (the summary's performance note), and whether the two binaries wrote
# the same rcurve_mpm.csv (cmp of the last pair).
# Usage: bench/mpm_speed.sh OLD_BIN NEW_BIN [RUNS] [CELL_MM] [END_MM] [THREADS]
# An old binary, from any commit REV (e.g. the branch point of the change under test, `git
# merge-base HEAD main`), built beside the working tree:
#   git worktree add /tmp/mpm-old REV
#   cmake -S /tmp/mpm-old -B /tmp/mpm-old/build -DCMAKE_BUILD_TYPE=Release \
#     -DFIBERBRIDGE_MODELS="mpm;beam"
#   cmake --build /tmp/mpm-old/build -j2 --target fiberbridge
#   bench/mpm_speed.sh /tmp/mpm-old/build/fiberbridge build/fiberbridge 3 2.5 170 1
# (or copy build/fiberbridge aside before the first edit). Not a test: nothing is asserted.
set -euo pipefail
old=${1:?old binary}
new=${2:?new binary}
runs=${3:-3}
cell=${4:-2.5}
end=${5:-170}
threads=${6:-1}
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# key of the mpm block of summary.json (one key per line)
mpm_value() {
  awk -v k="\"$2\"" '/"mpm": \{/{f=1} f&&index($0,k){gsub(/[^0-9.eE+-]/,"",$2); print $2; exit}' "$1"
}

run_one() { # binary case out
  local bin=$1 what=$2 out=$3
  local -a sets=(--set "Output directory=$out" --set "MPM/VTU every advances=0"
    --set "MPM/Threads=$threads")
  if [ "$what" = default ]; then
    (cd "$root/prm" && /usr/bin/time -f %U -o "$out.cpu" "$bin" run default.prm \
      --set "Run=extract, fit, mpm" "${sets[@]}") > "$out.log" 2>&1
  else
    local -a len=()
    # MPM/End ligament, the old name of MPM/Minimum ligament: the OLD binary may predate the
    # rename, and newer binaries still accept it (with a deprecation note).
    [ "$end" != full ] && len=(--set "MPM/End ligament=$end")
    (cd "$root/prm" && /usr/bin/time -f %U -o "$out.cpu" "$bin" run mpm_pva_control.prm \
      --set "Run=mpm" --set "MPM/Cell size=$cell" "${len[@]}" "${sets[@]}") > "$out.log" 2>&1
  fi
}

printf "%-8s %-4s %3s %9s %9s %13s %10s %10s\n" case bin run wall_s cpu_s psteps_per_s G_ss_err \
  R_J_err
for what in default pva; do
  ratios=()
  cpu_ratios=()
  for i in $(seq 1 "$runs"); do
    for b in old new; do
      bin=$old
      [ $b = new ] && bin=$new
      out="$work/$what-$b-$i"
      run_one "$bin" "$what" "$out"
      s="$out/summary.json"
      t=$(mpm_value "$s" wall_time_s)
      g=$(mpm_value "$s" G_ss_rel_error)
      e2=$(mpm_value "$s" rdelta_rel_error_vs_eq2)
      ps=$(grep -o "[0-9.e+]* particle-steps per second" "$s" | head -1 | awk '{print $1}')
      c=$(tail -1 "$out.cpu")
      awk -v w="$what" -v b=$b -v i="$i" -v t="$t" -v c="$c" -v p="$ps" -v g="$g" -v e="$e2" \
        'BEGIN{ge = (g == "" ? "n/a" : sprintf("%+.2f%%", 100*g));
               ee = (e == "" ? "n/a" : sprintf("%.2f%%", 100*e));
               printf "%-8s %-4s %3d %9.2f %9.2f %13s %10s %10s\n", w, b, i, t, c, p, ge, ee}'
      eval "t_$b=$t"
      eval "c_$b=$c"
    done
    ratios+=("$(awk -v a="$t_new" -v b="$t_old" 'BEGIN{print a/b}')")
    cpu_ratios+=("$(awk -v a="$c_new" -v b="$c_old" 'BEGIN{print a/b}')")
  done
  median() { printf "%s\n" "$@" | sort -g | awk '{v[NR]=$1} END{print v[int((NR+1)/2)]}'; }
  med=$(median "${ratios[@]}")
  cmed=$(median "${cpu_ratios[@]}")
  echo "$what: median ratio new/old over $runs pairs: model wall time $med (speed-up $(awk -v m="$med" 'BEGIN{printf "%.2f", 1/m}')x), process CPU time $cmed (speed-up $(awk -v m="$cmed" 'BEGIN{printf "%.2f", 1/m}')x)"
  grep -o '"performance: [^"]*"' "$work/$what-old-$runs/summary.json" | head -1 | sed 's/^/old /'
  grep -o '"performance: [^"]*"' "$work/$what-new-$runs/summary.json" | head -1 | sed 's/^/new /'
  if cmp -s "$work/$what-old-$runs/rcurve_mpm.csv" "$work/$what-new-$runs/rcurve_mpm.csv"; then
    echo "$what: rcurve_mpm.csv byte-identical"
  else
    echo "$what: rcurve_mpm.csv DIFFERS"
  fi
done
