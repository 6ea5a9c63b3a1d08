#!/usr/bin/env python3
"""Thin-arm FEM ladder: prm/lefm_thin_composite.prm at several element sizes and polynomial
degrees; for each run the mesh (cells, DoFs), the initiation load against corrected beam theory
(CBT, the closed form of source/law/specimen.cc), R_J at initiation against J_tip, the largest
|load/CBT - 1| over the recorded advances, and how the run ended. docs/verification.md,
"Thin arms". Usage: scripts/thin_arm_fem_ladder.py [BUILD_DIR] [--set K=V]...
Environment: THIN_LADDER_SIZES (comma-separated element sizes in mm, default 2,1,0.675,0.5,0.25,0.125)
and THIN_LADDER_DEGREES (default 1,2).
"""
import csv, json, math, os, re, subprocess, sys, tempfile

build = sys.argv[1] if len(sys.argv) > 1 and not sys.argv[1].startswith("--") else "build"
extra = [a for a in sys.argv[1:] if a != build]
root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
scene = os.path.join(root, "prm", "lefm_thin_composite.prm")
# The scene's specimen (SI): arm h, width B, moduli; J_tip.
h, B, E_L, E_T, G_LT, j_tip = 2.7e-3, 25e-3, 19.3e9, 6.11e9, 2.288e9, 500.0
gamma = 1.18 * math.sqrt(E_L * E_T) / G_LT
g = gamma / (1 + gamma)
chi = math.sqrt(E_L / (11 * G_LT) * (3 - 2 * g * g))


def cbt_load(a):
    return math.sqrt(j_tip * B * B * h**3 * E_L / 12) / (a + chi * h)


sizes = [float(v) for v in os.environ.get("THIN_LADDER_SIZES", "2,1,0.675,0.5,0.25,0.125").split(",")]
degrees = [int(v) for v in os.environ.get("THIN_LADDER_DEGREES", "1,2").split(",")]
print("| degree | element mm | cells | DoFs | load/CBT - 1 at a0 | max abs over growth | R_J/J_tip - 1 at a0 | outcome |")
print("|---|---|---|---|---|---|---|---|")
for degree in degrees:
    for size in sizes:
        with tempfile.TemporaryDirectory() as out:
            cmd = [os.path.join(build, "fiberbridge"), "run", scene, "--set", "Run=fem",
                   "--set", "Output directory=" + out, "--set", "FEM/Element size=%g" % size,
                   "--set", "FEM/Polynomial degree=%d" % degree]
            for e in extra:
                if e != "--set":
                    cmd += ["--set", e]
            p = subprocess.run(cmd, capture_output=True, text=True)
            log = p.stdout + p.stderr
            cells = dofs = "?"
            for line in log.splitlines():
                m = re.search(r"(\d+) cells, (\d+) dofs", line)
                if line.startswith("fem") and m:
                    cells, dofs = m.group(1), m.group(2)
            rc = os.path.join(out, "rcurve_fem.csv")
            if p.returncode != 0 or not os.path.exists(rc):
                why = log.strip().splitlines()[-1] if log.strip() else "no output"
                print("| Q%d | %g | %s | %s | | | | failed: %s |" % (degree, size, cells, dofs, why[:160]))
                continue
            rows = [r for r in csv.DictReader(l for l in open(rc) if not l.startswith("#"))]
            first = rows[0]
            err0 = float(first["load_N"]) / cbt_load(float(first["a_mm"]) * 1e-3) - 1
            errmax = max(abs(float(r["load_N"]) / cbt_load(float(r["a_mm"]) * 1e-3) - 1) for r in rows)
            rj = float(first["R_J_J_m2"]) / j_tip - 1
            notes = json.load(open(os.path.join(out, "summary.json")))
            fem = notes.get("fem", notes)
            stop = "%d advances" % len(rows)
            for n in fem.get("notes", []):
                if "no equilibrium" in n or "stopped" in n:
                    stop += "; " + n[:160]
            print("| Q%d | %g | %s | %s | %+.2f %% | %.2f %% | %+.2f %% | %s |" %
                  (degree, size, cells, dofs, 100 * err0, 100 * errmax, 100 * rj, stop))
        sys.stdout.flush()
