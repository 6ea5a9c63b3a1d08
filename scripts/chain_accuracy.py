#!/usr/bin/env python3
"""The chain's accuracy on records, from the chain study (issue 39): the RMS relative errors of the
G_ss and J_tip the measuring chain gives back on the virtual tests of the 20 Table 1 laws. They are
the defaults of Campaign/Chain accuracy of G_ss and of J_tip, the term a campaign of records adds
in quadrature to its replicates' intervals (docs/design.md, "Durability campaign"). Also printed:
how well u(G_B)^2 = (u_G G_ss)^2 + (u_J J_tip)^2 describes the errors of the bridging area
G_B = G_ss - J_tip the fit's stresses rest on (the RMS of err(G_B) / u(G_B): about 1 if it does).
G_ss is extract's plateau (G_ss_uncorrected_J_m2 where the fit was corrected by simulation): that
is the G_ss a campaign group reports; the corrected law's own G_ss (J_tip + J1 + J2, the table's
G_ss_J_m2) is printed beside. J_tip is the corrected one, as the campaign shifts it.
Usage, from the repository root:

    build/fiberbridge run prm/study_chain.prm --set "Chain study/Model correction=beam" \
      --set "Output directory=output/study_chain_beam"
    python3 scripts/chain_accuracy.py output/study_chain_beam

(the beam: a campaign's groups are corrected by it; on a study run with `auto` the script says
which cases the FEM corrected, whose J_tip runs lower).
"""
import csv
import json
import math
import os
import sys


def rows(folder):
    with open(os.path.join(folder, "chain_recovery.csv")) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def plateau(r):
    """Extract's plateau G_ss: the uncorrected column where the fit was corrected."""
    v = r.get("G_ss_uncorrected_J_m2", "")
    return float(v) if v not in ("", "nan") and math.isfinite(float(v)) else float(r["G_ss_J_m2"])


def forward_model(folder, case):
    """The model that corrected the case's fit (summary.json), "" when none ran or converged."""
    path = os.path.join(folder, "cases", case, "chain", "summary.json")
    try:
        with open(path) as f:
            c = json.load(f).get("fit_correction", {})
    except OSError:
        return ""
    return c.get("forward_model", "") if c.get("converged") else ""


def rms(values):
    return math.sqrt(sum(v * v for v in values) / len(values))


def main(folder):
    table1 = [r for r in rows(folder) if float(r["table1_law"]) == 1 and r["outcome"] == "recovered"]
    if not table1:
        sys.exit(f"{folder}/chain_recovery.csv: no recovered Table 1 case")
    eg = [plateau(r) / float(r["G_ss_true_J_m2"]) - 1 for r in table1]
    el = [float(r["G_ss_err_rel"]) for r in table1]
    ej = [float(r["J_tip_err_rel"]) for r in table1]
    u_g, u_j = rms(eg), rms(ej)
    print(f"{len(table1)} Table 1 cases recovered")
    not_beam = [r["case"] for r in table1 if forward_model(folder, r["case"]) not in ("beam", "")]
    if not_beam:
        print(f"note: corrected by another model than the campaign's beam: {', '.join(not_beam)}")
    print(f"Chain accuracy of G_ss = {u_g:.4f}   (RMS relative error; max |e| {max(map(abs, eg)):.4f})")
    print(f"Chain accuracy of J_tip = {u_j:.4f}   (RMS relative error; max |e| {max(map(abs, ej)):.4f})")
    print(f"(the corrected law's own G_ss, the plateau where no correction converged: RMS "
          f"relative error {rms(el):.4f}; max |e| "
          f"{max(map(abs, el)):.4f})")
    print("case, G_B true J/m^2, G_B error J/m^2, u(G_B) J/m^2, error / u(G_B)")
    z = []
    for r in table1:
        g_true, j_true = float(r["G_ss_true_J_m2"]), float(r["J_tip_true_J_m2"])
        g, j = plateau(r), float(r["J_tip_J_m2"])
        err = (g - j) - (g_true - j_true)
        u = math.hypot(u_g * g, u_j * j)
        z.append(err / u)
        print(f"{r['case']}, {g_true - j_true:.1f}, {err:+.1f}, {u:.1f}, {err / u:+.2f}")
    print(f"RMS of error / u(G_B): {rms(z):.2f}; |error| > 1.96 u(G_B) in "
          f"{sum(abs(v) > 1.96 for v in z)} of {len(z)}")
    # The law's stresses take the fraction u(G_B)/G_B: how well that describes their errors.
    for key in ("sigma1", "sigma2"):
        zs = []
        for r in table1:
            g, j = plateau(r), float(r["J_tip_J_m2"])
            f = math.hypot(u_g * g, u_j * j) / (g - j)
            true = float(r[f"{key}_true_kPa"])
            zs.append((float(r[f"{key}_kPa"]) - true) / (f * true))
        beyond = [r["case"] for r, v in zip(table1, zs) if abs(v) > 1.96]
        print(f"{key}: RMS of error / (u(G_B)/G_B x {key}) {rms(zs):.2f}; beyond 1.96: "
              f"{', '.join(beyond) or 'none'}")
    # The J_tip the seed's fit gives before the correction by simulation (Fit/Model correction =
    # none, or a correction that did not converge).
    eu = [(float(r["J_tip_uncorrected_J_m2"]) - float(r["J_tip_true_J_m2"])) /
          float(r["J_tip_true_J_m2"]) for r in table1]
    print(f"J_tip before the correction: RMS relative error {rms(eu):.4f} (max |e| "
          f"{max(map(abs, eu)):.4f})")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "output/study_chain_beam")
