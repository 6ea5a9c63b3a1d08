#!/usr/bin/env python3
"""The fit's correction by simulation with the beam and with the FEM as its forward model
(Fit/Model correction = beam | fem), side by side on the chain study's cached virtual tests of the
Table 1 laws (issue 39; docs/verification.md, "The correction's forward model"). Each case's
dic_scene.prm runs `dic, reduce, extract, fit` once per model; the table gives the corrected law's
errors against the case's truth, with G_ss both as extract's plateau of the record and as the
corrected law's own J_tip + J1 + J2 (summary.json's trilinear_corrected G_ss_J_m2). Usage, from
the repository root, after the chain study has written its cases:

    build/fiberbridge run prm/study_chain.prm
    python3 scripts/correction_models.py output/study_chain [case ...]

(about 2 s a case with the beam and 3-5 s with the FEM, 2 cores.)
"""
import csv
import json
import os
import subprocess
import sys

TABLE1 = [f"{m}_c{c}" for m in ("PVA", "EPI", "PRF", "PF", "DF") for c in (0, 8, 16, 24)]


def truth(study):
    with open(os.path.join(study, "chain_recovery.csv")) as f:
        return {r["case"]: r for r in csv.DictReader(l for l in f if not l.startswith("#"))}


def run(study, case, model, out):
    scene = os.path.join(study, "cases", case, "fem", "virtual_test", "dic_scene.prm")
    subprocess.run([os.environ.get("FIBERBRIDGE_BIN", "build/fiberbridge"), "run", scene,
                    "--set", "Run=dic, reduce, extract, fit",
                    "--set", f"Fit/Model correction={model}", "--set", "FEM/Element size=2",
                    "--set", f"Output directory={out}"],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def pct(got, true):
    return f"{100 * (got - float(true)) / float(true):+.1f}"


def main(study, cases):
    t = truth(study)
    print("| case | model | runs | forward s | J_tip | G_ss (law) | G_ss (record) | delta_c | "
          "sigma1 | sigma2 |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for case in cases:
        for model in ("beam", "fem"):
            s = run(study, case, model, os.path.join(study, "correction_models", case, model))
            fc, r = s["fit_correction"], t[case]
            if not fc["converged"]:
                print(f"| {case} | {model} | {fc['simulations']} | {fc['forward_time_s']:.2f} | "
                      f"not converged: {'; '.join(fc['notes'])} |")
                continue
            k = s["trilinear_corrected"]
            print(f"| {case} | {model} | {fc['forward_runs']} | {fc['forward_time_s']:.2f} | "
                  f"{pct(k['J_tip_J_m2'], r['J_tip_true_J_m2'])} | "
                  f"{pct(k['G_ss_J_m2'], r['G_ss_true_J_m2'])} | "
                  f"{pct(s['G_ss_J_m2'], r['G_ss_true_J_m2'])} | "
                  f"{pct(k['delta_c_mm'], r['delta_c_true_mm'])} | "
                  f"{pct(k['sigma1_kPa'], r['sigma1_true_kPa'])} | "
                  f"{pct(k['sigma2_kPa'], r['sigma2_true_kPa'])} |")


if __name__ == "__main__":
    args = sys.argv[1:]
    main(args[0] if args else "output/study_chain", args[1:] or TABLE1 + ["long_zone"])
