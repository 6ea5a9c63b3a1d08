"""reduce and identify on records a script holds (issue 41): a Record that read_record gave, a
mapping of numpy columns, a DicResult. They go through the reader's one cleaning and its
refusals, as a file's rows do; the arrays out in unchanged units are read-only views."""
import gc

import numpy as np
import pytest

from conftest import COLUMNS, RECORDS, SPECIMEN

# A record the beam wrote, with delta_root (tests/app/data/records/README: its header says how).
BEAM_RECORD = "tests/app/data/records/beam_delta_root.csv"
BEAM_SPECIMEN = dict(width_mm=25, height_mm=5.4, length_mm=123)
R_COLUMNS = ("R_energy_J_m2", "R_MBT_J_m2", "R_CC_J_m2", "R_MCC_J_m2", "R_CBBM_J_m2")


def assert_same_reduction(a, b):
    """Two reductions of the same records, to round-off: handing a Record back converts its
    columns mm -> m once more, which may move the last bit of an opening or crack length."""
    assert [r.name for r in a.records] == [r.name for r in b.records]
    for x, y in zip(a.records, b.records):
        assert len(x.a_mm) == len(y.a_mm) > 10, x.name
        np.testing.assert_allclose(x.a_mm, y.a_mm, rtol=1e-12)
        for c in R_COLUMNS:
            np.testing.assert_allclose(getattr(x, c), getattr(y, c), rtol=1e-9, err_msg=c)
        for method, values in x.methods.items():
            for key, v in values.items():
                assert v == pytest.approx(y.methods[method][key], rel=1e-9), (x.name, method, key)


def test_records_read_then_handed_back_reduce_as_their_files(fb):
    by_path = fb.reduce(RECORDS, columns=COLUMNS, **SPECIMEN)
    records = [fb.read_record(p, columns=COLUMNS) for p in RECORDS]
    assert_same_reduction(by_path, fb.reduce(records, **SPECIMEN))
    # A record in memory is cleaned again: the cleaning of cleaned rows changes nothing more.
    again = fb.reduce(records[0], **SPECIMEN).records[0]
    assert not any("spike" in c for c in again.cleaning), again.cleaning


def test_columns_in_memory_reduce_as_the_file_holding_them(fb):
    with open(BEAM_RECORD) as f:
        rows = [line.strip().split(",") for line in f if not line.startswith("#")]
    # Empty cells (the crack read every 2 s) are NaN: rows without a reading, as in the file.
    columns = {name: np.array([float(r[k]) if r[k] else np.nan for r in rows[1:]])
               for k, name in enumerate(rows[0])}
    columns["name"] = "beam_delta_root"
    by_path = fb.reduce(BEAM_RECORD, **BEAM_SPECIMEN)
    in_memory = fb.reduce(columns, **BEAM_SPECIMEN)
    assert_same_reduction(by_path, in_memory)
    np.testing.assert_allclose(in_memory.records[0].delta_root_mm,
                               by_path.records[0].delta_root_mm, rtol=1e-12)
    # ... and on to the law, as from the file.
    e_path, e_mem = fb.extract(by_path, delta_c_mm=4), fb.extract(in_memory, delta_c_mm=4)
    assert e_mem.J_tip_J_m2 == pytest.approx(e_path.J_tip_J_m2, rel=1e-9)
    np.testing.assert_allclose(e_mem.sigma_eq5_kPa, e_path.sigma_eq5_kPa, rtol=1e-9, atol=1e-9)


def test_a_record_without_crack_readings_reduces_against_the_equivalent_crack(fb):
    rec = fb.read_record(RECORDS[0], columns=COLUMNS)
    no_crack = {"time_s": rec.time_s, "opening_mm": rec.opening_mm, "load_N": rec.load_N}
    red = fb.reduce(no_crack, initial_crack_mm=rec.a_mm[0], **SPECIMEN)
    assert red.records[0].crack == "equivalent"
    assert red.records[0].name == "record1"


