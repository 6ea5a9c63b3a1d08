#!/bin/bash
# DCB-05: identified G_ss against the reduce plateaus under variants of the identification.
wt=$(cd "$(dirname "$0")/.." && pwd); bin=$wt/build/fiberbridge; out=${OUT:-/tmp/identify_dcb05}; mkdir -p $out
rec=$wt/data/dcb_records/DCB-05_Toughness.csv
run() { name=$1; shift
  nice $bin run $wt/prm/test_records.prm --set "Output directory=$out/$name" --set "Run=reduce, identify" \
    --set "Test/Files=$rec" --set "Identify/Per record=false" "$@" > $out/$name.log 2>&1 || { echo "$name failed"; tail -3 $out/$name.log; return; }
  python3 - $out/$name $name <<'PY'
import json, sys, csv
d, name = sys.argv[1], sys.argv[2]
s = json.load(open(d + "/summary.json"))
i = s["identify"]; r = s["reduce"]["records"][0]
rows = [row for row in csv.reader(l for l in open(d + "/identify_fit.csv") if not l.startswith("#"))][1:]
op = [float(x[1]) for x in rows]; a = [float(x[4]) for x in rows]; ma = [float(x[5]) for x in rows]
n = len(rows); last = range(2 * n // 3, n)
lag = sum(ma[k] - a[k] for k in last) / len(last)
ext_meas = a[-1] - a[0]; ext_model = ma[-1] - ma[0]
print(f"{name:12s} E_L {i['records'][0]['E_L_effective_GPa']:.1f} G_ss {i['G_ss_J_m2']:.0f} J_tip {i['J_tip_J_m2']:.0f} "
      f"load_rms {100*i['load_rms_rel']:.2f}% crack_rms {i['crack_rms_mm']:.2f} mm | model-reading a over last third {lag:+.2f} mm, "
      f"extension model/readings {ext_model:.1f}/{ext_meas:.1f} mm | plateau energy {r['energy']['plateau_J_m2']:.0f} MBT {r['MBT']['plateau_J_m2']:.0f} | {i['wall_time_s']:.0f} s")
PY
}
run base
run noF --set "Identify/Large displacement correction=false"
run crack03 --set "Identify/Crack scatter=0.3"
# the quoted E_L (19.3 GPa) instead of the one calibrated from the initial compliance through CBT
run quotedE --set "Identify/Calibrate modulus=false"
