#!/usr/bin/env python3
"""The Python module's call overhead (issue 41: under 1 % of the work): the wall time of a call
against the C++ work it runs (`compute_s`, timed inside the call around the items' own function,
with the GIL released), on reduce of a 10^5-row record (a file, and the same rows as numpy
columns) and on one FEM R curve of the defaults.
The overhead is everything else: the settings read by the scene reader (once per set of settings:
the module keeps them, source/python/python_scene.cc), the arguments, the numpy arrays and dicts
out, the package's wrapper. Medians of the calls after the first; the first is printed apart.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_overhead.py [--rows 100000] [--repeats 8]
"""
import argparse
import os
import statistics
import tempfile
import time

import numpy as np

import fiberbridge as fb

p = argparse.ArgumentParser()
p.add_argument("--rows", type=int, default=100000)
p.add_argument("--repeats", type=int, default=8)
args = p.parse_args()

# A 10^5-row record: the shared DCB-01 resampled finely in time (its crack readings held between
# readings, as a machine that logs fast writes them).
cols = {"time_s": "Time", "opening_mm": "Disp", "load_N": "Force", "a_mm": "CrackExt"}
rec = fb.read_record("data/dcb_records/DCB-01_Toughness.csv", columns=cols)
t = np.linspace(rec.time_s[0], rec.time_s[-1], args.rows)
opening = np.interp(t, rec.time_s, rec.opening_mm)
load = np.interp(t, rec.time_s, rec.load_N)
a = rec.a_mm[np.searchsorted(rec.time_s, t, side="right") - 1]
folder = tempfile.mkdtemp()
path = os.path.join(folder, "record_1e5.csv")
with open(path, "w") as f:
    f.write("time_s,opening_mm,load_N,a_mm\n")
    for row in zip(t, opening, load, a):
        f.write("%.10g,%.10g,%.10g,%.10g\n" % row)

specimen = dict(width_mm=25, height_mm=5.4, length_mm=123, E_L_MPa=19300)


def measure(name, call):
    walls, works = [], []
    for _ in range(args.repeats):
        t0 = time.perf_counter()
        r = call()
        walls.append(time.perf_counter() - t0)
        works.append(r.compute_s)
    first = walls[0] - works[0]
    walls, works = walls[1:], works[1:]
    wall, work = statistics.median(walls), statistics.median(works)
    print(f"{name}: call {wall * 1e3:.1f} ms, work {work * 1e3:.1f} ms, overhead "
          f"{(wall - work) * 1e3:.2f} ms = {100 * (wall - work) / wall:.2f} % of the call "
          f"(median of {len(walls)}); the first call with these settings "
          f"{first * 1e3:.2f} ms = {100 * first / (first + works[0]):.2f} % (it reads them)")


measure(f"reduce, {args.rows} rows", lambda: fb.reduce(path, **specimen))
# The same rows as numpy columns in memory: the columns are copied once into the record (and
# converted mm -> m) before the cleaning, which the work includes as it includes reading a file.
columns = {"time_s": t, "opening_mm": opening, "load_N": load, "a_mm": a}
measure(f"reduce, {args.rows} rows as arrays", lambda: fb.reduce(columns, **specimen))
measure("FEM R curve, defaults", lambda: fb.simulate(model="fem"))
