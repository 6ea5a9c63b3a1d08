"""cmake --install puts a package that imports and runs without the build tree (issue 41): into
a staging root (DESTDIR), then imported from there alone by a fresh interpreter."""
import os
import subprocess
import sys

from conftest import BIN


def test_the_installed_package_runs_on_its_own(tmp_path):
    build = os.path.dirname(os.path.abspath(BIN))
    stage = tmp_path / "root"
    env = dict(os.environ, DESTDIR=str(stage))
    p = subprocess.run(["cmake", "--install", build], env=env, capture_output=True, text=True)
    assert p.returncode == 0, p.stdout + p.stderr
    found = [root for root, _, files in os.walk(stage) if "__init__.py" in files and
             os.path.basename(root) == "fiberbridge"]
    assert len(found) == 1, found
    site = os.path.dirname(found[0])
    # Only the staged package on the path: not the build tree's (PYTHONPATH is replaced).
    env = dict(os.environ, PYTHONPATH=site, OMPI_MCA_ess_singleton_isolated="1")
    script = ("import fiberbridge as fb; print(fb.__file__); "
              "e = fb.extract('data/sample_rdelta_pva_control.csv'); "
              "print(round(e.G_ss_J_m2))")
    p = subprocess.run([sys.executable, "-c", script], env=env, capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    where, g_ss = p.stdout.split()
    assert where.startswith(str(stage)), where
    assert 1000 < int(g_ss) < 1200  # the sample's PVA control law: G_ss 1082 J/m^2
