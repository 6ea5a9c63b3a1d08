"""Shared by the module's tests: the package from the build tree (PYTHONPATH, set by ctest), the
command line beside it (FIBERBRIDGE_BIN), the shared records, and a fresh folder per test. Run
from the source tree (ctest's working directory) so the bundled scenes' paths hold."""
import csv
import json
import os
import subprocess

import pytest

BIN = os.environ.get("FIBERBRIDGE_BIN", "build/fiberbridge")
RECORDS = [f"data/dcb_records/DCB-0{k}_Toughness.csv" for k in (1, 2, 3, 5)]
# The shared records' columns and specimen (prm/test_records.prm, data/dcb_records/README.md).
COLUMNS = {"time_s": "Time", "opening_mm": "Disp", "load_N": "Force", "a_mm": "CrackExt"}
SPECIMEN = dict(width_mm=25, height_mm=5.4, length_mm=123, E_L_MPa=19300, E_T_MPa=6110,
                G_LT_MPa=2288, nu_LT=0.3)


def run_cli(*args):
    """The command line with `args`; its stdout, or the test fails with its stderr."""
    p = subprocess.run([BIN, *args], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    return p.stdout


def read_csv(path):
    """A CSV of ours (comment lines start with '#') as {column: [values]}: numbers as floats (an
    empty cell NaN), text as it is."""
    def value(v):
        if v in ("", None):
            return float("nan")
        try:
            return float(v)
        except ValueError:
            return v
    with open(path) as f:
        rows = [line for line in f if not line.startswith("#")]
    reader = csv.DictReader(rows)
    cols = {k: [] for k in reader.fieldnames}
    for row in reader:
        for k, v in row.items():
            cols[k].append(value(v))
    return cols


def read_summary(folder):
    with open(os.path.join(folder, "summary.json")) as f:
        return json.load(f)


@pytest.fixture
def fb():
    import fiberbridge
    return fiberbridge


@pytest.fixture
def out(tmp_path):
    return str(tmp_path)
