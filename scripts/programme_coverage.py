#!/usr/bin/env python3
"""The simulated programme's interval coverage over several draws (issue 39). One run of
prm/study_programme.prm draws each group's four specimens once (Programme study/Seed), so whether
its 95 % intervals hold Table 1 in a group is one Bernoulli trial per group: a single seed cannot
tell a chain's bias from an unlucky draw. This tabulates the runs of several seeds, per seed and
per group, for the interval holding Table 1 and holding the mean of the group's own drawn laws
(the chain's part of a miss), with the implied error of the bridging area G_B = G_ss - J_tip,
on which the fixed-breakpoint fit's sigma1 rests. Usage, from the repository root:

    for s in 1 2 3 4 5 6 7 8 9 10 11; do
      build/fiberbridge run prm/study_programme.prm --set "Programme study/Seed=$s" \\
        --set "Output directory=output/programme_seeds/seed_$s"
    done
    python3 scripts/programme_coverage.py output/programme_seeds/seed_*

(about 70 s a seed on a quiet 2-core machine: 80 FEM virtual tests and the campaign.)
"""
import csv
import os
import statistics
import sys


def rows(folder):
    with open(os.path.join(folder, "programme_recovery.csv")) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def within(r, q, rel, kpa):
    got, true = float(r[f"{q}_kPa"]), float(r[f"{q}_true_kPa"])
    return abs(got - true) <= max(rel * abs(true), kpa)


def main(folders):
    if not folders:
        sys.exit(__doc__)
    per_group = {}
    print("run, sigma1 holds Table 1, sigma1 holds drawn mean, sigma2 holds Table 1, "
          "sigma1 within 12 % or 10 kPa, sigma1 misses")
    held1, held2 = [], []
    for folder in folders:
        rs = rows(folder)
        h1 = sum(int(r["sigma1_interval_holds"]) for r in rs)
        m1 = sum(int(r["sigma1_interval_holds_specimen_mean"]) for r in rs)
        h2 = sum(int(r["sigma2_interval_holds"]) for r in rs)
        w1 = sum(within(r, "sigma1", 0.12, 10) for r in rs)
        held1.append(h1)
        held2.append(h2)
        misses = [f"{r['material']} c{r['cycles']}" for r in rs if r["sigma1_interval_holds"] == "0"]
        print(f"{folder}, {h1}/{len(rs)}, {m1}/{len(rs)}, {h2}/{len(rs)}, {w1}/{len(rs)}, "
              f"{'; '.join(misses)}")
        for r in rs:
            g = per_group.setdefault(f"{r['material']} c{r['cycles']}",
                                     {"n": 0, "h1": 0, "m1": 0, "gb": [], "s1": []})
            g["n"] += 1
            g["h1"] += int(r["sigma1_interval_holds"])
            g["m1"] += int(r["sigma1_interval_holds_specimen_mean"])
            # The drawn laws' mean bridging area (trilinear, breakpoints 0.1 and 1 mm) against
            # the campaign's G_ss - J_tip; and sigma1 against the drawn mean.
            dc = float(r["delta_c_true_mm"])
            s1, s2 = float(r["sigma1_specimen_mean_kPa"]), float(r["sigma2_specimen_mean_kPa"])
            gb_true = 0.5 * s1 * 1.0 + 0.5 * s2 * (dc - 0.1)  # kPa mm = J/m^2
            g["gb"].append(float(r["G_ss_J_m2"]) - float(r["J_tip_J_m2"]) - gb_true)
            g["s1"].append(float(r["sigma1_kPa"]) - s1)
    print(f"\nsigma1 intervals holding Table 1: mean {statistics.mean(held1):.1f}/20 over "
          f"{len(folders)} runs (min {min(held1)}, max {max(held1)}); sigma2: mean "
          f"{statistics.mean(held2):.1f}/20")
    print("\ngroup, sigma1 holds Table 1, holds drawn mean, median G_B error J/m^2, "
          "median sigma1 error against the drawn mean kPa")
    for name, g in per_group.items():
        print(f"{name}, {g['h1']}/{g['n']}, {g['m1']}/{g['n']}, "
              f"{statistics.median(g['gb']):+.1f}, {statistics.median(g['s1']):+.1f}")


if __name__ == "__main__":
    main(sys.argv[1:])
