"""read_records and reduce against the scene's reduce on the shared records (the same doubles),
and bad input as fb.InputError with the command line's message."""
import math

import numpy as np
import pytest

from conftest import COLUMNS, RECORDS, SPECIMEN, read_csv, read_summary, run_cli


@pytest.fixture(scope="module")
def scene_reduce(tmp_path_factory):
    """prm/test_records.prm's reduce (the shared records, their specimen) run by the CLI."""
    out = str(tmp_path_factory.mktemp("scene_reduce"))
    run_cli("run", "prm/test_records.prm", "--set", "Run=reduce", "--set",
            f"Output directory={out}")
    return out


def without_sources(block):
    """A reduce block without the records' paths (the scene names them from its folder)."""
    block = dict(block)
    block["records"] = [{k: v for k, v in r.items() if k != "source"} for r in block["records"]]
    return block


def test_read_record_gives_the_rows_reduce_cleaned(fb, scene_reduce):
    rec = fb.read_record(RECORDS[0], columns=COLUMNS)
    assert rec.name == "DCB-01_Toughness"
    clean = read_csv(f"{scene_reduce}/record_clean_DCB-01_Toughness.csv")
    assert isinstance(rec.load_N, np.ndarray) and rec.load_N.dtype == np.float64
    assert list(rec.line) == [int(x) for x in clean["line"]]
    # The CSV holds 10 significant digits (core/csv.cc): agreement to that, not better.
    np.testing.assert_allclose(rec.load_N, clean["load_N"], rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(rec.opening_mm, clean["opening_mm"], rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(rec.a_mm, clean["a_mm"], rtol=1e-9)
    assert rec.delta_root_mm.size == 0  # these records did not measure it
    assert rec.to_dict()["name"] == rec.name


def test_reduce_gives_the_scene_s_numbers(fb, scene_reduce):
    red = fb.reduce(RECORDS, columns=COLUMNS, **SPECIMEN)
    scene = read_summary(scene_reduce)["reduce"]
    # The same block, number for number (summary.json keeps every digit of a double).
    assert without_sources(red.summary) == without_sources(scene)
    assert [r.name for r in red.records] == [r["name"] for r in scene["records"]]
    first = red.records[0]
    assert first.methods["MBT"]["plateau_J_m2"] == scene["records"][0]["MBT"]["plateau_J_m2"]
    rc = read_csv(f"{scene_reduce}/rcurve_test.csv")
    mine = [i for i, name in enumerate(rc["record"]) if name == first.name]
    assert len(mine) == len(first.a_mm) > 10
    column = lambda key: [rc[key][i] for i in mine]
    # 10 significant digits in the CSV (core/csv.cc).
    np.testing.assert_allclose(first.a_mm, column("a_mm"), rtol=1e-9)
    np.testing.assert_allclose(first.R_energy_J_m2, column("R_energy_J_m2"), rtol=1e-9)
    np.testing.assert_allclose(first.R_MBT_J_m2, column("R_MBT_J_m2"), rtol=1e-9)
    assert red.mean.n_records == 4
    assert "4 records" in repr(red)


def test_missing_file_is_an_input_error_naming_it(fb):
    with pytest.raises(fb.InputError, match="no_such_record.csv"):
        fb.reduce(["no_such_record.csv"], columns=COLUMNS, **SPECIMEN)


def test_an_unknown_section_key_is_an_input_error_naming_the_call(fb):
    with pytest.raises(fb.InputError, match=r"fiberbridge\.reduce.*Widht"):
        fb.reduce(RECORDS[:1], columns=COLUMNS, settings={"Specimen/Widht": 25})


def test_a_value_its_key_refuses_is_an_input_error(fb):
    with pytest.raises(fb.InputError, match="Crack length"):
        fb.reduce(RECORDS[:1], columns=COLUMNS, crack_length="sometimes", **SPECIMEN)


def test_a_column_map_that_matches_nothing_names_the_file(fb):
    with pytest.raises(fb.InputError, match="DCB-01_Toughness.csv"):
        fb.read_record(RECORDS[0], columns={"load_N": "Kraft"})


def test_an_unknown_keyword_is_a_type_error_listing_the_known(fb):
    with pytest.raises(TypeError, match="width_mm"):
        fb.reduce(RECORDS[:1], widht_mm=25)


def test_the_specimen_is_required_as_in_the_scene(fb):
    # No width or height given: the Specimen section's defaults are the seed's wood DCB, so the
    # reduce runs; with a width of zero it is refused by the section's own rule.
    with pytest.raises(fb.InputError):
        fb.reduce(RECORDS[:1], columns=COLUMNS, width_mm=0)
    assert math.isfinite(fb.reduce(RECORDS[:1], columns=COLUMNS, **SPECIMEN)
                         .records[0].methods["energy"]["plateau_J_m2"])


def prm_section(path, section):
    """The `set Key = value` lines of one subsection of a .prm file as {"Section/Key": value}."""
    out, inside = {}, False
    for line in open(path):
        line = line.split("#")[0].strip()
        if line == f"subsection {section}":
            inside = True
        elif inside and line == "end":
            break
        elif inside and line.startswith("set "):
            key, value = line[4:].split("=", 1)
            out[f"{section}/{key.strip()}"] = value.strip()
    return out


def test_dic_gives_the_scene_s_record_on_a_virtual_test(fb, tmp_path):
    # The FEM's virtual test (frames and machine record, a few seconds), then its own DIC scene
    # run by the command line, and the same frames through fb.dic.
    vt = tmp_path / "vt"
    run_cli("run", "prm/fem_virtual_test_pva.prm", "--set", f"Output directory={vt}")
    scene = vt / "virtual_test" / "dic_scene.prm"
    out = tmp_path / "dic_out"
    run_cli("run", str(scene), "--set", "Run=dic, reduce", "--set", f"Output directory={out}")
    settings = prm_section(scene, "DIC")
    del settings["DIC/Frames"]
    r = fb.dic(str(vt / "virtual_test" / "frames" / "dcb_*.csv"),
               vt / "virtual_test" / "machine.csv", initial_crack_mm=100, settings=settings)
    s = read_summary(out)["dic"]
    assert r.frames_used == s["frames_used"]
    rows = read_csv(out / "dic_record.csv")
    assert len(r.a_mm) == len(rows["a_mm"]) > 10
    # 10 significant digits in the CSV (core/csv.cc).
    np.testing.assert_allclose(r.a_mm, rows["a_mm"], rtol=1e-9)
    np.testing.assert_allclose(r.delta_root_mm, rows["delta_root_mm"], rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(r.load_N, rows["load_N"], rtol=1e-9, atol=1e-12)
    with pytest.raises(fb.InputError, match="DIC/Frames"):
        fb.dic(str(tmp_path / "none_*.csv"), vt / "virtual_test" / "machine.csv",
               initial_crack_mm=100, settings=settings)
    # The DicResult goes on to reduce as the scene's dic_record.csv does. The CSV holds 10
    # digits, the DicResult every bit: on this record the plateaus agree to 1e-9, so 1e-7.
    specimen = {**prm_section(scene, "Specimen"), **prm_section(scene, "Material")}
    red = fb.reduce(r, settings=specimen)
    scene_red = read_summary(out)["reduce"]["records"][0]
    assert red.records[0].delta_root_mm.size > 10  # R(delta_root) for extract
    for method in ("energy", "MBT", "CBBM"):
        assert red.records[0].methods[method]["plateau_J_m2"] == pytest.approx(
            scene_red[method]["plateau_J_m2"], rel=1e-7), method