def bad(fb, data, match):
    with pytest.raises(fb.InputError, match=match):
        fb.reduce(data, **SPECIMEN)


def test_bad_columns_in_memory_are_input_errors_naming_the_record(fb):
    rec = fb.read_record(RECORDS[0], columns=COLUMNS)
    n = len(rec.load_N)
    bad(fb, {"opening_mm": rec.opening_mm, "load_N": rec.load_N[:-1]},
        r"records\[0\] 'record1'.*opening_mm has %d values and load_N %d" % (n, n - 1))
    bad(fb, {"opening_mm": rec.opening_mm}, r"records\[0\] has no load_N")
    bad(fb, {"opening_mm": rec.opening_mm, "load_kN": rec.load_N / 1e3},
        r"unknown column\(s\) load_kN; expected time_s, opening_mm, load_N")
    bad(fb, [rec, rec], "record name 'DCB-01_Toughness' repeats a record")
    bad(fb, {"opening_mm": rec.opening_mm, "load_N": ["1.5 kN"] * n},
        r"records\[0\] 'record1': column load_N is not numbers")
    # What the reader refuses in a file it refuses in arrays, naming the row: crack readings
    # 5 mm behind the ones before from row 201 on (a crack does not heal).
    a = rec.a_mm.copy()
    a[200:] -= 5
    bad(fb, {"opening_mm": rec.opening_mm, "load_N": rec.load_N, "a_mm": a, "name": "S1"},
        r"records\[0\] 'S1' \(arrays; line n is row n, from 1\).*201")
    with pytest.raises(TypeError, match=r"records\[1\] is a int"):
        fb.reduce([rec, 3], **SPECIMEN)
    # A reduced record has a row per crack reading, not the test's rows: not a record.
    reduced = fb.reduce(rec, **SPECIMEN).records[0]
    with pytest.raises(TypeError, match=r"records\[0\] is a ReducedRecord"):
        fb.reduce(reduced, **SPECIMEN)


def test_arrays_in_their_own_unit_are_read_only_views_that_keep_the_result(fb):
    red = fb.reduce(RECORDS[0], columns=COLUMNS, **SPECIMEN)
    R = red.records[0].R_energy_J_m2
    expected = R.copy()
    assert not R.flags.writeable and not R.flags.owndata
    with pytest.raises(ValueError):
        R[0] = 0
    del red
    gc.collect()
    np.testing.assert_array_equal(R, expected)  # the view kept the outcome alive


class Stop(Exception):
    pass


def test_progress_gets_a_line_per_record_and_can_stop_the_call(fb):
    lines = []
    fb.reduce(RECORDS, columns=COLUMNS, progress=lines.append, **SPECIMEN)
    assert lines == [f"reduce: DCB-0{k}_Toughness ({i + 1}/4)"
                     for i, k in enumerate((1, 2, 3, 5))]

    def stop(line):
        if "(2/4)" in line:
            raise Stop(line)
    with pytest.raises(Stop, match="DCB-02"):
        fb.reduce(RECORDS, columns=COLUMNS, progress=stop, **SPECIMEN)


SMALL = {"Identify/Starts": 1, "Identify/Max evaluations": 30, "Identify/Tolerance": 1e-3,
         "Identify/Number of elements": 40, "Identify/Tip advance": 2}


def test_identify_takes_a_record_in_memory_as_its_file(fb):
    path = "data/dcb_records/DCB-05_Toughness.csv"
    by_path = fb.identify(path, columns=COLUMNS, settings=SMALL, **SPECIMEN)
    by_record = fb.identify(fb.read_record(path, columns=COLUMNS), settings=SMALL, **SPECIMEN)
    for key in ("delta1_mm", "sigma1_kPa", "sigma2_kPa", "delta_c_mm", "J_tip_J_m2"):
        assert getattr(by_record, key) == pytest.approx(getattr(by_path, key), rel=1e-6), key
    assert not by_record.records[0].load_N.flags.writeable
