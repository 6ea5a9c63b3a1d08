#!/usr/bin/env python3
"""Where small rotations stop being good enough, for a DCB arm: the beam model of the thin-arm
composite (prm/lefm_thin_composite.prm, LEFM) at initiation, with Beam/Kinematics = small and
finite, at the J_tip that gives each opening/crack length; prints the small-rotation load and
opening errors against the finite ones. docs/verification.md, "Finite rotations of the beam
arms". Usage: scripts/beam_rotation_table.py [BUILD_DIR]
"""
import csv, os, subprocess, sys, tempfile

build = sys.argv[1] if len(sys.argv) > 1 else "build"
root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
scene = os.path.join(root, "prm", "lefm_thin_composite.prm")


def first_state(a0, j, kinematics):
    with tempfile.TemporaryDirectory() as out:
        subprocess.run([os.path.join(build, "fiberbridge"), "run", scene, "--set", "Run=beam",
                        "--set", "Output directory=" + out, "--set", "Specimen/Initial crack=%g" % a0,
                        "--set", "Cohesive law/J tip=%g" % j, "--set", "Beam/Kinematics=" + kinematics],
                       check=True, capture_output=True)
        rows = csv.DictReader(l for l in open(os.path.join(out, "rcurve_beam.csv")) if not l.startswith("#"))
        r = next(rows)
        return float(r["load_N"]), float(r["load_point_opening_mm"])


print("| a0 mm | J_tip J/m^2 | opening/a (finite) | load small/finite - 1 | opening small/finite - 1 |")
print("|---|---|---|---|---|")
for a0 in (35, 70):
    # The small-rotation opening/a at 500 J/m^2 scales with sqrt(J): aim at each ratio.
    P, d = first_state(a0, 500, "small")
    r500 = d / a0
    for target in (0.02, 0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4, 0.5):
        j = 500 * (target / r500) ** 2
        Ps, ds = first_state(a0, j, "small")
        Pf, df = first_state(a0, j, "finite")
        print("| %g | %.4g | %.3f | %+.3f %% | %+.3f %% |" % (a0, j, df / a0, 100 * (Ps / Pf - 1), 100 * (ds / df - 1)))
        sys.stdout.flush()
