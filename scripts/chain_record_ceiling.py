#!/usr/bin/env python3
"""What each chain-study virtual test itself holds, apart from the measuring chain (issue 39:
"study where each error comes from"). Run after the chain study, from the repository root:

    build/fiberbridge run prm/study_chain.prm --set "Chain study/Table 1=data/reference/seed_table1.csv"
    python3 scripts/chain_record_ceiling.py output/study_chain

For every case it reads the FEM's own R curve (cases/<case>/fem/rcurve_fem.csv: R_energy is the
FEM's exact dissipation per zone-front advance, R_eq2 the seed's Eq. 2), the virtual machine
record with the true zone front (fem/virtual_test/virtual_test_truth.csv) and the chain's result
(chain_recovery.csv), and prints:

- onset_a_mm, zone_mm, ligament_mm: where delta_root first reaches delta_c, the bridging zone's
  length there, and the specimen left ahead of the tip (Length 300 mm);
- fem_peak_G_err: the largest exact dissipation rate within [onset - 4, onset + 10] mm against the
  law's G_ss. Below about -2 % the record holds no steady state that meets the G_ss target;
- record_rise_excess: the machine record's direct energy against the true zone front, over the
  rise (a0 + 5 mm to the onset, 5-frame differences), against Eq. 2 at the same crack length:
  what the record gives an exact crack reading before any smoothing;
- record_J_tip: the same record's mean direct-energy R over its first 3 frames of growth;
- chain_G_err, chain_J_err: the chain's errors (chain_recovery.csv), for comparison.

Pure standard library (no numpy), so it runs wherever the study does.
"""
import csv
import sys


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def interp(x, xs, ys):
    if x <= xs[0]:
        return ys[0]
    for i in range(1, len(xs)):
        if x <= xs[i]:
            t = (x - xs[i - 1]) / (xs[i] - xs[i - 1]) if xs[i] > xs[i - 1] else 0.0
            return ys[i - 1] + t * (ys[i] - ys[i - 1])
    return ys[-1]


def case_numbers(root, case, width_m, length_mm):
    fem = rows(f"{root}/cases/{case}/fem/rcurve_fem.csv")
    a = [float(r["a_mm"]) for r in fem]
    energy = [float(r["R_energy_J_m2"]) for r in fem]
    eq2 = [float(r["R_eq2_J_m2"]) for r in fem]
    droot = [float(r["delta_root_mm"]) for r in fem]
    zone = [float(r["zone_length_mm"]) for r in fem]
    return a, energy, eq2, droot, zone


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else "output/study_chain"
    width_m, length_mm, window = 0.035, 300.0, 5
    print(f"{'case':16s} {'onset_a_mm':>10s} {'zone_mm':>8s} {'ligament_mm':>11s} "
          f"{'fem_peak_G_err':>14s} {'chain_G_err':>11s} {'record_rise_excess':>18s} "
          f"{'record_J_tip':>12s} {'chain_J_err':>11s}")
    for r in rows(f"{root}/chain_recovery.csv"):
        case = r["case"]
        if r["outcome"] != "recovered":
            continue
        a, energy, eq2, droot, zone = case_numbers(root, case, width_m, length_mm)
        G, dc = float(r["G_ss_true_J_m2"]), float(r["delta_c_true_mm"])
        J = float(r["J_tip_true_J_m2"])
        k = next((i for i, d in enumerate(droot) if d >= 0.999 * dc), len(a) - 1)
        near = [e for x, e in zip(a, energy) if a[k] - 4 <= x <= a[k] + 10]
        peak = max(near) / G - 1
        truth = rows(f"{root}/cases/{case}/fem/virtual_test/virtual_test_truth.csv")
        zf = [float(t["zone_front_mm"]) for t in truth]
        P = [float(t["load_N"]) for t in truth]
        u = [float(t["opening_mm"]) * 1e-3 for t in truth]
        W, D = 0.0, [0.0]
        for i in range(1, len(P)):
            W += 0.5 * (P[i] + P[i - 1]) * (u[i] - u[i - 1])
            D.append(W - 0.5 * P[i] * u[i])
        a0 = zf[0]
        first = next(i for i, z in enumerate(zf) if z > a0 + 1e-9)
        steps = [(D[i + 1] - D[i]) / ((zf[i + 1] - zf[i]) * 1e-3) / width_m
                 for i in range(first - 1, first + 2) if zf[i + 1] > zf[i]]
        j_record = sum(steps) / len(steps)
        excess = []
        for i in range(first, len(zf) - window, window):
            j = i + window
            mid = 0.5 * (zf[i] + zf[j])
            if mid < a0 + 5 or mid > a[k] or not zf[j] > zf[i]:
                continue
            R = (D[j] - D[i]) / ((zf[j] - zf[i]) * 1e-3) / width_m
            excess.append(R / interp(mid, a, eq2) - 1)
        rise = sum(excess) / len(excess) if excess else float("nan")
        print(f"{case:16s} {a[k]:10.0f} {zone[k]:8.1f} {length_mm - a[k]:11.0f} "
              f"{100 * peak:+13.1f}% {100 * float(r['G_ss_err_rel']):+10.1f}% "
              f"{100 * rise:+17.1f}% {j_record / J - 1:+11.1%} "
              f"{100 * float(r['J_tip_err_rel']):+10.1f}%")


if __name__ == "__main__":
    main()
