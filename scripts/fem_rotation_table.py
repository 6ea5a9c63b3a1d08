#!/usr/bin/env python3
"""Where small strain stops being good enough in the FEM: the LEFM composite of
prm/lefm_thin_composite.prm at initiation with FEM/Kinematics = small and finite, J_tip scanned to
set the opening over crack length; prints the small-strain load and opening errors against the
finite ones, the finite load against the beam model's elastica (Beam/Kinematics = finite), and
the cost of each kinematics (model wall time, Newton iterations). docs/verification.md, "Finite
rotations of the FEM arms". Usage: scripts/fem_rotation_table.py [BUILD_DIR]
"""
import csv, json, os, subprocess, sys, tempfile

build = sys.argv[1] if len(sys.argv) > 1 else "build"
root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
scene = os.path.join(root, "prm", "lefm_thin_composite.prm")


def first_state(j, kinematics):
    """(load N, opening mm, FEM wall s, Newton iterations, elastica load N) at initiation."""
    with tempfile.TemporaryDirectory() as out:
        subprocess.run([os.path.join(build, "fiberbridge"), "run", scene, "--set", "Run=fem, beam",
                        "--set", "Output directory=" + out, "--set", "Cohesive law/J tip=%g" % j,
                        "--set", "FEM/Kinematics=" + kinematics, "--set", "Beam/Kinematics=finite",
                        "--set", "FEM/Steady-state window=2", "--set", "FEM/Output every=0"],
                       check=True, capture_output=True)
        def row(name):
            return next(csv.DictReader(l for l in open(os.path.join(out, name)) if not l.startswith("#")))
        fem, beam = row("rcurve_fem.csv"), row("rcurve_beam.csv")
        summary = json.load(open(os.path.join(out, "summary.json")))["fem"]
        return (float(fem["load_N"]), float(fem["load_point_opening_mm"]), summary["wall_time_s"],
                summary["newton_iterations"], float(beam["load_N"]))


print("| J_tip J/m^2 | opening/a (finite) | load small/finite - 1 | opening small/finite - 1 "
      "| finite load / elastica - 1 | wall small s | wall finite s | Newton small | Newton finite |")
print("|---|---|---|---|---|---|---|---|---|")
for j in (5, 500, 2000, 5000, 10000, 20000):
    Ps, ds, ts, ns, _ = first_state(j, "small")
    Pf, df, tf, nf, Pe = first_state(j, "finite")
    print("| %g | %.3f | %+.3f %% | %+.3f %% | %+.3f %% | %.3f | %.3f | %d | %d |"
          % (j, df / 35, 100 * (Ps / Pf - 1), 100 * (ds / df - 1), 100 * (Pf / Pe - 1), ts, tf, ns, nf))
    sys.stdout.flush()
